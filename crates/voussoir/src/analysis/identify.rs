//! Inverse settlement analysis: which support motions caused the cracks we see?
//!
//! Input: a structure (with its known support motions, usually none), **observations** of the
//! crack pattern ([`Observations`], JSON) and the **unknowns** ([`Unknown`]: which support-motion
//! components are free, or a profile family). With the crack pattern fixed, the settlement LPs'
//! optimality conditions are linear in the unknown motions, the mechanism and the forces
//! together; [`crate::programs_identify`] builds that LP (equations in its doc comment). Its
//! solution is the motion whose optimal settlement mechanism opens the observed cracks with the
//! least absolute misfit of the widths (in tolerances).
//!
//! The result ([`IdentifyResult`]) carries:
//! - the identified amplitudes and the support motions they make;
//! - the misfit of every observation and the predicted opening of every crack;
//! - a **certificate**: the forward settlement analysis ([`crate::analysis::settle`]) run on the
//!   identified motions, compared with the prediction (same open points, same widths, same work
//!   of the dead loads);
//! - **identifiability**: for each unknown, its range over all motions that reproduce the
//!   pattern with every width within its tolerance (a min and a max LP), flagged not
//!   identifiable when unbounded or wider than the value;
//! - when no motion produces the pattern: a sentence saying so, and the closest motion (the
//!   least-misfit admissible mechanism with optimality dropped, see
//!   [`crate::programs_identify::ClosestProgram`]) with its forward analysis.

// Loops run over point numbers that index several parallel vectors at once.
#![allow(clippy::needless_range_loop)]

use crate::analysis::settlement::{
    settle, settle_with, SettlementForm, SettlementResult, SettlementStatus,
};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, Direction, LpStatus, SolverOptions};
use crate::programs::{settlement_force_program, ForceProgram};
use crate::programs_identify::{
    decided, Activity, ClosestProgram, IdentifyProgram, MisfitMode, PointRole,
};
use crate::settlement_input::Profile;
use crate::structure::{Assembly, Structure};
use serde::{Deserialize, Serialize};

/// Default measurement tolerance of a crack width (m): 0.1 mm, a crack gauge's resolution.
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

// --- Observations -------------------------------------------------------------------------

pub use crate::model::Width;

/// One observed crack. Exactly one of `at` (the nearest collocation point of any joint: the
/// surveyor's coordinates) and `joint` (a joint id: widths at its points in order, start then
/// end, or one width for all of them). A width of 0 says "observed closed here".
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Crack {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joint: Option<usize>,
    /// Width (m), ≥ 0.
    pub opening: Width,
    /// Measurement tolerance of this crack (m); default: the file's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
}

/// Where nothing was observed (plaster, not surveyed): a joint, or every joint point inside an
/// axis-aligned box `[x0, y0, x1, y1]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Unobserved {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joint: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub region: Option<[f64; 4]>,
}

/// The survey: cracks, unobserved parts, tolerance. Every joint point that is neither cracked
/// nor unobserved is observed closed.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Observations {
    /// Global measurement tolerance (m), default [`DEFAULT_TOLERANCE`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    #[serde(default)]
    pub cracks: Vec<Crack>,
    #[serde(default)]
    pub unobserved: Vec<Unobserved>,
}

/// An observation resolved to one collocation point.
#[derive(Clone, Debug, PartialEq)]
struct PointObs {
    crack: usize,
    point: usize,
    width: f64,
    tolerance: f64,
}

fn finite_nonneg(x: f64) -> bool {
    x.is_finite() && x >= 0.0
}

impl Observations {
    /// Resolve to one role per collocation point, and the list of observed points.
    fn resolve(
        &self,
        st: &Structure,
        map: &KinematicMap,
    ) -> Result<(Vec<PointRole>, Vec<PointObs>)> {
        let bad = |m: String| Err(Error::Request(m));
        let tol = self.tolerance.unwrap_or(DEFAULT_TOLERANCE);
        if !(tol.is_finite() && tol > 0.0) {
            return bad(format!(
                "observations: tolerance {tol} must be a finite number > 0 (m)"
            ));
        }
        let npts = map.num_points();
        let xy = |k: usize| st.joints[map.points[k].joint].points[map.points[k].index].x;
        let mut roles = vec![PointRole::Closed; npts];
        for (k, r) in roles.iter_mut().enumerate() {
            if map.gap[k] > 0.0 {
                *r = PointRole::Unobserved;
            }
        }
        for (i, u) in self.unobserved.iter().enumerate() {
            match (u.joint, u.region) {
                (Some(j), None) => {
                    if j >= st.joints.len() {
                        return bad(format!("unobserved[{i}]: joint {j} does not exist (the structure has {} joints)", st.joints.len()));
                    }
                    for r in &mut roles[map.joint_start[j]..map.joint_start[j + 1]] {
                        *r = PointRole::Unobserved;
                    }
                }
                (None, Some([x0, y0, x1, y1])) => {
                    if ![x0, y0, x1, y1].iter().all(|v| v.is_finite()) || x1 < x0 || y1 < y0 {
                        return bad(format!("unobserved[{i}]: region must be finite [x0, y0, x1, y1] with x0 ≤ x1, y0 ≤ y1"));
                    }
                    for (k, r) in roles.iter_mut().enumerate() {
                        let p = xy(k);
                        if p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1 {
                            *r = PointRole::Unobserved;
                        }
                    }
                }
                _ => {
                    return bad(format!(
                        "unobserved[{i}]: give exactly one of \"joint\" and \"region\""
                    ))
                }
            }
        }
        let mut seen: Vec<Option<usize>> = vec![None; npts];
        let mut obs = Vec::new();
        for (i, c) in self.cracks.iter().enumerate() {
            let tau = c.tolerance.unwrap_or(tol);
            if !(tau.is_finite() && tau > 0.0) {
                return bad(format!(
                    "cracks[{i}]: tolerance {tau} must be a finite number > 0 (m)"
                ));
            }
            let points: Vec<(usize, f64)> = st
                .crack_points(&format!("cracks[{i}]"), c.at, c.joint, &c.opening)?
                .into_iter()
                .map(|(j, k, w)| (map.joint_start[j] + k, w))
                .collect();
            for (k, w) in points {
                if !finite_nonneg(w) {
                    return bad(format!(
                        "cracks[{i}]: width {w} must be a finite number ≥ 0 (m)"
                    ));
                }
                if let Some(other) = seen[k] {
                    return bad(format!(
                        "cracks[{i}] and cracks[{other}] observe the same point of joint {}",
                        map.points[k].joint
                    ));
                }
                if map.gap[k] > 0.0 {
                    return bad(format!(
                        "cracks[{i}]: joint {} has a gap at that point (not in contact)",
                        map.points[k].joint
                    ));
                }
                seen[k] = Some(i);
                roles[k] = if w > 0.0 {
                    PointRole::Open {
                        width: w,
                        tolerance: tau,
                    }
                } else {
                    PointRole::Closed
                };
                obs.push(PointObs {
                    crack: i,
                    point: k,
                    width: w,
                    tolerance: tau,
                });
            }
        }
        Ok((roles, obs))
    }
}

// --- Unknowns -----------------------------------------------------------------------------

/// One unknown amplitude `a`: the support motions are `base + a · unit` (per support
/// `(u, v, θ)`, m and rad), with optional bounds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Unknown {
    pub name: String,
    /// Motion of every support per unit amplitude.
    pub unit: Vec<[f64; 3]>,
    /// Motion added whatever the amplitude (a profile's fixed part; usually zero).
    pub base: Vec<[f64; 3]>,
    pub lower: Option<f64>,
    pub upper: Option<f64>,
}

/// A support-motion component.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Component {
    /// Horizontal translation (m).
    U,
    /// Vertical translation (m, up positive).
    V,
    /// Rotation about the support's centroid (rad, counter-clockwise).
    Theta,
}

impl Component {
    fn index(self) -> usize {
        match self {
            Component::U => 0,
            Component::V => 1,
            Component::Theta => 2,
        }
    }
    pub fn name(self) -> &'static str {
        ["u", "v", "theta"][self.index()]
    }
}

impl Unknown {
    /// One component shared by the supports `names` (one support, or a set of foundation
    /// segments settling together), named `label.component`.
    pub fn supports(
        st: &Structure,
        label: &str,
        names: &[String],
        component: Component,
        lower: Option<f64>,
        upper: Option<f64>,
    ) -> Result<Unknown> {
        let ns = st.supports.len();
        let mut unit = vec![[0.0; 3]; ns];
        if names.is_empty() {
            return Err(Error::Request(format!(
                "unknown '{label}': no support given"
            )));
        }
        for n in names {
            let Some(s) = st.supports.iter().position(|s| &s.name == n) else {
                let known: Vec<&str> = st
                    .supports
                    .iter()
                    .map(|s| s.name.as_str())
                    .take(12)
                    .collect();
                return Err(Error::Request(format!(
                    "unknown '{label}': no support named '{n}' (the model has: {}{})",
                    known.join(", "),
                    if ns > 12 { ", …" } else { "" }
                )));
            };
            unit[s][component.index()] = 1.0;
        }
        Unknown::new(
            format!("{label}.{}", component.name()),
            unit,
            vec![[0.0; 3]; ns],
            lower,
            upper,
        )
    }

    /// A profile family: `at0` and `at1` are the profile with the unknown value set to 0 and
    /// to 1; the motions are `at0`'s plus the unknown times the difference (profiles are linear
    /// in their values, so this is exact when only values differ). Each support takes the
    /// profile's value and slope at its centroid (as [`crate::settlement_input::apply_profile`]).
    pub fn profile(
        st: &Structure,
        name: &str,
        at0: &Profile,
        at1: &Profile,
        lower: Option<f64>,
        upper: Option<f64>,
    ) -> Result<Unknown> {
        let (p0, p1) = (at0, at1);
        p0.validate()?;
        p1.validate()?;
        let motion = |p: &Profile| -> Vec<[f64; 3]> {
            st.supports
                .iter()
                .map(|s| {
                    let (v, slope) = p.eval(s.centroid[0]);
                    [0.0, v, slope]
                })
                .collect()
        };
        let (m0, m1) = (motion(p0), motion(p1));
        let unit: Vec<[f64; 3]> = m0
            .iter()
            .zip(&m1)
            .map(|(a, b)| [b[0] - a[0], b[1] - a[1], b[2] - a[2]])
            .collect();
        if unit.iter().all(|u| u.iter().all(|x| *x == 0.0)) {
            return Err(Error::Request(format!(
                "unknown '{name}': the profile moves no support with its unknown (no support centroid inside its range)"
            )));
        }
        Unknown::new(name.to_string(), unit, m0, lower, upper)
    }

    fn new(
        name: String,
        unit: Vec<[f64; 3]>,
        base: Vec<[f64; 3]>,
        lower: Option<f64>,
        upper: Option<f64>,
    ) -> Result<Unknown> {
        for b in [lower, upper].into_iter().flatten() {
            if !b.is_finite() {
                return Err(Error::Request(format!(
                    "unknown '{name}': bounds must be finite"
                )));
            }
        }
        if let (Some(a), Some(b)) = (lower, upper) {
            if a > b {
                return Err(Error::Request(format!(
                    "unknown '{name}': lower bound {a} > upper bound {b}"
                )));
            }
        }
        Ok(Unknown {
            name,
            unit,
            base,
            lower,
            upper,
        })
    }
}

// --- Result -------------------------------------------------------------------------------

/// Whether a motion reproducing the pattern exists.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum IdentifyStatus {
    /// A motion whose settlement mechanism opens exactly the observed pattern was found.
    Identified,
    /// No motion within the bounds makes the observed pattern a settlement mechanism; the
    /// closest motion is reported.
    Inconsistent,
}

/// One unknown's identified value and identifiability.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct UnknownResult {
    pub name: String,
    pub value: f64,
    pub lower_bound: Option<f64>,
    pub upper_bound: Option<f64>,
    /// Smallest and largest value over every motion reproducing the pattern with each width
    /// within its tolerance (None: the range LPs were not run, or no motion is within
    /// tolerance). Unbounded ends are `null` in `range_min`/`range_max`.
    pub range_min: Option<f64>,
    pub range_max: Option<f64>,
    pub range_computed: bool,
    pub identifiable: bool,
    /// One sentence on identifiability.
    pub note: String,
}

/// A support's identified motion (base plus unknowns).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SupportMotion {
    pub support: String,
    pub u: f64,
    pub v: f64,
    pub theta: f64,
}

/// One observed point against the prediction.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObservationResult {
    /// Index in `cracks`.
    pub crack: usize,
    pub joint: usize,
    /// Point of the joint (0: start, 1: end).
    pub point: usize,
    pub x: f64,
    pub y: f64,
    pub observed: f64,
    pub predicted: f64,
    /// predicted − observed (m).
    pub misfit: f64,
    pub tolerance: f64,
    pub within_tolerance: bool,
}

/// A predicted crack (a point that opens).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PredictedCrack {
    pub joint: usize,
    pub point: usize,
    pub x: f64,
    pub y: f64,
    pub opening: f64,
    /// `open`, `closed` (observed closed: a contradiction) or `unobserved`.
    pub observed: String,
}

/// The check that the forward settlement analysis of the identified motion reproduces the
/// prediction.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Reproduction {
    /// Forward analysis certified (status mechanism, duality gap within tolerance).
    pub forward_certified: bool,
    /// Work of the dead loads: forward optimum and on the predicted mechanism (kN·m).
    pub forward_work: Option<f64>,
    pub predicted_work: f64,
    /// |forward − predicted| / max(|forward|, floor).
    pub work_relative_difference: Option<f64>,
    /// Largest |forward opening − predicted opening| over all points (m).
    pub max_opening_difference: Option<f64>,
    /// Whether the forward analysis opens exactly the predicted points.
    pub same_open_points: bool,
    /// Forward certified, same work, same open points and openings within 1e-6 of the largest.
    pub reproduces: bool,
    pub message: String,
}

/// Result of an inverse settlement analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct IdentifyResult {
    pub status: IdentifyStatus,
    pub message: String,
    pub unknowns: Vec<UnknownResult>,
    /// Support motions (m, rad) of the identified (or closest) motion; moving supports only.
    pub support_motions: Vec<SupportMotion>,
    pub observations: Vec<ObservationResult>,
    /// Σ |misfit| / tolerance over the observations.
    pub total_misfit: f64,
    /// The same over every observed point, the implicitly closed ones included (equal to
    /// `total_misfit` when identified: closed points are closed by construction).
    pub misfit_all_points: f64,
    pub max_misfit: f64,
    pub predicted_cracks: Vec<PredictedCrack>,
    /// Whether the active set at unobserved points or Coulomb rows had to be fixed after a
    /// first solve.
    pub active_set_fixed: bool,
    pub certificate: Option<Reproduction>,
    /// The forward settlement analysis of the identified (or closest) motion.
    pub forward: SettlementResult,
}

/// Options of [`identify`].
#[derive(Clone, Copy, Debug)]
pub struct IdentifyOptions {
    pub solver: SolverOptions,
    /// Run the identifiability LPs (two per unknown).
    pub ranges: bool,
    /// Form of the forward settlement analysis (the certificate).
    pub form: SettlementForm,
}

impl Default for IdentifyOptions {
    fn default() -> Self {
        IdentifyOptions {
            solver: SolverOptions::default(),
            ranges: true,
            form: SettlementForm::Both,
        }
    }
}

// --- The analysis -------------------------------------------------------------------------

fn motions_of(st: &Structure, unknowns: &[Unknown], a: &[f64]) -> Vec<[f64; 3]> {
    let mut m: Vec<[f64; 3]> = st.supports.iter().map(|s| s.motion).collect();
    for (q, u) in unknowns.iter().enumerate() {
        for (s, mm) in m.iter_mut().enumerate() {
            for c in 0..3 {
                mm[c] += u.base[s][c] + a[q] * u.unit[s][c];
            }
        }
    }
    m
}

/// The forward settlement analysis, as `voussoir settle` runs it: [`settle`] for both LPs,
/// [`settle_with`] for the force-only form.
fn forward_settle(st: &Structure, opts: &IdentifyOptions) -> Result<SettlementResult> {
    match opts.form {
        SettlementForm::Both => settle(st, &opts.solver),
        form => settle_with(st, &opts.solver, form),
    }
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// Identify the unknown support motions from the observed crack pattern.
pub fn identify(
    st: &Structure,
    obs: &Observations,
    unknowns: &[Unknown],
    opts: &IdentifyOptions,
) -> Result<IdentifyResult> {
    if unknowns.is_empty() {
        return Err(Error::Request(
            "identify: give at least one unknown support motion".into(),
        ));
    }
    for u in unknowns {
        if u.unit.len() != st.supports.len() || u.base.len() != st.supports.len() {
            return Err(Error::Request(format!(
                "unknown '{}': one motion per support expected",
                u.name
            )));
        }
    }
    let map_base = KinematicMap::new(st);
    if let Some(k) = map_base.gap.iter().position(|g| *g > 0.0) {
        return Err(Error::Request(format!(
            "identify: joint {} of the model is already cracked (the model's \"cracks\"); give the surveyed cracks as observations instead",
            map_base.points[k].joint
        )));
    }
    if let Some(j) = map_base.laws.iter().position(|l| l.strength.is_some()) {
        return Err(Error::Request(format!(
            "identify: joint {j} has a finite compressive strength, which the inverse analysis does not handle (Heyman joints and Coulomb friction only)"
        )));
    }
    // Base motions: the structure's own plus the unknowns' fixed parts.
    let zero = vec![0.0; unknowns.len()];
    let st0 = st.with_support_motions(&motions_of(st, unknowns, &zero));
    let map = KinematicMap::new(&st0);
    let (roles, pobs) = obs.resolve(&st0, &map)?;
    let gtol = obs.tolerance.unwrap_or(DEFAULT_TOLERANCE);
    // Unit responses.
    let unit: Vec<(Vec<f64>, Vec<f64>)> = unknowns
        .iter()
        .map(|u| {
            let m = KinematicMap::new(&st0.with_support_motions(&u.unit));
            (m.support_normal, m.support_tangent)
        })
        .collect();
    let bounds: Vec<(f64, f64)> = unknowns
        .iter()
        .map(|u| {
            (
                u.lower.unwrap_or(f64::NEG_INFINITY),
                u.upper.unwrap_or(f64::INFINITY),
            )
        })
        .collect();
    let dead = st0.load_vector(false);
    let fp = settlement_force_program(&map, &dead);
    let mut activity = Activity::default();
    let mut active_set_fixed = false;
    let ip = IdentifyProgram::new(
        &map,
        &fp,
        &unit,
        &bounds,
        &roles,
        &activity,
        MisfitMode::Minimise,
    );
    let sol = lp::solve(&ip.lp, &opts.solver)?;
    let mut solved = (sol.status == LpStatus::Optimal).then_some((ip, sol));
    // Complementarity left open by the observations: impose the active set the solution
    // suggests and solve once more; keep the first solution if that fails (the certificate
    // then tells whether the forward analysis agrees).
    if let Some((ip, sol)) = &solved {
        if let Some(fix) = open_complementarity(&map, &fp, ip, &sol.x, &roles) {
            let ip2 = IdentifyProgram::new(
                &map,
                &fp,
                &unit,
                &bounds,
                &roles,
                &fix,
                MisfitMode::Minimise,
            );
            let sol2 = lp::solve(&ip2.lp, &opts.solver)?;
            if sol2.status == LpStatus::Optimal {
                activity = fix;
                active_set_fixed = true;
                solved = Some((ip2, sol2));
            }
        }
    }
    let Some((ip, sol)) = solved else {
        let why = "no motion within the bounds makes this pattern a settlement mechanism";
        return closest(
            st, &map, unknowns, &unit, &bounds, &roles, &pobs, opts, gtol, why,
        );
    };
    let a = ip.amplitudes(&sol.x);
    let d = ip.motion(&sol.x);
    let st_id = st.with_support_motions(&motions_of(st, unknowns, &a));
    let map_id = KinematicMap::new(&st_id);
    let (open, _) = map_id.jumps(&d, 1.0);
    let omax = max_abs(&open);
    // The pattern is produced only if every crack observed open is predicted open: the LP
    // forbids force there but cannot ask for a strictly positive opening.
    let wmax = pobs.iter().fold(0.0f64, |m, o| m.max(o.width));
    let shut: Vec<String> = pobs
        .iter()
        .filter(|o| o.width > 0.0 && open[o.point] <= 1e-7 * wmax)
        .map(|o| map.points[o.point].joint.to_string())
        .collect();
    if !shut.is_empty() {
        let why = format!(
            "the best motion with this pattern leaves the cracks at joints {} closed",
            dedup(shut)
        );
        return closest(
            st, &map, unknowns, &unit, &bounds, &roles, &pobs, opts, gtol, &why,
        );
    }
    let forward = forward_settle(&st_id, opts)?;
    let (observations, total, maxm) = compare(&st_id, &map_id, &pobs, &open);
    let predicted_cracks = predicted(&st_id, &map_id, &open, &roles, omax);
    // Certificate: run the forward analysis and compare.
    let predicted_work: f64 = dead.iter().zip(&d).map(|(f, x)| f * x).sum();
    let certificate = Some(reproduction(
        &st_id,
        &map_id,
        &forward,
        &open,
        predicted_work,
    ));
    // Identifiability.
    let mut unknown_results = Vec::new();
    for (q, u) in unknowns.iter().enumerate() {
        let (mut lo, mut hi, mut computed) = (None, None, false);
        let mut feasible = true;
        if opts.ranges {
            computed = true;
            for sense in [Direction::Minimise, Direction::Maximise] {
                let rp = IdentifyProgram::new(
                    &map,
                    &fp,
                    &unit,
                    &bounds,
                    &roles,
                    &activity,
                    MisfitMode::WithinTolerance { unknown: q, sense },
                );
                let s = lp::solve(&rp.lp, &opts.solver)?;
                let v = match s.status {
                    LpStatus::Optimal => Some(s.x[rp.a[q]]),
                    LpStatus::Unbounded => None,
                    LpStatus::Infeasible => {
                        feasible = false;
                        None
                    }
                };
                if sense == Direction::Minimise {
                    lo = v;
                } else {
                    hi = v;
                }
            }
        }
        let value = a[q] + 0.0; // no "-0"
        let (identifiable, note) = if !computed {
            (false, "range not computed".to_string())
        } else if !feasible {
            (false, "no motion reproduces the pattern with every width within its tolerance: the range is empty; widen the tolerances".to_string())
        } else {
            match (lo, hi) {
                (Some(l), Some(h)) => {
                    let w = h - l;
                    if w > value.abs() {
                        (false, format!("not identifiable: the range [{l:.6e}, {h:.6e}] is wider than the value"))
                    } else {
                        (true, format!("identifiable within [{l:.6e}, {h:.6e}]"))
                    }
                }
                _ => (false, "not identifiable: unbounded over the motions that fit the observations (no observed crack depends on it)".to_string()),
            }
        };
        unknown_results.push(UnknownResult {
            name: u.name.clone(),
            value,
            lower_bound: u.lower,
            upper_bound: u.upper,
            range_min: if feasible { lo } else { None },
            range_max: if feasible { hi } else { None },
            range_computed: computed,
            identifiable,
            note,
        });
    }
    let reproduces = certificate.as_ref().is_some_and(|c| c.reproduces);
    let message = if reproduces {
        format!(
            "identified: the settlement mechanism of these support motions opens the observed cracks (misfit {total:.3} tolerances in total, largest {maxm:.3e} m), and the forward settlement analysis reproduces it"
        )
    } else {
        format!(
            "identified a motion whose settlement mechanism opens the observed cracks (misfit {total:.3} tolerances), but the forward analysis does not reproduce it exactly: {}",
            certificate.as_ref().map(|c| c.message.as_str()).unwrap_or("")
        )
    };
    Ok(IdentifyResult {
        status: IdentifyStatus::Identified,
        message,
        unknowns: unknown_results,
        support_motions: support_motions(&st_id),
        observations,
        total_misfit: total,
        misfit_all_points: total,
        max_misfit: maxm,
        predicted_cracks,
        active_set_fixed,
        certificate,
        forward,
    })
}

/// Complementarity the observations did not fix: `p_n z = 0` at unobserved points and
/// `y (A x − U) = 0` on Coulomb rows. None if it holds; otherwise the active set to impose.
fn open_complementarity(
    map: &KinematicMap,
    fp: &ForceProgram,
    ip: &IdentifyProgram,
    x: &[f64],
    roles: &[PointRole],
) -> Option<Activity> {
    let f = &fp.lp;
    let xs = &x[ip.x0..ip.x0 + f.num_cols()];
    let ys = &x[ip.y0..ip.y0 + f.num_rows()];
    let d = ip.motion(x);
    let fscale = max_abs(xs).max(1e-300);
    let dscale = max_abs(&d).max(1e-300);
    // Reduced costs z_j = c_j(a) − A_jᵀy, read from the LP's own dual rows (they hold
    // z_j − c₀_j): complementarity at an unobserved point is p_n z = 0.
    let act = f.row_activity(xs);
    let zrow: Vec<f64> = {
        let full = ip.lp.row_activity(x);
        let zrow0 = f.num_rows();
        (0..f.num_cols())
            .map(|j| full[zrow0 + j] + f.cost[j])
            .collect()
    };
    let mut need = false;
    let mut point_open = vec![None; map.num_points()];
    for k in 0..map.num_points() {
        if map.bilateral[k] || decided(map, roles, &Activity::default(), k).is_some() {
            continue;
        }
        let Some(j) = fp.pn[k] else { continue };
        let (p, z) = (xs[j], zrow[j]);
        let is_open = z > 1e-9 * dscale;
        if is_open && p > 1e-9 * fscale {
            need = true;
        }
        point_open[k] = Some(is_open);
    }
    let mut row_active = vec![None; f.num_rows()];
    for i in map.num_dofs..f.num_rows() {
        let slack = f.row_upper[i] - act[i];
        if !f.row_upper[i].is_finite() {
            continue;
        }
        let active = slack <= 1e-9 * fscale;
        if !active && ys[i].abs() > 1e-9 * dscale {
            need = true;
        }
        row_active[i] = Some(active);
    }
    need.then_some(Activity {
        point_open,
        row_active,
    })
}

fn compare(
    st: &Structure,
    map: &KinematicMap,
    pobs: &[PointObs],
    open: &[f64],
) -> (Vec<ObservationResult>, f64, f64) {
    let mut total = 0.0;
    let mut maxm = 0.0f64;
    let list = pobs
        .iter()
        .map(|o| {
            let pr = map.points[o.point];
            let p = st.joints[pr.joint].points[pr.index].x;
            let predicted = open[o.point];
            let misfit = predicted - o.width;
            total += misfit.abs() / o.tolerance;
            maxm = maxm.max(misfit.abs());
            ObservationResult {
                crack: o.crack,
                joint: pr.joint,
                point: pr.index,
                x: p[0],
                y: p[1],
                observed: o.width,
                predicted,
                misfit,
                tolerance: o.tolerance,
                within_tolerance: misfit.abs() <= o.tolerance * (1.0 + 1e-9),
            }
        })
        .collect();
    (list, total, maxm)
}

fn predicted(
    st: &Structure,
    map: &KinematicMap,
    open: &[f64],
    roles: &[PointRole],
    omax: f64,
) -> Vec<PredictedCrack> {
    (0..map.num_points())
        .filter(|&k| open[k] > 1e-7 * omax && map.gap[k] <= 0.0)
        .map(|k| {
            let pr = map.points[k];
            let p = st.joints[pr.joint].points[pr.index].x;
            PredictedCrack {
                joint: pr.joint,
                point: pr.index,
                x: p[0],
                y: p[1],
                opening: open[k],
                observed: match roles[k] {
                    PointRole::Open { .. } => "open",
                    PointRole::Closed => "closed",
                    PointRole::Unobserved => "unobserved",
                }
                .to_string(),
            }
        })
        .collect()
}

fn reproduction(
    st: &Structure,
    map: &KinematicMap,
    forward: &SettlementResult,
    open: &[f64],
    predicted_work: f64,
) -> Reproduction {
    let certified = forward.status == SettlementStatus::Mechanism
        && forward.certificate.as_ref().is_some_and(|c| c.ok);
    let omax = max_abs(open);
    let thr = 1e-7 * omax.max(1e-300);
    let mut fopen = vec![0.0; map.num_points()];
    if forward.status == SettlementStatus::Mechanism {
        for (j, jr) in forward.joints.iter().enumerate() {
            for (i, p) in jr.points.iter().enumerate() {
                fopen[map.joint_start[j] + i] = p.opening;
            }
        }
    }
    let _ = st;
    let diff = (0..map.num_points())
        .filter(|&k| map.gap[k] <= 0.0)
        .fold(0.0f64, |m, k| m.max((fopen[k] - open[k]).abs()));
    let same = (0..map.num_points())
        .filter(|&k| map.gap[k] <= 0.0)
        .all(|k| (fopen[k] > thr) == (open[k] > thr));
    let fw = forward.work_dead_loads;
    let wrel =
        fw.map(|w| (w - predicted_work).abs() / w.abs().max(predicted_work.abs()).max(1e-300));
    let work_ok =
        wrel.is_some_and(|r| r <= 1e-6) || fw.is_some_and(|w| (w - predicted_work).abs() < 1e-12);
    let widths_ok = diff <= 1e-6 * omax.max(1e-300);
    let reproduces = certified && work_ok && same && widths_ok;
    let message = if reproduces {
        "the forward settlement analysis of the identified motion opens the same points with the same widths".to_string()
    } else if !certified {
        format!(
            "the forward settlement analysis is not certified ({})",
            forward.message
        )
    } else if work_ok {
        format!(
            "the forward analysis finds a mechanism with the same work of the dead loads (the predicted one is also optimal: the settlement mechanism is not unique), but {} (largest width difference {diff:.3e} m)",
            if same { "different widths" } else { "different open points" }
        )
    } else {
        format!("the forward analysis finds more work of the dead loads ({:.6e} against {predicted_work:.6e} kN·m)", fw.unwrap_or(f64::NAN))
    };
    Reproduction {
        forward_certified: certified,
        forward_work: fw,
        predicted_work,
        work_relative_difference: wrel,
        max_opening_difference: Some(diff),
        same_open_points: same,
        reproduces,
        message,
    }
}

fn support_motions(st: &Structure) -> Vec<SupportMotion> {
    st.supports
        .iter()
        .filter(|s| s.motion.iter().any(|x| *x != 0.0))
        .map(|s| SupportMotion {
            support: s.name.clone(),
            u: s.motion[0],
            v: s.motion[1],
            theta: s.motion[2],
        })
        .collect()
}

/// No motion makes the pattern a settlement mechanism: report the closest.
#[allow(clippy::too_many_arguments)]
fn closest(
    st: &Structure,
    map: &KinematicMap,
    unknowns: &[Unknown],
    unit: &[(Vec<f64>, Vec<f64>)],
    bounds: &[(f64, f64)],
    roles: &[PointRole],
    pobs: &[PointObs],
    opts: &IdentifyOptions,
    gtol: f64,
    reason: &str,
) -> Result<IdentifyResult> {
    // Closed points count at the global tolerance `gtol`.
    let mut targets: Vec<Option<(f64, f64)>> = vec![None; map.num_points()];
    for (k, r) in roles.iter().enumerate() {
        if map.bilateral[k] || map.gap[k] > 0.0 {
            continue;
        }
        targets[k] = match *r {
            PointRole::Closed => Some((0.0, gtol)),
            PointRole::Open { width, tolerance } => Some((width, tolerance)),
            PointRole::Unobserved => None,
        };
    }
    for o in pobs {
        if o.width == 0.0 {
            targets[o.point] = Some((0.0, o.tolerance));
        }
    }
    let cp = ClosestProgram::new(map, unit, bounds, &targets);
    let sol = lp::solve(&cp.lp, &opts.solver)?;
    if sol.status != LpStatus::Optimal {
        return Err(Error::Request(
            "identify: the observed pattern cannot be produced by any settlement, and no admissible motion within the bounds exists either (check the bounds and the known support motions)".into(),
        ));
    }
    let mut a: Vec<f64> = cp.amplitudes(&sol.x).iter().map(|v| v + 0.0).collect();
    let mut st_c = st.with_support_motions(&motions_of(st, unknowns, &a));
    let mut forward = forward_settle(&st_c, opts)?;
    let mut open = forward_openings(map, &forward);
    // With no known motions the forward analysis is homogeneous of degree one in the motions:
    // scaling them by t scales every opening by t. Take the t that minimises the misfit of the
    // forward openings over every observed point (closed ones at 0), if it stays in the bounds.
    let homogeneous = st.supports.iter().all(|s| s.motion == [0.0; 3])
        && unknowns
            .iter()
            .all(|u| u.base.iter().all(|b| *b == [0.0; 3]));
    if homogeneous && forward.status == SettlementStatus::Mechanism {
        let t = best_scaling(&open, &targets);
        let scaled: Vec<f64> = a.iter().map(|v| t * v + 0.0).collect();
        let inside = scaled
            .iter()
            .zip(bounds)
            .all(|(v, (lo, hi))| v >= lo && v <= hi);
        if inside && t > 0.0 && (t - 1.0).abs() > 1e-12 {
            a = scaled;
            st_c = st.with_support_motions(&motions_of(st, unknowns, &a));
            forward = forward_settle(&st_c, opts)?;
            open = forward_openings(map, &forward);
        }
    }
    let map_c = KinematicMap::new(&st_c);
    let omax = max_abs(&open);
    // Misfit over every observed point, the implicitly closed ones included.
    let all_misfit: f64 = targets
        .iter()
        .zip(&open)
        .filter_map(|(t, o)| t.map(|(w, tau)| (o - w).abs() / tau))
        .sum();
    let (observations, total, maxm) = compare(&st_c, &map_c, pobs, &open);
    let predicted_cracks = predicted(&st_c, &map_c, &open, roles, omax);
    let contradictions: Vec<String> = predicted_cracks
        .iter()
        .filter(|c| c.observed == "closed")
        .map(|c| format!("{}", c.joint))
        .collect();
    let missing: Vec<String> = observations
        .iter()
        .filter(|o| o.observed > 0.0 && o.predicted <= 1e-7 * omax.max(1e-300))
        .map(|o| format!("{}", o.joint))
        .collect();
    let mut why = String::new();
    if !contradictions.is_empty() {
        why.push_str(&format!(
            "; it also opens joints observed closed ({})",
            dedup(contradictions)
        ));
    }
    if !missing.is_empty() {
        why.push_str(&format!(
            "; it leaves closed joints observed open ({})",
            dedup(missing)
        ));
    }
    let unknown_results = unknowns
        .iter()
        .enumerate()
        .map(|(q, u)| UnknownResult {
            name: u.name.clone(),
            value: a[q],
            lower_bound: u.lower,
            upper_bound: u.upper,
            range_min: None,
            range_max: None,
            range_computed: false,
            identifiable: false,
            note: "no motion reproduces the pattern: no range".to_string(),
        })
        .collect();
    Ok(IdentifyResult {
        status: IdentifyStatus::Inconsistent,
        message: format!(
            "no settlement of the unknown support motions produces the observed crack pattern ({reason}); the closest motion (least misfit over every observed point, the pattern relaxed) is below, with the cracks its own settlement analysis opens (misfit {all_misfit:.3} tolerances over every observed point, closed ones included){why}"
        ),
        unknowns: unknown_results,
        support_motions: support_motions(&st_c),
        observations,
        total_misfit: total,
        misfit_all_points: all_misfit,
        max_misfit: maxm,
        predicted_cracks,
        active_set_fixed: false,
        certificate: None,
        forward,
    })
}

/// Openings of a forward result, by point (0 when it has no mechanism).
fn forward_openings(map: &KinematicMap, forward: &SettlementResult) -> Vec<f64> {
    let mut open = vec![0.0; map.num_points()];
    if forward.status == SettlementStatus::Mechanism {
        for (j, jr) in forward.joints.iter().enumerate() {
            for (i, p) in jr.points.iter().enumerate() {
                open[map.joint_start[j] + i] = p.opening;
            }
        }
    }
    open
}

/// The factor `t ≥ 0` minimising `Σ |t·o_k − w_k| / τ_k` over observed points `k`
/// (`targets[k] = (w_k, τ_k)`): a weighted median of the ratios `w_k / o_k` with weights
/// `o_k / τ_k` (points that do not open add a constant). Of equally good factors, the largest
/// (the one that opens the observed cracks most nearly at their widths).
fn best_scaling(open: &[f64], targets: &[Option<(f64, f64)>]) -> f64 {
    let mut items: Vec<(f64, f64)> = targets
        .iter()
        .zip(open)
        .filter_map(|(t, &o)| t.filter(|_| o > 0.0).map(|(w, tau)| (w / o, o / tau)))
        .collect();
    if items.is_empty() {
        return 1.0;
    }
    items.sort_by(|x, y| x.0.total_cmp(&y.0));
    let total: f64 = items.iter().map(|i| i.1).sum();
    // The slope of the misfit at t is (weight below t) − (weight above t): the minimisers are
    // where it changes sign; take the last ratio where the weight below does not exceed half.
    let mut below = 0.0;
    let mut best = items[0].0;
    for (r, w) in &items {
        if below <= 0.5 * total * (1.0 + 1e-12) {
            best = *r;
        }
        below += w;
    }
    best
}

fn dedup(mut v: Vec<String>) -> String {
    v.dedup();
    v.join(", ")
}
