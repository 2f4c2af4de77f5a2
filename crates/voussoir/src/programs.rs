//! The two LP forms every analysis is built from, both assembled from the [`KinematicMap`].
//!
//! * The **force program** (static): unknowns are contact forces `p_n ≥ 0` (free on bilateral
//!   joints), `p_t` free, and optionally the load multiplier λ; rows are block equilibrium
//!   `Nᵀ p_n + Tᵀ p_t + λ F_L = −F_D` (3 per block), plus the joint-law rows: Coulomb friction
//!   `|p_t| ≤ μ p_n + c` and the crushing domain `|M| ≤ N (t/2 − N/(2 f_c w))` (inscribed
//!   polygon) where materials ask for them.
//! * The **motion program** (kinematic): its LP dual, formed mechanically
//!   ([`crate::duality`]): unknowns are block DOFs `d` (plus sliding and crushing rates when
//!   joint laws are present); rows are opening `N d + g_n ≥ 0` (equality on bilateral joints)
//!   and no sliding `T d + g_t = 0` (or the associative sliding rule with friction).
//!
//! Points with a gap carry no force and constrain no motion.

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

/// Columns under assembly: cost, bounds, entries.
struct Columns {
    cols: Vec<(f64, f64, f64, Vec<(usize, f64)>)>,
}

impl Columns {
    fn add(&mut self, cost: f64, lo: f64, hi: f64, entries: Vec<(usize, f64)>) -> usize {
        self.cols.push((cost, lo, hi, entries));
        self.cols.len() - 1
    }
    fn entry(&mut self, col: usize, row: usize, v: f64) {
        self.cols[col].3.push((row, v));
    }
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
        let mut c = Columns { cols: Vec::new() };
        let lambda = live.map(|l| c.add(1.0, -INF, INF, l.iter().copied().enumerate().collect()));
        let mut pn = Vec::with_capacity(map.num_points());
        let mut pt = Vec::with_capacity(map.num_points());
        for k in 0..map.num_points() {
            let law = &map.laws[map.points[k].joint];
            // A point with a gap carries nothing, except on a joint of finite strength, where its
            // column only places the stress block's resultant (see `crushing_rows`).
            let gapped = map.gap[k] > 0.0;
            if gapped && law.strength.is_none() {
                pn.push(None);
                pt.push(None);
                continue;
            }
            let (cn, ct) = cost(k);
            let lo = if map.bilateral[k] { -INF } else { 0.0 };
            pn.push(Some(c.add(cn, lo, INF, KinematicMap::row(&map.normal, k))));
            pt.push(if gapped {
                None
            } else {
                Some(c.add(ct, -INF, INF, KinematicMap::row(&map.tangent, k)))
            });
        }
        friction_rows(map, &mut lp, &mut c, &pn, &pt);
        crushing_rows(map, &mut lp, &mut c, &pn);
        for (cost, lo, hi, entries) in c.cols {
            lp.add_column(cost, lo, hi, entries);
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

/// Coulomb: `|p_t| ≤ μ p_n + c` at every point of a joint with finite friction.
fn friction_rows(
    map: &KinematicMap,
    lp: &mut LinearProgram,
    c: &mut Columns,
    pn: &[Option<usize>],
    pt: &[Option<usize>],
) {
    for k in 0..map.num_points() {
        let law = &map.laws[map.points[k].joint];
        let (Some(mu), Some(cn), Some(ct)) = (law.friction, pn[k], pt[k]) else {
            continue;
        };
        if map.bilateral[k] {
            continue;
        }
        // Associative: |p_t| ≤ μ p_n + c. With fixed capacities: |p_t| ≤ limit (no dilatancy).
        let (bound, slope) = match &map.shear_limits {
            Some(lim) => (lim[k].max(0.0), 0.0),
            None => (law.cohesion, mu),
        };
        for sign in [1.0, -1.0] {
            let r = lp.add_row(-INF, bound);
            c.entry(ct, r, sign);
            c.entry(cn, r, -slope);
        }
    }
}

/// Finite compressive strength: `|M| ≤ N (t/2 − N / (2 f_c w))` per joint (rectangular stress
/// block), inscribed by `map.facets` chords so that strength is never overestimated.
/// `N = Σ p_n`, `M = Σ s_k p_n,k` with `s_k` the point's position along the joint.
fn crushing_rows(
    map: &KinematicMap,
    lp: &mut LinearProgram,
    c: &mut Columns,
    pn: &[Option<usize>],
) {
    for (j, law) in map.laws.iter().enumerate() {
        let Some(nmax) = law.max_normal_force() else {
            continue;
        };
        let range = map.joint_start[j]..map.joint_start[j + 1];
        if range.clone().any(|k| map.bilateral[k]) || nmax <= 0.0 {
            continue;
        }
        let cols: Vec<(usize, f64)> = range
            .clone()
            .filter_map(|k| pn[k].map(|col| (col, map.along[k])))
            .collect();
        let t = law.depth;
        let fw = nmax / t;
        let m_of = |n: f64| n * t / 2.0 - n * n / (2.0 * fw);
        // `facets == 0`: the chords are left to a conic solver (crate::conic).
        let kf = map.facets;
        for i in 0..kf {
            let (n0, n1) = (
                nmax * i as f64 / kf as f64,
                nmax * (i + 1) as f64 / kf as f64,
            );
            let a = (m_of(n1) - m_of(n0)) / (n1 - n0);
            let b = (m_of(n0) - a * n0).max(0.0);
            for sign in [1.0, -1.0] {
                // sign·M − a·N ≤ b
                let r = lp.add_row(-INF, b);
                for &(col, s) in &cols {
                    c.entry(col, r, sign * s - a);
                }
            }
        }
        // An opened joint bears on its closed side: the resultant stays in that half.
        for k in range {
            if map.gap[k] > 0.0 {
                let r = lp.add_row(-INF, 0.0);
                let side = map.along[k].signum();
                for &(col, s) in &cols {
                    c.entry(col, r, side * s);
                }
            }
        }
    }
}

/// The motion LP: `max work·d` subject to the joint rows — built as the LP dual of the force
/// program whose costs are the support motions `g`, so that both forms always describe the
/// same problem, joint laws included.
pub struct MotionProgram {
    pub lp: LinearProgram,
    /// Sign turning the motion LP's optimum into the force LP's.
    pub objective_sign: f64,
    pub num_dofs: usize,
}

impl MotionProgram {
    pub fn new(map: &KinematicMap, work: &[f64]) -> crate::error::Result<MotionProgram> {
        let fp = ForceProgram::new(map, work, None, Direction::Minimise, |k| {
            (map.support_normal[k], map.support_tangent[k])
        });
        let d = crate::duality::dual(&fp.lp)?;
        Ok(MotionProgram {
            lp: d.lp,
            objective_sign: d.objective_sign,
            num_dofs: map.num_dofs,
        })
    }

    /// Block DOFs from a solution of the motion LP. The force LP's equilibrium rows read
    /// `Nᵀp_n + Tᵀp_t = −F`; their dual variables are `−d`.
    pub fn motion(&self, x: &[f64]) -> Vec<f64> {
        x[..self.num_dofs].iter().map(|v| -v).collect()
    }
}
