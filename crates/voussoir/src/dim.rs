//! The dimension layer, defined once (the lesson of parry's `math` module): the few things a
//! block motion and a contact point need, with a 2D instance ([`Two`]) and a 3D one ([`Three`]).
//!
//! | | [`Two`] | [`Three`] |
//! |---|---|---|
//! | point, vector | `[x, y]` | `[x, y, z]` |
//! | rotation | angle θ (counter-clockwise) | rotation vector `[θx, θy, θz]` |
//! | DOFs per block | 3: `(u, v, θ)` | 6: `(u, v, w, θx, θy, θz)` |
//! | tangents per contact point | 1: `t = (−n_y, n_x)` | 2: an orthonormal pair with `t₁ × t₂ = n` |
//!
//! A block's small motion is a translation `u` of its reference point `c` and a rotation `ω`;
//! a point `x` of the block moves by `u + ω × (x − c)` (in 2D `ω × r = θ (−r_y, r_x)`). The
//! component of that motion along a direction `e` is linear in the DOFs:
//! `e·u + (r × e)·ω` — [`Dim::dof_row`] writes those coefficients. Everything built on
//! contact frames (the kinematic map, the programs, the analyses' solves) uses only this trait,
//! so it is written once for both dimensions.
//!
//! Generics over this trait were chosen over cargo features so that one binary reads and
//! analyses both 2D and 3D models (see `docs/architecture.md`).

use crate::vector::{self, cross};
use std::fmt::Debug;

/// A spatial dimension: its vector type, DOFs per block and tangents per contact point.
pub trait Dim: Copy + Clone + Debug + Default + Send + Sync + 'static {
    /// Spatial dimension (2 or 3).
    const N: usize;
    /// Degrees of freedom per block: `N` translations and the rotation's components.
    const DOFS: usize;
    /// Tangential directions per contact point (`N − 1`).
    const TANGENTS: usize;
    /// A point or free vector.
    type Vector: Copy
        + Clone
        + Debug
        + PartialEq
        + AsRef<[f64]>
        + AsMut<[f64]>
        + Send
        + Sync
        + serde::Serialize
        + serde::de::DeserializeOwned;
    /// The tangent directions of a contact point (an array of `TANGENTS` vectors).
    type Tangents: Copy + Clone + Debug + AsRef<[Self::Vector]> + Send + Sync;

    /// `a − b`.
    fn sub(a: Self::Vector, b: Self::Vector) -> Self::Vector;
    /// `a · b`.
    fn dot(a: Self::Vector, b: Self::Vector) -> f64;
    /// Coefficients of the motion of point `c + r` along `e` in the body's DOFs (translation
    /// then rotation): `out = [e, r × e]`, `out.len() == DOFS`.
    fn dof_row(r: Self::Vector, e: Self::Vector, out: &mut [f64]);
    /// The tangent directions of the unit normal `n` (deterministic: the same `n` always gives
    /// the same tangents).
    fn tangents(n: Self::Vector) -> Self::Tangents;
    /// Small displacement of point `x` of a body moving by `dofs` (translation and rotation)
    /// about its reference point `c`: `u + ω × (x − c)`.
    fn small_displacement(c: Self::Vector, dofs: &[f64], x: Self::Vector) -> Self::Vector;
}

/// The plane: x right, y up, gravity along −y.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Two;

/// Space: z up, gravity along −z (COMPAS's and Rhino's convention).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Three;

impl Dim for Two {
    const N: usize = 2;
    const DOFS: usize = 3;
    const TANGENTS: usize = 1;
    type Vector = [f64; 2];
    type Tangents = [[f64; 2]; 1];

    #[inline]
    fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
        vector::sub2(a, b)
    }
    #[inline]
    fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
        vector::dot2(a, b)
    }
    #[inline]
    fn dof_row(r: [f64; 2], e: [f64; 2], out: &mut [f64]) {
        out[0] = e[0];
        out[1] = e[1];
        out[2] = r[0] * e[1] - r[1] * e[0];
    }
    #[inline]
    fn tangents(n: [f64; 2]) -> [[f64; 2]; 1] {
        [[-n[1], n[0]]]
    }
    #[inline]
    fn small_displacement(c: [f64; 2], d: &[f64], x: [f64; 2]) -> [f64; 2] {
        [d[0] - d[2] * (x[1] - c[1]), d[1] + d[2] * (x[0] - c[0])]
    }
}

impl Dim for Three {
    const N: usize = 3;
    const DOFS: usize = 6;
    const TANGENTS: usize = 2;
    type Vector = [f64; 3];
    type Tangents = [[f64; 3]; 2];

    #[inline]
    fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        vector::sub3(a, b)
    }
    #[inline]
    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        vector::dot3(a, b)
    }
    #[inline]
    fn dof_row(r: [f64; 3], e: [f64; 3], out: &mut [f64]) {
        // (ω × r)·e = ω·(r × e)
        let m = cross(r, e);
        out[..3].copy_from_slice(&e);
        out[3..6].copy_from_slice(&m);
    }
    /// `t₁` is the normalised projection of the coordinate axis least aligned with `n` (the
    /// first such axis on ties), `t₂ = n × t₁`: a right-handed frame `(t₁, t₂, n)`.
    fn tangents(n: [f64; 3]) -> [[f64; 3]; 2] {
        let mut axis = 0;
        for k in 1..3 {
            if n[k].abs() < n[axis].abs() {
                axis = k;
            }
        }
        let mut e = [0.0; 3];
        e[axis] = 1.0;
        let d = Self::dot(e, n);
        let t = [e[0] - d * n[0], e[1] - d * n[1], e[2] - d * n[2]];
        let l = Self::dot(t, t).sqrt();
        let t1 = [t[0] / l, t[1] / l, t[2] / l];
        [t1, cross(n, t1)]
    }
    #[inline]
    fn small_displacement(c: [f64; 3], d: &[f64], x: [f64; 3]) -> [f64; 3] {
        let w = cross([d[3], d[4], d[5]], Self::sub(x, c));
        [d[0] + w[0], d[1] + w[1], d[2] + w[2]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The DOF row along `e` reproduces the small displacement's component along `e`.
    fn check_row<D: Dim>(c: D::Vector, x: D::Vector, d: &[f64], e: D::Vector) {
        let mut row = vec![0.0; D::DOFS];
        D::dof_row(D::sub(x, c), e, &mut row);
        let lhs: f64 = row.iter().zip(d).map(|(a, b)| a * b).sum();
        let rhs = D::dot(D::small_displacement(c, d, x), e);
        assert!((lhs - rhs).abs() < 1e-14, "{lhs} vs {rhs}");
    }

    #[test]
    fn dof_rows_match_small_displacements_in_2d_and_3d() {
        check_row::<Two>([0.3, 0.7], [1.1, -0.4], &[0.01, -0.02, 0.003], [0.6, 0.8]);
        check_row::<Three>(
            [0.3, 0.7, -0.2],
            [1.1, -0.4, 0.9],
            &[0.01, -0.02, 0.005, 0.003, -0.004, 0.002],
            [0.0, 0.6, 0.8],
        );
        // By hand, 2D: θ = 1 about the origin moves (1, 0) by (0, 1).
        assert_eq!(
            Two::small_displacement([0.0, 0.0], &[0.0, 0.0, 1.0], [1.0, 0.0]),
            [0.0, 1.0]
        );
        // By hand, 3D: ω = ẑ moves x̂ to ŷ; ω = x̂ moves ŷ to ẑ.
        let z =
            Three::small_displacement([0.0; 3], &[0.0, 0.0, 0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
        assert_eq!(z, [0.0, 1.0, 0.0]);
        let x =
            Three::small_displacement([0.0; 3], &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(x, [0.0, 0.0, 1.0]);
    }

    #[test]
    fn tangents_are_orthonormal_and_right_handed() {
        assert_eq!(Two::tangents([0.0, 1.0]), [[-1.0, 0.0]]);
        for n in [
            [0.0, 0.0, 1.0],
            [0.6, 0.0, 0.8],
            [1.0, 0.0, 0.0],
            [0.48, 0.6, 0.64],
        ] {
            let [t1, t2] = Three::tangents(n);
            for (a, b, v) in [
                (t1, t1, 1.0),
                (t2, t2, 1.0),
                (t1, t2, 0.0),
                (t1, n, 0.0),
                (t2, n, 0.0),
            ] {
                assert!((Three::dot(a, b) - v).abs() < 1e-15);
            }
            let c = cross(t1, t2);
            assert!((Three::dot(c, n) - 1.0).abs() < 1e-15);
        }
        // Horizontal bed joint: the tangents are the x and y axes.
        assert_eq!(
            Three::tangents([0.0, 0.0, 1.0]),
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
        );
    }
}
