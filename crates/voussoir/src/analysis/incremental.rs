//! Incremental (nonlinear kinematic) analysis: a collapse mechanism that evolves with the
//! geometry, cracks that close and carry force again (the paper's Section 6, Figs 13–17).
//!
//! ## State and step
//!
//! The state is a structure ([`Structure`] in 2D, [`Structure3d`] in 3D: the analysis is written
//! once over [`Assembly`] and [`IncrementalGeometry`]): the current block positions and, at every collocation point,
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

use crate::analysis::canonical::{CanonicalMechanism, CanonicalOptions, StepSelection};
use crate::analysis::limit::LimitStatus;
use crate::analysis::paths::{SettlementPath, WarmLimit};
use crate::analysis::settlement::SettlementStatus;
use crate::dim::{Dim, Three};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::geometry::{self, RigidMotion};
use crate::lp::SolverOptions;
use crate::reporting::report;
pub use crate::result::incremental::*;
use crate::structure::OPEN_TOLERANCE;
use crate::structure::{Assembly, Structure, Structure3d};

/// What the incremental analysis needs of a structure beyond [`Assembly`]: where its blocks
/// are (to attach the control point and check the step against the structure's size), how a
/// finite rigid motion moves a point, and setting one point's gap. Implemented for the 2D
/// [`Structure`] and the 3D [`Structure3d`]; the analysis itself is written once over it.
pub trait IncrementalGeometry: Assembly {
    /// Distance (m) from `x` to block `i`: 0 inside it (2D: strictly inside the polygon; 3D:
    /// inside the polyhedron), else the distance to its boundary.
    fn distance_to_block(&self, i: usize, x: <Self::D as Dim>::Vector) -> f64;
    /// The blocks' bounding-box diagonal and largest coordinate magnitude (m).
    fn extent(&self) -> (f64, f64);
    /// Reference point (centroid) of block `i`: where its DOFs act.
    fn block_reference(&self, i: usize) -> <Self::D as Dim>::Vector;
    /// Point `x` of block `i` moved by the finite rigid motion `s·d_i` (the motion
    /// [`Assembly::deformed`] gives the block).
    fn move_point(
        &self,
        i: usize,
        d: &[f64],
        s: f64,
        x: <Self::D as Dim>::Vector,
    ) -> <Self::D as Dim>::Vector;
    /// Euclidean length of a vector.
    fn norm(v: <Self::D as Dim>::Vector) -> f64;
    /// Position and gap of point `k` of joint `j`.
    fn joint_point(&self, j: usize, k: usize) -> (<Self::D as Dim>::Vector, f64);
    /// Number of points of joint `j`.
    fn joint_points(&self, j: usize) -> usize;
    fn set_gap(&mut self, j: usize, k: usize, gap: f64);
    /// The cracks the structure carries: its points with a gap, widths the gaps (m).
    fn gap_cracks(&self) -> Vec<<Self::D as crate::result::Spatial>::Crack>;
}

impl IncrementalGeometry for Structure {
    fn distance_to_block(&self, i: usize, x: [f64; 2]) -> f64 {
        let p = &self.blocks[i].polygon;
        if geometry::strictly_inside(x, p, 0.0) {
            0.0
        } else {
            (0..p.len())
                .map(|k| geometry::point_segment_distance(x, p[k], p[(k + 1) % p.len()]))
                .fold(f64::INFINITY, f64::min)
        }
    }
    fn extent(&self) -> (f64, f64) {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for q in self.blocks.iter().flat_map(|b| b.polygon.iter()) {
            for c in 0..2 {
                lo[c] = lo[c].min(q[c]);
                hi[c] = hi[c].max(q[c]);
            }
        }
        let far = lo.iter().chain(&hi).fold(0.0f64, |m, v| m.max(v.abs()));
        ((hi[0] - lo[0]).hypot(hi[1] - lo[1]), far)
    }
    fn block_reference(&self, i: usize) -> [f64; 2] {
        self.blocks[i].centroid
    }
    fn move_point(&self, i: usize, d: &[f64], s: f64, x: [f64; 2]) -> [f64; 2] {
        RigidMotion::scaled(
            self.blocks[i].centroid,
            [d[3 * i], d[3 * i + 1], d[3 * i + 2]],
            s,
        )
        .apply(x)
    }
    fn norm(v: [f64; 2]) -> f64 {
        geometry::norm(v)
    }
    fn joint_point(&self, j: usize, k: usize) -> ([f64; 2], f64) {
        let p = &self.joints[j].points[k];
        (p.x, p.gap)
    }
    fn joint_points(&self, j: usize) -> usize {
        self.joints[j].points.len()
    }
    fn set_gap(&mut self, j: usize, k: usize, gap: f64) {
        self.joints[j].points[k].gap = gap;
    }
    fn gap_cracks(&self) -> Vec<crate::result::Crack> {
        crate::reporting::cracks_of_gaps(self)
    }
}

impl IncrementalGeometry for Structure3d {
    fn distance_to_block(&self, i: usize, x: [f64; 3]) -> f64 {
        let s = &self.blocks[i].shape;
        if crate::geometry3d::winding_number(&s.vertices, &s.faces, x).abs() > 0.5 {
            return 0.0;
        }
        s.faces
            .iter()
            .flat_map(|f| (1..f.len().saturating_sub(1)).map(move |k| (f[0], f[k], f[k + 1])))
            .map(|(a, b, c)| {
                point_triangle_distance(x, s.vertices[a], s.vertices[b], s.vertices[c])
            })
            .fold(f64::INFINITY, f64::min)
    }
    fn extent(&self) -> (f64, f64) {
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for q in self.blocks.iter().flat_map(|b| b.shape.vertices.iter()) {
            for c in 0..3 {
                lo[c] = lo[c].min(q[c]);
                hi[c] = hi[c].max(q[c]);
            }
        }
        let far = lo.iter().chain(&hi).fold(0.0f64, |m, v| m.max(v.abs()));
        let d = Three::sub(hi, lo);
        (Three::dot(d, d).sqrt(), far)
    }
    fn block_reference(&self, i: usize) -> [f64; 3] {
        self.blocks[i].shape.centroid
    }
    fn move_point(&self, i: usize, d: &[f64], s: f64, x: [f64; 3]) -> [f64; 3] {
        use nalgebra::{Rotation3, Vector3};
        let c = self.blocks[i].shape.centroid;
        let m = &d[6 * i..6 * i + 6];
        let rot = Rotation3::from_scaled_axis(Vector3::new(s * m[3], s * m[4], s * m[5]));
        let r = rot * Vector3::new(x[0] - c[0], x[1] - c[1], x[2] - c[2]);
        [
            c[0] + s * m[0] + r[0],
            c[1] + s * m[1] + r[1],
            c[2] + s * m[2] + r[2],
        ]
    }
    fn norm(v: [f64; 3]) -> f64 {
        Three::dot(v, v).sqrt()
    }
    fn joint_point(&self, j: usize, k: usize) -> ([f64; 3], f64) {
        let p = &self.joints[j].points[k];
        (p.x, p.gap)
    }
    fn joint_points(&self, j: usize) -> usize {
        self.joints[j].points.len()
    }
    fn set_gap(&mut self, j: usize, k: usize, gap: f64) {
        self.joints[j].points[k].gap = gap;
    }
    fn gap_cracks(&self) -> Vec<crate::result::Crack3d> {
        // The joints as a report lists them (no motion), open where they have a gap.
        let map = self.kinematic_map();
        let zeros = vec![0.0; map.num_dofs];
        let np = map.num_points();
        let rep = report(
            self,
            &map,
            &zeros,
            0.0,
            &vec![0.0; np],
            &vec![0.0; np * map.tangents_per_point],
        );
        let open: Vec<Vec<bool>> = self
            .joints
            .iter()
            .map(|j| j.points.iter().map(|p| p.gap > 0.0).collect())
            .collect();
        let widths: Vec<Vec<f64>> = self
            .joints
            .iter()
            .map(|j| j.points.iter().map(|p| p.gap).collect())
            .collect();
        self.cracks(&rep.joints, &open, &widths)
    }
}

/// Distance from `p` to the triangle `(a, b, c)` (Ericson, Real-Time Collision Detection,
/// 5.1.5: the closest point by Voronoi regions).
fn point_triangle_distance(p: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> f64 {
    let (sub, dot) = (Three::sub, Three::dot);
    let at =
        |u: f64, v: f64, w: f64| -> [f64; 3] { [0, 1, 2].map(|i| u * a[i] + v * b[i] + w * c[i]) };
    let dist = |q: [f64; 3]| {
        let d = sub(p, q);
        dot(d, d).sqrt()
    };
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return dist(a);
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return dist(b);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let v = d1 / (d1 - d3);
        return dist(at(1.0 - v, v, 0.0));
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return dist(c);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let w = d2 / (d2 - d6);
        return dist(at(1.0 - w, 0.0, w));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return dist(at(0.0, 1.0 - w, w));
    }
    let denom = va + vb + vc;
    if !(denom.abs() > 0.0) {
        // A degenerate triangle: its vertices.
        return dist(a).min(dist(b)).min(dist(c));
    }
    let (v, w) = (vb / denom, vc / denom);
    dist(at(1.0 - v - w, v, w))
}

impl<D: crate::result::Spatial> Control<D> {
    /// A control point on `block`; `direction` is normalised.
    pub fn new<S: IncrementalGeometry<D = D>>(
        st: &S,
        block: usize,
        point: D::Vector,
        direction: D::Vector,
    ) -> Result<Control<D>> {
        if block >= st.num_blocks() {
            return Err(Error::Request(format!(
                "control block {block} does not exist (the model has {} blocks)",
                st.num_blocks()
            )));
        }
        if !point.as_ref().iter().all(|x| x.is_finite()) {
            return Err(Error::Request("the control point must be finite".into()));
        }
        let n = S::norm(direction);
        if !n.is_finite() || n <= 0.0 {
            return Err(Error::Request(
                "the control direction must be a non-zero vector".into(),
            ));
        }
        let mut direction = direction;
        for c in direction.as_mut() {
            *c /= n;
        }
        Ok(Control {
            block,
            point,
            direction,
        })
    }

    /// The control point at `x` on the block that contains it, or the nearest block.
    pub fn nearest<S: IncrementalGeometry<D = D>>(
        st: &S,
        x: D::Vector,
        direction: D::Vector,
    ) -> Result<Control<D>> {
        let mut best = (f64::INFINITY, 0usize);
        for i in 0..st.num_blocks() {
            let dist = st.distance_to_block(i, x);
            if dist < best.0 {
                best = (dist, i);
            }
        }
        // A point far from every block is a mistake (a typo, other units): refuse it rather
        // than attach it to whichever block happens to be nearest.
        let diag = st.extent().0;
        if !(best.0 <= CONTROL_REACH * diag) {
            let coords: Vec<String> = x.as_ref().iter().map(|c| c.to_string()).collect();
            return Err(Error::Request(format!(
                "control point ({}) is {:.3} m from the nearest block (block {}): give a point on the structure (within {:.0} % of its size)",
                coords.join(", "),
                best.0,
                best.1,
                100.0 * CONTROL_REACH
            )));
        }
        Control::new(st, best.1, x, direction)
    }
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
    /// The canonical selection (docs/canonical.md) of every step's collapse mechanism: least
    /// crack area among the step's optimal mechanisms, then the generic tie-break
    /// ([`crate::analysis::canonical::limit_mechanism`]; λ unchanged), so that the path (the
    /// moved geometry, hinges, cracks, events) does not depend on the LP method. `None`: the
    /// solver's own mechanism (the default, also of the request layer: `canonical_steps` asks
    /// for it; it costs 5–10× the raw CPU time, docs/performance.md).
    pub canonical: Option<CanonicalOptions>,
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
            canonical: None,
        }
    }
}

/// The structure after the settlement prescribed by its supports' motions: settlement
/// analysis, then every block moved by its finite rigid motion and every opened point given its
/// gap. `release` turns `fixed` supports into contact ones afterwards (see
/// [`crate::analysis::capacity::CapacityOptions::release_fixed`]).
pub fn settled<S: Assembly>(st: &S, solver: &SolverOptions, release: bool) -> Result<S> {
    Ok(settled_canonical(st, solver, release, None)?.0)
}

/// [`settled`] with the canonical settlement mechanism where `canonical` is given
/// ([`SettlementPath::with_canonical`]: least crack area among the optimal mechanisms, then the
/// generic tie-break), so that the settled geometry and its cracks do not depend on the LP
/// method; with how it was selected (`None` without `canonical`, or where the selection was not
/// reached: the solver's mechanism then settles the structure).
pub fn settled_canonical<S: Assembly>(
    st: &S,
    solver: &SolverOptions,
    release: bool,
    canonical: Option<CanonicalOptions>,
) -> Result<(S, Option<CanonicalMechanism>)> {
    let path = SettlementPath::with_canonical(
        st,
        solver,
        crate::analysis::laws::Crushing::Linear,
        crate::analysis::laws::DEFAULT_FACETS,
        None,
        canonical,
    )?;
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
    Ok((out, path.selection))
}

fn open_joints<S: IncrementalGeometry>(st: &S) -> Vec<usize> {
    (0..st.num_joints())
        .filter(|&j| (0..st.joint_points(j)).any(|k| st.joint_point(j, k).1 > 0.0))
        .collect()
}

/// Incremental analysis from `start` (undeformed, or settled with [`settled`]).
pub fn incremental<S: IncrementalGeometry>(
    start: &S,
    control: &Control<S::D>,
    opts: &IncrementalOptions,
) -> Result<IncrementalResult<S::D>> {
    incremental_with(start, control, opts, &mut |_| {})
}

/// [`incremental`], calling `progress` with every new point of the curve (for a progress bar).
pub fn incremental_with<S: IncrementalGeometry>(
    start: &S,
    control: &Control<S::D>,
    opts: &IncrementalOptions,
    progress: &mut dyn FnMut(&IncrementalPoint),
) -> Result<IncrementalResult<S::D>> {
    if !(opts.step > 0.0 && opts.step.is_finite()) {
        return Err(Error::Request("the step must be a positive number".into()));
    }
    if !(opts.max_displacement > 0.0 && opts.max_displacement.is_finite()) {
        return Err(Error::Request(
            "the maximum displacement must be a positive number".into(),
        ));
    }
    let (diag, far) = start.extent();
    if opts.step < MIN_RELATIVE_STEP * diag.max(far) {
        return Err(Error::Request(format!(
            "step {:.3e} m: below {MIN_RELATIVE_STEP:e} of the structure's size ({:.3e} m), too small for the geometry to record",
            opts.step,
            diag.max(far)
        )));
    }
    let wanted = (opts.max_displacement / opts.step).ceil();
    if wanted > opts.max_steps as f64 {
        // Numbers in e-notation when huge (`--max 1e300` printed 300 digits twice; session 24).
        let num = |x: f64| {
            if x.abs() >= 1e12 {
                format!("{x:.3e}")
            } else {
                format!("{x}")
            }
        };
        return Err(Error::Request(format!(
            "steps: a largest displacement of {} m in steps of {} m takes {} steps, more than the bound of {} (take a larger step)",
            num(opts.max_displacement),
            num(opts.step),
            num(wanted),
            opts.max_steps
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
    let mut snapshots: Vec<Snapshot<S::D>> = Vec::new();
    let mut xc = x0;
    let mut disp = 0.0f64;
    let mut peak = (f64::NEG_INFINITY, 0.0);
    let mut status = IncrementalStatus::MaxSteps;
    let mut steps = 0usize;
    let mut snaps = 0usize;
    let mut selection = opts.canonical.map(|_| StepSelection {
        steps: true,
        ..StepSelection::default()
    });
    // Dead-load moves in a row (no curve point between them): each should close a point; more
    // of them than the structure has points means the moves cycle (one closes a point and
    // opens another) — regression (session 18): the README's wall settled 5 mm and driven to
    // 20 mm ran its 100,000-step cap, minutes of LPs, where 17 mm ended in 0.15 s.
    let mut snaps_in_a_row = 0usize;
    let mut snap_cycle: Option<usize> = None;
    // Why a `ControlStill` run stopped: how the mechanism moves the control point.
    let mut still: Option<String> = None;
    for step in 0..opts.max_steps {
        steps = step;
        let map = KinematicMap::new(&st);
        if snaps_in_a_row > map.num_points() {
            snap_cycle = Some(map.num_points());
            status = IncrementalStatus::NoEquilibrium;
            break;
        }
        let sol = warm.solve(&st, &map)?;
        // `snap`: no equilibrium for any λ, but the dead loads alone drive a mechanism that
        // closes an open point (a hinge moving to the next joint): follow that mechanism, with
        // no point on the curve, until the point closes.
        let (d, lam, snap) = match (sol.status, sol.lambda) {
            (_, Some(l)) if !sol.mechanism.is_empty() => (
                select(&st, &map, &sol, opts, &mut selection, step)?,
                l,
                false,
            ),
            (LimitStatus::Locked, _) => {
                status = IncrementalStatus::Locked;
                break;
            }
            _ => match dead_load_ray(&st, &map, &opts.solver)? {
                Some(ray) if closes_a_gap(&map, &ray) => {
                    snaps += 1;
                    snaps_in_a_row += 1;
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
            snaps_in_a_row = 0;
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
        let c = st.block_reference(cb);
        let nd = <S::D as Dim>::DOFS;
        let uc = <S::D as Dim>::small_displacement(c, &d[nd * cb..nd * cb + nd], xc);
        let proj = <S::D as Dim>::dot(dir, uc);
        let dscale = d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if proj.abs() <= 1e-9 * dscale && !snap {
            status = IncrementalStatus::ControlStill;
            let m = <S::D as Dim>::dot(uc, uc).sqrt();
            let show = |v: &[f64], k: f64| {
                v.iter()
                    .map(|x| format!("{:.3}", (x * k * 1e3).round() / 1e3 + 0.0))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let dir_text = show(dir.as_ref(), 1.0);
            still = Some(if m > 1e-9 * dscale {
                format!(
                    "the collapse mechanism moves the control point along ({}), at right angles to the control direction ({}): there is no displacement along the direction to step by; take a control direction with a component along that motion, or another control point",
                    show(uc.as_ref(), 1.0 / m),
                    dir_text
                )
            } else {
                format!(
                    "the collapse mechanism does not move the control point (block {cb} stays still): there is no displacement along the control direction ({dir_text}) to step by; take a control point on a block that moves"
                )
            });
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
        let mut openings: Vec<Vec<f64>> = (0..st.num_joints())
            .map(|j| vec![0.0; st.joint_points(j)])
            .collect();
        for (k, p) in map.points.iter().enumerate() {
            openings[p.joint][p.index] = rate[k];
        }
        let mut next = st.deformed(d, alpha, &openings, alpha * rtol);
        for &k in &closing {
            let p = map.points[k];
            next.set_gap(p.joint, p.index, 0.0);
        }
        xc = st.move_point(cb, d, alpha, xc);
        let new_disp = <S::D as Dim>::dot(dir, <S::D as Dim>::sub(xc, x0));
        // Events.
        let mut any = false;
        for j in 0..st.num_joints() {
            for i in 0..st.joint_points(j).min(next.joint_points(j)) {
                let (ga, (xb, gb)) = (st.joint_point(j, i).1, next.joint_point(j, i));
                let kind = match (ga > 0.0, gb > 0.0) {
                    (false, true) => EventKind::Opened,
                    (true, false) => EventKind::Closed,
                    _ => continue,
                };
                any = true;
                let xb = xb.as_ref();
                events.push(Event {
                    step,
                    displacement: new_disp,
                    kind,
                    joint: j,
                    point: i,
                    x: xb[0],
                    y: xb[1],
                    z: xb.get(2).copied(),
                });
            }
        }
        if opts.snapshots
            && !snap
            && (step == 0 || any || (opts.snapshot_every > 0 && step % opts.snapshot_every == 0))
        {
            let zeros = vec![0.0; map.num_points() * map.tangents_per_point];
            let scale = 1.0 / proj;
            let dn: Vec<f64> = d.iter().map(|x| x * scale).collect();
            let rep = report(&st, &map, &dn, 0.0, &sol.pn, &zeros);
            snapshots.push(Snapshot {
                step,
                displacement: disp,
                load_multiplier: lam.max(0.0),
                blocks: rep.blocks,
                hinges: rep.hinges,
                geometry: st.shapes(),
            });
        }
        if !closing.is_empty() && !snap {
            // λ on the new geometry with the closing points still open: the value just before
            // the contact is restored, so that the jump shows at one displacement.
            let mut before = next.clone();
            for &k in &closing {
                let p = map.points[k];
                before.set_gap(p.joint, p.index, f64::MIN_POSITIVE);
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
            "reached the maximum control displacement {}",
            crate::lengths::Length::Position.show(opts.max_displacement)
        ),
        IncrementalStatus::MaxSteps => format!("stopped after {} steps", opts.max_steps),
        IncrementalStatus::Locked => {
            "no finite collapse load on the current geometry (locked)".to_string()
        }
        IncrementalStatus::NoEquilibrium if snap_cycle.is_some() => format!(
            "no equilibrium on the current geometry: the dead loads alone moved it {snaps_in_a_row} times in a row, more than its {} contact points, without an equilibrium at any λ: stopped",
            snap_cycle.unwrap_or(0)
        ),
        IncrementalStatus::NoEquilibrium => "no equilibrium on the current geometry".to_string(),
        IncrementalStatus::ControlStill => still.clone().unwrap_or_else(|| {
            "the mechanism does not move the control point along the direction".to_string()
        }),
    };
    let closed = events
        .iter()
        .filter(|e| e.kind == EventKind::Closed)
        .count();
    let mut message = format!(
        "peak λ = {} at a control displacement of {}; {} step{}, {} closure{}, {} hinge move{} under the dead loads; {}",
        crate::analysis::limit::show_multiplier(peak_l),
        crate::lengths::Length::Motion.show(peak.1),
        steps,
        if steps == 1 { "" } else { "s" },
        closed,
        if closed == 1 { "" } else { "s" },
        snaps,
        if snaps == 1 { "" } else { "s" },
        what
    );
    if let Some(c) = selection
        .as_ref()
        .filter(|c| !c.steps_not_reached.is_empty())
    {
        message.push_str(&format!(
            "; the canonical selection was not reached at {} of {} steps: the solver's own mechanism moved the structure there",
            c.steps_not_reached.len(),
            c.steps_not_reached.len() + c.steps_selected
        ));
    }
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
        cracks: st.gap_cracks(),
        steps,
        snaps,
        solves: warm.solves,
        iterations: warm.iterations,
        initial_geometry: start.shapes(),
        final_geometry: st.shapes(),
        canonical: selection.map(|selection| IncrementalCanonical {
            selection,
            ..IncrementalCanonical::default()
        }),
    })
}

/// The step's mechanism: the solver's, or with `opts.canonical` the canonical one among the
/// step's optimal mechanisms (λ unchanged), recorded in `rec` ([`StepSelection::select`]).
/// Where the selection is not reached the solver's mechanism stands and the step is listed.
fn select<S: Assembly>(
    st: &S,
    map: &KinematicMap,
    sol: &crate::analysis::limit::LimitSolution,
    opts: &IncrementalOptions,
    rec: &mut Option<StepSelection>,
    step: usize,
) -> Result<Vec<f64>> {
    Ok(match (opts.canonical.as_ref(), rec.as_mut()) {
        (Some(copts), Some(rec)) => rec.select(st, map, sol, &opts.solver, copts, step)?,
        _ => None,
    }
    .unwrap_or_else(|| sol.mechanism.clone()))
}

/// Whether mechanism `d` closes an open point.
fn closes_a_gap(map: &KinematicMap, d: &[f64]) -> bool {
    let (rate, _) = map.jumps(d, 0.0);
    let tol = OPEN_TOLERANCE * crate::scale::motion_scale(map, d, 0.0);
    (0..map.num_points()).any(|k| map.gap[k] > 0.0 && rate[k] < -tol)
}

/// When no λ gives equilibrium: a mechanism on which the live loads do no work and the dead
/// loads do positive work (a ray of the kinematic LP), with block DOFs bounded by 1.
fn dead_load_ray<S: Assembly>(
    st: &S,
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
