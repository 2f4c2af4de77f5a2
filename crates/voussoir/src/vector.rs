//! Vector arithmetic on plain `[f64; 2]` and `[f64; 3]` points — the one place it is written.
//!
//! Written by hand on purpose: models, results and files store points as plain arrays (that is
//! what serde writes), and the handful of one-line operations below would otherwise mean a
//! conversion to and from nalgebra's types at every call.

/// A point or vector in the plane.
pub type V2 = [f64; 2];
/// A point or vector in space.
pub type V3 = [f64; 3];

/// `a − b` in the plane.
#[inline]
pub fn sub2(a: V2, b: V2) -> V2 {
    [a[0] - b[0], a[1] - b[1]]
}
/// `a · b` in the plane.
#[inline]
pub fn dot2(a: V2, b: V2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
/// The plane's scalar cross product (perp-dot) `a₀ b₁ − a₁ b₀`.
#[inline]
pub fn perp_dot(a: V2, b: V2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
/// Euclidean length in the plane.
#[inline]
pub fn norm2(a: V2) -> f64 {
    a[0].hypot(a[1])
}

/// `a − b` in space.
#[inline]
pub fn sub3(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
/// `a + b` in space.
#[inline]
pub fn add3(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
/// `s a` in space.
#[inline]
pub fn scale3(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
/// `a · b` in space.
#[inline]
pub fn dot3(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
/// `a × b` in space.
#[inline]
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
/// Euclidean length in space.
#[inline]
pub fn norm3(a: V3) -> f64 {
    dot3(a, a).sqrt()
}
/// Whether every component is finite.
#[inline]
pub fn finite3(a: V3) -> bool {
    a.iter().all(|x| x.is_finite())
}
/// Dot product of two slices of equal length.
#[inline]
pub fn dot_n(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Newell's normal of the polygon `at(0), …, at(n−1)`: twice its vector area,
/// Σ (vᵢ − v₀) × (vᵢ₊₁ − v₀), exact for planar non-convex polygons and taken about the first
/// vertex so that far-off coordinates do not cancel. Zero for a degenerate polygon.
pub fn newell(n: usize, at: impl Fn(usize) -> V3) -> V3 {
    if n == 0 {
        return [0.0; 3];
    }
    let o = at(0);
    let mut s = [0.0; 3];
    for i in 1..n.saturating_sub(1) {
        s = add3(s, cross(sub3(at(i), o), sub3(at(i + 1), o)));
    }
    s
}

/// The mean of points.
pub fn mean3(n: usize, at: impl Fn(usize) -> V3) -> V3 {
    let mut c = [0.0; 3];
    for i in 0..n {
        c = add3(c, at(i));
    }
    if n == 0 {
        c
    } else {
        scale3(c, 1.0 / n as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn newell_of_a_unit_square_far_from_the_origin_is_twice_its_area() {
        let o = 1.0e6;
        let sq = [
            [o, o, 5.0],
            [o + 1.0, o, 5.0],
            [o + 1.0, o + 1.0, 5.0],
            [o, o + 1.0, 5.0],
        ];
        let n = newell(4, |i| sq[i]);
        assert!((n[2] - 2.0).abs() < 1e-12 && n[0].abs() < 1e-12 && n[1].abs() < 1e-12);
        assert_eq!(mean3(4, |i| sq[i]), [o + 0.5, o + 0.5, 5.0]);
        assert_eq!(cross([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]);
        assert_eq!(perp_dot([1.0, 0.0], [0.0, 1.0]), 1.0);
    }
}
