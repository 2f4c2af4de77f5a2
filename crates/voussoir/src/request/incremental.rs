//! The incremental (nonlinear kinematic) analysis: λ against the displacement of a control
//! point as the mechanism evolves and hinges close, after an optional settlement.

use super::{invalid, Names, Output, Request};
use crate::analysis::incremental::{
    incremental_with, settled_canonical, Control, IncrementalGeometry, IncrementalOptions,
    IncrementalPoint,
};
use crate::error::Result;
use crate::lp::{Method, SolverOptions};
use serde::{Deserialize, Serialize};

/// A direction as a front end writes it: an axis (`"+x"`, `"-y"`, `"+z"`, …), an angle in
/// degrees from +x towards +y (horizontal), or a vector of two (2D) or three (3D) components
/// of any length. Its meaning in the model's dimension is decided here ([`Toward::resolve`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Toward {
    Angle(f64),
    Vector(Vec<f64>),
    Axis(String),
}

impl Default for Toward {
    fn default() -> Self {
        Toward::Axis("+x".into())
    }
}

impl Toward {
    fn text(&self) -> String {
        match self {
            Toward::Angle(a) => crate::settlement_input::short_number(*a),
            Toward::Vector(v) => v
                .iter()
                .map(|x| crate::settlement_input::short_number(*x))
                .collect::<Vec<_>>()
                .join(","),
            Toward::Axis(s) => s.clone(),
        }
    }

    /// The direction in a model of `dims` dimensions (z up in 3D): an axis, an angle (in the
    /// plane in 2D, horizontal in 3D; multiples of 90° exactly), or a vector of the model's
    /// number of components. A 2D direction is refused on a 3D model and `±z` on a 2D one.
    pub fn resolve(&self, dims: usize, field: &str, names: Names) -> Result<Vec<f64>> {
        let given = || names.given(field, self.text());
        let v: Vec<f64> = match self {
            Toward::Axis(s) => {
                let t = s.trim().replace('−', "-").to_ascii_lowercase();
                let (axis, sign) = match t.as_str() {
                    "+x" | "x" | "right" | "positive" => (0, 1.0),
                    "-x" | "left" | "negative" => (0, -1.0),
                    "+y" | "y" => (1, 1.0),
                    "-y" => (1, -1.0),
                    "+z" | "z" => (2, 1.0),
                    "-z" => (2, -1.0),
                    _ => {
                        return invalid(format!(
                            "{}: expected +x, -x, +y, -y{}, an angle in degrees or a vector",
                            given(),
                            if dims == 3 { ", +z, -z" } else { "" }
                        ))
                    }
                };
                if axis >= dims {
                    return invalid(format!(
                        "{}: a 2D model's directions are in its plane (+x, -x, +y, -y, an angle or DX,DY)",
                        given()
                    ));
                }
                let mut v = vec![0.0; dims];
                v[axis] = sign;
                v
            }
            Toward::Angle(a) => {
                if !a.is_finite() {
                    return invalid(format!(
                        "{}: an angle must be a finite number of degrees",
                        given()
                    ));
                }
                let r = a.rem_euclid(360.0);
                let [x, y] = if r == 0.0 || r >= 360.0 {
                    [1.0, 0.0]
                } else if r == 90.0 {
                    [0.0, 1.0]
                } else if r == 180.0 {
                    [-1.0, 0.0]
                } else if r == 270.0 {
                    [0.0, -1.0]
                } else {
                    let t = a.to_radians();
                    [t.cos(), t.sin()]
                };
                let mut v = vec![x, y];
                v.resize(dims, 0.0);
                v
            }
            Toward::Vector(v) => {
                if v.len() != dims {
                    return invalid(if dims == 3 {
                        format!(
                            "{}: a 3D model's direction vector has three components DX,DY,DZ (z up)",
                            given()
                        )
                    } else {
                        format!("{}: a 2D direction has two components DX,DY", given())
                    });
                }
                v.clone()
            }
        };
        if v.iter().any(|x| !x.is_finite()) || v.iter().all(|x| *x == 0.0) {
            return invalid(format!("{}: expected a finite, non-zero vector", given()));
        }
        Ok(v)
    }
}

/// Options of an incremental analysis. Defaults: direction +x, up to 50 mm in steps of 0.5 mm,
/// stop when λ has fallen to zero, no snapshots beyond the first step and the events, fixed
/// supports released after a settlement, the canonical settlement mechanism (docs/canonical.md;
/// the steps' collapse mechanisms are the solver's unless `canonical_steps`). The control point is required. A support motion in
/// the request (moves, a profile) is a settlement run first: the analysis starts from the
/// settled geometry with its cracks open.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct IncrementalRequest {
    /// The control point, (x, y) of a 2D model or (x, y, z) of a 3D one, in m: the block that
    /// contains it (on the structure before any settlement), or the nearest, carries it.
    pub control: Vec<f64>,
    /// Along which the control displacement is measured (default +x).
    pub direction: Toward,
    /// Largest control displacement (m; default 0.05).
    pub max: f64,
    /// Control displacement per step (m; default 0.0005).
    pub step: f64,
    /// Keep `fixed` supports tied after the settlement (default: released to contact joints).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub keep_fixed: bool,
    /// Keep the mechanism every N steps (0: only the first step and the events).
    pub snapshot_every: usize,
    /// Go on after λ has fallen to zero (up to `max`).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub no_stop: bool,
    /// Settle by the solver's own settlement mechanism instead of the canonical one
    /// (docs/canonical.md).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub raw: bool,
    /// Also follow the canonical collapse mechanism at every step (by default the solver's:
    /// the selection costs 5–10× the raw CPU time, docs/performance.md). λ is the same at each
    /// step; where a step's optimum is not unique the path then does not depend on the method.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub canonical_steps: bool,
}

impl Default for IncrementalRequest {
    fn default() -> Self {
        IncrementalRequest {
            control: Vec::new(),
            direction: Toward::default(),
            max: 0.05,
            step: 5e-4,
            keep_fixed: false,
            snapshot_every: 0,
            no_stop: false,
            raw: false,
            canonical_steps: false,
        }
    }
}

impl IncrementalRequest {
    pub(super) fn validate(&self, req: &Request) -> Result<()> {
        let n = req.names;
        if self.control.iter().any(|x| !x.is_finite()) || !(2..=3).contains(&self.control.len()) {
            return invalid(format!(
                "{}: expected two numbers X,Y (2D) or three X,Y,Z (3D)",
                n.given("control", nums(&self.control))
            ));
        }
        for (field, x) in [("max", self.max), ("step", self.step)] {
            if !(x.is_finite() && x > 0.0) {
                return invalid(format!(
                    "{}: must be a positive length (m)",
                    n.given(field, x)
                ));
            }
        }
        if self.step > self.max {
            return invalid(format!(
                "{} mm is larger than {} mm",
                n.given("step", self.step * 1e3),
                n.given("max", self.max * 1e3)
            ));
        }
        // Regression (session 18): the flag was ignored in 3D and the steps ran on the
        // inscribed pyramid with nothing said.
        req.model.refuse_exact_cone(
            n,
            " does not apply to `incremental` (its steps are warm-started LPs: the inscribed pyramid)",
        )?;
        if self.raw && self.canonical_steps {
            // The steps' selection is a stage of the canonical selection: `raw` would leave
            // the settlement's out and keep the steps', which no other analysis does.
            return invalid(format!(
                "{} applies to the canonical selection, which {} leaves out",
                n.name("canonical_steps"),
                n.name("raw")
            ));
        }
        let m = &req.motion;
        if m.moves.is_empty() && m.profile.is_none() {
            if !m.fixed.is_empty() {
                return invalid(format!(
                    "{} only applies with {}",
                    n.name("fixed"),
                    n.name("move")
                ));
            }
            if self.keep_fixed {
                return invalid(format!(
                    "{} only applies with {}",
                    n.name("keep_fixed"),
                    n.name("move")
                ));
            }
            if self.raw {
                // It chooses the settlement's mechanism; without a settlement it was accepted
                // and ignored (session 24): the steps follow the solver's mechanism anyway
                // unless `canonical_steps`.
                return invalid(format!(
                    "{} chooses the solver's own settlement mechanism and only applies with {} or {} (without a settlement the steps follow the solver's mechanism already)",
                    n.name("raw"),
                    n.name("move"),
                    n.name("profile")
                ));
            }
        }
        Ok(())
    }

    pub(super) fn check_dimension(&self, req: &Request, dims: usize) -> Result<()> {
        let n = req.names;
        if self.control.len() != dims {
            return invalid(format!(
                "{}: expected {} finite numbers {} (the model is {dims}D)",
                n.given("control", nums(&self.control)),
                if dims == 3 { "three" } else { "two" },
                if dims == 3 { "X,Y,Z" } else { "X,Y" }
            ));
        }
        self.direction.resolve(dims, "direction", n)?;
        Ok(())
    }

    /// The solver: the dual simplex in both dimensions unless a method is asked for (a simplex
    /// basis is warm-started from step to step; docs/incremental.md), not the interior point
    /// other 3D analyses start with.
    pub fn solver(req: &Request) -> SolverOptions {
        SolverOptions {
            method: req.solver.method.unwrap_or(Method::DualSimplex),
            log: req.solver.log,
            ..SolverOptions::default()
        }
    }

    /// Settle first when the supports move, choose the control block on the structure before
    /// the settlement (so that a point on a joint names the same block with and without one),
    /// then step.
    pub(super) fn solve<S: IncrementalGeometry>(
        &self,
        st: &S,
        req: &Request,
        dims: usize,
        moving: bool,
        progress: &mut dyn FnMut(&IncrementalPoint),
    ) -> Result<(Output<S::D>, SolverOptions)> {
        let solver = Self::solver(req);
        let x = vector(&self.control);
        let dir = vector(&self.direction.resolve(dims, "direction", req.names)?);
        let (Some(x), Some(dir)) = (x, dir) else {
            return Err(crate::Error::Request(
                "internal: control point of the wrong dimension".into(),
            ));
        };
        let canonical = (!self.raw).then(super::mechanism_options);
        let (start, settlement) = if moving {
            let (s, m) = settled_canonical(st, &solver, !self.keep_fixed, canonical)?;
            (s, Some(m))
        } else {
            (st.clone(), None)
        };
        let block = Control::nearest(st, x, dir)?.block;
        let control = Control::new(&start, block, x, dir)?;
        let opts = IncrementalOptions {
            step: self.step,
            max_displacement: self.max,
            stop_after_peak: !self.no_stop,
            snapshot_every: self.snapshot_every,
            solver,
            canonical: canonical.filter(|_| self.canonical_steps),
            ..IncrementalOptions::default()
        };
        let mut r = incremental_with(&start, &control, &opts, progress)?;
        // The record where something was selected: the settlement, or the steps.
        if canonical.is_some() && (moving || self.canonical_steps) {
            let c = r.canonical.get_or_insert_with(Default::default);
            if let Some(m) = settlement {
                c.settlement_not_reached = m.is_none();
                if c.settlement_not_reached {
                    r.message.push_str("; the canonical selection of the settlement mechanism was not reached: the solver's own settled the structure, which may depend on the method");
                }
                c.selection.solves += m.as_ref().map_or(0, |m| m.solves);
                c.settlement = m;
            }
        }
        Ok((Output::Incremental(r), solver))
    }
}

fn nums(v: &[f64]) -> String {
    v.iter()
        .map(|x| crate::settlement_input::short_number(*x))
        .collect::<Vec<_>>()
        .join(",")
}

/// A point or vector of a dimension from its components.
pub(super) fn vector<V: serde::de::DeserializeOwned>(v: &[f64]) -> Option<V> {
    serde_json::from_value(serde_json::json!(v)).ok()
}
