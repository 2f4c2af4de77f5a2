//! Load capacity after a settlement: limit analysis on the deformed geometry (the paper's
//! Section 6, Figs 7, 10, 12).
//!
//! ## What is computed
//!
//! The supports of the structure carry prescribed motions (`support.motion`): they give the
//! *direction* of the settlement and its *largest* value. The settlement magnitude `s` is
//! measured in metres as the largest support translation `max_k |(u_k, v_k)|` (in radians if the
//! supports only rotate). For the unit settlement (motions divided by that magnitude):
//!
//! 1. the settlement analysis ([`crate::analysis::settlement`]) gives the mechanism `d₁` and the
//!    openings `o₁ = N d₁ + g_n` per collocation point, per unit of settlement;
//! 2. for each `s` the structure is **deformed** ([`deform`]): every block moves by the exact
//!    finite rigid motion `s·d₁` (rotation by `s·θ` about its centroid, not the linearised one),
//!    every support by `s·motion`, and every point takes the gap `s·o₁`. A point whose opening
//!    exceeds `1e-7` of the largest opening is *open*: it stays in the structure with its gap
//!    but carries no force (an opened joint bears only on its hinge point; a fully opened joint
//!    carries nothing). Loads move with their blocks and keep their directions;
//! 3. the classic limit analysis ([`crate::analysis::limit`]) on the deformed structure gives the
//!    collapse multiplier `λ(s)` and its mechanism.
//!
//! `λ(s)` is computed at `steps + 1` equally spaced settlements from 0 to the largest; `s = 0` is
//! the plain limit analysis of the undeformed structure (the same LP with the same options,
//! equal bit for bit). The settlement at which `λ` reaches zero (the structure can no longer carry its own weight) is
//! bracketed from the curve (λ is allowed to go negative: the live load, reversed, that would be
//! needed) and refined by the Illinois variant of regula falsi to `root_tolerance` (1e-6 m).
//!
//! ## Validity
//!
//! Limit analysis on the deformed geometry is valid only if the collapse mechanism does not
//! close hinges that the settlement opened (the paper's Remark 1: a crack must close before it
//! carries force again, so the structure then behaves as a nonlinear elastic, not a plastic,
//! body). Open points are absent from the limit LP, so its mechanism is free to move them either
//! way. Each step therefore evaluates the collapse mechanism's opening rate `N d` at every open
//! point: a negative rate (beyond `1e-7` of the largest rate) means the mechanism closes a
//! settlement crack, and the step is flagged `valid: false` with the joints concerned. That is
//! the case for the incremental analysis ([`crate::analysis::incremental`]).
//!
//! ## Re-using the solver
//!
//! For `s > 0` every deformed structure has the same joints, points and open set (openings
//! scale with `s`), so the limit LPs differ only in their coefficients. [`WarmLimit`] keeps all
//! points as columns (open ones fixed at zero by their bounds), so that the optimal basis of one
//! step is a valid starting basis for the next, and hands it to HiGHS (`Highs_setBasis`).
//! What that saves is measured in `docs/capacity.md`.

use crate::analysis::limit::{solve_limit, LimitSolution, LimitStatus};
use crate::analysis::settlement::{solve_settlement, SettlementStatus};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, Direction, SolverOptions};
use crate::programs::ForceProgram;
use crate::result::{report, BlockMotion, Geometry, Hinge};
use crate::structure::Structure;
use serde::{Deserialize, Serialize};

/// Relative threshold below which an opening counts as closed (same as the reports').
pub const OPEN_TOLERANCE: f64 = 1e-7;

/// Options of the capacity analysis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CapacityOptions {
    /// Number of intervals: the curve has `steps + 1` points from 0 to the largest settlement.
    pub steps: usize,
    /// Tolerance of the zero-capacity settlement (m).
    pub root_tolerance: f64,
    /// Re-use the previous optimal basis (HiGHS hot start) between steps.
    pub hot_start: bool,
    /// Keep the collapse mechanism (block motions) of every step in the result.
    pub mechanisms: bool,
    /// After the settlement, treat `fixed` supports as ordinary contact joints (no tension, no
    /// sliding). `fixed` is how the paper prescribes a settlement (an essential boundary
    /// condition); the analyses that follow it use unilateral contact at every support. Default
    /// true; false keeps the blocks tied to their fixed supports.
    pub release_fixed: bool,
    pub solver: SolverOptions,
}

impl Default for CapacityOptions {
    fn default() -> Self {
        CapacityOptions {
            steps: 40,
            root_tolerance: 1e-6,
            hot_start: true,
            mechanisms: true,
            release_fixed: true,
            solver: SolverOptions::default(),
        }
    }
}

/// One point of the capacity curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CapacityPoint {
    /// Settlement magnitude s (m).
    pub settlement: f64,
    /// λ(s): collapse multiplier on the deformed geometry; negative when the dead loads alone
    /// cannot be carried; `null` when locked or without any equilibrium.
    pub load_multiplier: Option<f64>,
    pub status: LimitStatus,
    /// False when the collapse mechanism closes points opened by the settlement (standard limit
    /// analysis is then not valid: use the incremental analysis).
    pub valid: bool,
    /// Joints with an open point that the collapse mechanism would close.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub closing_joints: Vec<usize>,
    /// Hinges of the collapse mechanism (positions on the deformed geometry).
    pub hinges: Vec<Hinge>,
}

/// The collapse mechanism at one settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CapacityMechanism {
    pub settlement: f64,
    /// Block motion rates, normalised to unit work of the live loads.
    pub blocks: Vec<BlockMotion>,
}

/// A support's motion per unit settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SupportDirection {
    pub support: String,
    /// `[u, v, θ]` per metre of settlement (θ in radians).
    pub motion: [f64; 3],
}

/// Overall outcome.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CapacityStatus {
    /// The curve was computed.
    Curve,
    /// The settlement analysis found no mechanism (see the message): no curve.
    NoSettlementMechanism,
}

/// Result of a capacity analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CapacityResult {
    pub status: CapacityStatus,
    pub message: String,
    /// Largest settlement (m, or rad for pure rotations).
    pub max_settlement: f64,
    /// Motion of each moving support per unit settlement.
    pub direction: Vec<SupportDirection>,
    /// `{settlement, load_multiplier, valid, …}` for s = 0 … max.
    pub curve: Vec<CapacityPoint>,
    /// The settlement at which λ reaches 0 (`null` if λ does not change sign in the range).
    pub zero_capacity_settlement: Option<f64>,
    /// Least-squares line `λ ≈ intercept + slope·s` through the valid points with s > 0, and the
    /// largest deviation from it relative to λ(0) (a measure of linearity).
    pub linear_fit: Option<LinearFit>,
    /// Settlement mechanism per unit settlement and its hinges.
    pub settlement_mechanism: Vec<BlockMotion>,
    pub settlement_hinges: Vec<Hinge>,
    /// Collapse mechanism per step (empty unless requested).
    pub mechanisms: Vec<CapacityMechanism>,
    /// LP solves and simplex iterations spent (curve and root finding).
    pub solves: usize,
    pub iterations: i64,
    /// The undeformed geometry.
    pub geometry: Geometry,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LinearFit {
    pub intercept: f64,
    pub slope: f64,
    pub max_relative_deviation: f64,
}

/// Magnitude of a set of support motions: the largest translation (or rotation if none).
pub fn settlement_magnitude(st: &Structure) -> f64 {
    let t = st
        .supports
        .iter()
        .fold(0.0f64, |m, s| m.max(s.motion[0].hypot(s.motion[1])));
    if t > 0.0 {
        t
    } else {
        st.supports
            .iter()
            .fold(0.0f64, |m, s| m.max(s.motion[2].abs()))
    }
}

/// Openings of every point per joint for mechanism `d` (with the supports' prescribed motions),
/// in the layout [`Structure::deformed`] takes, and the closed/open threshold.
pub fn joint_openings(
    st: &Structure,
    map: &KinematicMap,
    d: &[f64],
    support_scale: f64,
) -> (Vec<Vec<f64>>, f64) {
    let (open, _) = map.jumps(d, support_scale);
    let scale = open.iter().fold(0.0f64, |m, o| m.max(o.abs()));
    let mut out: Vec<Vec<f64>> = st
        .joints
        .iter()
        .map(|j| vec![0.0; j.points.len()])
        .collect();
    for (k, p) in map.points.iter().enumerate() {
        out[p.joint][p.index] = open[k];
    }
    (out, OPEN_TOLERANCE * scale)
}

/// Move `st` by the mechanism `d` scaled by `s` (blocks by exact finite rigid motions, supports
/// by `s·motion`): points whose opening `s·(N d + g_n)` exceeds `1e-7` of the largest opening
/// get that gap (added to any gap they had) and carry no force; the others stay in contact.
pub fn deform(st: &Structure, d: &[f64], s: f64) -> Result<Structure> {
    if d.len() != 3 * st.blocks.len() {
        return Err(Error::Request(format!(
            "a mechanism for {} blocks needs {} values, got {}",
            st.blocks.len(),
            3 * st.blocks.len(),
            d.len()
        )));
    }
    if !s.is_finite() || d.iter().any(|x| !x.is_finite()) {
        return Err(Error::Request(
            "deformation: the mechanism and its scale must be finite".into(),
        ));
    }
    let map = KinematicMap::new(st);
    let (openings, tol) = joint_openings(st, &map, d, 1.0);
    Ok(st.deformed(d, s, &openings, (s.abs() * tol).max(0.0)))
}

/// The settlement path: the structure with unit support motions, its settlement mechanism and
/// openings, from which every deformed structure is made.
pub struct SettlementPath {
    /// The structure with its support motions divided by `max_settlement`.
    pub unit: Structure,
    pub max_settlement: f64,
    pub status: SettlementStatus,
    /// Settlement mechanism per unit settlement (empty unless `status` is a mechanism).
    pub mechanism: Vec<f64>,
    openings: Vec<Vec<f64>>,
    open_tol: f64,
}

impl SettlementPath {
    pub fn new(st: &Structure, solver: &SolverOptions) -> Result<SettlementPath> {
        let mag = settlement_magnitude(st);
        if !(mag.is_finite() && mag > 0.0) {
            return Err(Error::Request(
                "capacity analysis needs a settlement: no support has a prescribed motion".into(),
            ));
        }
        let motions: Vec<[f64; 3]> = st
            .supports
            .iter()
            .map(|s| s.motion.map(|x| x / mag))
            .collect();
        let unit = st.with_support_motions(&motions);
        let map = KinematicMap::new(&unit);
        let sol = solve_settlement(&unit, &map, solver)?;
        let (openings, open_tol) = if sol.status == SettlementStatus::Mechanism {
            joint_openings(&unit, &map, &sol.mechanism, 1.0)
        } else {
            (vec![], 0.0)
        };
        Ok(SettlementPath {
            unit,
            max_settlement: mag,
            status: sol.status,
            mechanism: sol.mechanism,
            openings,
            open_tol,
        })
    }

    /// The structure after a settlement `s` (m). `s = 0` returns the undeformed structure as is.
    pub fn deformed(&self, s: f64) -> Structure {
        if s == 0.0 || self.mechanism.is_empty() {
            let mut st = self.unit.clone();
            for sp in st.supports.iter_mut() {
                sp.motion = [0.0; 3];
            }
            return st;
        }
        let mut st =
            self.unit
                .deformed(&self.mechanism, s, &self.openings, s.abs() * self.open_tol);
        for sp in st.supports.iter_mut() {
            sp.motion = [0.0; 3];
        }
        st
    }
}

/// Turn every `fixed` support into a contact one: its joints become unilateral (no tension).
pub fn release_fixed(st: &mut Structure) {
    use crate::model::Connection;
    use crate::structure::Body;
    let fixed: Vec<bool> = st
        .supports
        .iter()
        .map(|s| s.connection == Connection::Fixed)
        .collect();
    for j in st.joints.iter_mut() {
        if [j.a, j.b]
            .iter()
            .any(|b| matches!(b, Body::Support(k) if fixed[*k]))
        {
            j.bilateral = false;
        }
    }
    for sp in st.supports.iter_mut() {
        sp.connection = Connection::Contact;
    }
}

/// Open points whose opening rate under mechanism `d` is negative: the joints whose settlement
/// cracks the mechanism would close.
pub fn closing_joints(st: &Structure, map: &KinematicMap, d: &[f64]) -> Vec<usize> {
    if d.is_empty() {
        return vec![];
    }
    let (rate, _) = map.jumps(d, 0.0);
    let scale = rate.iter().fold(0.0f64, |m, o| m.max(o.abs()));
    let tol = OPEN_TOLERANCE * scale;
    let mut out: Vec<usize> = map
        .points
        .iter()
        .enumerate()
        .filter(|(k, _)| map.gap[*k] > 0.0 && rate[*k] < -tol)
        .map(|(_, p)| p.joint)
        .collect();
    out.dedup();
    let _ = st;
    out
}

/// A limit LP kept between solves on structures of one topology (same blocks, joints and
/// points): all points are columns, open ones fixed at zero, and the optimal basis of a solve
/// starts the next one.
pub struct WarmLimit {
    solver: SolverOptions,
    hot: bool,
    basis: Option<(Vec<i32>, Vec<i32>)>,
    shape: (usize, usize),
    /// LP solves and simplex iterations so far.
    pub solves: usize,
    pub iterations: i64,
}

impl WarmLimit {
    /// `hot = false` solves every LP from scratch with [`solve_limit`].
    pub fn new(solver: &SolverOptions, hot: bool) -> WarmLimit {
        WarmLimit {
            solver: *solver,
            hot,
            basis: None,
            shape: (0, 0),
            solves: 0,
            iterations: 0,
        }
    }

    /// Limit analysis of `st` (same meaning as [`solve_limit`]).
    pub fn solve(&mut self, st: &Structure, map: &KinematicMap) -> Result<LimitSolution> {
        self.solves += 1;
        // Joint laws (friction, crushing) give gapped points roles of their own in the force
        // program: those structures are solved from scratch.
        let sol = if self.hot && !map.has_joint_laws() {
            self.solve_hot(st, map)?
        } else {
            solve_limit(st, map, &self.solver)?
        };
        self.iterations += sol.iterations;
        Ok(sol)
    }

    fn solve_hot(&mut self, st: &Structure, map: &KinematicMap) -> Result<LimitSolution> {
        if !st.has_live_loads() {
            return Err(Error::Request(
                "limit analysis needs live loads (the model has none)".into(),
            ));
        }
        let dead = st.load_vector(false);
        let live = st.load_vector(true);
        let mut all = map.clone();
        all.gap.iter_mut().for_each(|g| *g = 0.0);
        let mut fp = ForceProgram::new(&all, &dead, Some(&live), Direction::Maximise, |_| {
            (0.0, 0.0)
        });
        for k in 0..map.num_points() {
            if map.gap[k] > 0.0 {
                for c in [fp.pn[k], fp.pt[k]].into_iter().flatten() {
                    fp.lp.col_lower[c] = 0.0;
                    fp.lp.col_upper[c] = 0.0;
                }
            }
        }
        let shape = (fp.lp.num_cols(), fp.lp.num_rows());
        if shape != self.shape {
            self.basis = None;
            self.shape = shape;
        }
        let mut opts = self.solver;
        // Presolve would discard the starting basis; without one it is worth its cost.
        opts.presolve = self.solver.presolve && self.basis.is_none();
        let mut model = lp::build(&fp.lp);
        lp::configure(&mut model, &opts)?;
        if let Some((cs, rs)) = &self.basis {
            let cs = sanitize(cs, &fp.lp.col_lower, &fp.lp.col_upper);
            let rs = sanitize(rs, &fp.lp.row_lower, &fp.lp.row_upper);
            // SAFETY: the pointer is the live HiGHS instance owned by `model`; the arrays have
            // exactly num_col and num_row entries (checked by `shape`).
            let ok =
                unsafe { highs_sys::Highs_setBasis(model.as_mut_ptr(), cs.as_ptr(), rs.as_ptr()) };
            if ok == highs_sys::kHighsStatusError {
                self.basis = None;
            }
        }
        let solved = match model.try_solve() {
            Ok(s) => s,
            Err(_) => {
                // A failed run: forget the basis and solve from scratch.
                self.basis = None;
                return solve_limit(st, map, &self.solver);
            }
        };
        let iterations = solved.simplex_iteration_count();
        let status = solved.status();
        use highs::HighsModelStatus as H;
        let n = map.num_points();
        let none = |status, iterations| LimitSolution {
            status,
            lambda: None,
            mechanism: vec![],
            pn: vec![0.0; n],
            pt: vec![0.0; n],
            iterations,
        };
        match status {
            H::Optimal => {}
            H::Unbounded => return Ok(none(LimitStatus::Locked, iterations)),
            H::Infeasible => return Ok(none(LimitStatus::NoEquilibrium, iterations)),
            _ => {
                // Anything unusual: forget the basis and solve from scratch.
                self.basis = None;
                let mut s = solve_limit(st, map, &self.solver)?;
                s.iterations += iterations;
                return Ok(s);
            }
        }
        let s = solved.get_solution();
        let x = s.columns().to_vec();
        let y = s.dual_rows()[..map.num_dofs].to_vec();
        let mut cs = vec![0i32; shape.0];
        let mut rs = vec![0i32; shape.1];
        // SAFETY: as above; HiGHS fills exactly num_col and num_row entries.
        let got = unsafe {
            let mut m: highs::Model = solved.into();
            highs_sys::Highs_getBasis(m.as_mut_ptr(), cs.as_mut_ptr(), rs.as_mut_ptr())
        };
        self.basis = if got == highs_sys::kHighsStatusError {
            None
        } else {
            Some((cs, rs))
        };
        let lambda = x[fp.lambda.expect("program has λ")];
        let (pn, pt) = fp.forces(&x);
        let wl: f64 = live.iter().zip(&y).map(|(a, b)| a * b).sum();
        let mechanism = if wl.abs() > 0.0 {
            y.iter().map(|v| v / wl).collect()
        } else {
            vec![0.0; y.len()]
        };
        Ok(LimitSolution {
            status: if lambda >= 0.0 {
                LimitStatus::Collapse
            } else {
                LimitStatus::NoEquilibrium
            },
            lambda: Some(lambda),
            mechanism,
            pn,
            pt,
            iterations,
        })
    }
}

/// Make nonbasic statuses consistent with (possibly changed) bounds.
fn sanitize(status: &[i32], lo: &[f64], hi: &[f64]) -> Vec<i32> {
    use highs_sys::{
        kHighsBasisStatusBasic as B, kHighsBasisStatusLower as L, kHighsBasisStatusUpper as U,
        kHighsBasisStatusZero as Z,
    };
    status
        .iter()
        .zip(lo.iter().zip(hi))
        .map(|(&s, (&l, &h))| {
            if s == B {
                B
            } else if l.is_finite() && (s == L || !h.is_finite()) {
                L
            } else if h.is_finite() {
                U
            } else {
                Z
            }
        })
        .collect()
}

/// λ as a number for root finding: locked counts as +∞, no equilibrium at all as −∞.
fn signed_lambda(s: &LimitSolution) -> f64 {
    match (s.status, s.lambda) {
        (_, Some(l)) => l,
        (LimitStatus::Locked, None) => f64::INFINITY,
        _ => f64::NEG_INFINITY,
    }
}

/// Capacity curve λ(s) after the settlement prescribed by the supports' motions.
pub fn capacity(st: &Structure, opts: &CapacityOptions) -> Result<CapacityResult> {
    if opts.steps == 0 {
        return Err(Error::Request(
            "a capacity curve needs at least one step".into(),
        ));
    }
    if opts.root_tolerance.is_nan() || opts.root_tolerance <= 0.0 {
        return Err(Error::Request("the root tolerance must be positive".into()));
    }
    if !st.has_live_loads() {
        return Err(Error::Request(
            "capacity analysis needs live loads (the model has none)".into(),
        ));
    }
    let path = SettlementPath::new(st, &opts.solver)?;
    let smax = path.max_settlement;
    let direction: Vec<SupportDirection> = path
        .unit
        .supports
        .iter()
        .filter(|s| s.motion.iter().any(|&x| x != 0.0))
        .map(|s| SupportDirection {
            support: s.name.clone(),
            motion: s.motion,
        })
        .collect();
    if path.status != SettlementStatus::Mechanism {
        return Ok(CapacityResult {
            status: CapacityStatus::NoSettlementMechanism,
            message: format!("settlement analysis: {}", path.status.sentence()),
            max_settlement: smax,
            direction,
            curve: vec![],
            zero_capacity_settlement: None,
            linear_fit: None,
            settlement_mechanism: vec![],
            settlement_hinges: vec![],
            mechanisms: vec![],
            solves: 0,
            iterations: 0,
            geometry: Geometry::of(st),
        });
    }
    let umap = KinematicMap::new(&path.unit);
    let zeros = vec![0.0; umap.num_points()];
    let srep = report(&path.unit, &umap, &path.mechanism, 1.0, &zeros, &zeros);

    let mut warm = WarmLimit::new(&opts.solver, opts.hot_start);
    let mut curve = Vec::with_capacity(opts.steps + 1);
    let mut mechanisms = Vec::new();
    let mut values = Vec::with_capacity(opts.steps + 1);
    let (mut solves, mut iterations) = (0usize, 0i64);
    for i in 0..=opts.steps {
        let s = smax * i as f64 / opts.steps as f64;
        let mut dst = path.deformed(s);
        if opts.release_fixed {
            release_fixed(&mut dst);
        }
        let map = KinematicMap::new(&dst);
        // At s = 0 no point has a gap: the warm LP is then the plain limit LP itself (same
        // columns, same options, no starting basis), so λ(0) is the plain limit analysis
        // exactly, and its basis starts the next step.
        let sol = warm.solve(&dst, &map)?;
        values.push(signed_lambda(&sol));
        let closing = closing_joints(&dst, &map, &sol.mechanism);
        let hinges = if sol.mechanism.is_empty() {
            vec![]
        } else {
            report(&dst, &map, &sol.mechanism, 0.0, &sol.pn, &sol.pt).hinges
        };
        if opts.mechanisms && !sol.mechanism.is_empty() {
            let rep = report(&dst, &map, &sol.mechanism, 0.0, &sol.pn, &sol.pt);
            mechanisms.push(CapacityMechanism {
                settlement: s,
                blocks: rep.blocks,
            });
        }
        curve.push(CapacityPoint {
            settlement: s,
            load_multiplier: sol.lambda,
            status: sol.status,
            valid: closing.is_empty(),
            closing_joints: closing,
            hinges,
        });
    }

    // Zero-capacity settlement: first sign change of λ on the curve, refined.
    let mut zero = None;
    if values[0] == 0.0 {
        zero = Some(0.0);
    } else {
        for i in 1..values.len() {
            if values[i - 1] > 0.0 && values[i] <= 0.0 {
                if values[i] == 0.0 {
                    zero = Some(curve[i].settlement);
                } else {
                    let lam = |s: f64, w: &mut WarmLimit| -> Result<f64> {
                        let mut dst = path.deformed(s);
                        if opts.release_fixed {
                            release_fixed(&mut dst);
                        }
                        let map = KinematicMap::new(&dst);
                        Ok(signed_lambda(&w.solve(&dst, &map)?))
                    };
                    zero = Some(illinois(
                        (curve[i - 1].settlement, values[i - 1]),
                        (curve[i].settlement, values[i]),
                        opts.root_tolerance,
                        |s| lam(s, &mut warm),
                    )?);
                }
                break;
            }
        }
    }
    solves += warm.solves;
    iterations += warm.iterations;

    let linear_fit = fit(&curve);
    let l0 = curve[0].load_multiplier;
    let invalid = curve.iter().filter(|p| !p.valid).count();
    let mut message = match (l0, zero) {
        (Some(l0), Some(z)) => format!(
            "λ falls from {l0:.6} at no settlement to 0 at a settlement of {:.4} cm",
            z * 100.0
        ),
        (Some(l0), None) => format!(
            "λ = {l0:.6} at no settlement and {} at the largest settlement {:.4} cm: no zero crossing in the range",
            curve.last().and_then(|p| p.load_multiplier).map_or("undefined".to_string(), |l| format!("{l:.6}")),
            smax * 100.0
        ),
        (None, _) => format!("at no settlement: {}", curve[0].status.sentence()),
    };
    if invalid > 0 {
        message.push_str(&format!(
            "; WARNING: at {invalid} of {} settlements the collapse mechanism closes cracks opened by the settlement, so limit analysis is not valid there (use the incremental analysis)",
            curve.len()
        ));
    }
    Ok(CapacityResult {
        status: CapacityStatus::Curve,
        message,
        max_settlement: smax,
        direction,
        curve,
        zero_capacity_settlement: zero,
        linear_fit,
        settlement_mechanism: srep.blocks,
        settlement_hinges: srep.hinges,
        mechanisms,
        solves,
        iterations,
        geometry: Geometry::of(st),
    })
}

/// Root of `f` in `[a, b]` with `f(a) > 0 ≥ f(b)` (values may be ±∞), to `tol` in x: Illinois
/// regula falsi, bisecting whenever a value is infinite.
fn illinois(
    mut a: (f64, f64),
    mut b: (f64, f64),
    tol: f64,
    mut f: impl FnMut(f64) -> Result<f64>,
) -> Result<f64> {
    let mut side = 0i8;
    let mut width = f64::INFINITY;
    for _ in 0..200 {
        let w = (b.0 - a.0).abs();
        if w <= tol {
            break;
        }
        // Bisect whenever the last step did not halve the bracket (λ may jump, e.g. where a
        // hinge opens): at most twice the iterations of plain bisection.
        let bisect = w > 0.5 * width;
        width = w;
        let x = if !bisect && a.1.is_finite() && b.1.is_finite() && a.1 != b.1 {
            let x = (a.0 * b.1 - b.0 * a.1) / (b.1 - a.1);
            // Stay strictly inside and away from the ends by a fraction of the tolerance.
            x.clamp(a.0.min(b.0) + 0.25 * tol, a.0.max(b.0) - 0.25 * tol)
        } else {
            0.5 * (a.0 + b.0)
        };
        let fx = f(x)?;
        if fx == 0.0 {
            return Ok(x);
        }
        if fx > 0.0 {
            a = (x, fx);
            if side == 1 {
                b.1 *= 0.5;
            }
            side = 1;
        } else {
            b = (x, fx);
            if side == -1 {
                a.1 *= 0.5;
            }
            side = -1;
        }
    }
    // The crossing is between a and b; linear interpolation when both are finite.
    Ok(if a.1.is_finite() && b.1.is_finite() && a.1 != b.1 {
        (a.0 * b.1 - b.0 * a.1) / (b.1 - a.1)
    } else {
        0.5 * (a.0 + b.0)
    })
}

fn fit(curve: &[CapacityPoint]) -> Option<LinearFit> {
    let pts: Vec<(f64, f64)> = curve
        .iter()
        .filter(|p| p.settlement > 0.0 && p.valid)
        .filter_map(|p| p.load_multiplier.map(|l| (p.settlement, l)))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let n = pts.len() as f64;
    let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    if sxx == 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    let l0 = curve[0].load_multiplier.unwrap_or(my).abs().max(1e-300);
    let dev = pts
        .iter()
        .fold(0.0f64, |m, p| m.max((p.1 - intercept - slope * p.0).abs()));
    Some(LinearFit {
        intercept,
        slope,
        max_relative_deviation: dev / l0,
    })
}
