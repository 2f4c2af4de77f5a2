//! Mesh-independent cracks (issue 30, item 2; docs/cracks.md, "Adapted crack lines").
//!
//! A rigid-block model cracks only along its element edges, so its crack pattern and its work
//! (or λ) depend on the mesh. Following the route the paper announces as future work (Milani
//! and Lourenço 2009, Milani 2015: interfaces moved onto the failure lines by sequential linear
//! programming; Chiozzi, Milani and Tralli 2017, Grillanda et al. 2021: a few crack lines
//! placed by a search that maximises the work or minimises λ), the crack lines are here
//! *inserted into the mesh and moved*:
//!
//! 1. Solve the paper's program on the model as given (iteration 0).
//!
//!    *Global stage* (`global_lines` > 0; iteration 1 of the record, `global: true`): the key
//!    points of the outline — its corners at the scale of an element and the ends of the
//!    settling zone — and from each the chords into the wall over a fan of `fan` directions
//!    (and through it where both sides are wall) are the candidate crack lines; they depend on
//!    the outline and the supports, not on the mesh. Each is cut into the mesh alone and solved
//!    once (the search trial below); the best is kept if it gains, then the next line is chosen
//!    the same way with it held (later rounds among the 12 best of the first), up to
//!    `global_lines`; each chosen line's far end is refined by golden section over one step of
//!    the fan. A greedy version of the placement of crack lines by a search (Chiozzi, Milani
//!    and Tralli 2017; Grillanda et al. 2021), so that the local stage starts from the same
//!    mechanism whatever the mesh.
//! 2. Read its crack polylines ([`crate::result::cracks`]); simplify each (Douglas–Peucker, to
//!    the element size) into straight runs, and extend every run that is not already a crack
//!    line to the wall's outline (the union of the blocks, its outer boundary and openings):
//!    a *crack line* is a chord of the wall between two points of its outline.
//! 3. Cut every element a crack line crosses into two along the line (exactly: the new
//!    vertices lie on the line), so that the two sides can open as a wedge about any point of
//!    it. A cut only adds freedom: the previous mechanism is still admissible, so the work
//!    never decreases (λ never increases).
//! 4. Move each end of each new crack line along the outline by a golden-section search of
//!    the work (λ) over an arc of the outline (`reach` of the wall's diagonal), the other
//!    lines held, every trial geometry cut afresh from the original mesh and solved (settle:
//!    the motion LP by Clarabel, its optimal value only); a move is kept only if it improves
//!    the objective. Lines of earlier iterations keep their positions.
//! 5. Solve the best geometry in full (certified) and repeat from 2 until the relative change
//!    of the objective is below `tolerance` in two iterations in a row, or no new crack line
//!    appears, or `iterations` are done.
//!
//! The search trials solve the settlement's motion LP only (or the limit analysis); each
//! iteration's reported result is the full analysis with its certificate. The library does no
//! I/O; the times in the record are wall-clock seconds (they are the only non-deterministic
//! numbers of an adapted result).

use crate::error::{Error, Result};
use crate::geometry::{
    area_centroid, cross, dot, norm, point_segment_distance, strictly_inside, sub,
};
use crate::lp::{self, LpStatus, SolverOptions};
use crate::model::{Block, Load, Model, Point};
pub use crate::result::adapt::{AdaptIteration, AdaptRecord, Adapted, Objective};
use crate::result::cracks::Crack;
use crate::result::BodyName;
use crate::structure::{BuildOptions, Structure};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use std::time::Instant;

/// Settings of the adaptation.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AdaptOptions {
    /// Largest number of adaptation iterations (after the unadapted solve).
    pub iterations: usize,
    /// Converged when the relative change of the objective is below this in two iterations in a
    /// row.
    pub tolerance: f64,
    /// Largest number of new crack lines taken from one iteration's cracks.
    pub lines_per_iteration: usize,
    /// Solves of the golden-section search per crack-line end.
    pub evaluations: usize,
    /// Half the arc of the outline searched for each end, as a fraction of the wall's diagonal.
    pub reach: f64,
    /// Crack lines placed by the global stage before the local one (0: no global stage;
    /// settlement only, `limit_adapt` has none): each
    /// chosen greedily, one at a time, among the candidate lines from the outline's corners
    /// and the ends of the settling zone over a fan of directions.
    pub global_lines: usize,
    /// Directions of the global stage's fan, over the full circle (36: every 10°).
    pub fan: usize,
}

impl Default for AdaptOptions {
    fn default() -> Self {
        AdaptOptions {
            iterations: 4,
            tolerance: 0.005,
            lines_per_iteration: 3,
            evaluations: 5,
            reach: 0.1,
            global_lines: 3,
            fan: 36,
        }
    }
}

/// An adapted model: the mesh with its crack lines cut in, its structure and the record.
#[derive(Clone, Debug)]
pub struct Adaptation {
    pub model: Model,
    pub structure: Structure,
    pub record: AdaptRecord,
}

/// What one solve of a geometry gives the adaptation.
#[derive(Clone, Debug)]
pub struct Evaluation {
    /// The work or λ; `None` when the program has no mechanism (no collapse, cannot stand).
    pub value: Option<f64>,
    /// The cracks (full solves only).
    pub cracks: Vec<Crack>,
    pub certified: bool,
}

/// Why `--adapt` cannot be applied to `model`, if it cannot: loads tied to block edges and
/// existing cracks name elements that the cuts replace.
pub fn check_model(model: &Model) -> Result<()> {
    if !model.cracks.is_empty() {
        return Err(Error::Request(
            "--adapt re-meshes the wall, so it takes a model without existing cracks (they name joints of the original mesh)".into(),
        ));
    }
    if model
        .loads
        .dead
        .iter()
        .chain(&model.loads.live)
        .any(|l| matches!(l, Load::Edge { .. }))
    {
        return Err(Error::Request(
            "--adapt re-meshes the wall: edge loads (tied to an element's edge) are not carried over; give them as point or body loads".into(),
        ));
    }
    Ok(())
}

/// Settlement with adapted crack lines: the work of the dead loads maximised over the
/// positions of the crack lines. The model's supports carry their prescribed motions.
pub fn settle_adapt(
    model: &Model,
    build: BuildOptions,
    opts: &SolverOptions,
    o: &AdaptOptions,
) -> Result<Adaptation> {
    adapt(model, build, Objective::SettlementWork, o, |st, full| {
        if full {
            let r = crate::analysis::settlement::settle(st, opts)?;
            let ok = r.certificate.as_ref().is_some_and(|c| c.ok);
            Ok(Evaluation {
                value: r.work_dead_loads,
                cracks: r.cracks,
                certified: ok,
            })
        } else {
            // The force LP (the paper's (69)–(71)): its optimum is the largest work of the dead
            // loads (LP duality with the motion LP (62)–(66)), and Clarabel reaches it in 42
            // iterations on the 0.5 m façade in triangles where the motion LP takes 243 (1.5
            // against 10.4 s; docs/cracks.md).
            let map = crate::discretize::KinematicMap::new(st);
            let fp = crate::programs::settlement_force_program(&map, &st.load_vector(false));
            let s = fp.solve(&search_solver(opts))?;
            Ok(Evaluation {
                value: (s.status == LpStatus::Optimal).then_some(s.objective),
                cracks: Vec::new(),
                certified: false,
            })
        }
    })
}

/// The solver of the search trials: Clarabel's interior point, whatever the final analysis
/// uses, on the program as it is (no HiGHS presolve). A trial needs only the optimal value of
/// the settlement's force LP (no vertex, no mechanism, no certificate): Clarabel gives it to
/// about 1e-7 relative in a fraction of the simplex's time (1.5 s against 51 s on the 0.5 m
/// façade in triangles; docs/cracks.md). Through HiGHS's presolve (which the solver layer
/// applies to large all-equation programs) the reduced force LP of the same façade was not
/// solved and the fallback chain's interior point answered in 14.5 s. The solver layer's
/// fallback chain still answers where Clarabel fails. The final geometry is solved with `opts`.
pub fn search_solver(opts: &SolverOptions) -> SolverOptions {
    SolverOptions {
        method: lp::Method::Clarabel,
        presolve: false,
        ..*opts
    }
}

/// A trial's value is kept as an improvement only when it beats the best by more than this,
/// relative: ten times the accuracy of the search solves (Clarabel's optimal values of the
/// façade's force LPs differ from the simplex's by 5e-8 to 9e-8, relative), so that a move is
/// never kept on the solver's noise and the certified objective stays monotone.
const IMPROVEMENT: f64 = 1e-6;

/// The global stage's later rounds try only this many of the candidates that gained most
/// alone in its first round.
const GLOBAL_SHORTLIST: usize = 12;

/// Limit analysis with adapted crack lines: λ minimised over the positions of the crack lines.
pub fn limit_adapt(
    model: &Model,
    build: BuildOptions,
    opts: &SolverOptions,
    crushing: crate::analysis::limit::Crushing,
    facets: usize,
    o: &AdaptOptions,
) -> Result<Adaptation> {
    adapt(model, build, Objective::LoadMultiplier, o, |st, _| {
        let r = crate::analysis::limit::limit_with(st, opts, crushing, facets)?;
        let ok = r.certificate.as_ref().is_some_and(|c| c.ok);
        Ok(Evaluation {
            value: if r.status == crate::analysis::limit::LimitStatus::Collapse {
                r.load_multiplier
            } else {
                None
            },
            cracks: r.cracks,
            certified: ok,
        })
    })
}

/// The adaptation with any solve: `solve(structure, full)` returns the objective (and, when
/// `full`, the cracks and the certificate).
pub fn adapt<F>(
    model: &Model,
    build: BuildOptions,
    objective: Objective,
    o: &AdaptOptions,
    mut solve: F,
) -> Result<Adaptation>
where
    F: FnMut(&Structure, bool) -> Result<Evaluation>,
{
    check_model(model)?;
    if !(o.tolerance > 0.0 && o.tolerance.is_finite()) {
        return Err(Error::Request(format!(
            "--adapt-tol must be a positive number (got {})",
            o.tolerance
        )));
    }
    if o.global_lines > 0 && objective == Objective::SettlementWork && o.fan < 4 {
        return Err(Error::Request(format!(
            "--adapt-fan must be at least 4 (got {})",
            o.fan
        )));
    }
    let start = Instant::now();
    // With the environment variable `VOUSSOIR_TRACE` set: each iteration's time in the trial
    // geometries (cut and joints), the trial solves and the full solve, on stderr.
    let trace = std::env::var_os("VOUSSOIR_TRACE").is_some();
    let st0 = Structure::new(model, build)?;
    let tol = st0.tolerance;
    let region = Region::of(model, tol)?;
    let sign = match objective {
        Objective::SettlementWork => 1.0,
        Objective::LoadMultiplier => -1.0,
    };
    let score = |v: Option<f64>| v.map_or(f64::NEG_INFINITY, |x| sign * x);

    let ev = solve(&st0, true)?;
    if trace {
        eprintln!(
            "adapt: iteration 0: {} blocks, full solve {:.2} s, value {:?}",
            st0.blocks.len(),
            start.elapsed().as_secs_f64(),
            ev.value
        );
    }
    let Some(v0) = ev.value else {
        return Err(Error::Request(match objective {
            Objective::SettlementWork => "--adapt: the model as given has no settlement mechanism (it cannot stand, or the motions are incompatible): there are no cracks to adapt".into(),
            Objective::LoadMultiplier => "--adapt: the model as given does not collapse under its live loads: there are no cracks to adapt".into(),
        }));
    };
    let mut iterations = vec![AdaptIteration {
        iteration: 0,
        blocks: st0.blocks.len(),
        lines: 0,
        value: v0,
        certified: ev.certified,
        evaluations: 0,
        global: false,
        time: start.elapsed().as_secs_f64(),
    }];
    let mut lines: Vec<Line> = Vec::new();
    let mut current = (model.clone(), st0);
    let mut cracks = ev.cracks;
    let mut value = v0;
    let mut converged = false;
    let mut small = 0usize;
    let reach = o.reach * region.size;
    // The global stage (iteration 1 of the record when it places a line): candidate crack
    // lines that do not depend on the mesh (from the outline's corners and the ends of the
    // settling zone, over a fan of directions), chosen greedily by one search solve each.
    let mut first = 1usize;
    // Settlement only: for the limit analysis the trials are full limit analyses, and a
    // no-tension panel under a horizontal load has no finite optimum to place lines towards
    // (a sliver from its toe; tests/issue30_adapt.rs).
    if o.global_lines > 0 && objective == Objective::SettlementWork {
        let t = Instant::now();
        let cands = region.candidates(model, o.fan, tol);
        if trace {
            eprintln!("adapt: global stage: {} candidate lines", cands.len());
        }
        let mut evaluations = 0usize;
        // A candidate that crosses no element (it runs along element edges: the grid's own
        // lines from its corners) leaves every block as the lines before it left them: a
        // polygon that the cut does not split is kept as it is, so the same number of blocks
        // is the same geometry, and its value is theirs, solved once (`same`: the lines
        // before, their blocks and their value once solved).
        type Ends = Vec<[(usize, f64); 2]>;
        let mut same: (Option<Ends>, usize, Option<f64>) = (None, 0, None);
        let mut reused = 0usize;
        let mut trial = |ls: &[Line], evaluations: &mut usize| -> f64 {
            let m = match cut_model(model, &region, ls, tol) {
                Ok(m) => m,
                Err(_) => return f64::NEG_INFINITY,
            };
            let before = &ls[..ls.len().saturating_sub(1)];
            let key: Ends = before.iter().map(|l| l.ends).collect();
            if same.0.as_ref() != Some(&key) {
                let blocks = match cut_model(model, &region, before, tol) {
                    Ok(b) => b.blocks.len(),
                    Err(_) => usize::MAX,
                };
                same = (Some(key), blocks, None);
            }
            let unchanged = m.blocks.len() == same.1;
            if let (true, Some(v)) = (unchanged, same.2) {
                reused += 1;
                return v;
            }
            *evaluations += 1;
            let v = match Structure::new(&m, build) {
                Ok(st) => solve(&st, false).map_or(f64::NEG_INFINITY, |e| score(e.value)),
                Err(_) => f64::NEG_INFINITY,
            };
            if unchanged {
                same.2 = Some(v);
            }
            v
        };
        let gains = |v: f64, best: f64| v > best + IMPROVEMENT * best.abs().max(1e-12);
        let mut best = score(Some(v0));
        let mut chosen: Vec<usize> = Vec::new();
        // Round 1 tries every candidate; the later rounds only the best of round 1.
        let mut pool: Vec<usize> = (0..cands.len()).collect();
        for r in 0..o.global_lines {
            let mut round: Option<(usize, f64)> = None;
            let mut values: Vec<(f64, usize)> = Vec::new();
            for &k in &pool {
                if chosen.contains(&k) {
                    continue;
                }
                let mut ls = lines.clone();
                ls.push(cands[k].line);
                let v = trial(&ls, &mut evaluations);
                values.push((v, k));
                if round.is_none_or(|(_, b)| v > b) {
                    round = Some((k, v));
                }
            }
            if r == 0 {
                values.sort_by(|x, y| y.0.total_cmp(&x.0).then(x.1.cmp(&y.1)));
                pool = values.iter().take(GLOBAL_SHORTLIST).map(|x| x.1).collect();
            }
            match round {
                Some((k, v)) if gains(v, best) => {
                    best = v;
                    chosen.push(k);
                    lines.push(cands[k].line);
                }
                _ => break,
            }
        }
        // The far end of each chosen line (its key point held) by golden section over one step
        // of the fan either way.
        for (li, &k) in chosen.iter().enumerate() {
            let (lp, s0) = lines[li].ends[1];
            let r = cands[k].reach;
            let mut f = |s: f64, evaluations: &mut usize| {
                let mut ls = lines.clone();
                ls[li].ends[1] = (lp, region.wrap(lp, s));
                if ls[li].degenerate(&region) {
                    return f64::NEG_INFINITY;
                }
                trial(&ls, evaluations)
            };
            let (s, v) = golden_section(s0 - r, s0 + r, o.evaluations, |s| f(s, &mut evaluations));
            if gains(v, best) {
                best = v;
                lines[li].ends[1] = (lp, region.wrap(lp, s));
            }
        }
        if trace {
            eprintln!(
                "adapt: global stage: {} candidates, {evaluations} trials ({reused} more cut no element: the value of the lines before), {} lines, {:.2} s, best trial {best}",
                cands.len(),
                lines.len(),
                t.elapsed().as_secs_f64()
            );
        }
        if !lines.is_empty() {
            let m = cut_model(model, &region, &lines, tol)?;
            let st = Structure::new(&m, build)?;
            let ev = solve(&st, true)?;
            let v = ev.value.unwrap_or(f64::NAN);
            iterations.push(AdaptIteration {
                iteration: 1,
                blocks: st.blocks.len(),
                lines: lines.len(),
                value: v,
                certified: ev.certified,
                evaluations,
                global: true,
                time: start.elapsed().as_secs_f64(),
            });
            current = (m, st);
            cracks = ev.cracks;
            value = v;
            first = 2;
        }
    }
    for it in first..first + o.iterations {
        let new = region.lines_from_cracks(&cracks, &lines, o.lines_per_iteration);
        // No crack to straighten (the first time) or no new one (later): nothing to move.
        if new.is_empty() {
            converged = true;
            break;
        }
        // The lines of earlier iterations keep their positions (they were searched then); only
        // this iteration's new lines are moved: each iteration costs about
        // `1 + 2·evaluations·new lines` search solves, not a number growing with all the lines.
        let first_new = lines.len();
        lines.extend(new);
        let mut evaluations = 0usize;
        let (mut t_geometry, mut t_solve) = (0.0f64, 0.0f64);
        let mut trial = |ls: &[Line], evaluations: &mut usize| -> f64 {
            *evaluations += 1;
            let t = Instant::now();
            let st = cut_model(model, &region, ls, tol).and_then(|m| Structure::new(&m, build));
            t_geometry += t.elapsed().as_secs_f64();
            let t = Instant::now();
            let v = match st {
                Ok(st) => solve(&st, false).map_or(f64::NEG_INFINITY, |e| score(e.value)),
                Err(_) => f64::NEG_INFINITY,
            };
            t_solve += t.elapsed().as_secs_f64();
            v
        };
        let mut best = trial(&lines, &mut evaluations);
        for li in first_new..lines.len() {
            for end in 0..2 {
                let s0 = lines[li].ends[end].1;
                let lp = lines[li].ends[end].0;
                let mut f = |s: f64, evaluations: &mut usize| {
                    let mut ls = lines.clone();
                    ls[li].ends[end] = (lp, region.wrap(lp, s));
                    if ls[li].degenerate(&region) {
                        return f64::NEG_INFINITY;
                    }
                    trial(&ls, evaluations)
                };
                let (s, v) = golden_section(s0 - reach, s0 + reach, o.evaluations, |s| {
                    f(s, &mut evaluations)
                });
                if v > best + IMPROVEMENT * best.abs().max(1e-12) {
                    best = v;
                    lines[li].ends[end] = (lp, region.wrap(lp, s));
                }
            }
        }
        let t = Instant::now();
        let m = cut_model(model, &region, &lines, tol)?;
        let st = Structure::new(&m, build)?;
        let ev = solve(&st, true)?;
        let v = ev.value.unwrap_or(f64::NAN);
        if trace {
            eprintln!(
                "adapt: iteration {it}: {} blocks, {} lines, {evaluations} trials (geometry {t_geometry:.2} s, solves {t_solve:.2} s), full solve {:.2} s, value {v}",
                st.blocks.len(),
                lines.len(),
                t.elapsed().as_secs_f64()
            );
        }
        iterations.push(AdaptIteration {
            iteration: it,
            blocks: st.blocks.len(),
            lines: lines.len(),
            value: v,
            certified: ev.certified,
            evaluations,
            global: false,
            time: start.elapsed().as_secs_f64(),
        });
        let change = (v - value).abs() / v.abs().max(value.abs()).max(f64::MIN_POSITIVE);
        current = (m, st);
        cracks = ev.cracks;
        value = v;
        // Converged after two iterations in a row below the tolerance: one small step says
        // little, as the next iteration's new lines can still raise the objective (the 0.5 m
        // façade grid: +0.35 %, then +3.3 %; docs/cracks.md).
        small = if change < o.tolerance { small + 1 } else { 0 };
        if small >= 2 {
            converged = true;
            break;
        }
    }
    let method = format!(
        "{}crack lines cut into the mesh along the straightened crack polylines and moved along the outline by golden-section search ({} solves per end, reach {:.3} m, each iteration's new lines only{}), {} the {}",
        if o.global_lines > 0 && objective == Objective::SettlementWork {
            format!("a global stage (up to {} crack lines chosen greedily among the chords from the outline's corners and the settling zone's ends over a fan of {} directions, by one search solve each), then ", o.global_lines, o.fan)
        } else {
            String::new()
        },
        o.evaluations,
        o.reach * region.size,
        match objective {
            Objective::SettlementWork => "; search trials: the force LP by Clarabel, the final geometry by the analysis's own method",
            Objective::LoadMultiplier => "",
        },
        match objective {
            Objective::SettlementWork => "maximising",
            Objective::LoadMultiplier => "minimising",
        },
        match objective {
            Objective::SettlementWork => "work of the dead loads",
            Objective::LoadMultiplier => "load multiplier",
        }
    );
    Ok(Adaptation {
        model: current.0,
        structure: current.1,
        record: AdaptRecord {
            method,
            objective,
            converged,
            tolerance: o.tolerance,
            iterations,
            lines: lines.iter().map(|l| l.points(&region)).collect(),
        },
    })
}

/// Golden-section search for the largest `f` on `[lo, hi]` with `n` evaluations; returns the
/// best point evaluated and its value.
fn golden_section(lo: f64, hi: f64, n: usize, mut f: impl FnMut(f64) -> f64) -> (f64, f64) {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let mut best = (f64::NAN, f64::NEG_INFINITY);
    let note = |x: f64, v: f64, best: &mut (f64, f64)| {
        if v > best.1 {
            *best = (x, v);
        }
    };
    if n == 0 {
        return best;
    }
    let mut x1 = b - g * (b - a);
    let mut f1 = f(x1);
    note(x1, f1, &mut best);
    if n == 1 {
        return best;
    }
    let mut x2 = a + g * (b - a);
    let mut f2 = f(x2);
    note(x2, f2, &mut best);
    for _ in 2..n {
        if f1 >= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
            note(x1, f1, &mut best);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
            note(x2, f2, &mut best);
        }
    }
    best
}

/// A crack line: a chord between two points of the outline, each `(loop, arc length)`.
#[derive(Clone, Copy, Debug)]
struct Line {
    ends: [(usize, f64); 2],
}

impl Line {
    fn points(&self, r: &Region) -> [Point; 2] {
        [r.point_at(self.ends[0]), r.point_at(self.ends[1])]
    }

    fn degenerate(&self, r: &Region) -> bool {
        let [a, b] = self.points(r);
        norm(sub(b, a)) < 0.05 * r.element
    }
}

/// A candidate line of the global stage, its key point first, and the arc either way over
/// which its far end is refined (one step of the fan at the far end's distance).
struct Candidate {
    line: Line,
    reach: f64,
}

/// The wall's outline: the union of its blocks (outer boundary and openings).
struct Region {
    loops: Vec<Vec<Point>>,
    /// Cumulative arc length at each vertex of each loop (last entry: the perimeter).
    cum: Vec<Vec<f64>>,
    /// Diagonal of the wall's bounding box.
    size: f64,
    /// Typical element size: the median square root of the blocks' areas.
    element: f64,
}

impl Region {
    fn of(model: &Model, tol: f64) -> Result<Region> {
        let subj: Vec<Vec<[f64; 2]>> = model.blocks.iter().map(|b| b.polygon.clone()).collect();
        let clip: Vec<Vec<[f64; 2]>> = Vec::new();
        let shapes = subj.overlay_as::<i64>(&clip, OverlayRule::Subject, FillRule::NonZero);
        if shapes.len() != 1 {
            return Err(Error::Request(format!(
                "--adapt needs a wall meshed from one outline (its blocks tiling one polygon, with or without openings): this model's blocks form {} separate pieces",
                shapes.len()
            )));
        }
        let loops: Vec<Vec<Point>> = shapes
            .into_iter()
            .flatten()
            .filter(|c| c.len() >= 3)
            .collect();
        let cum = loops
            .iter()
            .map(|l| {
                let mut c = vec![0.0];
                for i in 0..l.len() {
                    let d = norm(sub(l[(i + 1) % l.len()], l[i]));
                    c.push(c[i] + d);
                }
                c
            })
            .collect();
        let pts: Vec<Point> = loops.iter().flatten().copied().collect();
        let bb = crate::geometry::bbox(&pts);
        let size = (bb[2] - bb[0]).hypot(bb[3] - bb[1]).max(tol);
        let mut sizes: Vec<f64> = model
            .blocks
            .iter()
            .map(|b| area_centroid(&b.polygon).0.abs().sqrt())
            .collect();
        sizes.sort_by(f64::total_cmp);
        let element = sizes[sizes.len() / 2].max(tol);
        Ok(Region {
            loops,
            cum,
            size,
            element,
        })
    }

    fn perimeter(&self, l: usize) -> f64 {
        *self.cum[l].last().unwrap_or(&0.0)
    }

    fn wrap(&self, l: usize, s: f64) -> f64 {
        let p = self.perimeter(l);
        if p > 0.0 {
            s.rem_euclid(p)
        } else {
            0.0
        }
    }

    fn point_at(&self, (l, s): (usize, f64)) -> Point {
        let s = self.wrap(l, s);
        let c = &self.cum[l];
        let lp = &self.loops[l];
        let i = match c.binary_search_by(|x| x.total_cmp(&s)) {
            Ok(i) => i.min(lp.len() - 1),
            Err(i) => (i - 1).min(lp.len() - 1),
        };
        let (a, b) = (lp[i], lp[(i + 1) % lp.len()]);
        let len = c[i + 1] - c[i];
        let t = if len > 0.0 { (s - c[i]) / len } else { 0.0 };
        [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
    }

    /// The nearest point of the outline, as `(loop, arc length)`.
    fn project(&self, p: Point) -> (usize, f64) {
        let mut best = (f64::INFINITY, (0, 0.0));
        for (l, lp) in self.loops.iter().enumerate() {
            for i in 0..lp.len() {
                let (a, b) = (lp[i], lp[(i + 1) % lp.len()]);
                let d = sub(b, a);
                let len2 = dot(d, d);
                let t = if len2 > 0.0 {
                    (dot(sub(p, a), d) / len2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let q = [a[0] + t * d[0], a[1] + t * d[1]];
                let dist = norm(sub(p, q));
                if dist < best.0 {
                    best = (dist, (l, self.cum[l][i] + t * len2.sqrt()));
                }
            }
        }
        best.1
    }

    /// Whether `p` lies inside the wall (inside an odd number of its loops of at least an
    /// element's area: not the slivers between blocks that do not quite meet), farther than
    /// `tol` from the outline.
    fn inside(&self, p: Point, tol: f64) -> bool {
        self.loops
            .iter()
            .filter(|l| {
                area_centroid(l).0.abs() >= self.element * self.element
                    && strictly_inside(p, l, tol)
            })
            .count()
            % 2
            == 1
    }

    /// The key points of the global stage (module docs): the outline's corners at the scale of
    /// an element — vertices where the outline turns by more than 60° between the chords to
    /// its points one element before and after (along the loop), the sharpest within an
    /// element kept — and the ends of the settling zone: the ends of each stretch of the
    /// outline resting on supports of one motion, where that motion is not zero (an end within
    /// an element of a corner is that corner).
    fn key_points(&self, model: &Model, tol: f64) -> Vec<Point> {
        let e = self.element;
        let mut corners: Vec<(f64, Point)> = Vec::new();
        for lp in &self.loops {
            // Slivers between blocks that do not quite meet, and holes smaller than an
            // element, have no corner of the wall's.
            if area_centroid(lp).0.abs() < e * e {
                continue;
            }
            // The loop's vertices that the outline keeps at a quarter of an element (the steps
            // of a grid along a slope are not corners).
            let mut closed = lp.clone();
            closed.push(lp[0]);
            let kept = douglas_peucker(&closed, 0.25 * e);
            for v in kept.iter().take(kept.len().saturating_sub(1)) {
                let (l2, s) = self.project(*v);
                let (a, b) = (self.point_at((l2, s - e)), self.point_at((l2, s + e)));
                let (u, w) = (sub(*v, a), sub(b, *v));
                let (lu, lw) = (norm(u), norm(w));
                if lu <= tol || lw <= tol {
                    continue;
                }
                let turn = (dot(u, w) / (lu * lw)).clamp(-1.0, 1.0).acos();
                if turn > 60f64.to_radians() {
                    corners.push((turn, *v));
                }
            }
        }
        // The sharpest first; a corner within an element of a sharper one is the same corner.
        corners.sort_by(|x, y| {
            y.0.total_cmp(&x.0)
                .then(x.1[0].total_cmp(&y.1[0]))
                .then(x.1[1].total_cmp(&y.1[1]))
        });
        let mut keys: Vec<Point> = Vec::new();
        for (_, v) in corners {
            if !keys.iter().any(|k| norm(sub(*k, v)) < e) {
                keys.push(v);
            }
        }
        // The outline's contact with each support: its edges lying on the outline.
        let on_outline =
            |p: Point| norm(sub(self.point_at(self.project(p)), p)) <= tol.max(1e-9 * self.size);
        let mut ends: Vec<(Point, usize)> = Vec::new();
        for (k, sp) in model.supports.iter().enumerate() {
            let n = sp.polygon.len();
            for i in 0..n {
                let (a, b) = (sp.polygon[i], sp.polygon[(i + 1) % n]);
                if norm(sub(b, a)) > tol && on_outline([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]) {
                    ends.push((a, k));
                    ends.push((b, k));
                }
            }
        }
        for &(p, k) in &ends {
            let m = model.supports[k].motion;
            if m.iter().all(|x| *x == 0.0) {
                continue;
            }
            // An end of a stretch of one motion: no contact edge of another support with the same
            // motion, and no other contact edge of this support, meets it there.
            let same = ends
                .iter()
                .filter(|(q, j)| norm(sub(*q, p)) <= tol && model.supports[*j].motion == m)
                .count();
            if same <= 1 && !keys.iter().any(|q| norm(sub(*q, p)) < e) {
                keys.push(p);
            }
        }
        keys
    }

    /// The global stage's candidate crack lines: from each key point of the outline (a corner
    /// turning by more than 30°, or an end of the settling zone: a vertex shared by two
    /// supports of different motions, within one element of the outline, projected onto it),
    /// the chord in each of `fan` directions over the full circle that enters the wall, to the
    /// first point where it leaves it; and where both a direction and its opposite enter the
    /// wall, the chord through the key point. Depends on the outline and the supports only,
    /// not on the mesh. Duplicates (both ends within 5 % of an element) are dropped.
    fn candidates(&self, model: &Model, fan: usize, tol: f64) -> Vec<Candidate> {
        let keys = self.key_points(model, tol);
        if std::env::var_os("VOUSSOIR_TRACE").is_some() {
            eprintln!("adapt: global stage: {} key points {keys:?}", keys.len());
        }
        let step = std::f64::consts::TAU / fan as f64;
        let eps = 1e-6 * self.size;
        let mut out: Vec<Candidate> = Vec::new();
        for p in keys {
            // The first exit of the ray from `p` along each direction (if it enters the wall).
            let exits: Vec<Option<(Point, f64)>> = (0..fan)
                .map(|k| {
                    let th = step * k as f64;
                    let d = [th.cos(), th.sin()];
                    // Slivers between blocks that do not quite meet are not the outline.
                    let t = self
                        .hits_of(p, d, self.element * self.element)
                        .into_iter()
                        .filter(|t| *t > eps)
                        .fold(f64::INFINITY, f64::min);
                    if !t.is_finite() {
                        return None;
                    }
                    let q = [p[0] + t * d[0], p[1] + t * d[1]];
                    let m = [p[0] + 0.5 * t * d[0], p[1] + 0.5 * t * d[1]];
                    self.inside(m, 1e-9 * self.size).then_some((q, t))
                })
                .collect();
            let push = |a: Point, b: Point, len: f64, out: &mut Vec<Candidate>| {
                let line = Line {
                    ends: [self.project(a), self.project(b)],
                };
                if line.degenerate(self) || self.along_outline(&line) {
                    return;
                }
                let [a, b] = line.points(self);
                let near = 0.05 * self.element;
                if out.iter().any(|c| {
                    let [x, y] = c.line.points(self);
                    (norm(sub(x, a)) < near && norm(sub(y, b)) < near)
                        || (norm(sub(x, b)) < near && norm(sub(y, a)) < near)
                }) {
                    return;
                }
                out.push(Candidate {
                    line,
                    reach: len * step,
                });
            };
            for k in 0..fan {
                if let Some((q, t)) = exits[k] {
                    push(p, q, t, &mut out);
                }
            }
            if fan % 2 == 0 {
                for k in 0..fan / 2 {
                    if let (Some((q, t)), Some((r, _))) = (exits[k], exits[k + fan / 2]) {
                        // Through the key point: from `r` to `q`, the far end `q` searched.
                        push(r, q, t, &mut out);
                    }
                }
            }
        }
        out
    }

    /// Whether a line runs along the outline (its midpoint on it): it would cut nothing.
    fn along_outline(&self, l: &Line) -> bool {
        let [a, b] = l.points(self);
        let m = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        norm(sub(self.point_at(self.project(m)), m)) < 0.01 * self.element
    }

    /// Parameters `t` where the line `p + t·d` (d a unit vector) crosses the outline.
    fn hits(&self, p: Point, d: Point) -> Vec<f64> {
        self.hits_of(p, d, 0.0)
    }

    /// [`Region::hits`] on the loops of area at least `min_area` only.
    fn hits_of(&self, p: Point, d: Point, min_area: f64) -> Vec<f64> {
        let mut ts = Vec::new();
        for lp in &self.loops {
            if min_area > 0.0 && area_centroid(lp).0.abs() < min_area {
                continue;
            }
            for i in 0..lp.len() {
                let (a, b) = (lp[i], lp[(i + 1) % lp.len()]);
                let e = sub(b, a);
                let den = cross(d, e);
                if den.abs() < 1e-14 * norm(e).max(1e-300) {
                    continue;
                }
                // p + t d = a + u e
                let ap = sub(a, p);
                let t = cross(ap, e) / den;
                let u = cross(ap, d) / den;
                if (-1e-9..=1.0 + 1e-9).contains(&u) {
                    ts.push(t);
                }
            }
        }
        ts
    }

    /// New crack lines from a result's cracks: each crack (widest first, down to 2 % of the
    /// widest, joints between blocks only) simplified to straight runs at least one element
    /// long, each run not already along a crack line extended to the outline both ways.
    fn lines_from_cracks(&self, cracks: &[Crack], existing: &[Line], max: usize) -> Vec<Line> {
        let mut out: Vec<Line> = Vec::new();
        let widest = cracks.iter().map(|c| c.max_opening).fold(0.0f64, f64::max);
        if widest <= 0.0 {
            return out;
        }
        let mut known: Vec<[Point; 2]> = existing.iter().map(|l| l.points(self)).collect();
        for c in cracks {
            if out.len() >= max {
                break;
            }
            if c.max_opening < 0.02 * widest || c.closed_loop {
                continue;
            }
            // Cracks along the foundation are the supports' joints: no line to move.
            if c.faces
                .iter()
                .all(|f| f.iter().any(|b| matches!(b, BodyName::Support(_))))
            {
                continue;
            }
            let runs = douglas_peucker(&c.points, 0.75 * self.element);
            for w in runs.windows(2) {
                if out.len() >= max {
                    break;
                }
                let (p, q) = (w[0], w[1]);
                let len = norm(sub(q, p));
                if len < self.element {
                    continue;
                }
                let near = 0.05 * self.element;
                if known.iter().any(|k| {
                    point_segment_distance(p, k[0], k[1]) <= near
                        && point_segment_distance(q, k[0], k[1]) <= near
                }) {
                    continue;
                }
                let d = [(q[0] - p[0]) / len, (q[1] - p[1]) / len];
                let eps = 1e-6 * self.size;
                let ts = self.hits(p, d);
                let ta = ts
                    .iter()
                    .copied()
                    .filter(|t| *t <= eps)
                    .fold(f64::NEG_INFINITY, f64::max);
                let tb = ts
                    .iter()
                    .copied()
                    .filter(|t| *t >= len - eps)
                    .fold(f64::INFINITY, f64::min);
                if !ta.is_finite() || !tb.is_finite() {
                    continue;
                }
                let a = [p[0] + ta * d[0], p[1] + ta * d[1]];
                let b = [p[0] + tb * d[0], p[1] + tb * d[1]];
                let line = Line {
                    ends: [self.project(a), self.project(b)],
                };
                if line.degenerate(self) || self.along_outline(&line) {
                    continue;
                }
                known.push(line.points(self));
                out.push(line);
            }
        }
        out
    }
}

/// The vertices kept by the Douglas–Peucker simplification of a polyline at `tol`.
fn douglas_peucker(p: &[Point], tol: f64) -> Vec<Point> {
    if p.len() <= 2 {
        return p.to_vec();
    }
    let mut keep = vec![false; p.len()];
    keep[0] = true;
    keep[p.len() - 1] = true;
    let mut stack = vec![(0usize, p.len() - 1)];
    while let Some((i, j)) = stack.pop() {
        let mut far = (0.0, 0usize);
        for k in i + 1..j {
            let d = point_segment_distance(p[k], p[i], p[j]);
            if d > far.0 {
                far = (d, k);
            }
        }
        if far.0 > tol {
            keep[far.1] = true;
            stack.push((i, far.1));
            stack.push((far.1, j));
        }
    }
    p.iter()
        .zip(keep)
        .filter(|(_, k)| *k)
        .map(|(q, _)| *q)
        .collect()
}

/// The model with every block cut along the crack lines (each extended by a hair beyond the
/// outline so that the border elements are cut through). Loads follow their blocks.
fn cut_model(model: &Model, region: &Region, lines: &[Line], tol: f64) -> Result<Model> {
    let mut pieces: Vec<(usize, Vec<Point>)> = model
        .blocks
        .iter()
        .enumerate()
        .map(|(i, b)| (i, b.polygon.clone()))
        .collect();
    let margin = 1e-6 * region.size;
    for l in lines {
        let [a, b] = l.points(region);
        let len = norm(sub(b, a));
        if len <= tol {
            continue;
        }
        let d = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
        let a = [a[0] - margin * d[0], a[1] - margin * d[1]];
        let b = [b[0] + margin * d[0], b[1] + margin * d[1]];
        let mut next = Vec::with_capacity(pieces.len() + 16);
        for (parent, p) in pieces {
            let mut out = Vec::new();
            split_polygon(&p, a, b, tol, &mut out, 0);
            next.extend(out.into_iter().map(|q| (parent, q)));
        }
        pieces = next;
    }
    let blocks: Vec<Block> = pieces
        .iter()
        .map(|(parent, p)| Block {
            polygon: p.clone(),
            material: model.blocks[*parent].material.clone(),
        })
        .collect();
    let of_parent = |b: usize| -> Vec<usize> {
        pieces
            .iter()
            .enumerate()
            .filter(|(_, (p, _))| *p == b)
            .map(|(i, _)| i)
            .collect()
    };
    let map_load = |l: &Load| -> Load {
        match l {
            Load::Point { block, at, force } => {
                let cands = of_parent(*block);
                let inside = cands.iter().copied().find(|&i| {
                    let poly = &pieces[i].1;
                    strictly_inside(*at, poly, tol)
                        || (0..poly.len()).any(|k| {
                            point_segment_distance(*at, poly[k], poly[(k + 1) % poly.len()]) <= tol
                        })
                });
                Load::Point {
                    block: inside.or(cands.first().copied()).unwrap_or(*block),
                    at: *at,
                    force: *force,
                }
            }
            Load::Body {
                coefficients,
                blocks,
            } => Load::Body {
                coefficients: *coefficients,
                blocks: blocks
                    .as_ref()
                    .map(|bs| bs.iter().flat_map(|b| of_parent(*b)).collect()),
            },
            other => other.clone(),
        }
    };
    let mut m = model.clone();
    m.blocks = blocks;
    m.loads.dead = model.loads.dead.iter().map(map_load).collect();
    m.loads.live = model.loads.live.iter().map(map_load).collect();
    Ok(m)
}

/// Split the simple polygon `p` (counter-clockwise) along the segment `a`–`b` wherever the
/// segment runs through its interior; the pieces go to `out`. New vertices lie on the line.
fn split_polygon(
    p: &[Point],
    a: Point,
    b: Point,
    tol: f64,
    out: &mut Vec<Vec<Point>>,
    depth: usize,
) {
    let len = norm(sub(b, a));
    let d = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
    let s: Vec<f64> = p
        .iter()
        .map(|v| {
            let x = cross(d, sub(*v, a));
            if x.abs() <= tol {
                0.0
            } else {
                x
            }
        })
        .collect();
    if depth > 64 || s.iter().all(|x| *x >= 0.0) || s.iter().all(|x| *x <= 0.0) {
        out.push(p.to_vec());
        return;
    }
    let n = p.len();
    let mut q: Vec<Point> = Vec::with_capacity(n + 4);
    let mut on: Vec<usize> = Vec::new();
    for i in 0..n {
        let j = (i + 1) % n;
        if s[i] == 0.0 {
            on.push(q.len());
        }
        q.push(p[i]);
        if s[i] * s[j] < 0.0 {
            let t = s[i] / (s[i] - s[j]);
            // The crossing, put exactly on the line.
            let x = [
                p[i][0] + t * (p[j][0] - p[i][0]),
                p[i][1] + t * (p[j][1] - p[i][1]),
            ];
            let u = dot(sub(x, a), d);
            on.push(q.len());
            q.push([a[0] + u * d[0], a[1] + u * d[1]]);
        }
    }
    let mut along: Vec<(f64, usize)> = on.iter().map(|&k| (dot(sub(q[k], a), d), k)).collect();
    along.sort_by(|x, y| x.0.total_cmp(&y.0));
    for w in along.windows(2) {
        let ((t0, i0), (t1, i1)) = (w[0], w[1]);
        if t1 - t0 <= tol || t0 < -tol || t1 > len + tol {
            continue;
        }
        let (i, j) = (i0.min(i1), i0.max(i1));
        if j - i == 1 || (i == 0 && j == q.len() - 1) {
            continue; // an edge of the polygon, not a diagonal
        }
        let tm = 0.5 * (t0 + t1);
        let mid = [a[0] + tm * d[0], a[1] + tm * d[1]];
        if !strictly_inside(mid, &q, tol) {
            continue;
        }
        let p1: Vec<Point> = q[i..=j].to_vec();
        let mut p2: Vec<Point> = q[j..].to_vec();
        p2.extend_from_slice(&q[..=i]);
        split_polygon(&p1, a, b, tol, out, depth + 1);
        split_polygon(&p2, a, b, tol, out, depth + 1);
        return;
    }
    out.push(p.to_vec());
}

/// The Hausdorff distance between two polylines (m): the largest distance from a point of
/// either to the other, `max(sup_{p∈a} d(p, b), sup_{q∈b} d(q, a))`, over every point of the
/// segments, not only their vertices. Used to compare the crack lines of two meshes (issue 30:
/// the longest cracks of the façade adapted from a grid and from triangles within 1 m).
///
/// Branch and bound on the pieces of `a`'s segments: the distance to one segment of `b` is
/// convex along a piece (the distance to a convex set), so on the piece `[p, q]` the distance
/// to `b` is at most `min_j max(d_j(p), d_j(q))`; pieces whose bound cannot beat the largest
/// distance found are dropped, the others halved, down to 1e-9 of the polylines' extent: the
/// result is exact to that. A polyline of one point is that point; an empty one gives
/// `f64::INFINITY`.
pub fn hausdorff_polylines(a: &[Point], b: &[Point]) -> f64 {
    if a.is_empty() || b.is_empty() {
        return f64::INFINITY;
    }
    let pts: Vec<Point> = a.iter().chain(b).copied().collect();
    let bb = crate::geometry::bbox(&pts);
    let eps = 1e-9 * (bb[2] - bb[0]).hypot(bb[3] - bb[1]).max(1e-300);
    directed_hausdorff(a, b, eps).max(directed_hausdorff(b, a, eps))
}

/// `sup_{p∈a} d(p, b)` to within `eps` (see [`hausdorff_polylines`]).
fn directed_hausdorff(a: &[Point], b: &[Point], eps: f64) -> f64 {
    let segs: Vec<(Point, Point)> = if b.len() == 1 {
        vec![(b[0], b[0])]
    } else {
        b.windows(2).map(|w| (w[0], w[1])).collect()
    };
    let each = |p: Point| -> Vec<f64> {
        segs.iter()
            .map(|(u, v)| point_segment_distance(p, *u, *v))
            .collect()
    };
    let nearest = |d: &[f64]| d.iter().copied().fold(f64::INFINITY, f64::min);
    let mut best = a
        .iter()
        .map(|p| nearest(&each(*p)))
        .fold(f64::NEG_INFINITY, f64::max);
    let mut stack: Vec<(Point, Point, Vec<f64>, Vec<f64>)> = a
        .windows(2)
        .map(|w| (w[0], w[1], each(w[0]), each(w[1])))
        .collect();
    while let Some((p, q, dp, dq)) = stack.pop() {
        let bound = dp
            .iter()
            .zip(&dq)
            .map(|(x, y)| x.max(*y))
            .fold(f64::INFINITY, f64::min);
        if bound <= best + eps || norm(sub(q, p)) <= eps {
            continue;
        }
        let m = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])];
        let dm = each(m);
        best = best.max(nearest(&dm));
        stack.push((p, m, dp, dm.clone()));
        stack.push((m, q, dm, dq));
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_splits_along_its_diagonal_line() {
        let sq = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut out = Vec::new();
        split_polygon(&sq, [-0.5, 0.25], [1.5, 0.75], 1e-12, &mut out, 0);
        assert_eq!(out.len(), 2);
        let areas: Vec<f64> = out.iter().map(|p| area_centroid(p).0).collect();
        assert!((areas[0] + areas[1] - 1.0).abs() < 1e-12);
        assert!(areas.iter().all(|a| *a > 0.0));
        // A segment that stops short of the square leaves it whole.
        let mut out = Vec::new();
        split_polygon(&sq, [-0.5, 0.25], [0.5, 0.5], 1e-12, &mut out, 0);
        assert_eq!(out.len(), 1);
    }

    #[test]
    fn an_l_shape_crossed_twice_gives_three_pieces() {
        // A U shape cut by a horizontal line through both arms.
        let u = vec![
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 2.0],
            [2.0, 2.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        let mut out = Vec::new();
        split_polygon(&u, [-1.0, 1.5], [4.0, 1.5], 1e-12, &mut out, 0);
        assert_eq!(out.len(), 3);
        let total: f64 = out.iter().map(|p| area_centroid(p).0).sum();
        assert!((total - 5.0).abs() < 1e-12);
    }

    #[test]
    fn golden_section_finds_a_peak() {
        let (x, v) = golden_section(0.0, 4.0, 30, |x| -(x - 1.3f64).powi(2));
        assert!((x - 1.3).abs() < 1e-4 && v <= 0.0);
    }
}
