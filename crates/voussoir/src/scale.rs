//! What "open", "sliding", "zero" and "certified" mean: relative to the problem's own scale.
//!
//! Every analysis, 2D and 3D, decides these questions here and nowhere else
//! (docs/tolerances.md). A number is compared with the scale of the quantity it belongs to,
//! never with its own size alone (round-off on a rigid motion is 1e-18 m, and 1e-18 is not
//! small next to another 1e-18) and never with a fixed absolute number (a model in millimetres
//! and one in kilometres are the same structure):
//!
//! | question | compared with | tolerance |
//! |---|---|---|
//! | is a point open, does it slide | the **motion scale**: the largest displacement of a contact point, taken on either side (block or support, [`motion_scale`]) | [`OPEN_TOLERANCE`] |
//! | do two works agree (the duality gap of a settlement) | `max(|primal|, |dual|, WORK_FLOOR · W·u)`, with `W` the total dead load and `u` the largest displacement the support motions give a contact point ([`settlement_work_scale`]) | `GAP_TOLERANCE` (1e-7) |
//! | do the static λ and the mechanism's λ agree (limit) | `max(|λ|, WORK_FLOOR · λ_unit)`, with `λ_unit` the ratio of the dead load's force to the live load's ([`lambda_unit`]) | `CERTIFICATE_TOLERANCE` (1e-6) |
//! | is a collapse mechanism admissible | its own motion scale, with the supports held still (a limit mechanism is a rate; support motions play no part in it) | `CERTIFICATE_TOLERANCE` |
//! | is a settlement mechanism admissible | the motion scale of the settlement | 1e-6 |
//! | is λ zero (it stands, but with no reserve) or negative (it cannot stand) | `λ_unit` | [`LAMBDA_ZERO`] |
//!
//! The floor [`WORK_FLOOR`] is where a relative comparison turns into an absolute one: a work
//! below a thousandth of the problem's work scale (a settlement that moves the structure almost
//! rigidly, a collapse multiplier of zero) is measured against that thousandth, so that its
//! round-off is not reported as a failed certificate.

use crate::discretize::KinematicMap;

/// Relative threshold below which an opening (or a slip) counts as closed: a fraction of the
/// motion scale ([`motion_scale`]).
pub const OPEN_TOLERANCE: f64 = 1e-7;

/// Works (and multipliers) smaller than this fraction of the problem's scale are compared on
/// that scale, not on their own size.
pub const WORK_FLOOR: f64 = 1e-3;

/// A negative collapse multiplier within this fraction of [`lambda_unit`] of zero is zero (a
/// small positive one is kept: μ = 1e-9 gives λ = 1e-9): the interior
/// point methods stop within about 1e-9 of the scaled program's optimum, on either side.
pub const LAMBDA_ZERO: f64 = 1e-8;

/// The motion scale of block motions `d` with the supports' prescribed motions scaled by
/// `support_scale`: the largest displacement, along a joint's normal or tangent, of a contact
/// point taken on one side of its joint (`Σ |a_c d_c| + |s g|` over the row of the kinematic
/// map). A rigid motion of the whole structure has openings of round-off size but this scale
/// of its translation; a mechanism has it of the size of its largest opening or more.
pub fn motion_scale(map: &KinematicMap, d: &[f64], support_scale: f64) -> f64 {
    let mut m = 0.0f64;
    for (rows, g) in [
        (&map.normal, &map.support_normal),
        (&map.tangent, &map.support_tangent),
    ] {
        for (k, gk) in g.iter().enumerate() {
            let mut v = (support_scale * gk).abs();
            if let Some(row) = rows.outer_view(k) {
                for (c, &a) in row.iter() {
                    v += (a * d[c]).abs();
                }
            }
            m = m.max(v);
        }
    }
    m
}

/// Block motions `d` with their round-off set to zero: a component whose largest effect on a
/// contact point (`|a_c d_c|` over column `c` of the kinematic map, normal and tangent rows)
/// is within [`OPEN_TOLERANCE`] of the [`motion_scale`] is zero, as an opening that small is
/// closed. An LP vertex of the same mechanism has exact zeros there or 1e-9 of round-off,
/// depending on the path the solver took (docs/performance.md, "Capacity step round-off and
/// the as-written face extremes (session 26)"); a structure deformed by a round-off rotation
/// has joints turned by it, whose map entries of 1e-11 steered the scaling of its programs
/// and so their least violation. Both dimensions (a column is a translation or a rotation).
pub fn without_round_off(map: &KinematicMap, d: &[f64], support_scale: f64) -> Vec<f64> {
    let tol = open_threshold(map, d, support_scale);
    let mut reach = vec![0.0f64; d.len()];
    for rows in [&map.normal, &map.tangent] {
        for k in 0..rows.rows() {
            if let Some(row) = rows.outer_view(k) {
                for (c, &a) in row.iter() {
                    if let Some(r) = reach.get_mut(c) {
                        *r = r.max(a.abs());
                    }
                }
            }
        }
    }
    d.iter()
        .zip(&reach)
        .map(|(&x, &r)| if (x * r).abs() <= tol { 0.0 } else { x })
        .collect()
}

/// The opening (or slip) below which a point counts as closed, for motions `d` with the
/// supports' motions scaled by `support_scale`: [`OPEN_TOLERANCE`] of the [`motion_scale`].
pub fn open_threshold(map: &KinematicMap, d: &[f64], support_scale: f64) -> f64 {
    OPEN_TOLERANCE * motion_scale(map, d, support_scale)
}

/// The sum of the magnitudes of the block forces of a load vector (the total weight, for the
/// dead loads); moments are left out (they are not forces).
pub fn force_scale(dofs_per_block: usize, loads: &[f64]) -> f64 {
    let translations = if dofs_per_block == 3 { 2 } else { 3 };
    loads
        .chunks(dofs_per_block)
        .map(|f| {
            f[..translations.min(f.len())]
                .iter()
                .map(|v| v * v)
                .sum::<f64>()
                .sqrt()
        })
        .sum()
}

/// The multiplier scale of a limit analysis: the dead loads' force over the live loads'
/// (1 when either is absent). λ·F_L weighs as much as F_D at `λ = lambda_unit`.
pub fn lambda_unit(dofs_per_block: usize, dead: &[f64], live: &[f64]) -> f64 {
    lambda_unit_of(
        force_scale(dofs_per_block, dead),
        force_scale(dofs_per_block, live),
    )
}

/// [`lambda_unit`] from the two force scales: `fd / fl`, 1 when either is absent.
pub fn lambda_unit_of(fd: f64, fl: f64) -> f64 {
    if fd > 0.0 && fl > 0.0 && (fd / fl).is_finite() {
        fd / fl
    } else {
        1.0
    }
}

/// The work scale of a settlement: the total dead load times the largest displacement that the
/// prescribed support motions give a contact point.
pub fn settlement_work_scale(map: &KinematicMap, dead: &[f64]) -> f64 {
    let u = map
        .support_normal
        .iter()
        .chain(&map.support_tangent)
        .fold(0.0f64, |m, g| m.max(g.abs()));
    force_scale(map.dofs_per_block, dead) * u
}

/// `|a − b|` relative to `max(|a|, |b|, WORK_FLOOR · scale)`; 0 when all three are zero,
/// infinite when a value is not finite.
pub fn relative_gap(a: f64, b: f64, scale: f64) -> f64 {
    if !(a.is_finite() && b.is_finite()) {
        return f64::INFINITY;
    }
    let den = a.abs().max(b.abs()).max(WORK_FLOOR * scale.abs());
    if den == 0.0 {
        return if a == b { 0.0 } else { f64::INFINITY };
    }
    let g = (a - b).abs() / den;
    if g.is_nan() {
        f64::INFINITY
    } else {
        g
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_gap_uses_the_floor_only_for_small_values() {
        // Two works of round-off size on a problem whose work scale is 1: no gap to speak of.
        assert!(relative_gap(1e-15, -1e-15, 1.0) < 1e-11);
        // Ordinary works: the relative difference.
        assert!((relative_gap(2.0, 2.0 * (1.0 + 1e-5), 1.0) - 1e-5 / (1.0 + 1e-5)).abs() < 1e-12);
        assert_eq!(relative_gap(0.0, 0.0, 0.0), 0.0);
        assert_eq!(relative_gap(f64::NAN, 0.0, 1.0), f64::INFINITY);
    }

    #[test]
    fn force_scale_leaves_moments_out() {
        // Two 2D blocks: (3, 4, moment 100) and (0, -5, 0): 5 + 5.
        assert_eq!(force_scale(3, &[3.0, 4.0, 100.0, 0.0, -5.0, 0.0]), 10.0);
        // One 3D block: (2, 3, 6) → 7; moments ignored.
        assert_eq!(force_scale(6, &[2.0, 3.0, 6.0, 9.0, 9.0, 9.0]), 7.0);
        assert_eq!(lambda_unit(3, &[0.0, -10.0, 0.0], &[2.0, 0.0, 0.0]), 5.0);
    }
}
