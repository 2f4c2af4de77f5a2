//! `--raw` and `--no-ranges`: the canonical selection among optimal solutions of `settle` and
//! `limit` (docs/canonical.md), and its lines in the summaries.

use clap::Args;
use std::fmt::Write as _;
use voussoir::analysis::canonical::{Canonical, Selection};
use voussoir::result::Spatial;

#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Canonical solution")]
pub struct CanonicalArgs {
    /// Report the solver's own optimal solution (a vertex with simplex, an interior point with
    /// clarabel) instead of the canonical one (the default in 2D and 3D): faster, but when the
    /// optimum is not unique the crack pattern and the forces depend on --method
    /// (docs/canonical.md). With --non-associative (2D): the last iterate's own mechanism
    /// instead of the least crack area among the optima of its program.
    #[arg(long)]
    pub raw: bool,
    /// Skip the ranges of the support reactions over the optimal force fields (2 LPs per
    /// reaction component of every loaded support; computed by default on 2D models of at most
    /// 500 blocks, not on 3D models).
    #[arg(long, conflicts_with = "ranges")]
    pub no_ranges: bool,
    /// Compute the reaction ranges whatever the model's size and dimension (in 3D: minutes on
    /// a model of a few hundred blocks).
    #[arg(long)]
    pub ranges: bool,
    /// Relative precision REL of the least friction coefficient μ that an optimal force field
    /// needs on the joints without friction of their own (a bisection; default 0.05: the field
    /// is selected at a μ within 5 % of the least). Finer precision costs programs at μ just
    /// short of the least, the costly ones: 1e-4 took 89 s instead of 13 s on a 3,200-block
    /// wall (docs/canonical.md). Without it, on large models (force programs of 20,000 columns
    /// and more, about 1,800 blocks in 2D) the search stops where μ = 2, above masonry's
    /// friction, is shown inadmissible, and states the bracket; given, it searches on.
    #[arg(long, value_name = "REL")]
    pub least_friction_precision: Option<f64>,
}

/// `capacity`, `tilt` and `sweep`: the canonical mechanism is their default too (least crack
/// area among the optimal mechanisms, then a generic tie-break; docs/canonical.md).
#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Canonical solution")]
pub struct RawArgs {
    /// Report the solver's own optimal mechanisms instead of the canonical ones (the default in
    /// 2D and 3D): faster, but where the optimum is not unique the hinges and cracks depend on
    /// --method; λ, the critical tilt and the works are the same either way
    /// (docs/canonical.md). Where the selection does not apply (the exact friction cone, conic
    /// crushing, non-associative friction) the solver's own is reported anyway.
    #[arg(long)]
    pub raw: bool,
}

/// `limit`'s flags: the canonical selection is opt-in there (docs/canonical.md: on a symmetric
/// arch the generic tie-break picks one of two mirror mechanisms).
#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Canonical solution")]
pub struct LimitCanonicalArgs {
    /// Report the canonical collapse mechanism and forces (least crack area among the optimal
    /// mechanisms, then a generic tie-break; physical forces of least complementary energy)
    /// instead of the solver's own (docs/canonical.md). With --non-associative: the mechanism
    /// of least crack area (openings and slips) among the optima of the last iterate's program;
    /// the forces stay the iteration's.
    #[arg(long)]
    pub canonical: bool,
    /// With --canonical: skip the ranges of the support reactions.
    #[arg(long)]
    pub no_ranges: bool,
    /// With --canonical: relative precision REL of the least friction coefficient μ that an optimal force field
    /// needs on the joints without friction of their own (a bisection; default 0.05: the field
    /// is selected at a μ within 5 % of the least). Finer precision costs programs at μ just
    /// short of the least, the costly ones: 1e-4 took 89 s instead of 13 s on a 3,200-block
    /// wall (docs/canonical.md). Without it, on large models the search stops where μ = 2 is
    /// shown inadmissible, and states the bracket (as `settle`).
    #[arg(long, value_name = "REL")]
    pub least_friction_precision: Option<f64>,
}

/// The summary lines of a canonical selection.
pub fn summary<D: Spatial>(c: &Option<Canonical<D>>) -> String {
    let mut s = String::new();
    let Some(c) = c else {
        return s;
    };
    let m = &c.mechanism;
    let how = match m.selected_by {
        Selection::Optimum => "the optimal mechanism is unique",
        Selection::LeastCrackArea => {
            "the optimal mechanism is not unique: the one of least crack area (unique) is reported"
        }
        Selection::GenericVertex => {
            "the optimal mechanism is not unique, nor the one of least crack area: of those, the vertex fixed by the generic tie-break is reported"
        }
    };
    let _ = writeln!(
        s,
        "canonical: {how} (crack area {:.6e}, solver's {:.6e})",
        m.crack_area, m.crack_area_solver
    );
    if let Some(f) = &c.forces {
        let _ = writeln!(s, "{}", f.summary_line());
        for r in &f.rejected {
            if let (None, Some(why)) = (r.gap, &r.reason) {
                let _ = writeln!(
                    s,
                    "canonical forces: {} not computed: {why}",
                    r.field.name()
                );
            }
        }
        let list: Vec<String> = f
            .rejected
            .iter()
            .filter_map(|r| {
                r.gap
                    .map(|g| format!("{} (duality gap {:.1e})", r.field.name(), g))
            })
            .collect();
        if !list.is_empty() {
            let _ = writeln!(
                s,
                "canonical forces: not reported, their duality certificate failing with the mechanism: {}",
                list.join(", ")
            );
        }
        let ranged: Vec<&str> = f
            .reaction_ranges
            .iter()
            .filter(|r| !r.unique)
            .map(|r| r.support.as_str())
            .collect();
        if !f.reaction_ranges.is_empty() {
            if ranged.is_empty() {
                let _ = writeln!(
                    s,
                    "every support reaction is the same in every optimal field"
                );
            } else {
                let _ = writeln!(
                    s,
                    "reactions not unique over the optimal fields (ranges in the JSON): {}",
                    ranged.join(", ")
                );
            }
        }
    }
    s
}
