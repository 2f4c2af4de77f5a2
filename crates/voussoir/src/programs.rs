//! The two LP forms every analysis is built from, both assembled from the [`KinematicMap`].
//!
//! * The **force program** (static): unknowns are contact forces `p_n ≥ 0` (free on bilateral
//!   joints), `p_t` free, and optionally the load multiplier λ; rows are block equilibrium
//!   `Nᵀ p_n + Tᵀ p_t + λ F_L = −F_D` (3 per block).
//! * The **motion program** (kinematic): unknowns are block DOFs `d`; rows are opening
//!   `N d ≥ −g_n` (equality on bilateral joints) and no sliding `T d = −g_t` (2 per point).
//!
//! Points with a gap carry no force and constrain no motion (they are left out).

use crate::discretize::KinematicMap;
use crate::lp::{Direction, LinearProgram};

const INF: f64 = f64::INFINITY;

/// The force LP and where its variables are.
pub struct ForceProgram {
    pub lp: LinearProgram,
    /// Column of λ, if the program has one.
    pub lambda: Option<usize>,
    /// Column of `p_n` and `p_t` per point (None for points with a gap).
    pub pn: Vec<Option<usize>>,
    pub pt: Vec<Option<usize>>,
}

impl ForceProgram {
    /// Assemble. `dead` and `live` are block load resultants (`live` = None: no λ column).
    /// `cost(k)` gives the objective coefficients `(c_n, c_t)` of point `k`; λ has cost 1.
    pub fn new(
        map: &KinematicMap,
        dead: &[f64],
        live: Option<&[f64]>,
        direction: Direction,
        cost: impl Fn(usize) -> (f64, f64),
    ) -> ForceProgram {
        let mut lp = LinearProgram::new(direction);
        for &f in dead {
            lp.add_row(-f, -f);
        }
        let lambda = live.map(|l| lp.add_column(1.0, -INF, INF, l.iter().copied().enumerate()));
        let mut pn = Vec::with_capacity(map.num_points());
        let mut pt = Vec::with_capacity(map.num_points());
        for k in 0..map.num_points() {
            if map.gap[k] > 0.0 {
                pn.push(None);
                pt.push(None);
                continue;
            }
            let (cn, ct) = cost(k);
            let lo = if map.bilateral[k] { -INF } else { 0.0 };
            pn.push(Some(lp.add_column(
                cn,
                lo,
                INF,
                KinematicMap::row(&map.normal, k),
            )));
            pt.push(Some(lp.add_column(
                ct,
                -INF,
                INF,
                KinematicMap::row(&map.tangent, k),
            )));
        }
        ForceProgram { lp, lambda, pn, pt }
    }

    /// Point forces `(p_n, p_t)` from a solution vector (0 where a point has no column).
    pub fn forces(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let get = |c: &Option<usize>| c.map_or(0.0, |j| x[j]);
        (
            self.pn.iter().map(get).collect(),
            self.pt.iter().map(get).collect(),
        )
    }
}

/// The motion LP: maximise `work·d` subject to the joint rows.
pub struct MotionProgram {
    pub lp: LinearProgram,
    /// Row of the opening and sliding constraint per point (None for points with a gap).
    pub normal_row: Vec<Option<usize>>,
    pub tangent_row: Vec<Option<usize>>,
}

impl MotionProgram {
    pub fn new(map: &KinematicMap, work: &[f64]) -> MotionProgram {
        let mut lp = LinearProgram::new(Direction::Maximise);
        let mut normal_row = Vec::with_capacity(map.num_points());
        let mut tangent_row = Vec::with_capacity(map.num_points());
        // Column entries, gathered from the CSR rows of N and T.
        let mut cols: Vec<Vec<(usize, f64)>> = vec![Vec::new(); map.num_dofs];
        for k in 0..map.num_points() {
            if map.gap[k] > 0.0 {
                normal_row.push(None);
                tangent_row.push(None);
                continue;
            }
            let gn = -map.support_normal[k];
            let r = lp.add_row(gn, if map.bilateral[k] { gn } else { INF });
            for (c, v) in KinematicMap::row(&map.normal, k) {
                cols[c].push((r, v));
            }
            normal_row.push(Some(r));
            let gt = -map.support_tangent[k];
            let r = lp.add_row(gt, gt);
            for (c, v) in KinematicMap::row(&map.tangent, k) {
                cols[c].push((r, v));
            }
            tangent_row.push(Some(r));
        }
        for (c, entries) in cols.into_iter().enumerate() {
            lp.add_column(work[c], -INF, INF, entries);
        }
        MotionProgram {
            lp,
            normal_row,
            tangent_row,
        }
    }
}
