//! Free columns that the others already span, left out before HiGHS's interior point.
//!
//! In a 3D force program without friction every contact point has two free shear forces, and
//! the shears of one joint all act on the same twelve (six at a support) equilibrium rows:
//! whatever their number, they span three directions only (the tangential resultant and the
//! torsion about the joint's normal). On the 48 × 48 dome that makes 34,617 free columns on
//! 13,393 rows after presolve, and HiGHS's interior point (IPX) spends most of its run pivoting
//! the free columns one by one into the starting basis of its preconditioner, most of them
//! only to find them dependent (docs/performance.md, "Dome 48 × 48 (session 20)").
//!
//! [`reduce`] keeps, in each group of free columns of zero cost with the same rows, a set that
//! spans the group (modified Gram–Schmidt in column order, a column left out where its part
//! outside the kept ones is below [`DEPENDENT`] of its norm), and [`Reduced::expand`] puts the
//! left-out columns back at zero. Exact: a left-out column `a_j = Σ α_k a_k` of the kept ones,
//! with `c_j = 0 = Σ α_k c_k`, adds nothing to the feasible values of `Ax`, and its dual row
//! `a_jᵀy = 0` is implied by the kept ones' (the dual feasible set is unchanged). A vertex of
//! the reduced program with the left-out columns at zero (nonbasic, free) is a vertex of the
//! program as written, with the same optimal value and duals.

use super::{Basis, BasisStatus, LinearProgram, LpSolution};
use std::collections::HashMap;

/// A free column whose part outside the span of the kept columns of its group is below this
/// fraction of its norm is left out (the shears of one joint are dependent to round-off, about
/// 1e-16 of their size).
pub const DEPENDENT: f64 = 1e-10;

/// The program without the left-out columns, and the way back.
pub struct Reduced {
    pub lp: LinearProgram,
    /// Column of the program as written of each column of the reduced one.
    kept: Vec<usize>,
}

/// The reduced program of `lp`, or `None` when no free column is left out.
pub fn reduce(lp: &LinearProgram) -> Option<Reduced> {
    let n = lp.num_cols();
    // Groups of free columns of zero cost by their row pattern, in column order.
    let mut groups: HashMap<Vec<usize>, Vec<usize>> = HashMap::new();
    for j in 0..n {
        if lp.cost[j] == 0.0
            && lp.col_lower[j] == f64::NEG_INFINITY
            && lp.col_upper[j] == f64::INFINITY
            && lp.col_start[j + 1] > lp.col_start[j]
        {
            let rows: Vec<usize> = lp.column(j).map(|(i, _)| i).collect();
            groups.entry(rows).or_default().push(j);
        }
    }
    let mut drop = vec![false; n];
    let mut dropped = 0usize;
    for (rows, cols) in &groups {
        if cols.len() <= 1 {
            continue;
        }
        let m = rows.len();
        // Orthonormal basis of the kept columns' span (dense, m ≤ 12 for a joint).
        let mut basis: Vec<Vec<f64>> = Vec::new();
        for &j in cols {
            let mut v: Vec<f64> = vec![0.0; m];
            // The column's values in the order of its rows (the pattern is the key).
            for (slot, (_, a)) in v.iter_mut().zip(lp.column(j)) {
                *slot = a;
            }
            let norm0 = v.iter().map(|a| a * a).sum::<f64>().sqrt();
            if basis.len() == m || norm0 == 0.0 {
                drop[j] = basis.len() == m;
                dropped += usize::from(drop[j]);
                continue;
            }
            // Twice, for the orthogonality that round-off loses in one pass.
            for _ in 0..2 {
                for q in &basis {
                    let d: f64 = q.iter().zip(&v).map(|(a, b)| a * b).sum();
                    v.iter_mut().zip(q).for_each(|(a, b)| *a -= d * b);
                }
            }
            let norm = v.iter().map(|a| a * a).sum::<f64>().sqrt();
            if norm <= DEPENDENT * norm0 {
                drop[j] = true;
                dropped += 1;
            } else {
                v.iter_mut().for_each(|a| *a /= norm);
                basis.push(v);
            }
        }
    }
    if dropped == 0 {
        return None;
    }
    let kept: Vec<usize> = (0..n).filter(|&j| !drop[j]).collect();
    let mut out = LinearProgram {
        maximise: lp.maximise,
        cost: Vec::with_capacity(kept.len()),
        col_lower: Vec::with_capacity(kept.len()),
        col_upper: Vec::with_capacity(kept.len()),
        row_lower: lp.row_lower.clone(),
        row_upper: lp.row_upper.clone(),
        col_start: Vec::with_capacity(kept.len() + 1),
        row_index: Vec::new(),
        value: Vec::new(),
    };
    out.col_start.push(0);
    for &j in &kept {
        out.cost.push(lp.cost[j]);
        out.col_lower.push(lp.col_lower[j]);
        out.col_upper.push(lp.col_upper[j]);
        for (i, a) in lp.column(j) {
            out.row_index.push(i);
            out.value.push(a);
        }
        out.col_start.push(out.row_index.len());
    }
    Some(Reduced { lp: out, kept })
}

impl Reduced {
    /// Columns left out.
    pub fn left_out(&self, original: &LinearProgram) -> usize {
        original.num_cols() - self.kept.len()
    }

    /// The solution of the program as written (`original`) from one of the reduced program:
    /// the left-out columns at zero, their reduced costs `c_j − a_jᵀy` from the row duals.
    pub fn expand(&self, original: &LinearProgram, mut s: LpSolution) -> LpSolution {
        let n = original.num_cols();
        if s.x.len() == self.kept.len() {
            let mut x = vec![0.0; n];
            for (k, &j) in self.kept.iter().enumerate() {
                x[j] = s.x[k];
            }
            s.x = x;
        }
        if s.col_dual.len() == self.kept.len() && s.row_dual.len() == original.num_rows() {
            let mut z: Vec<f64> = (0..n)
                .map(|j| {
                    original.cost[j]
                        - original
                            .column(j)
                            .map(|(i, a)| a * s.row_dual[i])
                            .sum::<f64>()
                })
                .collect();
            for (k, &j) in self.kept.iter().enumerate() {
                z[j] = s.col_dual[k];
            }
            s.col_dual = z;
        }
        s
    }

    /// A basis of the reduced program as one of the program as written: the left-out columns
    /// nonbasic at zero (free).
    pub fn expand_basis(&self, original: &LinearProgram, b: Basis) -> Basis {
        let mut cols = vec![BasisStatus::Zero; original.num_cols()];
        for (k, &j) in self.kept.iter().enumerate() {
            cols[j] = b.cols[k];
        }
        Basis { cols, rows: b.rows }
    }
}

/// Solve `lp` by `solve` with its spanned free columns left out ([`reduce`]), and put the answer
/// and its basis back on the columns of `lp`; `None` where nothing is left out (solve `lp`
/// itself). `who` names the solve in the `VOUSSOIR_TRACE` line. The one place both backends
/// that start from a crash basis (HiGHS's interior point, Clarabel's crossover) go through.
pub fn solve_reduced(
    lp: &LinearProgram,
    who: &str,
    solve: impl FnOnce(&LinearProgram) -> crate::error::Result<super::Solved>,
) -> Option<crate::error::Result<super::Solved>> {
    let r = reduce(lp)?;
    if std::env::var_os("VOUSSOIR_TRACE").is_some() {
        eprintln!(
            "trace: {who}: {} of {} columns left out (free, spanned by others)",
            r.left_out(lp),
            lp.num_cols()
        );
    }
    Some(solve(&r.lp).map(|solved| super::Solved {
        basis: solved.basis.map(|b| r.expand_basis(lp, b)),
        solution: r.expand(lp, solved.solution),
    }))
}
