//! `--adapt` of `settle` and `limit` (2D): crack lines moved to their optimal position
//! (docs/cracks.md, "Adapted crack lines").

use crate::common::{Fail, Input};
use clap::Args;
use std::path::{Path, PathBuf};
use voussoir::analysis::adapt::{AdaptOptions, AdaptRecord, Objective};
use voussoir::model::Model;
use voussoir::model3d::AnyModel;
use voussoir::request::{AnyResult, Hooks, Request};

#[derive(Args, Clone, Debug)]
#[command(next_help_heading = "Adapted crack lines (2D)")]
pub struct AdaptArgs {
    /// Mesh-independent cracks: cut straight crack lines into the mesh along the cracks found
    /// and move their ends along the wall's outline (golden-section search) to the position that
    /// maximises the work of the dead loads (settle) or minimises λ (limit); iterate until the
    /// relative change is below --adapt-tol twice in a row. 2D models whose blocks tile one outline
    /// (docs/cracks.md). The result is the analysis of the adapted mesh plus an `adapt` record.
    #[arg(long)]
    pub adapt: bool,
    /// Largest number of adaptation iterations [default: 4].
    #[arg(long, value_name = "N")]
    pub adapt_iterations: Option<usize>,
    /// Converged when the work (λ) changes by less than this fraction in two iterations in a
    /// row [default: 0.005].
    #[arg(long, value_name = "TOL")]
    pub adapt_tol: Option<f64>,
    /// Crack lines placed by the global stage before the local iterations, greedily, among
    /// candidate lines from the outline's corners and the settling zone's ends (0: no global
    /// stage) [default: 3].
    #[arg(long, value_name = "N")]
    pub adapt_global: Option<usize>,
    /// Directions of the global stage's fan of candidate lines from each key point, over the
    /// full circle (at least 4) [default: 36, every 10°].
    #[arg(long, value_name = "N")]
    pub adapt_fan: Option<usize>,
    /// Write the adapted model (the mesh with the crack lines cut in, its supports' motions and
    /// joint laws as analysed) as a model JSON to FILE, atomically, as soon as the adaptation
    /// ends and before the final analysis runs on it: `settle FILE` (`limit FILE`) with the same
    /// options gives the same result without adapting again.
    #[arg(long, value_name = "FILE")]
    pub adapted_model: Option<PathBuf>,
}

impl AdaptArgs {
    /// The adaptation's settings, `None` without `--adapt`.
    pub fn options(&self) -> Result<Option<AdaptOptions>, Fail> {
        if !self.adapt {
            if self.adapt_iterations.is_some() {
                return Err(Fail("--adapt-iterations goes with --adapt".into()));
            }
            if self.adapt_tol.is_some() {
                return Err(Fail("--adapt-tol goes with --adapt".into()));
            }
            if self.adapt_global.is_some() {
                return Err(Fail("--adapt-global goes with --adapt".into()));
            }
            if self.adapt_fan.is_some() {
                return Err(Fail("--adapt-fan goes with --adapt".into()));
            }
            if self.adapted_model.is_some() {
                return Err(Fail("--adapted-model goes with --adapt".into()));
            }
            return Ok(None);
        }
        let mut o = AdaptOptions::default();
        if let Some(n) = self.adapt_iterations {
            if n == 0 {
                return Err(Fail("--adapt-iterations must be at least 1".into()));
            }
            o.iterations = n;
        }
        if let Some(t) = self.adapt_tol {
            if !(t > 0.0 && t.is_finite()) {
                return Err(Fail(format!(
                    "--adapt-tol must be a positive number (got {t})"
                )));
            }
            o.tolerance = t;
        }
        if let Some(n) = self.adapt_global {
            o.global_lines = n;
        }
        if let Some(n) = self.adapt_fan {
            if n < 4 {
                return Err(Fail(format!("--adapt-fan must be at least 4 (got {n})")));
            }
            o.fan = n;
        }
        Ok(Some(o))
    }
}

/// Run `req` on `model`, with `--adapted-model` honoured: the adapted model written
/// (atomically) once the adaptation ends, before the final analysis, so that a long final
/// analysis can be stopped and run again on it. Refused before anything runs when the file is
/// the input model.
pub fn run(
    input: &Input,
    model: &AnyModel,
    req: &Request,
    out: Option<&Path>,
) -> Result<AnyResult, Fail> {
    let Some(path) = out else {
        return input.run(model, req);
    };
    if let (Ok(a), Ok(b)) = (
        std::fs::canonicalize(path),
        std::fs::canonicalize(&input.path),
    ) {
        if a == b {
            return Err(Fail(format!(
                "refusing to write {}: it is the input {}",
                path.display(),
                input.path.display()
            )));
        }
    }
    let mut failed: Option<Fail> = None;
    let mut write = |m: &Model, rec: &AdaptRecord| {
        let r = voussoir_io::files::to_json(m).and_then(|json| {
            voussoir_io::write_all_or_nothing(&[(path, json.as_bytes())], &[&input.path])
        });
        match r {
            Ok(()) => eprintln!(
                "wrote {} (the adapted model: {} blocks, {} crack line{})",
                path.display(),
                m.blocks.len(),
                rec.lines.len(),
                if rec.lines.len() == 1 { "" } else { "s" }
            ),
            Err(e) => failed = Some(Fail(format!("--adapted-model: {}", e.0))),
        }
    };
    let r = input.run_with(
        model,
        req,
        &mut Hooks {
            adapted: Some(&mut write),
            ..Hooks::default()
        },
    );
    match failed {
        Some(e) => Err(e),
        None => r,
    }
}

/// The summary lines of an adaptation.
pub fn summary(r: &AdaptRecord) -> String {
    let what = match r.objective {
        Objective::SettlementWork => "work",
        Objective::LoadMultiplier => "λ",
    };
    let unit = match r.objective {
        Objective::SettlementWork => " kN·m",
        Objective::LoadMultiplier => "",
    };
    let n = r.iterations.len().saturating_sub(1);
    let mut s = format!(
        "adapted crack lines: {} ({} iteration{}, tolerance {}), {} line{}\n",
        if r.converged {
            "converged"
        } else {
            "NOT converged"
        },
        n,
        if n == 1 { "" } else { "s" },
        r.tolerance,
        r.lines.len(),
        if r.lines.len() == 1 { "" } else { "s" },
    );
    for it in &r.iterations {
        s += &format!(
            "  iteration {}{}: {} blocks, {} line{}, {what} {:.6}{unit}{}, {} search solves, {:.1} s\n",
            it.iteration,
            if it.global { " (global stage)" } else { "" },
            it.blocks,
            it.lines,
            if it.lines == 1 { "" } else { "s" },
            it.value,
            if it.certified { " (certified)" } else { " (NOT certified)" },
            it.evaluations,
            it.time
        );
    }
    for (k, l) in r.lines.iter().enumerate() {
        s += &format!(
            "  line {}: ({:.4}, {:.4}) to ({:.4}, {:.4}) m\n",
            k + 1,
            l[0][0],
            l[0][1],
            l[1][0],
            l[1][1]
        );
    }
    s
}
