//! The inverse-settlement LP: the support motions whose settlement mechanism opens the observed
//! cracks. Built in this one place from the settlement force program ([`ForceProgram`]), so that
//! the inverse problem is, row for row, the optimality system of the forward one.
//!
//! ## The forward problem and its optimality conditions
//!
//! With support motions `m = m₀ + Σ_q a_q m_q` (base motions plus unknown amplitudes `a_q` of
//! unit motions `m_q`), the settlement force LP (the paper's dual (69)–(71), with joint laws) is
//!
//! ```text
//!   (F)  min c(a)ᵀx   s.t.  L ≤ A x ≤ U,  l ≤ x ≤ u         c(a) = c₀ + Σ_q a_q c_q
//! ```
//! where `x` stacks the contact forces `p_n, p_t`, the first rows of `A` are block equilibrium
//! `Nᵀp_n + Tᵀp_t = −F_D` and the others the joint laws (Coulomb rows `±p_t − μ p_n ≤ c`).
//! The cost of a force column is the opening (`g_n`) or sliding (`g_t`) the support motions
//! cause at its point, so `c` is linear in `a`. With row multipliers `y` (`d = −y` on the
//! equilibrium rows is the mechanism, the other multipliers are sliding rates), reduced costs
//! `z = c(a) − Aᵀy` and the geometric opening `u_n,k = g_n,k(a) + N_k d`, the optimality
//! conditions of (F) (equivalently: the settlement primal (62)–(66) and dual both optimal) are
//!
//! ```text
//!   primal:  L ≤ A x ≤ U,  l ≤ x ≤ u
//!   dual:    z_j = 0 on free columns (p_t; p_n of fixed supports),  z_j ≥ 0 on p_n ≥ 0,
//!            y_i free on equality rows, y_i ≤ 0 on `≤` rows
//!   complementarity:  x_j z_j = 0,  y_i (A_i x − U_i) = 0.
//! ```
//! Everything is linear in `(x, y, a)` except complementarity. The observed crack pattern fixes
//! it at every observed point:
//!
//! ```text
//!   observed open, width w (tolerance τ):  p_n,k = 0,       u_n,k − w = e⁺ − e⁻,  e± ≥ 0
//!   observed closed:                       u_n,k = 0        (p_n,k ≥ 0 free to carry force)
//!   unobserved:                            nothing beyond z ≥ 0, p_n ≥ 0
//! ```
//! except on frictional joints, where an open point may also be a point sliding with dilatancy
//! (`u_n = μ|u_t| > 0` while carrying force): there `p_n = 0` is not imposed and its
//! complementarity is left to the check below ([`decided`]).
//! (On a closed frictional point `u_n = z + μ(s⁺ + s⁻) = 0` with `z, s ≥ 0` also stops sliding,
//! so the Coulomb rows' complementarity holds there; on an open point `p_n = 0` makes both
//! Coulomb rows active when the cohesion is zero.) The inverse LP is then
//!
//! ```text
//!   (I)  min Σ_o (e⁺_o + e⁻_o) / τ_o   over  x, y, a, e   subject to all the rows above,
//!        a_q within its bounds
//! ```
//! the least absolute misfit, in tolerances. Any solution is a KKT point of (F) with the support
//! motions `m(a)`: the mechanism `d` is an optimal settlement mechanism for those motions, and
//! its openings are the predicted crack widths. Complementarity left open (unobserved points,
//! Coulomb rows with cohesion) is checked on the solution; where it fails, [`Activity`] fixes
//! the active set the solution suggests and (I) is solved once more.
//!
//! The identifiability LPs use the same rows with `|e_o| ≤ τ_o` and minimise or maximise one
//! `a_q` ([`MisfitMode::WithinTolerance`]). Two variants of (I) serve as further candidates of
//! [`crate::analysis::identify`]: the balanced tie-break ([`MisfitMode::Balanced`]: with
//! `Σ_o |e_o|/τ_o` kept at its least, minimise `max_o |e_o|/τ_o`), and (I) with every observed
//! crack opening by a fraction of its width ([`MisfitMode::MinimiseOpening`]: `(I)` can forbid
//! force at a crack but not ask it to open, so its optimum may close one).

// Loops run over point and column numbers that index several parallel vectors at once.
#![allow(clippy::needless_range_loop)]

use crate::discretize::KinematicMap;
use crate::lp::{Direction, LinearProgram};
use crate::programs::ForceProgram;

const INF: f64 = f64::INFINITY;

/// A column under assembly: cost, lower and upper bound, `(row, value)` entries.
type Col = (f64, f64, f64, Vec<(usize, f64)>);

/// What the observations say about one collocation point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PointRole {
    /// Observed closed: no opening.
    Closed,
    /// Observed open with width `width` (m), measured within `tolerance` (m).
    Open { width: f64, tolerance: f64 },
    /// Not observed: nothing assumed.
    Unobserved,
}

/// Whether point `k` is taken as open (`p_n = 0`), in contact (`z = 0`: zero reduced cost, which
/// on a Heyman joint is zero opening) or undecided. An observed-open point of a frictional joint
/// is undecided: it may be open, or slide with dilatancy (`u_n = μ|u_t| > 0`) while carrying
/// force.
pub fn decided(
    map: &KinematicMap,
    roles: &[PointRole],
    activity: &Activity,
    k: usize,
) -> Option<bool> {
    let later = || activity.point_open.get(k).copied().flatten();
    match roles[k] {
        PointRole::Open { .. } if map.laws[map.points[k].joint].friction.is_some() => later(),
        PointRole::Open { .. } => Some(true),
        PointRole::Closed => Some(false),
        PointRole::Unobserved => later(),
    }
}

/// Active-set decisions taken after a first solve, where the observations left complementarity
/// open. `None` everywhere: nothing fixed.
#[derive(Clone, Debug, Default)]
pub struct Activity {
    /// Per point: `Some(true)` open (no force), `Some(false)` in contact (zero reduced cost).
    pub point_open: Vec<Option<bool>>,
    /// Per row of the force program: `Some(true)` the row is active (equality at its bound),
    /// `Some(false)` inactive (multiplier zero).
    pub row_active: Vec<Option<bool>>,
}

/// How the misfit enters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MisfitMode {
    /// Minimise `Σ |e_o| / τ_o`.
    Minimise,
    /// Minimise `Σ |e_o| / τ_o` with every observed-open point opening by at least
    /// `fraction · w_o` (`e⁻_o ≤ (1 − fraction) w_o`): the least misfit among motions that
    /// really open every observed crack.
    MinimiseOpening { fraction: f64 },
    /// Among motions with `Σ |e_o| / τ_o ≤ total`, minimise the largest `|e_o| / τ_o`: the
    /// tie-break between equally good least-absolute fits (the most balanced one).
    Balanced { total: f64 },
    /// `|e_o| ≤ τ_o`, objective `sense · a_q` (identifiability range of unknown `q`).
    WithinTolerance { unknown: usize, sense: Direction },
}

/// The inverse LP and where its variables are.
pub struct IdentifyProgram {
    pub lp: LinearProgram,
    /// Columns of the force program's variables (same order as in `fp.lp`).
    pub x0: usize,
    /// First column of the force program's row multipliers `y` (one per row of `fp.lp`).
    pub y0: usize,
    /// Column of each unknown amplitude `a_q`.
    pub a: Vec<usize>,
    /// Columns `(e⁺, e⁻)` of each open point, by point.
    pub misfit: Vec<Option<(usize, usize)>>,
    pub num_dofs: usize,
}

impl IdentifyProgram {
    /// Assemble (I).
    ///
    /// * `map`, `fp`: kinematic map and settlement force program with the base motions `m₀`
    ///   (their costs are `c₀`).
    /// * `unit`: per unknown, the opening and sliding `(g_n, g_t)` its unit motion causes at each
    ///   point (the `support_normal`/`support_tangent` of a map with that motion).
    /// * `bounds`: per unknown, `(lower, upper)` (±∞ when free).
    /// * `roles`: per point.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        map: &KinematicMap,
        fp: &ForceProgram,
        unit: &[(Vec<f64>, Vec<f64>)],
        bounds: &[(f64, f64)],
        roles: &[PointRole],
        activity: &Activity,
        mode: MisfitMode,
    ) -> IdentifyProgram {
        let f = &fp.lp;
        let (nr, nc) = (f.num_rows(), f.num_cols());
        let npts = map.num_points();
        let direction = match mode {
            MisfitMode::WithinTolerance { sense, .. } => sense,
            _ => Direction::Minimise,
        };
        let mut lp = LinearProgram::new(direction);
        // Columns under assembly: (cost, lo, hi, entries).
        let mut cols: Vec<Col> = Vec::new();
        // Primal rows of (F), with active-set fixes.
        for i in 0..nr {
            let (lo, hi) = (f.row_lower[i], f.row_upper[i]);
            match activity.row_active.get(i).copied().flatten() {
                Some(true) if hi.is_finite() => lp.add_row(hi, hi),
                Some(true) if lo.is_finite() => lp.add_row(lo, lo),
                _ => lp.add_row(lo, hi),
            };
        }
        // Which point each column of (F) belongs to, and whether it is a p_n column.
        let mut col_point: Vec<Option<(usize, bool)>> = vec![None; nc];
        let nt = map.tangents_per_point;
        for k in 0..npts {
            if let Some(j) = fp.pn[k] {
                col_point[j] = Some((k, true));
            }
        }
        for (r, c) in fp.pt.iter().enumerate() {
            if let Some(j) = c {
                col_point[*j] = Some((r / nt.max(1), false));
            }
        }
        let open_at = |k: usize| -> Option<bool> { decided(map, roles, activity, k) };
        // x columns: (F)'s forces; an open point carries no normal force.
        for j in 0..nc {
            let (mut lo, mut hi) = (f.col_lower[j], f.col_upper[j]);
            if let Some((k, true)) = col_point[j] {
                if !map.bilateral[k] && open_at(k) == Some(true) {
                    lo = 0.0;
                    hi = 0.0;
                }
            }
            cols.push((0.0, lo, hi, f.column(j).collect()));
        }
        // Dual rows z_j = c₀_j + Σ a_q c_qj − Σ_i A_ij y_i: 0 on free columns, ≥ 0 on p_n ≥ 0.
        let zrow0 = lp.num_rows();
        for j in 0..nc {
            let c0 = f.cost[j];
            let closed = matches!(col_point[j], Some((k, true)) if open_at(k) == Some(false));
            if f.col_lower[j] == -INF || closed {
                lp.add_row(-c0, -c0);
            } else {
                lp.add_row(-c0, INF);
            }
        }
        // Opening rows u_n,k = g₀_k + Σ a_q g_qk + N_k d (d = −y on the equilibrium rows).
        let mut urow: Vec<Option<usize>> = vec![None; npts];
        let mut misfit_rows: Vec<(usize, usize, f64)> = Vec::new(); // (point, row, 1/τ)
        for k in 0..npts {
            if fp.pn[k].is_none() || map.bilateral[k] {
                continue;
            }
            let g0 = map.support_normal[k];
            match roles[k] {
                PointRole::Closed => urow[k] = Some(lp.add_row(-g0, -g0)),
                PointRole::Open { width, tolerance } => {
                    let r = lp.add_row(width - g0, width - g0);
                    urow[k] = Some(r);
                    misfit_rows.push((k, r, 1.0 / tolerance));
                }
                PointRole::Unobserved => {}
            }
        }
        // y columns.
        let y0 = cols.len();
        let mut ycols: Vec<Vec<(usize, f64)>> = vec![Vec::new(); nr];
        for j in 0..nc {
            for (i, v) in f.column(j) {
                ycols[i].push((zrow0 + j, -v));
            }
        }
        for k in 0..npts {
            if let Some(r) = urow[k] {
                // u_n = … + N_k d = … − N_k y_dof.
                for (dof, v) in KinematicMap::row(&map.normal, k) {
                    ycols[dof].push((r, -v));
                }
            }
        }
        for (i, entries) in ycols.into_iter().enumerate() {
            let (lo, hi) = (f.row_lower[i], f.row_upper[i]);
            let (mut ylo, mut yhi) = if lo == hi || (lo.is_finite() && hi.is_finite()) {
                (-INF, INF)
            } else if hi.is_finite() {
                (-INF, 0.0)
            } else if lo.is_finite() {
                (0.0, INF)
            } else {
                (0.0, 0.0)
            };
            if activity.row_active.get(i).copied().flatten() == Some(false) {
                ylo = 0.0;
                yhi = 0.0;
            }
            cols.push((0.0, ylo, yhi, entries));
        }
        // Unknown amplitudes: their unit costs in the dual rows, unit openings in the u rows.
        let mut a = Vec::with_capacity(unit.len());
        for (q, (gn, gt)) in unit.iter().enumerate() {
            let mut entries = Vec::new();
            for k in 0..npts {
                if let Some(j) = fp.pn[k] {
                    entries.push((zrow0 + j, gn[k]));
                }
                if let Some(r) = urow[k] {
                    entries.push((r, gn[k]));
                }
            }
            // Shear columns, one per point and tangent (`g_t` has the same numbering).
            for (r, c) in fp.pt.iter().enumerate() {
                if let Some(j) = c {
                    entries.push((zrow0 + j, gt[r]));
                }
            }
            let entries = merged(entries);
            let cost = match mode {
                MisfitMode::WithinTolerance { unknown, .. } if unknown == q => 1.0,
                _ => 0.0,
            };
            a.push(cols.len());
            cols.push((cost, bounds[q].0, bounds[q].1, entries));
        }
        // Misfit columns: u − w = e⁺ − e⁻ (`inv_tau` is 1/τ).
        let mut misfit = vec![None; npts];
        // Balanced mode: row `Σ (e⁺ + e⁻)/τ ≤ total`, and per point `(e⁺ + e⁻)/τ − r ≤ 0`.
        let balanced = match mode {
            MisfitMode::Balanced { total } => {
                let sum_row = lp.add_row(-INF, total);
                Some((sum_row, Vec::new()))
            }
            _ => None,
        };
        let mut balanced = balanced;
        for (k, r, inv_tau) in misfit_rows {
            let width = match roles[k] {
                PointRole::Open { width, .. } => width,
                _ => 0.0,
            };
            let (cost, hi_plus, hi_minus) = match mode {
                MisfitMode::Minimise => (inv_tau, INF, INF),
                MisfitMode::MinimiseOpening { fraction } => {
                    (inv_tau, INF, ((1.0 - fraction) * width).max(0.0))
                }
                MisfitMode::Balanced { .. } => (0.0, INF, INF),
                MisfitMode::WithinTolerance { .. } => (0.0, 1.0 / inv_tau, 1.0 / inv_tau),
            };
            let mut ep_entries = vec![(r, -1.0)];
            let mut em_entries = vec![(r, 1.0)];
            if let Some((sum_row, rows)) = balanced.as_mut() {
                let max_row = lp.add_row(-INF, 0.0);
                rows.push(max_row);
                for e in [&mut ep_entries, &mut em_entries] {
                    e.push((*sum_row, inv_tau));
                    e.push((max_row, inv_tau));
                }
            }
            let ep = cols.len();
            cols.push((cost, 0.0, hi_plus, ep_entries));
            let em = cols.len();
            cols.push((cost, 0.0, hi_minus, em_entries));
            misfit[k] = Some((ep, em));
        }
        // The largest misfit `r` (balanced mode).
        if let Some((_, rows)) = balanced {
            cols.push((1.0, 0.0, INF, rows.into_iter().map(|i| (i, -1.0)).collect()));
        }
        for (cost, lo, hi, entries) in cols {
            lp.add_column(cost, lo, hi, entries);
        }
        IdentifyProgram {
            lp,
            x0: 0,
            y0,
            a,
            misfit,
            num_dofs: map.num_dofs,
        }
    }

    /// Block motions `d = −y` on the equilibrium rows.
    pub fn motion(&self, x: &[f64]) -> Vec<f64> {
        x[self.y0..self.y0 + self.num_dofs]
            .iter()
            .map(|v| -v)
            .collect()
    }

    /// Unknown amplitudes.
    pub fn amplitudes(&self, x: &[f64]) -> Vec<f64> {
        self.a.iter().map(|&j| x[j]).collect()
    }
}

/// The relaxed problem behind "the closest motion" when no motion reproduces the pattern: the
/// optimality of the mechanism is dropped and only its admissibility kept,
///
/// ```text
///   min Σ_o |u_n,o − w_o| / τ_o   over  d, a
///   s.t.  u_n,k ≥ 0 (contact),  u_n,k = 0 and u_t,k = 0 (fixed supports),
///         u_t,k = 0 (no sliding)  or  u_n,k ≥ μ |u_t,k| (Coulomb, associative),
/// ```
/// with every observed point in the sum, closed ones at `w = 0`. The forward settlement
/// analysis of the motion found then says which pattern that motion really opens.
pub struct ClosestProgram {
    pub lp: LinearProgram,
    pub a: Vec<usize>,
    pub num_dofs: usize,
}

impl ClosestProgram {
    /// `targets[k]`: `Some((w, τ))` for observed points (closed: `w = 0`).
    pub fn new(
        map: &KinematicMap,
        unit: &[(Vec<f64>, Vec<f64>)],
        bounds: &[(f64, f64)],
        targets: &[Option<(f64, f64)>],
    ) -> ClosestProgram {
        let npts = map.num_points();
        let mut lp = LinearProgram::new(Direction::Minimise);
        let mut dcols: Vec<Vec<(usize, f64)>> = vec![Vec::new(); map.num_dofs];
        let mut acols: Vec<Vec<(usize, f64)>> = vec![Vec::new(); unit.len()];
        let mut extra: Vec<(f64, usize)> = Vec::new(); // misfit columns: (1/τ, row)
                                                       // Adds a row `cn·u_n,k + ct·u_t,r ∈ [lo, hi]` (`r`: a sliding row of point k), bounds
                                                       // without the base motion.
        let mut add =
            |lp: &mut LinearProgram, k: usize, cn: f64, r: usize, ct: f64, lo: f64, hi: f64| {
                let g0 = cn * map.support_normal[k] + ct * map.support_tangent[r];
                let row = lp.add_row(lo - g0, hi - g0);
                for (m, i, c) in [(&map.normal, k, cn), (&map.tangent, r, ct)] {
                    if c != 0.0 {
                        for (dof, v) in KinematicMap::row(m, i) {
                            dcols[dof].push((row, c * v));
                        }
                    }
                }
                for (q, (gn, gt)) in unit.iter().enumerate() {
                    let v = cn * gn[k] + ct * gt[r];
                    if v != 0.0 {
                        acols[q].push((row, v));
                    }
                }
                row
            };
        let nt = map.tangents_per_point;
        for k in 0..npts {
            if map.gap[k] > 0.0 {
                continue;
            }
            let law = &map.laws[map.points[k].joint];
            let r0 = k * nt;
            if map.bilateral[k] {
                add(&mut lp, k, 1.0, r0, 0.0, 0.0, 0.0);
                for r in r0..r0 + nt {
                    add(&mut lp, k, 0.0, r, 1.0, 0.0, 0.0);
                }
            } else {
                add(&mut lp, k, 1.0, r0, 0.0, 0.0, INF);
                for r in r0..r0 + nt {
                    match law.friction {
                        // Associative Coulomb, per tangent (in 3D an inscribed box of the cone).
                        Some(mu) => {
                            add(&mut lp, k, 1.0, r, mu, 0.0, INF);
                            add(&mut lp, k, 1.0, r, -mu, 0.0, INF);
                        }
                        None => {
                            add(&mut lp, k, 0.0, r, 1.0, 0.0, 0.0);
                        }
                    }
                }
            }
            if let Some((w, tau)) = targets[k] {
                let r = add(&mut lp, k, 1.0, r0, 0.0, w, w);
                extra.push((1.0 / tau, r));
            }
        }
        for entries in dcols {
            lp.add_column(0.0, -INF, INF, merged(entries));
        }
        let mut a = Vec::new();
        for (q, entries) in acols.into_iter().enumerate() {
            a.push(lp.add_column(0.0, bounds[q].0, bounds[q].1, merged(entries)));
        }
        for (w, r) in extra {
            lp.add_column(w, 0.0, INF, [(r, -1.0)]);
            lp.add_column(w, 0.0, INF, [(r, 1.0)]);
        }
        ClosestProgram {
            lp,
            a,
            num_dofs: map.num_dofs,
        }
    }

    pub fn amplitudes(&self, x: &[f64]) -> Vec<f64> {
        self.a.iter().map(|&j| x[j]).collect()
    }
}

/// Sum the entries of a column that fall on the same row (a Coulomb row combines the opening
/// and sliding rows, which share DOFs): HiGHS refuses repeated entries.
fn merged(mut e: Vec<(usize, f64)>) -> Vec<(usize, f64)> {
    e.sort_by_key(|&(r, _)| r);
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(e.len());
    for (r, v) in e {
        match out.last_mut() {
            Some((lr, lv)) if *lr == r => *lv += v,
            _ => out.push((r, v)),
        }
    }
    out
}
