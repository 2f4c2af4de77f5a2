//! Prescribed support motions: per-support moves and settlement profiles along a foundation
//! made of many segments.
//!
//! A profile `v(x)` (vertical, m, positive up) is applied to each support as the rigid motion
//! that matches it at the support's centroid: translation `v(c_x)` and rotation `dv/dx`
//! (exact for a linear profile). Supports outside the profile's range do not move.
//!
//! Foundations as drawn: [`apply_profile_as_drawn`] first cuts every support that spans one of
//! the profile's breakpoints ([`Profile::breakpoints`]) at those x values
//! ([`split_supports_at`]), so that each part lies on one linear piece of the profile and moves
//! exactly as it says; [`split_support`] cuts one support where asked. The parts of support
//! `NAME` are named `NAME@0`, `NAME@1`, … from the left (by their leftmost x, then their lowest
//! point: a strip of a non-convex support may hold several pieces). A support that spans no
//! breakpoint is left untouched.

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

    /// The x values where the profile is not one linear function: its ends and, for a table,
    /// every point (increasing, without repeats).
    pub fn breakpoints(&self) -> Vec<f64> {
        let mut xs = match self {
            Profile::Uniform { x0, x1, .. } | Profile::Linear { x0, x1, .. } => vec![*x0, *x1],
            Profile::Table { points } => points.iter().map(|p| p[0]).collect(),
        };
        xs.sort_by(f64::total_cmp);
        xs.dedup();
        xs
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
    /// The x range of the support's vertices.
    fn x_range(&self, i: usize) -> [f64; 2];
    fn motion(&self, i: usize) -> &[f64];
    /// Whether support `i` is tied to its blocks (`fixed`).
    fn is_fixed(&self, i: usize) -> bool;
    /// The model's size: the diagonal of the box around every vertex of its blocks and supports
    /// (0 for a model without any).
    fn extent(&self) -> f64;
    /// Replace support `i` by its parts cut at `cuts` (increasing, strictly inside its x range),
    /// named `NAME@0`, `NAME@1`, … from the left, in its place in the list. Each part keeps the
    /// support's connection and moves with it rigidly (its motion re-expressed about the part's
    /// centroid). Returns the number of parts.
    fn split(&mut self, i: usize, cuts: &[f64]) -> Result<usize>;
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
    fn x_range(&self, i: usize) -> [f64; 2] {
        crate::support_split::x_range2(&self.supports[i].polygon)
    }
    fn motion(&self, i: usize) -> &[f64] {
        &self.supports[i].motion
    }
    fn is_fixed(&self, i: usize) -> bool {
        self.supports[i].connection == crate::model::Connection::Fixed
    }
    fn extent(&self) -> f64 {
        let points: Vec<crate::model::Point> = self
            .blocks
            .iter()
            .flat_map(|b| b.polygon.iter())
            .chain(self.supports.iter().flat_map(|s| s.polygon.iter()))
            .copied()
            .collect();
        let [x0, y0, x1, y1] = crate::geometry::bbox(&points);
        if points.is_empty() {
            0.0
        } else {
            (x1 - x0).hypot(y1 - y0)
        }
    }
    fn split(&mut self, i: usize, cuts: &[f64]) -> Result<usize> {
        use crate::geometry::area_centroid;
        let s = &self.supports[i];
        if s.polygon.len() < 3 {
            return Err(Error::Request(
                "its polygon has fewer than 3 vertices".into(),
            ));
        }
        let c0 = area_centroid(&s.polygon).1;
        let [u, v, t] = s.motion;
        let parts: Vec<crate::model::Support> =
            crate::support_split::split_polygon(&s.polygon, cuts)?
                .into_iter()
                .flatten()
                .enumerate()
                .map(|(k, polygon)| {
                    let c = area_centroid(&polygon).1;
                    crate::model::Support {
                        name: format!("{}@{k}", s.name),
                        motion: [u - t * (c[1] - c0[1]), v + t * (c[0] - c0[0]), t],
                        polygon,
                        connection: s.connection,
                    }
                })
                .collect();
        let n = parts.len();
        self.supports.splice(i..=i, parts);
        Ok(n)
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
    fn x_range(&self, i: usize) -> [f64; 2] {
        crate::support_split::x_range3(&self.supports[i].vertices)
    }
    fn motion(&self, i: usize) -> &[f64] {
        &self.supports[i].motion
    }
    fn is_fixed(&self, i: usize) -> bool {
        self.supports[i].connection == crate::model::Connection::Fixed
    }
    fn extent(&self) -> f64 {
        let points: Vec<crate::model3d::Point3> = self
            .blocks
            .iter()
            .flat_map(|b| b.vertices.iter())
            .chain(self.supports.iter().flat_map(|s| s.vertices.iter()))
            .copied()
            .collect();
        let [lo, hi] = crate::geometry3d::bbox3(&points);
        if points.is_empty() {
            0.0
        } else {
            crate::vector::norm3(crate::vector::sub3(hi, lo))
        }
    }
    fn split(&mut self, i: usize, cuts: &[f64]) -> Result<usize> {
        use crate::geometry3d::clean_polyhedron;
        let s = &self.supports[i];
        let centroid = |v: &[[f64; 3]], f: &[Vec<usize>]| {
            clean_polyhedron("support", v, f, 1e-12).map(|p| p.centroid)
        };
        let c0 = centroid(&s.vertices, &s.faces)?;
        let m = s.motion;
        let mut parts = Vec::new();
        for (k, (vertices, faces)) in
            crate::support_split::split_polyhedron(&s.vertices, &s.faces, cuts)?
                .into_iter()
                .enumerate()
        {
            let c = centroid(&vertices, &faces)?;
            // A rigid motion (t, θ) about c0 moves c by t + θ × (c − c0).
            let r = [c[0] - c0[0], c[1] - c0[1], c[2] - c0[2]];
            let w = [m[3], m[4], m[5]];
            let motion = [
                m[0] + w[1] * r[2] - w[2] * r[1],
                m[1] + w[2] * r[0] - w[0] * r[2],
                m[2] + w[0] * r[1] - w[1] * r[0],
                m[3],
                m[4],
                m[5],
            ];
            parts.push(crate::model3d::Support3d {
                name: format!("{}@{k}", s.name),
                vertices,
                faces,
                motion,
                connection: s.connection,
            });
        }
        let n = parts.len();
        self.supports.splice(i..=i, parts);
        Ok(n)
    }
}

/// One part of a split support, as reported.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SupportPart {
    pub name: String,
    /// x range of the part's vertices (m).
    pub x_range: [f64; 2],
    /// The part's motion (`[u, v, θ]` in 2D, `[u, v, w, θx, θy, θz]` in 3D; m and rad, about
    /// its centroid), once every motion is applied ([`refresh_motions`]).
    pub motion: Vec<f64>,
}

/// A support cut into parts: where, and the parts from the left.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SupportSplit {
    pub support: String,
    /// The cuts `x = c` (m), increasing.
    pub cuts: Vec<f64>,
    pub parts: Vec<SupportPart>,
}

/// A number for a message: plain where that is short, else in e-notation (1e-300, not 300
/// zeros).
pub fn short_number(x: f64) -> String {
    if x == 0.0 || (1e-4..1e15).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Cut support `name` at the x values `cuts` (any order; each strictly inside the support's x
/// range) into parts `NAME@0`, `NAME@1`, … from the left (see the module's notes). Refused: an
/// unknown support, a cut that is not a finite number or lies outside the support, a model
/// that already has a support named `NAME@K`.
pub fn split_support<M: ModelSupports>(
    model: &mut M,
    name: &str,
    cuts: &[f64],
) -> Result<SupportSplit> {
    let i = support_index(model, name)?;
    let bad = |m: String| Err(Error::Request(format!("support '{name}': {m}")));
    if let Some(c) = cuts.iter().find(|c| !c.is_finite()) {
        return bad(format!(
            "the cut x = {} is not a finite number",
            short_number(*c)
        ));
    }
    let mut cuts = cuts.to_vec();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    if cuts.is_empty() {
        return bad("no cut given".into());
    }
    let r = model.x_range(i);
    if let Some(c) = cuts
        .iter()
        .find(|c| !crate::support_split::strictly_inside(r, **c))
    {
        return bad(format!(
            "the cut x = {} m is not inside the support (it spans x = {} … {} m)",
            short_number(*c),
            short_number(r[0]),
            short_number(r[1])
        ));
    }
    let prefix = format!("{name}@");
    if let Some(other) = model.support_names().into_iter().find(|s| {
        s.strip_prefix(&prefix)
            .is_some_and(|k| !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()))
    }) {
        return bad(format!(
            "its parts would be named {prefix}0, {prefix}1, … and the model already has a support '{other}'"
        ));
    }
    let n = model.split(i, &cuts).map_err(|e| match e {
        Error::Request(m) | Error::Model(m) => Error::Request(format!("support '{name}': {m}")),
        e => e,
    })?;
    let parts = (i..i + n)
        .map(|k| SupportPart {
            name: model.support_names()[k].to_string(),
            x_range: model.x_range(k),
            motion: model.motion(k).to_vec(),
        })
        .collect();
    Ok(SupportSplit {
        support: name.to_string(),
        cuts,
        parts,
    })
}

/// Cut every support that spans one of the x values `xs` (strictly inside its x range) there;
/// the others are left untouched. Returns the supports cut, in the model's order.
pub fn split_supports_at<M: ModelSupports>(model: &mut M, xs: &[f64]) -> Result<Vec<SupportSplit>> {
    let names: Vec<String> = model
        .support_names()
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut out = Vec::new();
    for name in names {
        let i = support_index(model, &name)?;
        let r = model.x_range(i);
        let cuts: Vec<f64> = xs
            .iter()
            .copied()
            .filter(|&c| crate::support_split::strictly_inside(r, c))
            .collect();
        if !cuts.is_empty() {
            out.push(split_support(model, &name, &cuts)?);
        }
    }
    Ok(out)
}

/// Cut every support into `n` parts of equal x extent (`NAME@0` … from the left; `n ≥ 2`).
pub fn split_supports_equally<M: ModelSupports>(
    model: &mut M,
    n: usize,
) -> Result<Vec<SupportSplit>> {
    if n < 2 {
        return Err(Error::Request(format!(
            "cannot cut a support into {n} part(s): give 2 or more"
        )));
    }
    let names: Vec<String> = model
        .support_names()
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut out = Vec::new();
    for name in names {
        let i = support_index(model, &name)?;
        let [x0, x1] = model.x_range(i);
        let cuts: Vec<f64> = (1..n)
            .map(|k| x0 + (x1 - x0) * k as f64 / n as f64)
            .collect();
        out.push(split_support(model, &name, &cuts)?);
    }
    Ok(out)
}

/// Apply a profile to the supports as drawn: cut every support that spans a breakpoint of the
/// profile there ([`split_supports_at`]), then apply the profile to every support by its
/// centroid ([`apply_profile`]; exact for each part, which lies on one linear piece). Returns
/// the supports cut.
pub fn apply_profile_as_drawn<M: ModelSupports>(
    model: &mut M,
    profile: &Profile,
) -> Result<Vec<SupportSplit>> {
    profile.validate()?;
    let mut splits = split_supports_at(model, &profile.breakpoints())?;
    apply_profile(model, profile)?;
    refresh_motions(model, &mut splits);
    Ok(splits)
}

/// Update the motions reported for the parts of `splits` from the model (after later moves or
/// profiles; a part cut again keeps the motion it had).
pub fn refresh_motions<M: ModelSupports>(model: &M, splits: &mut [SupportSplit]) {
    let names = model.support_names();
    for p in splits.iter_mut().flat_map(|s| s.parts.iter_mut()) {
        if let Some(i) = names.iter().position(|n| *n == p.name) {
            p.motion = model.motion(i).to_vec();
        }
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
