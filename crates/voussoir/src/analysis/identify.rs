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
//! Every candidate motion is then judged on its own **forward** settlement analysis
//! ([`misfit`]: Σ |opening − observed| / tolerance over every observed point, on the forward
//! mechanism — the solver's, or among equally optimal ones the closest to the observations):
//! the LP's motion and its balanced tie-break, the mean motion within tolerance, the closest
//! motion of the relaxed pattern ([`crate::programs_identify::ClosestProgram`]) and an
//! exploration of the misfit landscape (a scan of directions of motion, exact along each, and
//! a local refinement). The least misfit is reported, with the separate minima found.
//!
//! The result ([`IdentifyResult`]) carries:
//! - the identified amplitudes and the support motions they make;
//! - the misfit of every observation and the forward opening of every crack;
//! - a **certificate** (for a motion from the LP): the forward settlement analysis compared
//!   with the LP's mechanism (same open points, same widths, same work of the dead loads);
//! - **identifiability**: for each unknown, its range over all motions that reproduce the
//!   pattern with every width within its tolerance (a min and a max LP), flagged not
//!   identifiable when unbounded or wider than the value;
//! - the **minima** of the misfit found (several when the landscape has separate basins; a flat
//!   one when the least misfit is not unique);
//! - the verdict: identified when a motion fits every width within tolerance or opens exactly
//!   the observed pattern; inconsistent only when none does, with the closest motion.

// Loops run over point numbers that index several parallel vectors at once.
#![allow(clippy::needless_range_loop)]

use crate::analysis::settlement::{
    settlement_result, settlement_result_checked, solve_settlement_with, SettlementForm,
    SettlementResult, SettlementSolution, SettlementStatus,
};
use crate::dim::Dim;
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, Direction, LinearProgram, LpSolution, LpStatus, SolverOptions};
use crate::programs::{
    optimal_face, settlement_force_program, settlement_motion_program, ForceProgram,
};
use crate::programs_identify::{
    decided, Activity, ClosestProgram, IdentifyProgram, MisfitMode, PointRole,
};
use crate::result::Spatial;
use crate::settlement_input::Profile;
use crate::structure::{Assembly, Structure, Structure3d};
use serde::{Deserialize, Serialize};

/// Default measurement tolerance of a crack width (m): 0.1 mm, a crack gauge's resolution.
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

// --- Observations -------------------------------------------------------------------------

pub use crate::model::Width;

crack_record! {
    /// One observed crack. Exactly one of `at` (the nearest collocation point of any joint: the
    /// surveyor's coordinates, `[x, y]` in 2D, `[x, y, z]` in 3D), `joint` (a joint id: widths at its points in order, start then
    /// end, or one width for all of them) and `polyline` (a crack line as drawn: every joint point
    /// within `snap` of it, default a quarter of that point's joint length; one width, or two at
    /// its start and end, interpolated along it). A width of 0 says "observed closed here".
    #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Crack {
        {
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub at: Option<Vec<f64>>,
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub joint: Option<usize>,
            /// A crack line `[[x, y], …]`, in the file's `coordinate_units` (2D models).
            #[serde(default, alias = "points", skip_serializing_if = "Option::is_none")]
            pub polyline: Option<Vec<[f64; 2]>>,
            /// Catch distance of a `polyline`, in the file's `coordinate_units`.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub snap: Option<f64>,
            /// Width, ≥ 0, in `units` (this crack's, else the file's; default m).
            #[serde(alias = "openings")]
            pub opening: Width,
        }
        {
            /// Measurement tolerance of this crack, in the same unit as its width; default: the file's.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub tolerance: Option<f64>,
            /// Unit of this crack's width and tolerance: `"m"`, `"cm"` or `"mm"` (default: the file's).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub units: Option<String>,
        }
    }
}

/// Where nothing was observed (plaster, not surveyed): a joint, or every joint point inside an
/// axis-aligned box `[x0, y0, x1, y1]` (3D: `[x0, y0, z0, x1, y1, z1]`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Unobserved {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joint: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub region: Option<Vec<f64>>,
}

/// The survey: cracks, unobserved parts, tolerance. Every joint point that is neither cracked
/// nor unobserved is observed closed.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Observations {
    /// Unit of the widths and tolerances: `"m"` (default), `"cm"` or `"mm"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub units: Option<String>,
    /// Unit of the coordinates (`at`, `polyline`, `snap`, `region`): `"m"` (default), `"cm"`
    /// or `"mm"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coordinate_units: Option<String>,
    /// Global measurement tolerance (in `units`), default [`DEFAULT_TOLERANCE`] m.
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
    fn resolve<S: IdentifyGeometry>(
        &self,
        st: &S,
        map: &KinematicMap,
    ) -> Result<(Vec<PointRole>, Vec<PointObs>)> {
        let bad = |m: String| Err(Error::Request(m));
        let unit = |what: &str, field: &str, name: Option<&str>| {
            crate::model::length_unit_of(what, field, name).map_err(Error::Request)
        };
        let fw = unit("observations", "units", self.units.as_deref())?;
        let fc = unit(
            "observations",
            "coordinate_units",
            self.coordinate_units.as_deref(),
        )?;
        let file_unit = self.units.as_deref().unwrap_or("m");
        let tol = match self.tolerance {
            Some(t) => {
                if !(t.is_finite() && t > 0.0) {
                    return bad(format!(
                        "observations: tolerance {t} must be a finite number > 0 ({file_unit})"
                    ));
                }
                t * fw
            }
            None => DEFAULT_TOLERANCE,
        };
        let npts = map.num_points();
        let positions = point_positions(st);
        let mut roles = vec![PointRole::Closed; npts];
        for (k, r) in roles.iter_mut().enumerate() {
            if map.gap[k] > 0.0 {
                *r = PointRole::Unobserved;
            }
        }
        for (i, u) in self.unobserved.iter().enumerate() {
            match (u.joint, u.region.as_deref()) {
                (Some(j), None) => {
                    if j >= st.num_joints() {
                        return bad(format!("unobserved[{i}]: joint {j} does not exist (the structure has {} joints)", st.num_joints()));
                    }
                    for r in &mut roles[map.joint_start[j]..map.joint_start[j + 1]] {
                        *r = PointRole::Unobserved;
                    }
                }
                (None, Some(region)) => {
                    // [lo…, hi…]: two corners of the dimension's box.
                    let n = <S::D as Dim>::N;
                    let ok = region.len() == 2 * n
                        && region.iter().all(|v| v.is_finite())
                        && (0..n).all(|c| region[n + c] >= region[c]);
                    if !ok {
                        return bad(if n == 2 {
                            format!("unobserved[{i}]: region must be finite [x0, y0, x1, y1] with x0 ≤ x1, y0 ≤ y1")
                        } else {
                            format!("unobserved[{i}]: region must be finite [x0, y0, z0, x1, y1, z1] with x0 ≤ x1, y0 ≤ y1, z0 ≤ z1 (the model is 3D)")
                        });
                    }
                    let region: Vec<f64> = region.iter().map(|v| v * fc).collect();
                    for (k, r) in roles.iter_mut().enumerate() {
                        let p = &positions[k];
                        if (0..n).all(|c| p[c] >= region[c] && p[c] <= region[n + c]) {
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
            let what = format!("cracks[{i}]");
            let (cw, cunit) = match c.units.as_deref() {
                Some(u) => (unit(&what, "units", Some(u))?, u),
                None => (fw, file_unit),
            };
            let tau = match c.tolerance {
                Some(t) => {
                    if !(t.is_finite() && t > 0.0) {
                        return bad(format!(
                            "cracks[{i}]: tolerance {t} must be a finite number > 0 ({cunit})"
                        ));
                    }
                    t * cw
                }
                None => tol,
            };
            let points: Vec<(usize, f64)> = st
                .observed_points(&what, c, cw, cunit, fc)?
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

/// One unknown amplitude `a`: the support motions are `base + a · unit` (per support its
/// `Dim::DOFS` components: `(u, v, θ)` in 2D, `(u, v, w, θx, θy, θz)` in 3D, m and rad), with
/// optional bounds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Unknown {
    pub name: String,
    /// Motion of every support per unit amplitude.
    pub unit: Vec<Vec<f64>>,
    /// Motion added whatever the amplitude (a profile's fixed part; usually zero).
    pub base: Vec<Vec<f64>>,
    pub lower: Option<f64>,
    pub upper: Option<f64>,
}

/// A support-motion component: `u`, `v`, `theta` of a 2D model; `u`, `v`, `w`, `theta_x`,
/// `theta_y`, `theta_z` of a 3D one (z up).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Component {
    /// Translation along x (m).
    U,
    /// Translation along y (m; in 2D vertical, up positive).
    V,
    /// 2D: rotation about the support's centroid (rad, counter-clockwise).
    Theta,
    /// 3D: translation along z (m, up positive).
    W,
    /// 3D: rotation about x through the support's centroid (rad, right-handed).
    #[serde(rename = "theta_x")]
    ThetaX,
    /// 3D: rotation about y (rad).
    #[serde(rename = "theta_y")]
    ThetaY,
    /// 3D: rotation about z (rad).
    #[serde(rename = "theta_z")]
    ThetaZ,
}

impl Component {
    /// Index of the component in a support motion of `dofs` values (3: 2D, 6: 3D), or None
    /// when it is not a component of that dimension.
    pub fn index_in(self, dofs: usize) -> Option<usize> {
        match (self, dofs) {
            (Component::U, _) => Some(0),
            (Component::V, _) => Some(1),
            (Component::Theta, 3) => Some(2),
            (Component::W, 6) => Some(2),
            (Component::ThetaX, 6) => Some(3),
            (Component::ThetaY, 6) => Some(4),
            (Component::ThetaZ, 6) => Some(5),
            _ => None,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Component::U => "u",
            Component::V => "v",
            Component::Theta => "theta",
            Component::W => "w",
            Component::ThetaX => "theta_x",
            Component::ThetaY => "theta_y",
            Component::ThetaZ => "theta_z",
        }
    }
    /// The component named `name` (`θ` for theta, `θx`… for the 3D rotations), any dimension.
    pub fn parse(name: &str) -> Option<Component> {
        Some(match name {
            "u" => Component::U,
            "v" => Component::V,
            "theta" | "θ" => Component::Theta,
            "w" => Component::W,
            "theta_x" | "θx" => Component::ThetaX,
            "theta_y" | "θy" => Component::ThetaY,
            "theta_z" | "θz" => Component::ThetaZ,
            _ => return None,
        })
    }
}

/// What the inverse analysis needs of a structure beyond [`Assembly`]: the collocation points
/// an observed crack names, and the support motions of a settlement profile. Implemented for
/// the 2D [`Structure`] and the 3D [`Structure3d`]; the analysis itself is written once over
/// it.
pub trait IdentifyGeometry: Assembly {
    /// The points crack `c` names, as `(joint, point index, width in m)` (see [`Crack`]):
    /// widths scaled by `width_scale` (unit `width_unit`), coordinates by `coordinate_scale`.
    fn observed_points(
        &self,
        what: &str,
        c: &Crack,
        width_scale: f64,
        width_unit: &str,
        coordinate_scale: f64,
    ) -> Result<Vec<(usize, usize, f64)>>;
    /// Each support's motion under profile `p` (its value and slope at the support's centroid).
    fn profile_motions(&self, name: &str, p: &Profile) -> Result<Vec<Vec<f64>>>;
}

impl IdentifyGeometry for Structure {
    fn observed_points(
        &self,
        what: &str,
        c: &Crack,
        width_scale: f64,
        width_unit: &str,
        coordinate_scale: f64,
    ) -> Result<Vec<(usize, usize, f64)>> {
        let at = match c.at.as_deref() {
            None => None,
            Some(&[x, y]) => Some([x, y]),
            Some(_) => {
                return Err(Error::Request(format!(
                    "{what}: \"at\" must be two finite coordinates [x, y] (the model is 2D)"
                )))
            }
        };
        self.crack_site_points(
            what,
            &crate::structure::CrackSite {
                at,
                joint: c.joint,
                polyline: c.polyline.as_deref(),
                snap: c.snap,
                opening: &c.opening,
                width_scale,
                width_unit,
                coordinate_scale,
            },
        )
    }
    fn profile_motions(&self, _name: &str, p: &Profile) -> Result<Vec<Vec<f64>>> {
        Ok(self
            .supports
            .iter()
            .map(|s| {
                let (v, slope) = p.eval(s.centroid[0]);
                vec![0.0, v, slope]
            })
            .collect())
    }
}

impl IdentifyGeometry for Structure3d {
    /// By `at` (`[x, y, z]`, the nearest point of any joint, ties to the lowest joint and
    /// point) or by `joint` (widths per point in the joint's order, or one for all); a crack
    /// line (`polyline`) is a 2D survey's and is refused.
    fn observed_points(
        &self,
        what: &str,
        c: &Crack,
        ws: f64,
        unit: &str,
        fc: f64,
    ) -> Result<Vec<(usize, usize, f64)>> {
        use crate::model::Width;
        let bad = |m: String| Err(Error::Request(format!("{what}: {m}")));
        c.opening
            .check(unit)
            .map_err(|m| Error::Request(format!("{what}: {m}")))?;
        if c.polyline.is_some() || c.snap.is_some() {
            return bad("\"polyline\" and \"snap\" (a crack line as drawn) apply to 2D models; on a 3D model give \"at\": [x, y, z] or \"joint\"".into());
        }
        Ok(match (c.at.as_deref(), c.joint, &c.opening) {
            (Some(p), None, Width::One(w)) => {
                if p.len() != 3 || !p.iter().all(|x| x.is_finite()) {
                    return bad(
                        "\"at\" must be three finite coordinates [x, y, z] (the model is 3D)"
                            .into(),
                    );
                }
                let p = [p[0] * fc, p[1] * fc, p[2] * fc];
                let mut best: Option<(f64, usize, usize)> = None;
                for (j, jt) in self.joints.iter().enumerate() {
                    for (k, q) in jt.points.iter().enumerate() {
                        let d = crate::dim::Three::sub(q.x, p);
                        let dd = crate::dim::Three::dot(d, d).sqrt();
                        if best.is_none_or(|(b, _, _)| dd < b) {
                            best = Some((dd, j, k));
                        }
                    }
                }
                match best {
                    Some((_, j, k)) => vec![(j, k, *w * ws)],
                    None => return bad("the structure has no joints".into()),
                }
            }
            (Some(_), None, Width::PerPoint(_)) => {
                return bad("a crack located by \"at\" takes one width".into())
            }
            (None, Some(j), w) => {
                let n = self.joints.get(j).map(|jt| jt.points.len());
                w.on_joint(j, n, self.joints.len(), ws)
                    .map_err(|m| Error::Request(format!("{what}: {m}")))?
            }
            _ => return bad("give exactly one of \"at\" and \"joint\"".into()),
        })
    }
    fn profile_motions(&self, name: &str, _p: &Profile) -> Result<Vec<Vec<f64>>> {
        Err(Error::Request(format!(
            "unknown '{name}': a settlement profile as unknown applies to 2D models; on a 3D model give the supports' components (NAME=u,v,w,…)"
        )))
    }
}

/// The position of every collocation point, in the kinematic map's order.
fn point_positions<S: Assembly>(st: &S) -> Vec<Vec<f64>> {
    st.contact_joints()
        .iter()
        .flat_map(|j| j.points.iter().map(|(x, _)| x.as_ref().to_vec()))
        .collect()
}

impl Unknown {
    /// One component shared by the supports `names` (one support, or a set of foundation
    /// segments settling together), named `label.component`.
    pub fn supports<S: Assembly>(
        st: &S,
        label: &str,
        names: &[String],
        component: Component,
        lower: Option<f64>,
        upper: Option<f64>,
    ) -> Result<Unknown> {
        let ns = st.num_supports();
        let dofs = <S::D as Dim>::DOFS;
        let Some(index) = component.index_in(dofs) else {
            return Err(Error::Request(format!(
                "unknown '{label}': '{}' is not a component of a {} support motion ({})",
                component.name(),
                if dofs == 3 { "2D" } else { "3D" },
                if dofs == 3 {
                    "u, v, theta"
                } else {
                    "u, v, w, theta_x, theta_y, theta_z"
                }
            )));
        };
        let mut unit = vec![vec![0.0; dofs]; ns];
        if names.is_empty() {
            return Err(Error::Request(format!(
                "unknown '{label}': no support given"
            )));
        }
        for n in names {
            let Some(s) = (0..ns).position(|s| st.support_name(s) == n) else {
                let known: Vec<&str> = (0..ns).map(|s| st.support_name(s)).take(12).collect();
                return Err(Error::Request(format!(
                    "unknown '{label}': no support named '{n}' (the model has: {}{})",
                    known.join(", "),
                    if ns > 12 { ", …" } else { "" }
                )));
            };
            unit[s][index] = 1.0;
        }
        Unknown::new(
            format!("{label}.{}", component.name()),
            unit,
            vec![vec![0.0; dofs]; ns],
            lower,
            upper,
        )
    }

    /// A profile family: `at0` and `at1` are the profile with the unknown value set to 0 and
    /// to 1; the motions are `at0`'s plus the unknown times the difference (profiles are linear
    /// in their values, so this is exact when only values differ). Each support takes the
    /// profile's value and slope at its centroid (as [`crate::settlement_input::apply_profile`]).
    /// 2D models only.
    pub fn profile<S: IdentifyGeometry>(
        st: &S,
        name: &str,
        at0: &Profile,
        at1: &Profile,
        lower: Option<f64>,
        upper: Option<f64>,
    ) -> Result<Unknown> {
        let (p0, p1) = (at0, at1);
        p0.validate()?;
        p1.validate()?;
        let (m0, m1) = (st.profile_motions(name, p0)?, st.profile_motions(name, p1)?);
        let unit: Vec<Vec<f64>> = m0
            .iter()
            .zip(&m1)
            .map(|(a, b)| a.iter().zip(b).map(|(x, y)| y - x).collect())
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
        unit: Vec<Vec<f64>>,
        base: Vec<Vec<f64>>,
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

// The result types live in `crate::result::identify` (results are read by views, which import
// no algorithm module); re-exported here for compatibility.
pub use crate::result::identify::*;

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

fn motions_of<S: Assembly>(st: &S, unknowns: &[Unknown], a: &[f64]) -> Vec<Vec<f64>> {
    let mut m: Vec<Vec<f64>> = (0..st.num_supports())
        .map(|s| st.support_motion(s).to_vec())
        .collect();
    for (q, u) in unknowns.iter().enumerate() {
        for (s, mm) in m.iter_mut().enumerate() {
            for c in 0..mm.len() {
                mm[c] += u.base[s][c] + a[q] * u.unit[s][c];
            }
        }
    }
    m
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// A point counts as open when its opening exceeds this fraction of the largest opening or
/// observed width (whichever is larger); below it, an opening is round-off of the LPs.
const OPEN_FRACTION: f64 = 1e-7;

/// A least-misfit fit is "exact" below this misfit (tolerances, summed): the landscape is then
/// not explored further (nothing can fit better).
const EXACT_MISFIT: f64 = 1e-6;

/// Models above this many degrees of freedom get no exploration of the misfit landscape beyond
/// the LP candidates (each evaluation is a forward settlement analysis).
const EXPLORE_MAX_DOFS: usize = 6000;

/// The optimal face of a forward analysis: mechanisms whose work of the dead loads is within
/// this (relative) of the solver's optimum. The solver's own mechanism is on it; a looser
/// margin would admit nearly optimal mechanisms whose openings differ measurably.
const FACE_TOLERANCE: f64 = 1e-9;

/// Two misfits are equal within this (relative) margin.
fn same_misfit(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

/// Everything the misfit of a motion depends on: the structure with its known motions, the
/// unknowns and the observations resolved to points.
struct Setup<'a, S: IdentifyGeometry> {
    st: &'a S,
    unknowns: &'a [Unknown],
    opts: &'a IdentifyOptions,
    /// The structure with the base motions (the unknowns at zero).
    st0: S,
    /// Position of every collocation point of `st0`, in the map's order.
    positions: Vec<Vec<f64>>,
    /// Its kinematic map (point numbering is the same for every motion).
    map: KinematicMap,
    roles: Vec<PointRole>,
    pobs: Vec<PointObs>,
    /// Per point: `Some((w, τ))` where observed (closed ones at `w = 0`, the implicitly closed
    /// ones at the global tolerance), `None` where unobserved or not in contact.
    targets: Vec<Option<(f64, f64)>>,
    /// Largest observed width (m), or the global tolerance when no crack is observed open.
    wref: f64,
    bounds: Vec<(f64, f64)>,
    /// Per unknown, the opening and sliding `(g_n, g_t)` its unit motion causes at each point.
    unit: Vec<(Vec<f64>, Vec<f64>)>,
    /// The forward analysis is homogeneous of degree one in the unknowns (no known motions):
    /// scaling the motions scales every opening.
    homogeneous: bool,
    /// Full evaluations done (candidates often coincide to round-off: one evaluation serves
    /// motions within 1e-8 of each other, relative).
    cache: std::cell::RefCell<Vec<Eval<S::D>>>,
}

/// The forward settlement analysis of one motion, judged against the observations.
#[derive(Clone)]
struct Eval<D: Spatial> {
    a: Vec<f64>,
    forward: SettlementResult<D>,
    open: Vec<f64>,
    /// Σ |opening − w| / τ over every observed point (∞ when the forward analysis finds no
    /// mechanism).
    misfit: f64,
    /// Every observed point within its tolerance.
    within: bool,
    /// Joints with a point observed open that the forward analysis leaves closed.
    shut: Vec<usize>,
    /// Joints with a point observed closed that the forward analysis opens.
    extra: Vec<usize>,
}

impl<D: Spatial> Eval<D> {
    /// The forward analysis opens exactly the observed crack pattern.
    fn opens_pattern(&self) -> bool {
        self.misfit.is_finite() && self.shut.is_empty() && self.extra.is_empty()
    }
}

/// The mechanism an LP predicted for its motion, to compare with the forward analysis.
struct Prediction {
    open: Vec<f64>,
    work: f64,
}

struct Candidate<D: Spatial> {
    eval: Eval<D>,
    prediction: Option<Prediction>,
}

impl<'a, S: IdentifyGeometry> Setup<'a, S> {
    fn new(
        st: &'a S,
        obs: &Observations,
        unknowns: &'a [Unknown],
        opts: &'a IdentifyOptions,
    ) -> Result<Setup<'a, S>> {
        if unknowns.is_empty() {
            return Err(Error::Request(
                "identify: give at least one unknown support motion".into(),
            ));
        }
        for u in unknowns {
            let dofs = <S::D as Dim>::DOFS;
            if u.unit.len() != st.num_supports()
                || u.base.len() != st.num_supports()
                || u.unit.iter().chain(&u.base).any(|m| m.len() != dofs)
            {
                return Err(Error::Request(format!(
                    "unknown '{}': one motion of {dofs} components per support expected",
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
        // Closed points count at the global tolerance, listed ones at their own.
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
        for o in &pobs {
            if o.width == 0.0 && targets[o.point].is_some() {
                targets[o.point] = Some((0.0, o.tolerance));
            }
        }
        let wmax = pobs.iter().fold(0.0f64, |m, o| m.max(o.width));
        let wref = if wmax > 0.0 { wmax } else { gtol };
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
        let homogeneous =
            (0..st0.num_supports()).all(|k| st0.support_motion(k).iter().all(|x| *x == 0.0));
        let positions = point_positions(&st0);
        Ok(Setup {
            st,
            unknowns,
            opts,
            st0,
            positions,
            map,
            roles,
            pobs,
            targets,
            wref,
            bounds,
            unit,
            homogeneous,
            cache: Default::default(),
        })
    }

    /// Σ |o − w| / τ over every observed point.
    fn misfit_of(&self, open: &[f64]) -> f64 {
        self.targets
            .iter()
            .zip(open)
            .filter_map(|(t, o)| t.map(|(w, tau)| (o - w).abs() / tau))
            .sum()
    }

    /// Run the forward settlement analysis of amplitudes `a` and judge it: the solver's own
    /// optimal mechanism ([`crate::analysis::settle`] for both LPs,
    /// [`crate::analysis::settlement::settle_with`] for the force-only form, as `voussoir settle
    /// --raw` reports it) or, when that is not unique, among the equally optimal ones the one
    /// closest to the observations.
    fn evaluate(&self, a: &[f64]) -> Result<Eval<S::D>> {
        let scales = self.scales();
        let same = |e: &Eval<S::D>| {
            e.a.iter()
                .zip(a)
                .zip(&scales)
                .all(|((x, y), sc)| (x - y).abs() <= 1e-8 * x.abs().max(y.abs()) + 1e-12 * sc)
        };
        if let Some(e) = self.cache.borrow().iter().find(|e| same(e)) {
            return Ok(e.clone());
        }
        let e = self.evaluate_with(a, true)?;
        self.cache.borrow_mut().push(e.clone());
        Ok(e)
    }

    /// The forward settlement analysis of amplitudes `a`, judged against the observations.
    /// With `closest`, when the solver's optimal mechanism does not fit exactly, the optimal
    /// face of the motion LP is searched for the optimal mechanism of least misfit (the
    /// settlement mechanism is not always unique: any optimal one is the structure's
    /// settlement; the solver's vertex is an arbitrary choice among them).
    fn evaluate_with(&self, a: &[f64], closest: bool) -> Result<Eval<S::D>> {
        let a: Vec<f64> = a.iter().map(|v| v + 0.0).collect();
        let st_a = self
            .st
            .with_support_motions(&motions_of(self.st, self.unknowns, &a));
        let map_a = KinematicMap::new(&st_a);
        let mut sol = solve_settlement_with(&st_a, &map_a, &self.opts.solver, self.opts.form)?;
        if closest && sol.status == SettlementStatus::Mechanism {
            if let Some(d) = self.closest_optimal_mechanism(&st_a, &map_a, &sol)? {
                let dead = st_a.load_vector(false);
                sol.primal = dead.iter().zip(&d).map(|(f, x)| f * x).sum();
                sol.mechanism = d;
            }
        }
        let forward = match self.opts.form {
            SettlementForm::Both => settlement_result(&st_a, &map_a, &sol),
            _ => settlement_result_checked(&st_a, &map_a, &sol),
        };
        let open = forward_openings(&self.map, &forward);
        let mechanism = forward.status == SettlementStatus::Mechanism;
        let misfit = if mechanism {
            self.misfit_of(&open)
        } else {
            f64::INFINITY
        };
        let thr = OPEN_FRACTION * max_abs(&open).max(self.wref);
        let within = mechanism
            && self
                .targets
                .iter()
                .zip(&open)
                .all(|(t, o)| t.is_none_or(|(w, tau)| (o - w).abs() <= tau * (1.0 + 1e-9)));
        let (mut shut, mut extra) = (Vec::new(), Vec::new());
        for k in 0..self.map.num_points() {
            let joint = self.map.points[k].joint;
            match (self.roles[k], self.targets[k]) {
                (PointRole::Open { .. }, Some(_)) if open[k] <= thr => shut.push(joint),
                // Observed closed: a crack narrower than the tolerance is not seen.
                (PointRole::Closed, Some((_, tau))) if open[k] > thr.max(tau) => extra.push(joint),
                _ => {}
            }
        }
        shut.dedup();
        extra.dedup();
        Ok(Eval {
            a,
            forward,
            open,
            misfit,
            within,
            shut,
            extra,
        })
    }

    /// Evaluate, counting a failed forward analysis (a solver failure at an extreme motion) as
    /// no candidate: the exploration only looks for better motions.
    fn try_evaluate(&self, a: &[f64]) -> Option<Eval<S::D>> {
        self.evaluate(a).ok().filter(|e| e.misfit.is_finite())
    }

    /// [`Setup::try_evaluate`] on the solver's own mechanism (no search of the optimal face):
    /// the exploration's steps, an upper bound of the misfit; the minima it finds are
    /// evaluated in full.
    fn try_quick(&self, a: &[f64]) -> Option<Eval<S::D>> {
        self.evaluate_with(a, false)
            .ok()
            .filter(|e| e.misfit.is_finite())
    }

    /// The optimal mechanism of least misfit: the motion LP restricted to its optimal face
    /// (its optimum held to [`FACE_TOLERANCE`]), minimising `Σ |u_n − w| / τ` over the observed
    /// points. `None` when the solver's own mechanism fits exactly or is no worse.
    fn closest_optimal_mechanism(
        &self,
        st_a: &S,
        map_a: &KinematicMap,
        sol: &SettlementSolution,
    ) -> Result<Option<Vec<f64>>> {
        let (open, _) = map_a.jumps(&sol.mechanism, 1.0);
        let raw = self.misfit_of(&open);
        if raw <= EXACT_MISFIT || !sol.primal.is_finite() {
            return Ok(None);
        }
        let dead = st_a.load_vector(false);
        let mp = settlement_motion_program(map_a, &dead)?;
        let face = optimal_face(&mp.lp, sol.primal * mp.objective_sign, FACE_TOLERANCE);
        // Rows u_n,k − e⁺ + e⁻ = w_k, with u_n,k = N_k d + g_k and d = −y (the first columns).
        let mut rows: Vec<ExtraRow> = Vec::new();
        let mut tol = Vec::new();
        for (k, t) in self.targets.iter().enumerate() {
            let Some((w, tau)) = *t else { continue };
            let entries: Vec<(usize, f64)> = KinematicMap::row(&map_a.normal, k)
                .into_iter()
                .map(|(dof, v)| (dof, -v))
                .collect();
            let rhs = w - map_a.support_normal[k];
            rows.push((entries, rhs, rhs));
            tol.push(tau);
        }
        let mut lp = with_rows(&face, &rows);
        let first = face.num_rows();
        for (i, tau) in tol.iter().enumerate() {
            lp.add_column(1.0 / tau, 0.0, f64::INFINITY, [(first + i, -1.0)]);
            lp.add_column(1.0 / tau, 0.0, f64::INFINITY, [(first + i, 1.0)]);
        }
        let s = lp::solve(&lp, &self.opts.solver)?;
        if s.status != LpStatus::Optimal {
            return Ok(None);
        }
        let d = mp.motion(&s.x);
        let (open_d, _) = map_a.jumps(&d, 1.0);
        let m = self.misfit_of(&open_d);
        Ok((m < raw && !same_misfit(m, raw)).then_some(d))
    }

    /// A characteristic amplitude per unknown: the one whose unit response opens or slides a
    /// point by the largest observed width (the exploration works in these units).
    fn scales(&self) -> Vec<f64> {
        self.unit
            .iter()
            .map(|(gn, gt)| {
                let g = max_abs(gn).max(max_abs(gt));
                if g > 0.0 {
                    self.wref / g
                } else {
                    1.0
                }
            })
            .collect()
    }

    fn clamp(&self, a: &mut [f64]) {
        for (v, (lo, hi)) in a.iter_mut().zip(&self.bounds) {
            *v = v.max(*lo).min(*hi);
        }
    }

    /// Degrees of freedom of the model: the exploration is skipped above [`EXPLORE_MAX_DOFS`].
    fn explorable(&self) -> bool {
        self.map.num_dofs <= EXPLORE_MAX_DOFS
    }
}

/// The misfit of a motion, the function [`identify`] minimises: the forward settlement
/// analysis ([`crate::analysis::settle`], or the form `opts.form`) of the support motions that
/// the unknowns' `values` make, against the observations — `Σ |opening − w| / τ` over every
/// observed point, the implicitly closed ones at `w = 0` with the global tolerance, unobserved
/// points left out. `f64::INFINITY` when the forward analysis finds no mechanism.
pub fn misfit<S: IdentifyGeometry>(
    st: &S,
    obs: &Observations,
    unknowns: &[Unknown],
    values: &[f64],
    opts: &IdentifyOptions,
) -> Result<f64> {
    let s = Setup::new(st, obs, unknowns, opts)?;
    if values.len() != unknowns.len() {
        return Err(Error::Request(format!(
            "misfit: {} values for {} unknowns",
            values.len(),
            unknowns.len()
        )));
    }
    Ok(s.evaluate(values)?.misfit)
}

/// The LPs on the observed pattern (the optimality conditions of the forward analysis with
/// the observed complementarity).
struct PatternLps<'s, 'a, S: IdentifyGeometry> {
    s: &'s Setup<'a, S>,
    fp: ForceProgram,
    dead: Vec<f64>,
    activity: Activity,
}

impl<S: IdentifyGeometry> PatternLps<'_, '_, S> {
    fn program(&self, mode: MisfitMode) -> IdentifyProgram {
        IdentifyProgram::new(
            &self.s.map,
            &self.fp,
            &self.s.unit,
            &self.s.bounds,
            &self.s.roles,
            &self.activity,
            mode,
        )
    }

    fn solve(&self, mode: MisfitMode) -> Result<Option<(IdentifyProgram, LpSolution)>> {
        let ip = self.program(mode);
        let sol = lp::solve(&ip.lp, &self.s.opts.solver)?;
        Ok((sol.status == LpStatus::Optimal).then_some((ip, sol)))
    }

    /// The LP's motion, evaluated by the forward analysis, with the LP's own mechanism as the
    /// prediction to compare.
    fn candidate(&self, ip: &IdentifyProgram, sol: &LpSolution) -> Result<Candidate<S::D>> {
        let a = ip.amplitudes(&sol.x);
        let d = ip.motion(&sol.x);
        let st_id = self
            .s
            .st
            .with_support_motions(&motions_of(self.s.st, self.s.unknowns, &a));
        let map_id = KinematicMap::new(&st_id);
        let (open, _) = map_id.jumps(&d, 1.0);
        let work: f64 = self.dead.iter().zip(&d).map(|(f, x)| f * x).sum();
        Ok(Candidate {
            eval: self.s.evaluate(&a)?,
            prediction: Some(Prediction { open, work }),
        })
    }
}

/// One local minimum of the misfit found by the exploration.
struct Found<D: Spatial> {
    eval: Eval<D>,
    /// The misfit is equally low over a range of motions around it (a plateau).
    flat: bool,
}

/// Identify the unknown support motions from the observed crack pattern.
pub fn identify<S: IdentifyGeometry>(
    st: &S,
    obs: &Observations,
    unknowns: &[Unknown],
    opts: &IdentifyOptions,
) -> Result<IdentifyResult<S::D>> {
    let s = Setup::new(st, obs, unknowns, opts)?;
    let dead = s.st0.load_vector(false);
    let fp = settlement_force_program(&s.map, &dead);
    let mut lps = PatternLps {
        s: &s,
        fp,
        dead,
        activity: Activity::default(),
    };
    // 1. The observed pattern as a settlement mechanism, least misfit (the LP (I)).
    let mut active_set_fixed = false;
    let mut first = lps.solve(MisfitMode::Minimise)?;
    // Complementarity left open by the observations: impose the active set the solution
    // suggests and solve once more; keep the first solution if that fails.
    if let Some((ip, sol)) = &first {
        if let Some(fix) = open_complementarity(&s.map, &lps.fp, ip, &sol.x, &s.roles) {
            let previous = std::mem::replace(&mut lps.activity, fix);
            match lps.solve(MisfitMode::Minimise)? {
                Some(second) => {
                    active_set_fixed = true;
                    first = Some(second);
                }
                None => lps.activity = previous,
            }
        }
    }
    let pattern_feasible = first.is_some();
    // Candidates in order of preference between equal misfits.
    let mut cands: Vec<Candidate<S::D>> = Vec::new();
    if let Some((ip, sol)) = &first {
        // Equally good least-absolute fits are common (a flat valley of the misfit): of those,
        // the most balanced one (least largest misfit of one crack).
        let total = sol.objective.max(0.0) * (1.0 + 1e-9) + 1e-12;
        if let Some((ipb, solb)) = lps.solve(MisfitMode::Balanced { total })? {
            cands.push(lps.candidate(&ipb, &solb)?);
        }
        cands.push(lps.candidate(ip, sol)?);
        // The LP cannot ask an observed crack to open (only to carry no force); if its motions
        // leave one shut, ask for every observed crack to open by at least 1 % of its width.
        if cands.iter().all(|c| !c.eval.shut.is_empty()) {
            if let Some((ipo, solo)) = lps.solve(MisfitMode::MinimiseOpening { fraction: 0.01 })? {
                cands.push(lps.candidate(&ipo, &solo)?);
            }
        }
    }
    // The motions that make the observed pattern a settlement mechanism with every width
    // within its tolerance: the range of each unknown over them (two LPs per unknown), and
    // the mean of those LPs' motions as one more candidate (the set is convex: the mean is in
    // it, and away from its vertices, where the forward mechanism may not be unique).
    let ranges = if pattern_feasible {
        let (ranges, mean) = within_ranges(&lps, opts.ranges)?;
        if let Some(a) = mean {
            cands.push(Candidate {
                eval: s.evaluate(&a)?,
                prediction: None,
            });
        }
        ranges
    } else {
        vec![Range::default(); unknowns.len()]
    };
    let lp_best = cands
        .iter()
        .map(|c| c.eval.misfit)
        .fold(f64::INFINITY, f64::min);
    // 2. Unless a candidate fits exactly: the closest admissible motion of the relaxed
    // pattern, and an exploration of the misfit landscape on forward analyses.
    let mut found: Vec<Found<S::D>> = Vec::new();
    let mut explored = false;
    if lp_best > EXACT_MISFIT {
        let cp = ClosestProgram::new(&s.map, &s.unit, &s.bounds, &s.targets);
        let sol = lp::solve(&cp.lp, &opts.solver)?;
        if sol.status == LpStatus::Optimal {
            let a = cp.amplitudes(&sol.x);
            if let Some(eval) = s.try_evaluate(&a) {
                cands.push(Candidate {
                    eval,
                    prediction: None,
                });
            }
        }
        if s.explorable() || (s.homogeneous && unknowns.len() == 1) {
            explored = true;
            found = explore(&s, &cands)?;
        }
    }
    if cands.is_empty() && found.is_empty() {
        return Err(Error::Request(
            "identify: the observed pattern cannot be produced by any settlement, and no admissible motion within the bounds exists either (check the bounds and the known support motions)".into(),
        ));
    }
    // 3. The least misfit of every motion considered; between equal misfits, one within
    // tolerance, then one opening the observed pattern, then one leaving the fewest observed
    // cracks shut (a motion that explains something over one that explains nothing), then the
    // least misfit over the listed cracks alone (the surveyed widths matched most nearly),
    // then the order above (LP first).
    let least = cands
        .iter()
        .map(|c| &c.eval)
        .chain(found.iter().map(|f| &f.eval))
        .map(|e| e.misfit)
        .fold(f64::INFINITY, f64::min);
    let listed = |e: &Eval<S::D>| -> f64 {
        s.pobs
            .iter()
            .map(|o| (e.open[o.point] - o.width).abs() / o.tolerance)
            .sum()
    };
    let better = |x: &Eval<S::D>, y: &Eval<S::D>| -> std::cmp::Ordering {
        let key = |e: &Eval<S::D>| {
            (
                !same_misfit(e.misfit, least),
                !e.within,
                !e.opens_pattern(),
                e.shut.len(),
            )
        };
        key(x).cmp(&key(y)).then_with(|| {
            let (a, b) = (listed(x), listed(y));
            if same_misfit(a, b) {
                std::cmp::Ordering::Equal
            } else {
                a.total_cmp(&b)
            }
        })
    };
    let pick = |evals: Vec<&Eval<S::D>>| -> Option<usize> {
        (0..evals.len()).reduce(|i, j| {
            if better(evals[j], evals[i]).is_lt() {
                j
            } else {
                i
            }
        })
    };
    let best_cand = pick(cands.iter().map(|c| &c.eval).collect());
    let best_found = pick(found.iter().map(|f| &f.eval).collect());
    let (best, prediction) = match (best_cand, best_found) {
        (Some(i), Some(j)) if better(&found[j].eval, &cands[i].eval).is_lt() => {
            (found.swap_remove(j).eval, None)
        }
        (Some(i), _) => {
            let c = cands.swap_remove(i);
            (c.eval, c.prediction)
        }
        (None, Some(j)) => (found.swap_remove(j).eval, None),
        (None, None) => unreachable!("checked above"),
    };
    // The minima: the best first, then the separate ones the exploration found. An equally
    // low motion elsewhere with no rise of the misfit between makes the minimum flat.
    let mut best_flat = false;
    let mut others = Vec::new();
    for f in &found {
        match relation(&s, &best, &f.eval)? {
            Relation::Separate => others.push(minimum(&f.eval, f.flat)),
            Relation::Connected => best_flat |= same_misfit(f.eval.misfit, best.misfit),
            Relation::Same => best_flat |= f.flat,
        }
    }
    // An equally good candidate elsewhere in the same basin also makes it flat.
    for c in &cands {
        if !best_flat && same_misfit(c.eval.misfit, best.misfit) {
            best_flat = relation(&s, &best, &c.eval)? == Relation::Connected;
        }
    }
    let mut minima = vec![minimum(&best, best_flat)];
    minima.extend(others);
    minima.truncate(5);
    // The least-misfit motions (other than the best) that fit every width within its
    // tolerance, and that open the observed pattern.
    let witness = |f: &dyn Fn(&Eval<S::D>) -> bool| {
        cands
            .iter()
            .map(|c| &c.eval)
            .chain(found.iter().map(|f| &f.eval))
            .filter(|e| f(e))
            .min_by(|a, b| a.misfit.total_cmp(&b.misfit))
    };
    let witnesses = Witnesses {
        within: witness(&|e: &Eval<S::D>| e.within),
        pattern: witness(&|e: &Eval<S::D>| e.opens_pattern()),
        // Whether some motion with the observed pattern fits every width (the LP's answer).
        within_lp: pattern_feasible.then_some(ranges[0].feasible),
    };
    result(
        &s,
        &ranges,
        best,
        prediction,
        minima,
        explored,
        pattern_feasible,
        active_set_fixed,
        witnesses,
    )
}

/// Other motions worth naming in the message.
struct Witnesses<'e, D: Spatial> {
    within: Option<&'e Eval<D>>,
    pattern: Option<&'e Eval<D>>,
    within_lp: Option<bool>,
}

/// A row to add: `(column, value)` entries, lower and upper bound.
type ExtraRow = (Vec<(usize, f64)>, f64, f64);

/// `lp` with more rows `lo ≤ Σ v·x_j ≤ hi` over existing columns (`(entries, lo, hi)`), in
/// order after its own.
fn with_rows(lp: &LinearProgram, rows: &[ExtraRow]) -> LinearProgram {
    let mut by_col: Vec<Vec<(usize, f64)>> = vec![Vec::new(); lp.num_cols()];
    let mut out = lp.rows_only();
    for (entries, lo, hi) in rows {
        let r = out.add_row(*lo, *hi);
        for &(j, v) in entries {
            by_col[j].push((r, v));
        }
    }
    for (j, extra) in by_col.into_iter().enumerate() {
        let mut col: Vec<(usize, f64)> = lp.column(j).collect();
        col.extend(extra);
        out.add_column(
            lp.cost[j],
            lp.col_lower[j],
            lp.col_upper[j],
            merged_entries(col),
        );
    }
    out
}

/// Sum the entries of a column that fall on the same row (the solvers refuse repeats).
fn merged_entries(mut e: Vec<(usize, f64)>) -> Vec<(usize, f64)> {
    e.sort_by_key(|&(r, _)| r);
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(e.len());
    for (r, v) in e {
        match out.last_mut() {
            Some((lr, lv)) if *lr == r => *lv += v,
            _ => out.push((r, v)),
        }
    }
    out
}

/// One unknown's range over the motions that make the observed pattern a settlement mechanism
/// with every width within its tolerance (`None`: unbounded or not computed).
#[derive(Clone, Copy, Debug, Default)]
struct Range {
    lo: Option<f64>,
    hi: Option<f64>,
    /// Some motion fits every width within its tolerance.
    feasible: bool,
    computed: bool,
}

/// The ranges (every unknown when `all`, else the first one only, not reported: to find one
/// motion within tolerance) and the mean motion of the LPs that reached an optimum.
fn within_ranges<S: IdentifyGeometry>(
    lps: &PatternLps<S>,
    all: bool,
) -> Result<(Vec<Range>, Option<Vec<f64>>)> {
    let n = lps.s.unknowns.len();
    let mut ranges = vec![Range::default(); n];
    let mut sum = vec![0.0; n];
    let mut count = 0usize;
    for (q, range) in ranges.iter_mut().enumerate().take(if all { n } else { 1 }) {
        range.feasible = true;
        for sense in [Direction::Minimise, Direction::Maximise] {
            let rp = lps.program(MisfitMode::WithinTolerance { unknown: q, sense });
            let sol = lp::solve(&rp.lp, &lps.s.opts.solver)?;
            let v = match sol.status {
                LpStatus::Optimal => {
                    for (acc, a) in sum.iter_mut().zip(rp.amplitudes(&sol.x)) {
                        *acc += a;
                    }
                    count += 1;
                    Some(sol.x[rp.a[q]])
                }
                LpStatus::Unbounded => None,
                LpStatus::Infeasible => {
                    range.feasible = false;
                    None
                }
            };
            if sense == Direction::Minimise {
                range.lo = v;
            } else {
                range.hi = v;
            }
        }
        if !range.feasible {
            range.lo = None;
            range.hi = None;
        }
        range.computed = all;
    }
    let mean = (count > 0).then(|| sum.iter().map(|v| v / count as f64).collect());
    Ok((ranges, mean))
}

fn minimum<D: Spatial>(e: &Eval<D>, flat: bool) -> Minimum {
    Minimum {
        values: e.a.clone(),
        misfit: e.misfit,
        opens_pattern: e.opens_pattern(),
        within_tolerance: e.within,
        flat,
    }
}

/// How two local minima relate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Relation {
    /// The same motion (within 1e-6 of the characteristic amplitudes).
    Same,
    /// Different motions with no rise of the misfit between them (one basin).
    Connected,
    /// The misfit rises between them (at the midpoint, or at zero motion when the segment
    /// passes through it): separate minima.
    Separate,
}

fn relation<S: IdentifyGeometry>(s: &Setup<S>, a: &Eval<S::D>, b: &Eval<S::D>) -> Result<Relation> {
    let scales = s.scales();
    let dist =
        a.a.iter()
            .zip(&b.a)
            .zip(&scales)
            .fold(0.0f64, |m, ((x, y), sc)| m.max((x - y).abs() / sc));
    if dist <= 1e-6 {
        return Ok(Relation::Same);
    }
    let top = a.misfit.max(b.misfit);
    let rises = |m: f64| m > top && !same_misfit(m, top);
    // One unknown, no known motions, opposite signs: the segment passes through zero motion,
    // whose misfit needs no analysis (nothing opens).
    if s.homogeneous && a.a.len() == 1 && a.a[0] * b.a[0] < 0.0 {
        let m0 = s.misfit_of(&vec![0.0; s.map.num_points()]);
        if rises(m0) {
            return Ok(Relation::Separate);
        }
    }
    let mid: Vec<f64> = a.a.iter().zip(&b.a).map(|(x, y)| 0.5 * (x + y)).collect();
    Ok(if s.try_quick(&mid).is_none_or(|e| rises(e.misfit)) {
        Relation::Separate
    } else {
        Relation::Connected
    })
}

/// Explore the misfit landscape on forward analyses: with no known motions and at most three
/// unknowns, a scan of directions of motion, each at its best amplitude (exact: the forward
/// openings scale with the amplitude); then a compass search from the scan's local minima and
/// from the best candidate. Returns the local minima found, least misfit first, separate ones
/// only.
fn explore<S: IdentifyGeometry>(
    s: &Setup<S>,
    cands: &[Candidate<S::D>],
) -> Result<Vec<Found<S::D>>> {
    let n = s.unknowns.len();
    let scales = s.scales();
    let mut found: Vec<Found<S::D>> = Vec::new();
    if s.homogeneous && n <= 3 {
        let rays = ray_scan(s, &scales)?;
        for (i, flat) in ray_minima(&rays, n) {
            // Refine a minimum between the scan's directions: for one unknown the ray's
            // minimum is exact (the misfit is convex along it); for two, a golden-section
            // search on the angle, each angle at its exact best amplitude; for three, a
            // compass search. A plateau is left as it is.
            let a = if flat || n == 1 {
                rays[i].amplitudes()
            } else if n == 2 {
                refine_angle(s, &scales, &rays[i])
            } else {
                rays[i].amplitudes()
            };
            let Some(e) = s.try_quick(&a) else {
                continue;
            };
            let e = if n == 3 && !flat && s.explorable() {
                compass(s, e, &scales)
            } else {
                e
            };
            // The minimum in full (the optimal mechanism closest to the observations).
            if let Some(e) = s.try_evaluate(&e.a) {
                found.push(Found { eval: e, flat });
            }
        }
    } else if s.explorable() {
        // Known motions or more than three unknowns: a compass search from the best candidate.
        if let Some(c) = cands
            .iter()
            .filter(|c| c.eval.misfit.is_finite())
            .min_by(|a, b| a.eval.misfit.total_cmp(&b.eval.misfit))
        {
            if let Some(e) = s.try_quick(&c.eval.a) {
                if let Some(e) = s.try_evaluate(&compass(s, e, &scales).a) {
                    found.push(Found {
                        eval: e,
                        flat: false,
                    });
                }
            }
        }
    }
    found.sort_by(|a, b| a.eval.misfit.total_cmp(&b.eval.misfit));
    // Keep separate minima only; an equally low one in the same basin makes it flat.
    let mut kept: Vec<Found<S::D>> = Vec::new();
    for f in found {
        let mut distinct = true;
        for k in kept.iter_mut() {
            match relation(s, &k.eval, &f.eval)? {
                Relation::Separate => continue,
                Relation::Connected => k.flat |= same_misfit(k.eval.misfit, f.eval.misfit),
                Relation::Same => k.flat |= f.flat,
            }
            distinct = false;
            break;
        }
        if distinct {
            kept.push(f);
        }
    }
    Ok(kept)
}

/// Golden-section search on the angle of a two-unknown direction, between the scan's
/// neighbours of `ray` (±5°), each angle at its exact best amplitude.
fn refine_angle<S: IdentifyGeometry>(s: &Setup<S>, scales: &[f64], ray: &Ray) -> Vec<f64> {
    let phi0 = ray.dir[1].atan2(ray.dir[0]);
    let step = std::f64::consts::TAU / 72.0;
    let at = |phi: f64| -> Option<Ray> { ray_at(s, scales, vec![phi.cos(), phi.sin()]) };
    let value = |r: &Option<Ray>| r.as_ref().map_or(f64::INFINITY, |r| r.misfit);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (phi0 - step, phi0 + step);
    let mut x1 = hi - g * (hi - lo);
    let mut x2 = lo + g * (hi - lo);
    let (mut r1, mut r2) = (at(x1), at(x2));
    let mut best: (f64, Vec<f64>) = (ray.misfit, ray.amplitudes());
    for _ in 0..16 {
        for r in [&r1, &r2].into_iter().flatten() {
            if r.misfit < best.0 && !same_misfit(r.misfit, best.0) {
                best = (r.misfit, r.amplitudes());
            }
        }
        if value(&r1) <= value(&r2) {
            hi = x2;
            x2 = x1;
            r2 = r1;
            x1 = hi - g * (hi - lo);
            r1 = at(x1);
        } else {
            lo = x1;
            x1 = x2;
            r1 = r2;
            x2 = lo + g * (hi - lo);
            r2 = at(x2);
        }
    }
    for r in [&r1, &r2].into_iter().flatten() {
        if r.misfit < best.0 && !same_misfit(r.misfit, best.0) {
            best = (r.misfit, r.amplitudes());
        }
    }
    best.1
}

/// A direction of motion (in the unknowns' characteristic units) and the best amplitude
/// along it.
struct Ray {
    dir: Vec<f64>,
    /// Amplitudes per unit of `t`.
    a1: Vec<f64>,
    t: f64,
    misfit: f64,
}

impl Ray {
    fn amplitudes(&self) -> Vec<f64> {
        self.a1.iter().map(|v| v * self.t + 0.0).collect()
    }
}

/// Directions of motion: ±1 for one unknown, 72 on the circle for two, 194 on the sphere
/// (Fibonacci lattice) for three.
fn directions(n: usize) -> Vec<Vec<f64>> {
    match n {
        1 => vec![vec![1.0], vec![-1.0]],
        2 => (0..72)
            .map(|i| {
                let p = std::f64::consts::TAU * i as f64 / 72.0;
                vec![p.cos(), p.sin()]
            })
            .collect(),
        _ => {
            let m = 194;
            let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
            (0..m)
                .map(|i| {
                    let z = 1.0 - (2 * i + 1) as f64 / m as f64;
                    let r = (1.0 - z * z).max(0.0).sqrt();
                    let p = golden * i as f64;
                    vec![r * p.cos(), r * p.sin(), z]
                })
                .collect()
        }
    }
}

/// Each direction's best amplitude within the bounds: one forward analysis per direction.
fn ray_scan<S: IdentifyGeometry>(s: &Setup<S>, scales: &[f64]) -> Result<Vec<Ray>> {
    Ok(directions(s.unknowns.len())
        .into_iter()
        .filter_map(|dir| ray_at(s, scales, dir))
        .collect())
}

/// The best amplitude along one direction (None: no amplitude within the bounds, or the
/// forward analysis failed).
fn ray_at<S: IdentifyGeometry>(s: &Setup<S>, scales: &[f64], dir: Vec<f64>) -> Option<Ray> {
    let a1: Vec<f64> = dir.iter().zip(scales).map(|(d, sc)| d * sc).collect();
    // The amplitudes t·a1 within the bounds.
    let (mut lo, mut hi) = (0.0f64, f64::INFINITY);
    for (c, (blo, bhi)) in a1.iter().zip(&s.bounds) {
        if *c > 0.0 {
            lo = lo.max(blo / c);
            hi = hi.min(bhi / c);
        } else if *c < 0.0 {
            lo = lo.max(bhi / c);
            hi = hi.min(blo / c);
        } else if *blo > 0.0 || *bhi < 0.0 {
            hi = -1.0;
        }
    }
    if lo > hi || !lo.is_finite() {
        return None;
    }
    // Any amplitude in the range gives the openings per unit t.
    let t0 = if hi.is_finite() {
        0.5 * (lo + hi)
    } else {
        lo.max(1.0)
    };
    let open1: Vec<f64> = if t0 > 0.0 {
        let at: Vec<f64> = a1.iter().map(|v| v * t0).collect();
        let e = s.try_quick(&at)?;
        e.open.iter().map(|o| o / t0).collect()
    } else {
        vec![0.0; s.map.num_points()]
    };
    let (t, misfit) = ray_minimiser(&open1, &s.targets, lo, hi);
    Some(Ray { dir, a1, t, misfit })
}

/// The factor `t` in `[lo, hi]` (`lo ≥ 0`) minimising `Σ |t·o_k − w_k| / τ_k` over observed
/// points (`targets[k] = (w_k, τ_k)`), and that minimum. The function is convex and piecewise
/// linear: its minimum is at a ratio `w_k / o_k` or at an end of the range; of equally good
/// factors the largest (the one that opens the observed cracks most nearly at their widths).
fn ray_minimiser(open: &[f64], targets: &[Option<(f64, f64)>], lo: f64, hi: f64) -> (f64, f64) {
    let f = |t: f64| -> f64 {
        targets
            .iter()
            .zip(open)
            .filter_map(|(tg, o)| tg.map(|(w, tau)| (t * o - w).abs() / tau))
            .sum()
    };
    let mut ts: Vec<f64> = targets
        .iter()
        .zip(open)
        .filter_map(|(tg, &o)| tg.filter(|_| o > 0.0).map(|(w, _)| w / o))
        .map(|t| t.max(lo).min(hi))
        .collect();
    ts.push(lo);
    if hi.is_finite() {
        ts.push(hi);
    }
    ts.sort_by(|a, b| a.total_cmp(b));
    let mut best = (lo, f(lo));
    for t in ts {
        let v = f(t);
        if v < best.1 || same_misfit(v, best.1) {
            best = (t, v.min(best.1));
        }
    }
    best
}

/// The rays' local minima: plateaus (directions linked by neighbours of equal misfit, one
/// direction alone included) none of whose members has a lower neighbour. Per minimum the
/// member nearest the plateau's mean direction and whether the plateau has more than one
/// member. At most four, least misfit first. Directions whose best amplitude is zero (no
/// motion) are left out.
fn ray_minima(rays: &[Ray], n: usize) -> Vec<(usize, bool)> {
    let m = rays.len();
    let dot = |i: usize, j: usize| -> f64 {
        rays[i]
            .dir
            .iter()
            .zip(&rays[j].dir)
            .map(|(a, b)| a * b)
            .sum()
    };
    // Neighbours on the direction grid: adjacent on the circle, the six nearest on the sphere.
    let neighbours: Vec<Vec<usize>> = (0..m)
        .map(|i| {
            if n == 1 {
                return vec![];
            }
            let mut others: Vec<usize> = (0..m).filter(|&j| j != i).collect();
            others.sort_by(|&a, &b| dot(i, b).total_cmp(&dot(i, a)));
            others.truncate(if n == 2 { 2 } else { 6 });
            others
        })
        .collect();
    let mut seen = vec![false; m];
    let mut out: Vec<(f64, usize, bool)> = Vec::new();
    for i in 0..m {
        if seen[i] || !rays[i].misfit.is_finite() {
            continue;
        }
        let mut plateau = vec![i];
        seen[i] = true;
        let mut q = 0;
        let mut lower = false;
        while q < plateau.len() {
            let c = plateau[q];
            q += 1;
            for &j in &neighbours[c] {
                if same_misfit(rays[c].misfit, rays[j].misfit) {
                    if !seen[j] {
                        seen[j] = true;
                        plateau.push(j);
                    }
                } else if rays[j].misfit < rays[c].misfit {
                    lower = true;
                }
            }
        }
        if lower {
            continue;
        }
        let moving: Vec<usize> = plateau
            .iter()
            .copied()
            .filter(|&c| rays[c].t > 0.0)
            .collect();
        if moving.is_empty() {
            continue;
        }
        let mut mean = vec![0.0; n];
        for &c in &moving {
            for (mv, d) in mean.iter_mut().zip(&rays[c].dir) {
                *mv += d;
            }
        }
        let pick = *moving
            .iter()
            .max_by(|&&a, &&b| {
                let da: f64 = rays[a].dir.iter().zip(&mean).map(|(x, y)| x * y).sum();
                let db: f64 = rays[b].dir.iter().zip(&mean).map(|(x, y)| x * y).sum();
                da.total_cmp(&db).then(b.cmp(&a))
            })
            .expect("a plateau has a member");
        out.push((rays[pick].misfit, pick, plateau.len() > 1));
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out.truncate(4);
    out.into_iter().map(|(_, i, f)| (i, f)).collect()
}

/// A compass search on forward analyses from `start`: steps along each unknown and (up to
/// three unknowns) the diagonals, in characteristic units, halved when no step improves.
fn compass<S: IdentifyGeometry>(s: &Setup<S>, start: Eval<S::D>, scales: &[f64]) -> Eval<S::D> {
    let n = s.unknowns.len();
    let mut dirs: Vec<Vec<f64>> = Vec::new();
    for q in 0..n {
        for sign in [1.0, -1.0] {
            let mut d = vec![0.0; n];
            d[q] = sign;
            dirs.push(d);
        }
    }
    if (2..=3).contains(&n) {
        for mask in 0..(1usize << n) {
            dirs.push(
                (0..n)
                    .map(|q| if mask >> q & 1 == 1 { -1.0 } else { 1.0 })
                    .collect(),
            );
        }
    }
    let budget = 8 * dirs.len();
    let size = start
        .a
        .iter()
        .zip(scales)
        .fold(0.0f64, |m, (v, sc)| m.max(v.abs() / sc));
    let mut h = 0.05 * size.max(1.0);
    let hmin = 1e-3 * h;
    let mut cur = start;
    let mut evals = 0;
    while h >= hmin && evals < budget {
        let mut improved = false;
        for d in &dirs {
            let mut y: Vec<f64> = cur
                .a
                .iter()
                .zip(d)
                .zip(scales)
                .map(|((v, dv), sc)| v + h * dv * sc)
                .collect();
            s.clamp(&mut y);
            if y == cur.a {
                continue;
            }
            evals += 1;
            if let Some(e) = s.try_quick(&y) {
                if e.misfit < cur.misfit && !same_misfit(e.misfit, cur.misfit) {
                    cur = e;
                    improved = true;
                    break;
                }
            }
            if evals >= budget {
                break;
            }
        }
        if !improved {
            h *= 0.5;
        }
    }
    cur
}

/// Build the result for the chosen motion.
#[allow(clippy::too_many_arguments)]
fn result<S: IdentifyGeometry>(
    s: &Setup<S>,
    ranges: &[Range],
    best: Eval<S::D>,
    prediction: Option<Prediction>,
    minima: Vec<Minimum>,
    explored: bool,
    pattern_feasible: bool,
    active_set_fixed: bool,
    witnesses: Witnesses<S::D>,
) -> Result<IdentifyResult<S::D>> {
    let (st0, map) = (&s.positions, &s.map);
    let st_best =
        s.st.with_support_motions(&motions_of(s.st, s.unknowns, &best.a));
    let (observations, total, maxm) = compare(st0, map, &s.pobs, &best.open);
    let omax = max_abs(&best.open);
    let predicted_cracks = predicted(st0, map, &best.open, &s.roles, omax);
    let certificate = prediction
        .as_ref()
        .map(|p| reproduction(st0, map, &best.forward, &p.open, p.work));
    let identified = best.within
        || best.opens_pattern()
        || witnesses.within.is_some()
        || witnesses.pattern.is_some();
    // Identifiability: the range of each unknown over every motion that makes the observed
    // pattern a settlement mechanism with every width within its tolerance.
    let mut unknown_results = Vec::new();
    for (q, u) in s.unknowns.iter().enumerate() {
        let Range {
            lo,
            hi,
            feasible,
            computed,
        } = ranges[q];
        let value = best.a[q] + 0.0; // no "-0"
        let (identifiable, note) = if !pattern_feasible {
            (
                false,
                "no motion makes the observed pattern a settlement mechanism: no range".to_string(),
            )
        } else if !computed {
            (false, "range not computed".to_string())
        } else if !feasible {
            (false, "no motion reproduces the pattern with every width within its tolerance: the range is empty; widen the tolerances".to_string())
        } else {
            match (lo, hi) {
                (Some(l), Some(h)) => {
                    let w = h - l;
                    let len = u.length();
                    let range = format!("[{}, {}] {}", len.number(l), len.number(h), len.unit());
                    if w > value.abs() {
                        (false, format!("not identifiable: the range {range} is wider than the value"))
                    } else {
                        (true, format!("identifiable within {range}"))
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
    let all = best.misfit;
    let joints = |v: &[usize]| dedup(v.iter().map(|j| j.to_string()).collect());
    // What the chosen motion's own settlement does differently from the survey.
    let mut why = String::new();
    if !best.extra.is_empty() {
        why.push_str(&format!(
            "; it opens joints observed closed ({})",
            joints(&best.extra)
        ));
    }
    if !best.shut.is_empty() {
        why.push_str(&format!(
            "; it leaves closed joints observed open ({})",
            joints(&best.shut)
        ));
    }
    let maxm_text = crate::lengths::Length::Opening.show(maxm);
    let mut message = if !identified {
        let reason = if pattern_feasible {
            "the motions that make it a settlement mechanism leave, on their own forward settlement analysis, an observed crack closed or open another"
        } else {
            "no motion within the bounds makes this pattern a settlement mechanism"
        };
        format!(
            "no settlement of the unknown support motions produces the observed crack pattern ({reason}), nor fits every width within its tolerance; the closest motion (least misfit over every observed point, closed ones included, on its own forward settlement analysis) is below, with the cracks its settlement opens (misfit {all:.3} tolerances){why}"
        )
    } else if best.within && best.opens_pattern() {
        let reproduced = certificate.as_ref().is_none_or(|c| c.reproduces);
        format!(
            "identified: the settlement mechanism of these support motions opens the observed cracks (misfit {total:.3} tolerances in total, largest {maxm_text}){}",
            if reproduced {
                ", and the forward settlement analysis reproduces it"
            } else {
                ", every width within its tolerance on the forward settlement analysis"
            }
        )
    } else if best.within {
        format!(
            "identified: the forward settlement analysis of these support motions reproduces every observed width within its tolerance (misfit {all:.3} tolerances over every observed point, largest {maxm_text}){}",
            why.replace("; it", "; it still")
        )
    } else {
        // The least misfit does not fit every width within its tolerance.
        let mut m = if best.opens_pattern() {
            format!(
                "identified: the settlement mechanism of these support motions opens the observed crack pattern with the least misfit ({all:.3} tolerances over every observed point, largest {maxm_text}), though not every width within its tolerance"
            )
        } else {
            format!(
                "identified: the least misfit ({all:.3} tolerances over every observed point, largest {maxm_text}) is this motion's{why}"
            )
            .replace("motion's; it", "motion's: it")
        };
        match (witnesses.within, witnesses.within_lp) {
            (Some(w), _) => m.push_str(&format!(
                "; the motion {} fits every width within its tolerance (misfit {:.3} tolerances)",
                values_text(s, &w.a),
                w.misfit
            )),
            (None, Some(false)) => m.push_str(
                "; no motion with the observed pattern fits every width within its tolerance",
            ),
            (None, _) => m.push_str("; no motion found fits every width within its tolerance"),
        }
        if let Some(p) = witnesses.pattern.filter(|_| !best.opens_pattern()) {
            m.push_str(&format!(
                "; the motion {} opens the observed crack pattern (misfit {:.3} tolerances)",
                values_text(s, &p.a),
                p.misfit
            ));
        }
        m
    };
    if minima.len() > 1 {
        let list: Vec<String> = minima[1..]
            .iter()
            .map(|m| format!("{:.3} at {}", m.misfit, values_text(s, &m.values)))
            .collect();
        message.push_str(&format!(
            "; the misfit has {} separate minima: this one and {}",
            minima.len(),
            list.join(", ")
        ));
    }
    if minima[0].flat {
        message.push_str("; the least misfit is not unique: a range of motions around this one fits equally well");
    }
    if !explored && !same_misfit(all, 0.0) && all > EXACT_MISFIT {
        message.push_str(&format!(
            "; the misfit landscape was not explored beyond the LP candidates (a model of more than {EXPLORE_MAX_DOFS} degrees of freedom)"
        ));
    }
    Ok(IdentifyResult {
        status: if identified {
            IdentifyStatus::Identified
        } else {
            IdentifyStatus::Inconsistent
        },
        message,
        unknowns: unknown_results,
        support_motions: support_motions(&st_best),
        observations,
        total_misfit: total,
        misfit_all_points: all,
        max_misfit: maxm,
        predicted_cracks,
        active_set_fixed,
        certificate,
        minima,
        landscape_explored: explored,
        forward: best.forward,
    })
}

impl Unknown {
    /// The kind of length of this unknown's value, for the summaries ([`crate::lengths`]): a
    /// rotation (only the supports' θ move with it), else a translation.
    pub fn length(&self) -> crate::lengths::Length {
        // The translations are the first half of a 3D motion, the first two of a 2D one.
        let split = |m: &Vec<f64>| if m.len() == 6 { 3 } else { 2 };
        let rotation = self
            .unit
            .iter()
            .all(|m| m[..split(m)].iter().all(|x| *x == 0.0))
            && self
                .unit
                .iter()
                .any(|m| m[split(m)..].iter().any(|x| *x != 0.0));
        if rotation {
            crate::lengths::Length::Rotation
        } else {
            crate::lengths::Length::Motion
        }
    }
}

/// `name = value` for each unknown, in the summaries' units ([`crate::lengths`]): cm for
/// translations, mrad for rotations.
fn values_text<S: IdentifyGeometry>(s: &Setup<S>, a: &[f64]) -> String {
    let parts: Vec<String> = s
        .unknowns
        .iter()
        .zip(a)
        .map(|(u, v)| format!("{} = {}", u.name, u.length().show(*v)))
        .collect();
    format!("({})", parts.join(", "))
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
    st: &[Vec<f64>],
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
            let p = &st[o.point];
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
                z: p.get(2).copied(),
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
    st: &[Vec<f64>],
    map: &KinematicMap,
    open: &[f64],
    roles: &[PointRole],
    omax: f64,
) -> Vec<PredictedCrack> {
    (0..map.num_points())
        .filter(|&k| open[k] > 1e-7 * omax && map.gap[k] <= 0.0)
        .map(|k| {
            let pr = map.points[k];
            let p = &st[k];
            PredictedCrack {
                joint: pr.joint,
                point: pr.index,
                x: p[0],
                y: p[1],
                z: p.get(2).copied(),
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

fn reproduction<D: Spatial>(
    st: &[Vec<f64>],
    map: &KinematicMap,
    forward: &SettlementResult<D>,
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
            "the forward analysis finds a mechanism with the same work of the dead loads (the predicted one is also optimal: the settlement mechanism is not unique), but {} (largest width difference {})",
            if same { "different widths" } else { "different open points" },
            crate::lengths::Length::Opening.show(diff)
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

fn support_motions<S: Assembly>(st: &S) -> Vec<SupportMotion<S::D>> {
    (0..st.num_supports())
        .filter(|&k| st.support_motion(k).iter().any(|x| *x != 0.0))
        .map(|k| SupportMotion {
            support: st.support_name(k).to_string(),
            motion: <S::D as Spatial>::motion(st.support_motion(k)),
        })
        .collect()
}

/// Openings of a forward result, by point (0 when it has no mechanism).
fn forward_openings<D: Spatial>(map: &KinematicMap, forward: &SettlementResult<D>) -> Vec<f64> {
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

fn dedup(mut v: Vec<String>) -> String {
    v.dedup();
    v.join(", ")
}
