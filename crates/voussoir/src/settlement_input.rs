//! Prescribed support motions: per-support moves and settlement profiles along a foundation
//! made of many segments.
//!
//! A profile `v(x)` (vertical, m, positive up) is applied to each support as the rigid motion
//! that matches it at the support's centroid: translation `v(c_x)` and rotation `dv/dx`
//! (exact for a linear profile). Supports outside the profile's range do not move.

use crate::error::{Error, Result};
use crate::model::Model;
use crate::model3d::Model3d;
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

/// The supports of a model of either dimension, as the settlement inputs see them.
pub trait ModelSupports {
    /// Values of a support motion (3 in 2D, 6 in 3D).
    const MOTION: usize;
    /// Index of the vertical translation and of the rotation in the vertical x plane, and the
    /// sign that turns a profile's slope `dv/dx` into that rotation.
    const VERTICAL: (usize, usize, f64);
    fn support_names(&self) -> Vec<&str>;
    fn motion_mut(&mut self, i: usize) -> &mut [f64];
    fn set_fixed(&mut self, i: usize);
    /// x of the support's centroid (`None` for a shape too broken to have one; the model's
    /// validation names it later).
    fn centroid_x(&self, i: usize) -> Option<f64>;
}

impl ModelSupports for Model {
    const MOTION: usize = 3;
    const VERTICAL: (usize, usize, f64) = (1, 2, 1.0);
    fn support_names(&self) -> Vec<&str> {
        self.supports.iter().map(|s| s.name.as_str()).collect()
    }
    fn motion_mut(&mut self, i: usize) -> &mut [f64] {
        &mut self.supports[i].motion
    }
    fn set_fixed(&mut self, i: usize) {
        self.supports[i].connection = crate::model::Connection::Fixed;
    }
    fn centroid_x(&self, i: usize) -> Option<f64> {
        let p = &self.supports[i].polygon;
        (p.len() >= 3).then(|| crate::geometry::area_centroid(p).1[0])
    }
}

impl ModelSupports for Model3d {
    const MOTION: usize = 6;
    // w(x) = w0 + s·x is the rigid motion with rotation θy = −s about the centroid.
    const VERTICAL: (usize, usize, f64) = (2, 4, -1.0);
    fn support_names(&self) -> Vec<&str> {
        self.supports.iter().map(|s| s.name.as_str()).collect()
    }
    fn motion_mut(&mut self, i: usize) -> &mut [f64] {
        &mut self.supports[i].motion
    }
    fn set_fixed(&mut self, i: usize) {
        self.supports[i].connection = crate::model::Connection::Fixed;
    }
    fn centroid_x(&self, i: usize) -> Option<f64> {
        let s = &self.supports[i];
        crate::geometry3d::clean_polyhedron("support", &s.vertices, &s.faces, 1e-12)
            .ok()
            .map(|p| p.centroid[0])
    }
}

/// Apply a vertical settlement profile along x to every support (by its centroid): vertical
/// translation `v(c_x)` and the rotation of slope `dv/dx`.
pub fn apply_profile<M: ModelSupports>(model: &mut M, profile: &Profile) -> Result<()> {
    profile.validate()?;
    let (tv, rv, sign) = M::VERTICAL;
    for i in 0..model.support_names().len() {
        let Some(cx) = model.centroid_x(i) else {
            continue;
        };
        let (v, slope) = profile.eval(cx);
        let m = model.motion_mut(i);
        m[tv] += v;
        m[rv] += sign * slope;
    }
    Ok(())
}

fn support_index<M: ModelSupports>(model: &M, name: &str) -> Result<usize> {
    let names = model.support_names();
    names.iter().position(|s| *s == name).ok_or_else(|| {
        Error::Request(format!(
            "no support named '{name}' (the model has: {})",
            names.join(", ")
        ))
    })
}

/// Prescribe the motion of support `name` (`M::MOTION` values).
pub fn move_support<M: ModelSupports>(model: &mut M, name: &str, motion: &[f64]) -> Result<()> {
    if !motion.iter().all(|x| x.is_finite()) {
        return Err(Error::Request(format!(
            "motion of support '{name}' is not finite"
        )));
    }
    if motion.len() != M::MOTION {
        return Err(Error::Request(format!(
            "motion of support '{name}' needs {} values, got {}",
            M::MOTION,
            motion.len()
        )));
    }
    let i = support_index(model, name)?;
    model.motion_mut(i).copy_from_slice(motion);
    Ok(())
}

/// Declare support `name` fixed (bilateral).
pub fn fix_support<M: ModelSupports>(model: &mut M, name: &str) -> Result<()> {
    let i = support_index(model, name)?;
    model.set_fixed(i);
    Ok(())
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
