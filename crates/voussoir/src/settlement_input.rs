//! Prescribed support motions: per-support moves and settlement profiles along a foundation
//! made of many segments.
//!
//! A profile `v(x)` (vertical, m, positive up) is applied to each support as the rigid motion
//! that matches it at the support's centroid: translation `v(c_x)` and rotation `dv/dx`
//! (exact for a linear profile). Supports outside the profile's range do not move.

use crate::error::{Error, Result};
use crate::model::Model;
use serde::{Deserialize, Serialize};

/// A vertical settlement profile along x.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "lowercase", deny_unknown_fields)]
pub enum Profile {
    /// `v` on `x0 ≤ x ≤ x1` (by support centroid), 0 elsewhere.
    Uniform { x0: f64, x1: f64, v: f64 },
    /// Linear between `(x0, v0)` and `(x1, v1)`, 0 outside `[x0, x1]`.
    Linear { x0: f64, v0: f64, x1: f64, v1: f64 },
    /// Piecewise-linear interpolation of `(x, v)` pairs (sorted by x), 0 outside.
    Table { points: Vec<[f64; 2]> },
}

impl Profile {
    /// `(v, dv/dx)` at `x`.
    pub fn eval(&self, x: f64) -> (f64, f64) {
        match self {
            Profile::Uniform { x0, x1, v } => {
                if x >= *x0 && x <= *x1 {
                    (*v, 0.0)
                } else {
                    (0.0, 0.0)
                }
            }
            Profile::Linear { x0, v0, x1, v1 } => {
                if x >= x0.min(*x1) && x <= x0.max(*x1) && x1 != x0 {
                    let s = (v1 - v0) / (x1 - x0);
                    (v0 + s * (x - x0), s)
                } else {
                    (0.0, 0.0)
                }
            }
            Profile::Table { points } => {
                for w in points.windows(2) {
                    let ([xa, va], [xb, vb]) = (w[0], w[1]);
                    if x >= xa && x <= xb && xb > xa {
                        let s = (vb - va) / (xb - xa);
                        return (va + s * (x - xa), s);
                    }
                }
                (0.0, 0.0)
            }
        }
    }

    pub fn validate(&self) -> Result<()> {
        let bad = |m: &str| Err(Error::Request(format!("settlement profile: {m}")));
        match self {
            Profile::Uniform { x0, x1, v } => {
                if ![*x0, *x1, *v].iter().all(|a| a.is_finite()) || x1 < x0 {
                    return bad("uniform needs finite x0 ≤ x1 and v");
                }
            }
            Profile::Linear { x0, v0, x1, v1 } => {
                if ![*x0, *v0, *x1, *v1].iter().all(|a| a.is_finite()) || x1 <= x0 {
                    return bad("linear needs finite values and x0 < x1");
                }
            }
            Profile::Table { points } => {
                if points.len() < 2
                    || points
                        .iter()
                        .any(|p| !p[0].is_finite() || !p[1].is_finite())
                {
                    return bad("a table needs at least two finite (x, v) pairs");
                }
                if points.windows(2).any(|w| w[1][0] <= w[0][0]) {
                    return bad("table x values must increase");
                }
            }
        }
        Ok(())
    }
}

/// Add a profile's motion to every support of `model` (by centroid).
pub fn apply_profile(model: &mut Model, profile: &Profile) -> Result<()> {
    profile.validate()?;
    for s in model.supports.iter_mut() {
        if s.polygon.len() < 3 {
            continue;
        }
        let (_, c) = crate::geometry::area_centroid(&s.polygon);
        let (v, slope) = profile.eval(c[0]);
        s.motion[1] += v;
        s.motion[2] += slope;
    }
    Ok(())
}

/// Set the motion of support `name` (θ in radians).
pub fn move_support(model: &mut Model, name: &str, motion: [f64; 3]) -> Result<()> {
    if !motion.iter().all(|x| x.is_finite()) {
        return Err(Error::Request(format!(
            "motion of support '{name}' is not finite"
        )));
    }
    let known = || {
        model
            .supports
            .iter()
            .map(|s| s.name.clone())
            .collect::<Vec<_>>()
            .join(", ")
    };
    match model.supports.iter().position(|s| s.name == name) {
        Some(i) => {
            model.supports[i].motion = motion;
            Ok(())
        }
        None => Err(Error::Request(format!(
            "no support named '{name}' (the model has: {})",
            known()
        ))),
    }
}

/// Declare support `name` fixed (bilateral).
pub fn fix_support(model: &mut Model, name: &str) -> Result<()> {
    match model.supports.iter_mut().find(|s| s.name == name) {
        Some(s) => {
            s.connection = crate::model::Connection::Fixed;
            Ok(())
        }
        None => Err(Error::Request(format!("no support named '{name}'"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{wall, WallSpec};

    #[test]
    fn profiles_validate_and_apply_by_centroid() {
        let uniform = |x0, x1| Profile::Uniform { x0, x1, v: -0.2 };
        assert!(uniform(1.0, 2.0).validate().is_ok());
        assert!(uniform(2.0, 1.0).validate().is_err());
        let linear = Profile::Linear {
            x0: 0.0,
            v0: 0.0,
            x1: 0.0,
            v1: 1.0,
        };
        assert!(linear.validate().is_err());
        // A wall of 5 units of 0.4 m: foundation centroids at 0.2, 0.6, 1.0, 1.4, 1.8.
        let mut m = wall(&WallSpec {
            courses: 2,
            units: 5,
            ..WallSpec::default()
        })
        .unwrap();
        let linear = Profile::Linear {
            x0: 0.4,
            v0: 0.0,
            x1: 2.0,
            v1: -0.04,
        };
        apply_profile(&mut m, &linear).unwrap();
        let v: Vec<f64> = m.supports.iter().map(|s| s.motion[1]).collect();
        let th: Vec<f64> = m.supports.iter().map(|s| s.motion[2]).collect();
        let expect = [0.0, -0.005, -0.015, -0.025, -0.035];
        for (a, b) in v.iter().zip(expect) {
            assert!((a - b).abs() < 1e-15, "{v:?}");
        }
        // Each segment inside the range also rotates with the profile's slope.
        assert!(th[0] == 0.0 && th[1..].iter().all(|t| (t + 0.025).abs() < 1e-15));
        let mut m = wall(&WallSpec {
            courses: 2,
            units: 5,
            ..WallSpec::default()
        })
        .unwrap();
        let table = Profile::Table {
            points: vec![[0.0, 0.0], [1.0, -0.1], [2.0, -0.1]],
        };
        apply_profile(&mut m, &table).unwrap();
        assert!((m.supports[1].motion[1] + 0.06).abs() < 1e-15);
        assert!((m.supports[4].motion[1] + 0.1).abs() < 1e-15);
    }
}
