//! A sparse LU factorisation of a square matrix, for the solver layer's own look at a simplex
//! basis ([`super::kept`]): the basic solution and its duals of a program that a kept basis may
//! already solve. The factorisation is faer's sparse LU (`faer::sparse::linalg`, its own
//! fill-reducing order and partial pivoting); this module only adapts a basis to it and refuses
//! what it cannot use (a singular basis gives non-finite solutions: refused). Nothing here decides
//! an answer: the point and duals it gives are certified by the solver layer's checks like any
//! backend's.

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};

/// A square sparse matrix by columns.
pub struct Csc {
    pub n: usize,
    pub col_start: Vec<usize>,
    pub row_index: Vec<usize>,
    pub value: Vec<f64>,
}

/// `M`'s LU factors (faer's).
pub struct Lu {
    n: usize,
    lu: faer::sparse::linalg::solvers::Lu<usize, f64>,
}

impl Lu {
    /// The factors of `m`, or `None` where faer refuses it or it is singular (a solve of a
    /// vector of ones is not finite).
    pub fn factor(m: &Csc) -> Option<Lu> {
        let n = m.n;
        let mut t = Vec::with_capacity(m.value.len());
        for j in 0..n {
            for p in m.col_start[j]..m.col_start[j + 1] {
                t.push(Triplet::new(m.row_index[p], j, m.value[p]));
            }
        }
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &t).ok()?;
        let lu = Lu {
            n,
            lu: a.sp_lu().ok()?,
        };
        let probe = lu.solve(&vec![1.0; n]);
        probe.iter().all(|v| v.is_finite()).then_some(lu)
    }

    /// `M z = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let mut z = b.to_vec();
        self.lu
            .solve_in_place(faer::MatMut::from_column_major_slice_mut(&mut z, self.n, 1));
        z
    }

    /// `Mᵀ y = c`.
    pub fn solve_transpose(&self, c: &[f64]) -> Vec<f64> {
        let mut y = c.to_vec();
        self.lu
            .solve_transpose_in_place(faer::MatMut::from_column_major_slice_mut(&mut y, self.n, 1));
        y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn csc(n: usize, dense: &[&[f64]]) -> Csc {
        let (mut cs, mut ri, mut v) = (vec![0], vec![], vec![]);
        for j in 0..n {
            for (i, row) in dense.iter().enumerate() {
                if row[j] != 0.0 {
                    ri.push(i);
                    v.push(row[j]);
                }
            }
            cs.push(ri.len());
        }
        Csc {
            n,
            col_start: cs,
            row_index: ri,
            value: v,
        }
    }

    fn mul(a: &[&[f64]], x: &[f64]) -> Vec<f64> {
        a.iter()
            .map(|r| r.iter().zip(x).map(|(a, b)| a * b).sum())
            .collect()
    }

    #[test]
    fn solves_and_transposed_solves_of_a_permuted_unsymmetric_matrix() {
        // No natural diagonal: a pivot order is needed.
        let a: [&[f64]; 4] = [
            &[0.0, 2.0, 0.0, 1.0],
            &[3.0, 0.0, 0.0, 0.0],
            &[1.0, 0.0, 4.0, 0.0],
            &[0.0, 1.0, 1.0, 5.0],
        ];
        let lu = Lu::factor(&csc(4, &a)).expect("nonsingular");
        let x = [1.0, -2.0, 0.5, 3.0];
        let b = mul(&a, &x);
        let z = lu.solve(&b);
        for (u, v) in z.iter().zip(&x) {
            assert!((u - v).abs() < 1e-12, "{z:?}");
        }
        let at: Vec<Vec<f64>> = (0..4).map(|j| (0..4).map(|i| a[i][j]).collect()).collect();
        let atr: Vec<&[f64]> = at.iter().map(|r| r.as_slice()).collect();
        let c = mul(&atr, &x);
        let y = lu.solve_transpose(&c);
        for (u, v) in y.iter().zip(&x) {
            assert!((u - v).abs() < 1e-12, "{y:?}");
        }
    }

    #[test]
    fn a_singular_matrix_is_refused() {
        let a: [&[f64]; 3] = [&[1.0, 2.0, 0.0], &[2.0, 4.0, 0.0], &[0.0, 0.0, 1.0]];
        assert!(Lu::factor(&csc(3, &a)).is_none());
    }
}
