//! A sparse LU factorisation of a square matrix (left-looking, Gilbert–Peierls, with threshold
//! partial pivoting and a fill-reducing column order from AMD on the pattern of `MᵀM`), for
//! the solver layer's own look at a simplex basis ([`super::kept`]): the basic solution and its
//! duals of a program that a kept basis may already solve. Nothing here decides an answer: the
//! point and duals it gives are certified by the solver layer's checks like any backend's.
//!
//! Written here rather than taken from faer (whose sparse LU does this well): with faer 0.24
//! (`std`, `sparse-linalg`) the release binary grew from 24.3 MB to 27.4 MB, over the 25 MB the
//! README promises (`crates/voussoir-cli/tests/readme.rs`), for this one use (session 26, lead).
//! The column order is the `amd` crate's (already built for Clarabel).

// The loops run over several arrays indexed alike (rows, columns, pivots).
#![allow(clippy::needless_range_loop)]

/// A square sparse matrix by columns.
pub struct Csc {
    pub n: usize,
    pub col_start: Vec<usize>,
    pub row_index: Vec<usize>,
    pub value: Vec<f64>,
}

/// `L U = P M Q`: `L` unit lower triangular (its diagonal stored first in each column), `U`
/// upper triangular (its diagonal stored last in each column), both with rows in pivot order.
pub struct Lu {
    n: usize,
    lp: Vec<usize>,
    li: Vec<usize>,
    lx: Vec<f64>,
    up: Vec<usize>,
    ui: Vec<usize>,
    ux: Vec<f64>,
    /// Row `i` of `M` is pivot row `pinv[i]`.
    pinv: Vec<usize>,
    /// Pivot column `k` is column `q[k]` of `M`.
    q: Vec<usize>,
}

/// The fill-reducing column order: AMD on the pattern of `MᵀM` (two columns are neighbours
/// where they share a row). `None` where AMD refuses.
fn column_order(m: &Csc) -> Option<Vec<usize>> {
    let n = m.n;
    // Rows → columns.
    let mut row_count = vec![0usize; n + 1];
    for &i in &m.row_index {
        row_count[i + 1] += 1;
    }
    for i in 0..n {
        row_count[i + 1] += row_count[i];
    }
    let mut rc = vec![0usize; m.row_index.len()];
    let mut next = row_count.clone();
    for j in 0..n {
        for &i in &m.row_index[m.col_start[j]..m.col_start[j + 1]] {
            rc[next[i]] = j;
            next[i] += 1;
        }
    }
    let mut mark = vec![usize::MAX; n];
    let mut ap = Vec::with_capacity(n + 1);
    let mut ai = Vec::new();
    ap.push(0usize);
    for j in 0..n {
        for &i in &m.row_index[m.col_start[j]..m.col_start[j + 1]] {
            for &k in &rc[row_count[i]..row_count[i + 1]] {
                if k != j && mark[k] != j {
                    mark[k] = j;
                    ai.push(k);
                }
            }
        }
        ap.push(ai.len());
    }
    let control = amd::Control::default();
    let (p, _, _) = amd::order(n, &ap, &ai, &control).ok()?;
    (p.len() == n).then_some(p)
}

impl Lu {
    /// Factorise `m`; `None` where it is singular (no pivot above round-off in a column) or
    /// holds a number that is not finite.
    pub fn factor(m: &Csc) -> Option<Lu> {
        let n = m.n;
        if m.value.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let q = column_order(m)?;
        let largest = m.value.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let tiny = largest * 1e-14;
        let none = usize::MAX;
        let mut pinv = vec![none; n];
        let (mut lp, mut li, mut lx) = (Vec::with_capacity(n + 1), Vec::new(), Vec::new());
        let (mut up, mut ui, mut ux) = (Vec::with_capacity(n + 1), Vec::new(), Vec::new());
        let mut x = vec![0.0f64; n];
        // The reach of a column: `xi[top..n]` in topological order; `stack`/`pos` for the
        // depth-first search; `mark[i] == k` where row i was reached for column k.
        let mut xi = vec![0usize; n];
        let mut stack = vec![0usize; n];
        let mut pos = vec![0usize; n];
        let mut mark = vec![none; n];
        for k in 0..n {
            lp.push(li.len());
            up.push(ui.len());
            let col = q[k];
            // Reach of column `col` in the graph of L (rows already pivoted lead to their
            // column of L).
            let mut top = n;
            for &start in &m.row_index[m.col_start[col]..m.col_start[col + 1]] {
                if mark[start] == k {
                    continue;
                }
                let mut head = 0usize;
                stack[0] = start;
                loop {
                    let j = stack[head];
                    let c = pinv[j];
                    if mark[j] != k {
                        mark[j] = k;
                        // Skip the column's first entry: its own pivot row.
                        pos[head] = if c == none { 0 } else { lp[c] + 1 };
                    }
                    let mut done = true;
                    if c != none {
                        let end = lp[c + 1];
                        let mut p = pos[head];
                        while p < end {
                            let i = li[p];
                            p += 1;
                            if mark[i] != k {
                                pos[head] = p;
                                head += 1;
                                stack[head] = i;
                                done = false;
                                break;
                            }
                        }
                    }
                    if done {
                        top -= 1;
                        xi[top] = j;
                        if head == 0 {
                            break;
                        }
                        head -= 1;
                    }
                }
            }
            // x = L \ M(:, col) on the reach.
            for &i in &xi[top..n] {
                x[i] = 0.0;
            }
            for p in m.col_start[col]..m.col_start[col + 1] {
                x[m.row_index[p]] = m.value[p];
            }
            for &j in &xi[top..n] {
                let c = pinv[j];
                if c == none {
                    continue;
                }
                let xj = x[j];
                if xj != 0.0 {
                    for p in lp[c] + 1..lp[c + 1] {
                        x[li[p]] -= lx[p] * xj;
                    }
                }
            }
            // The pivot: the largest candidate (partial pivoting).
            let mut ipiv = none;
            let mut a = -1.0f64;
            for &i in &xi[top..n] {
                if pinv[i] == none {
                    if x[i].abs() > a {
                        a = x[i].abs();
                        ipiv = i;
                    }
                } else {
                    ui.push(pinv[i]);
                    ux.push(x[i]);
                }
            }
            if ipiv == none || a <= tiny || !a.is_finite() {
                return None;
            }
            let pivot = x[ipiv];
            ui.push(k);
            ux.push(pivot);
            pinv[ipiv] = k;
            li.push(ipiv);
            lx.push(1.0);
            for &i in &xi[top..n] {
                if pinv[i] == none {
                    li.push(i);
                    lx.push(x[i] / pivot);
                }
                x[i] = 0.0;
            }
        }
        lp.push(li.len());
        up.push(ui.len());
        for i in li.iter_mut() {
            *i = pinv[*i];
        }
        Some(Lu {
            n,
            lp,
            li,
            lx,
            up,
            ui,
            ux,
            pinv,
            q,
        })
    }

    /// `M z = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let n = self.n;
        let mut w = vec![0.0; n];
        for i in 0..n {
            w[self.pinv[i]] = b[i];
        }
        // L w = P b (unit diagonal first in each column).
        for k in 0..n {
            let v = w[k];
            if v != 0.0 {
                for p in self.lp[k] + 1..self.lp[k + 1] {
                    w[self.li[p]] -= self.lx[p] * v;
                }
            }
        }
        // U v = w (diagonal last in each column).
        for k in (0..n).rev() {
            let d = self.up[k + 1] - 1;
            w[k] /= self.ux[d];
            let v = w[k];
            if v != 0.0 {
                for p in self.up[k]..d {
                    w[self.ui[p]] -= self.ux[p] * v;
                }
            }
        }
        let mut z = vec![0.0; n];
        for k in 0..n {
            z[self.q[k]] = w[k];
        }
        z
    }

    /// `Mᵀ y = c`.
    pub fn solve_transpose(&self, c: &[f64]) -> Vec<f64> {
        let n = self.n;
        let mut w: Vec<f64> = (0..n).map(|k| c[self.q[k]]).collect();
        // Uᵀ v = Qᵀc.
        for k in 0..n {
            let d = self.up[k + 1] - 1;
            let mut s = w[k];
            for p in self.up[k]..d {
                s -= self.ux[p] * w[self.ui[p]];
            }
            w[k] = s / self.ux[d];
        }
        // Lᵀ u = v.
        for k in (0..n).rev() {
            let mut s = w[k];
            for p in self.lp[k] + 1..self.lp[k + 1] {
                s -= self.lx[p] * w[self.li[p]];
            }
            w[k] = s;
        }
        (0..n).map(|i| w[self.pinv[i]]).collect()
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
