//! Incremental (nonlinear kinematic) analysis: a collapse mechanism that evolves with the
//! geometry, cracks that close and carry force again (the paper's Section 6, Figs 13–17).
//!
//! ## State and step
//!
//! The state is a [`Structure`]: the current block positions and, at every collocation point,
//! its gap (0: in contact; > 0: open, carrying no force). A step:
//!
//! 1. **Mechanism.** The classic limit LP on the current geometry ([`WarmLimit`], the same LP as
//!    [`crate::analysis::limit`]): static `max λ` over contact forces at the points in contact,
//!    whose equilibrium-row duals are the kinematic LP's solution, the mechanism `d` with
//!    `min −F_Dᵀd  s.t.  F_Lᵀd = 1,  N_c d ≥ 0,  T_c d = 0` over the points `c` in contact.
//!    Open points have no rows: they may close or open further.
//! 2. **Load multiplier** by virtual work on the current geometry, `λ = −F_Dᵀd / F_Lᵀd`, which is
//!    the LP optimum. A negative value means the dead loads alone drive the mechanism (the live
//!    load is not needed): the curve reports `load_multiplier = max(λ, 0)` — the paper's "λ = 0
//!    while the hinges close under self-weight" — and keeps the raw value as
//!    `equilibrium_multiplier`.
//! 3. **Step length.** The mechanism is scaled so that the control point moves by `step` along
//!    the control direction, unless an open point would close first: the step is then cut at the
//!    smallest `gap / (−N_k d)` over open points with a closing rate, so that no point
//!    penetrates.
//! 4. **Advance.** Every block moves by the exact finite rigid motion (rotation about its
//!    centroid), gaps are updated by the opening increments, points that open get their gap,
//!    points whose gap reaches zero come back into contact. Each change is an event
//!    (`opened` / `closed`). When a point closes, λ is also evaluated on the new geometry with
//!    the point still open, so the curve shows the jump at one displacement.
//!
//! The LP is solved again at every step, so the mechanism may change whenever the geometry
//! makes another one weaker, not only when a hinge closes; for a fixed set of hinges that is the
//! paper's procedure (same mechanism, λ by virtual work on the moved geometry). The choice of
//! the limit LP with the step cut at the first closure, rather than an LP with the gap
//! constraints `N_k d ≥ −g_k` for a prescribed step, keeps the LP scale-free (its mechanism does
//! not depend on the step length) and makes every closure an exact event.
//!
//! The analysis stops when λ falls to zero or below after having been positive (collapse under
//! the dead loads), at the maximum control displacement, or when the LP has no mechanism
//! (locked) or no equilibrium.

use crate::analysis::limit::LimitStatus;
use crate::analysis::paths::{SettlementPath, WarmLimit};
use crate::analysis::settlement::SettlementStatus;
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::geometry::{self, small_displacement, RigidMotion};
use crate::lp::SolverOptions;
use crate::model::Point;
use crate::reporting::report;
pub use crate::result::incremental::*;
use crate::result::Geometry;
use crate::structure::OPEN_TOLERANCE;
use crate::structure::{Assembly, Structure};

impl Control {
    /// A control point on `block`; `direction` is normalised.
    pub fn new(st: &Structure, block: usize, point: Point, direction: Point) -> Result<Control> {
        if block >= st.blocks.len() {
            return Err(Error::Request(format!(
                "control block {block} does not exist (the model has {} blocks)",
                st.blocks.len()
            )));
        }
        if !(point[0].is_finite() && point[1].is_finite()) {
            return Err(Error::Request("the control point must be finite".into()));
        }
        let n = geometry::norm(direction);
        if !n.is_finite() || n <= 0.0 {
            return Err(Error::Request(
                "the control direction must be a non-zero vector".into(),
            ));
        }
        Ok(Control {
            block,
            point,
            direction: [direction[0] / n, direction[1] / n],
        })
    }

    /// The control point at `x` on the block that contains it, or the nearest block.
    pub fn nearest(st: &Structure, x: Point, direction: Point) -> Result<Control> {
        let mut best = (f64::INFINITY, 0usize);
        for (i, b) in st.blocks.iter().enumerate() {
            let p = &b.polygon;
            let dist = if geometry::strictly_inside(x, p, 0.0) {
                0.0
            } else {
                (0..p.len())
                    .map(|k| geometry::point_segment_distance(x, p[k], p[(k + 1) % p.len()]))
                    .fold(f64::INFINITY, f64::min)
            };
            if dist < best.0 {
                best = (dist, i);
            }
        }
        // A point far from every block is a mistake (a typo, other units): refuse it rather
        // than attach it to whichever block happens to be nearest.
        let diag = size_of(st).0;
        if !(best.0 <= CONTROL_REACH * diag) {
            return Err(Error::Request(format!(
                "control point ({}, {}) is {:.3} m from the nearest block (block {}): give a point on the structure (within {:.0} % of its size)",
                x[0],
                x[1],
                best.0,
                best.1,
                100.0 * CONTROL_REACH
            )));
        }
        Control::new(st, best.1, x, direction)
    }
}

/// The blocks' bounding-box diagonal and largest coordinate magnitude (m).
fn size_of(st: &Structure) -> (f64, f64) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in st.blocks.iter().flat_map(|b| b.polygon.iter()) {
        for c in 0..2 {
            lo[c] = lo[c].min(q[c]);
            hi[c] = hi[c].max(q[c]);
        }
    }
    let far = lo.iter().chain(&hi).fold(0.0f64, |m, v| m.max(v.abs()));
    ((hi[0] - lo[0]).hypot(hi[1] - lo[1]), far)
}

/// The smallest step, relative to the structure's size (or its distance from the origin, if
/// larger): below it the moved coordinates cannot record the step in double precision.
pub const MIN_RELATIVE_STEP: f64 = 1e-10;

/// How far (relative to the structure's bounding-box diagonal) a control point may lie from the
/// nearest block.
pub const CONTROL_REACH: f64 = 0.02;

/// Options of the incremental analysis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IncrementalOptions {
    /// Control displacement per step (m).
    pub step: f64,
    /// Largest control displacement (m, absolute value).
    pub max_displacement: f64,
    /// Safety cap on the number of steps (including the ones cut short by closures).
    pub max_steps: usize,
    /// Stop when λ ≤ 0 after having been positive.
    pub stop_after_peak: bool,
    /// Keep the mechanism and geometry every `snapshot_every` steps (0: none) in addition to
    /// the first step and the steps with events.
    pub snapshot_every: usize,
    /// Keep snapshots at all (first step, events, every `snapshot_every`).
    pub snapshots: bool,
    pub hot_start: bool,
    pub solver: SolverOptions,
}

impl Default for IncrementalOptions {
    fn default() -> Self {
        IncrementalOptions {
            step: 5e-4,
            max_displacement: 0.05,
            max_steps: 100_000,
            stop_after_peak: true,
            snapshot_every: 0,
            snapshots: true,
            hot_start: true,
            solver: SolverOptions::default(),
        }
    }
}

/// The structure after the settlement prescribed by its supports' motions: settlement
/// analysis, then every block moved by its finite rigid motion and every opened point given its
/// gap. `release` turns `fixed` supports into contact ones afterwards (see
/// [`crate::analysis::capacity::CapacityOptions::release_fixed`]).
pub fn settled(st: &Structure, solver: &SolverOptions, release: bool) -> Result<Structure> {
    let path = SettlementPath::new(st, solver)?;
    if path.status != SettlementStatus::Mechanism {
        return Err(Error::Request(format!(
            "settlement analysis: {}",
            path.status.sentence()
        )));
    }
    let mut out = path.deformed(path.max_settlement)?;
    if release {
        out.release_fixed();
    }
    Ok(out)
}

fn open_joints(st: &Structure) -> Vec<usize> {
    st.joints
        .iter()
        .enumerate()
        .filter(|(_, j)| j.points.iter().any(|p| p.gap > 0.0))
        .map(|(i, _)| i)
        .collect()
}

/// Incremental analysis from `start` (undeformed, or settled with [`settled`]).
pub fn incremental(
    start: &Structure,
    control: &Control,
    opts: &IncrementalOptions,
) -> Result<IncrementalResult> {
    incremental_with(start, control, opts, &mut |_| {})
}

/// [`incremental`], calling `progress` with every new point of the curve (for a progress bar).
pub fn incremental_with(
    start: &Structure,
    control: &Control,
    opts: &IncrementalOptions,
    progress: &mut dyn FnMut(&IncrementalPoint),
) -> Result<IncrementalResult> {
    if !(opts.step > 0.0 && opts.step.is_finite()) {
        return Err(Error::Request("the step must be a positive number".into()));
    }
    if !(opts.max_displacement > 0.0 && opts.max_displacement.is_finite()) {
        return Err(Error::Request(
            "the maximum displacement must be a positive number".into(),
        ));
    }
    let (diag, far) = size_of(start);
    if opts.step < MIN_RELATIVE_STEP * diag.max(far) {
        return Err(Error::Request(format!(
            "step {:.3e} m: below {MIN_RELATIVE_STEP:e} of the structure's size ({:.3e} m), too small for the geometry to record",
            opts.step,
            diag.max(far)
        )));
    }
    let wanted = (opts.max_displacement / opts.step).ceil();
    if wanted > opts.max_steps as f64 {
        return Err(Error::Request(format!(
            "steps: a largest displacement of {} m in steps of {} m takes {wanted:.0} steps, more than the bound of {} (take a larger step)",
            opts.max_displacement, opts.step, opts.max_steps
        )));
    }
    if !start.has_live_loads() {
        return Err(Error::Request(
            "incremental analysis needs live loads (the model has none)".into(),
        ));
    }
    let control = Control::new(start, control.block, control.point, control.direction)?;
    let dir = control.direction;
    let cb = control.block;
    let x0 = control.point;

    let mut st = start.clone();
    let mut warm = WarmLimit::new(&opts.solver, opts.hot_start);
    let mut curve: Vec<IncrementalPoint> = Vec::new();
    let mut events: Vec<Event> = Vec::new();
    let mut snapshots: Vec<Snapshot> = Vec::new();
    let mut xc = x0;
    let mut disp = 0.0f64;
    let mut peak = (f64::NEG_INFINITY, 0.0);
    let mut status = IncrementalStatus::MaxSteps;
    let mut steps = 0usize;
    let mut snaps = 0usize;
    for step in 0..opts.max_steps {
        steps = step;
        let map = KinematicMap::new(&st);
        let sol = warm.solve(&st, &map)?;
        // `snap`: no equilibrium for any λ, but the dead loads alone drive a mechanism that
        // closes an open point (a hinge moving to the next joint): follow that mechanism, with
        // no point on the curve, until the point closes.
        let (d, lam, snap) = match (sol.status, sol.lambda) {
            (_, Some(l)) if !sol.mechanism.is_empty() => (sol.mechanism.clone(), l, false),
            (LimitStatus::Locked, _) => {
                status = IncrementalStatus::Locked;
                break;
            }
            _ => match dead_load_ray(&st, &map, &opts.solver)? {
                Some(ray) if closes_a_gap(&map, &ray) => {
                    snaps += 1;
                    (ray, f64::NEG_INFINITY, true)
                }
                _ => {
                    status = IncrementalStatus::NoEquilibrium;
                    break;
                }
            },
        };
        let closing_now = closes_a_gap(&map, &d);
        if !snap {
            curve.push(IncrementalPoint {
                step,
                displacement: disp,
                load_multiplier: lam.max(0.0),
                equilibrium_multiplier: lam,
                before_closure: false,
            });
            if let Some(p) = curve.last() {
                progress(p);
            }
            if lam > peak.0 {
                peak = (lam, disp);
            }
            // λ ≤ 0 after the peak is collapse, unless the mechanism is closing a crack (a
            // closure can raise λ again).
            if opts.stop_after_peak && peak.0 > 0.0 && lam <= 0.0 && !closing_now {
                status = IncrementalStatus::Collapsed;
                break;
            }
        }
        if disp.abs() >= opts.max_displacement * (1.0 - 1e-12) {
            status = IncrementalStatus::MaxDisplacement;
            break;
        }
        let d = &d;
        let c = st.blocks[cb].centroid;
        let uc = small_displacement(c, [d[3 * cb], d[3 * cb + 1], d[3 * cb + 2]], xc);
        let proj = geometry::dot(dir, uc);
        let dscale = d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if proj.abs() <= 1e-9 * dscale && !snap {
            status = IncrementalStatus::ControlStill;
            break;
        }
        let remaining = opts.max_displacement - disp.abs();
        let alpha_step = if proj.abs() > 1e-9 * dscale {
            opts.step.min(remaining.max(0.0)) / proj.abs()
        } else {
            f64::INFINITY
        };
        let (rate, _) = map.jumps(d, 0.0);
        let rtol = OPEN_TOLERANCE * crate::scale::motion_scale(&map, d, 0.0);
        let mut alpha = alpha_step;
        for k in 0..map.num_points() {
            if map.gap[k] > 0.0 && rate[k] < -rtol {
                alpha = alpha.min(map.gap[k] / -rate[k]);
            }
        }
        if !alpha.is_finite() {
            status = IncrementalStatus::NoEquilibrium;
            break;
        }
        let closing: Vec<usize> = (0..map.num_points())
            .filter(|&k| {
                map.gap[k] > 0.0 && rate[k] < -rtol && map.gap[k] / -rate[k] <= alpha * (1.0 + 1e-9)
            })
            .collect();
        let mut openings: Vec<Vec<f64>> = st
            .joints
            .iter()
            .map(|j| vec![0.0; j.points.len()])
            .collect();
        for (k, p) in map.points.iter().enumerate() {
            openings[p.joint][p.index] = rate[k];
        }
        let mut next = st.deformed(d, alpha, &openings, alpha * rtol);
        for &k in &closing {
            let p = map.points[k];
            next.joints[p.joint].points[p.index].gap = 0.0;
        }
        let m = RigidMotion::scaled(c, [d[3 * cb], d[3 * cb + 1], d[3 * cb + 2]], alpha);
        xc = m.apply(xc);
        let new_disp = geometry::dot(dir, geometry::sub(xc, x0));
        // Events.
        let mut any = false;
        for (j, (a, b)) in st.joints.iter().zip(&next.joints).enumerate() {
            for (i, (pa, pb)) in a.points.iter().zip(&b.points).enumerate() {
                let kind = match (pa.gap > 0.0, pb.gap > 0.0) {
                    (false, true) => EventKind::Opened,
                    (true, false) => EventKind::Closed,
                    _ => continue,
                };
                any = true;
                events.push(Event {
                    step,
                    displacement: new_disp,
                    kind,
                    joint: j,
                    point: i,
                    x: pb.x[0],
                    y: pb.x[1],
                });
            }
        }
        if opts.snapshots
            && !snap
            && (step == 0 || any || (opts.snapshot_every > 0 && step % opts.snapshot_every == 0))
        {
            let zeros = vec![0.0; map.num_points()];
            let scale = 1.0 / proj;
            let dn: Vec<f64> = d.iter().map(|x| x * scale).collect();
            let rep = report(&st, &map, &dn, 0.0, &sol.pn, &zeros);
            snapshots.push(Snapshot {
                step,
                displacement: disp,
                load_multiplier: lam.max(0.0),
                blocks: rep.blocks,
                hinges: rep.hinges,
                geometry: Geometry::of(&st),
            });
        }
        if !closing.is_empty() && !snap {
            // λ on the new geometry with the closing points still open: the value just before
            // the contact is restored, so that the jump shows at one displacement.
            let mut before = next.clone();
            for &k in &closing {
                let p = map.points[k];
                before.joints[p.joint].points[p.index].gap = f64::MIN_POSITIVE;
            }
            let bmap = KinematicMap::new(&before);
            let bs = warm.solve(&before, &bmap)?;
            if let Some(l) = bs.lambda {
                curve.push(IncrementalPoint {
                    step,
                    displacement: new_disp,
                    load_multiplier: l.max(0.0),
                    equilibrium_multiplier: l,
                    before_closure: true,
                });
            }
        }
        disp = new_disp;
        st = next;
    }
    let peak_l = peak.0.max(0.0);
    let what = match status {
        IncrementalStatus::Collapsed => "λ fell to zero after its peak".to_string(),
        IncrementalStatus::MaxDisplacement => format!(
            "reached the maximum control displacement {:.4} m",
            opts.max_displacement
        ),
        IncrementalStatus::MaxSteps => format!("stopped after {} steps", opts.max_steps),
        IncrementalStatus::Locked => {
            "no finite collapse load on the current geometry (locked)".to_string()
        }
        IncrementalStatus::NoEquilibrium => "no equilibrium on the current geometry".to_string(),
        IncrementalStatus::ControlStill => {
            "the mechanism does not move the control point along the direction".to_string()
        }
    };
    let closed = events
        .iter()
        .filter(|e| e.kind == EventKind::Closed)
        .count();
    let message = format!(
        "peak λ = {:.6} at a control displacement of {}; {} step{}, {} closure{}, {} hinge move{} under the dead loads; {}",
        peak_l,
        crate::lengths::Length::Motion.show(peak.1),
        steps,
        if steps == 1 { "" } else { "s" },
        closed,
        if closed == 1 { "" } else { "s" },
        snaps,
        if snaps == 1 { "" } else { "s" },
        what
    );
    Ok(IncrementalResult {
        status,
        message,
        solver: opts.solver.info(),
        control,
        curve,
        events,
        snapshots,
        peak_load_multiplier: peak_l,
        peak_displacement: peak.1,
        initial_open_joints: open_joints(start),
        cracks: crate::reporting::cracks_of_gaps(&st),
        steps,
        snaps,
        solves: warm.solves,
        iterations: warm.iterations,
        initial_geometry: Geometry::of(start),
        final_geometry: Geometry::of(&st),
    })
}

/// Whether mechanism `d` closes an open point.
fn closes_a_gap(map: &KinematicMap, d: &[f64]) -> bool {
    let (rate, _) = map.jumps(d, 0.0);
    let tol = OPEN_TOLERANCE * crate::scale::motion_scale(map, d, 0.0);
    (0..map.num_points()).any(|k| map.gap[k] > 0.0 && rate[k] < -tol)
}

/// When no λ gives equilibrium: a mechanism on which the live loads do no work and the dead
/// loads do positive work (a ray of the kinematic LP), with block DOFs bounded by 1.
fn dead_load_ray(
    st: &Structure,
    map: &KinematicMap,
    solver: &SolverOptions,
) -> Result<Option<Vec<f64>>> {
    use crate::lp::LpStatus;
    let dead = st.load_vector(false);
    let live = st.load_vector(true);
    let lp = crate::programs::dead_load_ray_program(map, &dead, &live);
    let sol = crate::lp::solve(&lp, solver)?;
    let wscale: f64 = dead.iter().map(|f| f.abs()).sum::<f64>().max(1e-300);
    Ok(match sol.status {
        LpStatus::Optimal if sol.objective > 1e-12 * wscale => Some(sol.x),
        _ => None,
    })
}
