//! Nondimensional programs: every program is scaled before it reaches a backend, so that its
//! numbers are of order one whatever the model's units and size, and the backends' tolerances
//! (absolute on the numbers they are given) act as relative ones.
//!
//! Rigid-block statics is scale-free: a model ×10⁹ in size or ×10¹⁸ in weight has the same
//! mechanism and the same collapse multiplier (up to the powers of the scales that the
//! multiplier carries). The programs of [`crate::programs`] are written in the user's units —
//! rows are equilibrium of forces (kN) and moments (kN·m), columns are forces, the load
//! multiplier, motions (m) — and scaling them is the same as writing them with lengths divided
//! by a characteristic length and forces by a characteristic force:
//!
//! 1. **Rows and columns are equilibrated** (geometric means, ignoring round-off entries): a
//!    moment row is divided by the lever arms in it (a characteristic length), the
//!    λ column by the size of the live loads.
//! 2. **One characteristic magnitude of the unknowns** makes the largest right-hand side or
//!    finite bound one (the total dead load of a force program, the largest support motion of
//!    a motion program).
//! 3. **The objective** is divided by its largest coefficient.
//!
//! Every factor is a power of two, so the scaled program is the user's program exactly (no
//! rounding), and so are the unscaled results: `x = C x̃`, row duals `y = R ỹ / σ`, column
//! duals `z = z̃ / (σ C)`, objective `= õ / σ`. The three rows of a second-order cone share one
//! factor (a cone is invariant under a common positive scaling).
//!
//! A program whose factors all lie within `2^±10` (numbers between about 10⁻³ and 10³: a model
//! in metres and kilonewtons of ordinary size) is solved as written: the backends' own scaling
//! and tolerances are right for it, and its solution — where several are optimal, the vertex
//! the solver stops at — stays the one it always was.

use super::{Cone3, LinearProgram, LpSolution};

/// Row factors `R`, column factors `C` and the objective factor `σ` of a program, and one
/// factor per cone.
#[derive(Clone, Debug, PartialEq)]
pub struct Scaling {
    pub row: Vec<f64>,
    pub col: Vec<f64>,
    pub objective: f64,
    pub cone: Vec<f64>,
}

/// Programs whose factors all lie within `2^±BAND` (about 10³) are solved unscaled.
pub const BAND: i32 = 10;

/// Passes of geometric-mean equilibration (each a column and a row sweep).
const PASSES: usize = 8;

/// Entries below this fraction of the largest of their column (or row) are round-off — the
/// cosine 6·10⁻¹⁷ of a right angle — and do not steer the scaling.
const ROUND_OFF: f64 = 1e-12;

/// The power of two nearest to `x` (in the logarithm), within `2^±1000`; 1 for zero, infinite
/// or NaN values.
fn pow2(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let e = x.log2().round().clamp(-1000.0, 1000.0) as i32;
    2f64.powi(e)
}

/// `1 / √(min·max)` of the magnitudes of one row or column that are not round-off; 1 if it
/// has none.
fn geometric(a: &[f64]) -> f64 {
    let max = a.iter().fold(0.0f64, |m, &v| m.max(v));
    if !(max > 0.0 && max.is_finite()) {
        return 1.0;
    }
    let min = a
        .iter()
        .filter(|&&v| v >= ROUND_OFF * max)
        .fold(max, |m, &v| m.min(v));
    // √min·√max, not √(min·max): the product of two magnitudes of 1e-200 underflows.
    1.0 / (min.sqrt() * max.sqrt())
}

impl Scaling {
    /// The factors that make `lp` (and its cones) nondimensional: geometric-mean
    /// equilibration, columns first (so that a column out of scale with the rest — the live
    /// loads of a model whose live load is 10²⁰ times its weight — is scaled as a column, not
    /// shared with the rows it touches).
    pub fn of(lp: &LinearProgram, cones: &[Cone3]) -> Scaling {
        let (m, n) = (lp.num_rows(), lp.num_cols());
        let mut row = vec![1.0; m];
        let mut col = vec![1.0; n];
        let mut cone = vec![1.0; cones.len()];
        // Entries by row (the LP stores columns); a cone counts as one row.
        let mut by_row: Vec<Vec<(usize, f64)>> = vec![Vec::new(); m + cones.len()];
        for j in 0..n {
            for (i, v) in lp.column(j) {
                by_row[i].push((j, v.abs()));
            }
        }
        for (k, c) in cones.iter().enumerate() {
            for (entries, _) in c {
                by_row[m + k].extend(entries.iter().map(|&(j, v)| (j, v.abs())));
            }
        }
        let mut by_col: Vec<Vec<(usize, f64)>> = vec![Vec::new(); n];
        for (i, r) in by_row.iter().enumerate() {
            for &(j, a) in r {
                by_col[j].push((i, a));
            }
        }
        let factor = |i: usize, row: &[f64], cone: &[f64]| if i < m { row[i] } else { cone[i - m] };
        let mut buf = Vec::new();
        for _ in 0..PASSES {
            for j in 0..n {
                buf.clear();
                buf.extend(by_col[j].iter().map(|&(i, a)| a * factor(i, &row, &cone)));
                col[j] = geometric(&buf);
            }
            for (i, r) in by_row.iter().enumerate() {
                buf.clear();
                buf.extend(r.iter().map(|&(j, a)| a * col[j]));
                let g = geometric(&buf);
                if i < m {
                    row[i] = g;
                } else {
                    cone[i - m] = g;
                }
            }
        }
        row.iter_mut().for_each(|r| *r = pow2(*r));
        col.iter_mut().for_each(|c| *c = pow2(*c));
        cone.iter_mut().for_each(|c| *c = pow2(*c));
        // One magnitude of the unknowns: the largest right-hand side or bound becomes one.
        let mut big = 0.0f64;
        let mut see = |v: f64| {
            if v.is_finite() {
                big = big.max(v.abs());
            }
        };
        for i in 0..m {
            see(lp.row_lower[i] * row[i]);
            see(lp.row_upper[i] * row[i]);
        }
        for (k, c) in cones.iter().enumerate() {
            for (_, b) in c {
                see(b * cone[k]);
            }
        }
        for j in 0..n {
            see(lp.col_lower[j] / col[j]);
            see(lp.col_upper[j] / col[j]);
        }
        // x = C·u·x̃ and rows divided by u: the matrix is unchanged, the bounds divided by u.
        let unit = pow2(big);
        col.iter_mut().for_each(|c| *c *= unit);
        row.iter_mut().for_each(|r| *r /= unit);
        cone.iter_mut().for_each(|r| *r /= unit);
        let mut cmax = 0.0f64;
        for j in 0..n {
            cmax = cmax.max((lp.cost[j] * col[j]).abs());
        }
        Scaling {
            row,
            col,
            objective: if cmax > 0.0 { pow2(1.0 / cmax) } else { 1.0 },
            cone,
        }
    }

    /// The factors of `lp` if it needs them: `None` when every factor lies within
    /// `2^±`[`BAND`] — a program in ordinary units, which the backends' own scaling handles,
    /// is solved as written (so that its solution, among equal optima, stays the one it was).
    pub fn needed(lp: &LinearProgram, cones: &[Cone3]) -> Option<Scaling> {
        let s = Scaling::of(lp, cones);
        let (lo, hi) = (2f64.powi(-BAND), 2f64.powi(BAND));
        let inside = std::iter::once(&s.objective)
            .chain(&s.row)
            .chain(&s.col)
            .chain(&s.cone)
            .all(|&f| (lo..=hi).contains(&f));
        (!inside).then_some(s)
    }

    /// The scaled program: `R A C x̃` within `R·[lo, hi]`, `x̃` within `[lo, hi] / C`, cost
    /// `σ C c`.
    pub fn apply(&self, lp: &LinearProgram) -> LinearProgram {
        let mut s = lp.clone();
        for j in 0..lp.num_cols() {
            let c = self.col[j];
            s.cost[j] *= self.objective * c;
            s.col_lower[j] /= c;
            s.col_upper[j] /= c;
            for k in lp.col_start[j]..lp.col_start[j + 1] {
                s.value[k] *= self.row[lp.row_index[k]] * c;
            }
        }
        for i in 0..lp.num_rows() {
            s.row_lower[i] *= self.row[i];
            s.row_upper[i] *= self.row[i];
        }
        s
    }

    /// The scaled cones (each row `b − a·x` times the cone's factor, `x = C x̃`).
    pub fn apply_cones(&self, cones: &[Cone3]) -> Vec<Cone3> {
        cones
            .iter()
            .zip(&self.cone)
            .map(|(c, &f)| {
                c.clone().map(|(entries, b)| {
                    (
                        entries
                            .into_iter()
                            .map(|(j, v)| (j, v * f * self.col[j]))
                            .collect(),
                        b * f,
                    )
                })
            })
            .collect()
    }

    /// A solution of the scaled program, in the user's units.
    pub fn unscale(&self, mut s: LpSolution) -> LpSolution {
        s.objective /= self.objective;
        for (x, c) in s.x.iter_mut().zip(&self.col) {
            *x *= c;
        }
        for (z, c) in s.col_dual.iter_mut().zip(&self.col) {
            *z /= self.objective * c;
        }
        for (y, r) in s.row_dual.iter_mut().zip(&self.row) {
            *y *= r / self.objective;
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lp::{solve, Direction, LpStatus, SolverOptions};

    /// `max x + y  s.t. x + 2y ≤ 4, 3x + y ≤ 6` (optimum 2.8 at (1.6, 1.2), duals 0.4, 0.2), with
    /// its rows in units `a` and its columns in units `b`: the same answer in those units at
    /// every scale from 1e-150 to 1e150.
    #[test]
    fn a_program_in_any_units_has_the_same_solution() {
        for e in [-150, -40, -9, 0, 9, 40, 150] {
            let (a, b) = (10f64.powi(e), 10f64.powi(-e / 2));
            let mut lp = LinearProgram::new(Direction::Maximise);
            let r0 = lp.add_row(f64::NEG_INFINITY, 4.0 * a);
            let r1 = lp.add_row(f64::NEG_INFINITY, 6.0 * a);
            lp.add_column(b, 0.0, f64::INFINITY, [(r0, a), (r1, 3.0 * a)]);
            lp.add_column(b, 0.0, f64::INFINITY, [(r0, 2.0 * a), (r1, a)]);
            let s = solve(&lp, &SolverOptions::default()).unwrap();
            assert_eq!(
                s.status,
                LpStatus::Optimal,
                "{e}: {:?}",
                Scaling::of(&lp, &[])
            );
            let rel = |v: f64, r: f64| ((v - r) / r).abs();
            assert!(
                rel(s.x[0], 1.6) < 1e-12 && rel(s.x[1], 1.2) < 1e-12,
                "{e}: {:?}",
                s.x
            );
            assert!(rel(s.objective, 2.8 * b) < 1e-12, "{e}: {}", s.objective);
            assert!(rel(s.row_dual[0].abs(), 0.4 * b / a) < 1e-12, "{e}");
            assert!(rel(s.row_dual[1].abs(), 0.2 * b / a) < 1e-12, "{e}");
        }
    }

    #[test]
    fn factors_are_powers_of_two() {
        let mut lp = LinearProgram::new(Direction::Minimise);
        let r = lp.add_row(3e7, 3e7);
        lp.add_column(5e-3, 0.0, f64::INFINITY, [(r, 7e4)]);
        let s = Scaling::of(&lp, &[]);
        for f in s.row.iter().chain(&s.col).chain([&s.objective]) {
            assert_eq!(f.log2().fract(), 0.0, "{f}");
        }
        let scaled = s.apply(&lp);
        assert!(scaled.row_upper[0] <= 2f64.sqrt() && scaled.row_upper[0] >= 0.5f64.sqrt());
        assert!(scaled.value[0] <= 2f64.sqrt() && scaled.value[0] >= 0.5f64.sqrt());
    }
}
