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
//!
//! ## Where each program of the paper is built
//!
//! | program | paper | builder |
//! |---|---|---|
//! | settlement, force form (dual): `min g·p`, `F_D + Nᵀp_n + Tᵀp_t = 0`, `p_n ≥ 0` | (69)–(71) | [`settlement_force_program`] |
//! | settlement, motion form (primal): `max F_D·d`, `N d + g_n ≥ 0`, `T d + g_t = 0` | (62)–(66) | [`settlement_motion_program`] |
//! | limit analysis, static: `max λ`, `F_D + λF_L + Nᵀp_n + Tᵀp_t = 0`, `p_n ≥ 0` | Remark 3 | [`limit_force_program`] (and [`limit_force_program_fixed_topology`] for warm-started sequences) |
//! | limit analysis, kinematic: `F_L·d = 1`, `λ = −F_D·d` | Remark 3 | the row duals of the static program ([`crate::analysis::limit`]) |
//! | exact crushing domain `|M| ≤ N(t/2 − N/(2 f_c w))`; exact 3D friction cone `‖p_t‖ ≤ μ p_n + c` | (finite strength; 3D friction) | [`ForceProgram::cones`] from [`limit_force_program_conic`], [`limit_force_program_exact`], [`settlement_force_program_conic`] |
//! | a dead-load ray (no λ in equilibrium) | — | [`dead_load_ray_program`] |
//! | equilibrium under dead loads alone (does it stand; geometric safety factor) | safe theorem | [`equilibrium_program`] |
//! | least / largest reaction component over admissible states (thrust range) | safe theorem | [`reaction_extreme_program`] |
//! | the optimal force fields with open points unloaded, Coulomb at μ (canonical forces) | — | [`physical_force_program`] |
//!
//! Every analysis, the benchmark and the sweeps call these builders; nothing else assembles a
//! program of the paper.

use crate::discretize::KinematicMap;
use crate::lp::{Cone3, Direction, LinearProgram};

const INF: f64 = f64::INFINITY;

/// The force LP and where its variables are.
pub struct ForceProgram {
    pub lp: LinearProgram,
    /// Second-order cones to add to `lp` (the exact crushing domain); empty for an LP.
    pub cones: Vec<Cone3>,
    /// Column of λ, if the program has one.
    pub lambda: Option<usize>,
    /// Column of `p_n` and `p_t` per point (None for points with a gap).
    pub pn: Vec<Option<usize>>,
    pub pt: Vec<Option<usize>>,
    /// The loads' force scale (the total dead load) the crushing polygons are placed by.
    pub force_scale: f64,
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
    /// `normal_cost(k)` is the objective coefficient of `p_n` at point `k`, `tangent_cost(r)`
    /// that of the shear on sliding row `r` (`r = k·tangents_per_point + j`); λ has cost 1.
    pub fn new(
        map: &KinematicMap,
        dead: &[f64],
        live: Option<&[f64]>,
        direction: Direction,
        normal_cost: impl Fn(usize) -> f64,
        tangent_cost: impl Fn(usize) -> f64,
    ) -> ForceProgram {
        Self::build(map, dead, live, direction, normal_cost, tangent_cost, false)
    }

    /// [`ForceProgram::new`]; with `closable_gaps` a point with a gap `Δ` (an existing crack)
    /// is a unilateral contact that must first close: a normal force column (no shear: an open
    /// crack slides freely) whose cost gains `Δ`, so that the motion program reads
    /// `N d + g_n + Δ ≥ 0` (the paper's (42) and (58)). Without it such a point carries
    /// nothing, as an infinitesimal mechanism cannot close a finite gap (limit analysis).
    fn build(
        map: &KinematicMap,
        dead: &[f64],
        live: Option<&[f64]>,
        direction: Direction,
        normal_cost: impl Fn(usize) -> f64,
        tangent_cost: impl Fn(usize) -> f64,
        closable_gaps: bool,
    ) -> ForceProgram {
        let nt = map.tangents_per_point;
        let mut lp = LinearProgram::new(direction);
        for &f in dead {
            lp.add_row(-f, -f);
        }
        let mut c = Columns { cols: Vec::new() };
        let lambda = live.map(|l| c.add(1.0, -INF, INF, l.iter().copied().enumerate().collect()));
        let mut pn = Vec::with_capacity(map.num_points());
        let mut pt = Vec::with_capacity(map.num_tangent_rows());
        for k in 0..map.num_points() {
            let law = &map.laws[map.points[k].joint];
            // A point with a gap carries nothing, except on a joint of finite strength, where its
            // column only places the stress block's resultant (see `crushing_rows`).
            let gapped = map.gap[k] > 0.0;
            if gapped && closable_gaps && law.strength.is_none() && !map.bilateral[k] {
                let row_n = KinematicMap::row(&map.normal, k);
                pn.push(Some(c.add(normal_cost(k) + map.gap[k], 0.0, INF, row_n)));
                pt.extend((0..nt).map(|_| None));
                continue;
            }
            if gapped && law.strength.is_none() {
                pn.push(None);
                pt.extend((0..nt).map(|_| None));
                continue;
            }
            let lo = if map.bilateral[k] { -INF } else { 0.0 };
            let row_n = KinematicMap::row(&map.normal, k);
            pn.push(Some(c.add(normal_cost(k), lo, INF, row_n)));
            for r in k * nt..(k + 1) * nt {
                pt.push(if gapped {
                    None
                } else {
                    let row_t = KinematicMap::row(&map.tangent, r);
                    Some(c.add(tangent_cost(r), -INF, INF, row_t))
                });
            }
        }
        friction_rows(map, &mut lp, &mut c, &pn, &pt);
        // The force scale: the total dead load (the live loads' if there is none).
        let scale = match force_scale(map, dead) {
            s if s > 0.0 => s,
            _ => live.map_or(0.0, |l| force_scale(map, l)),
        };
        crushing_rows(map, &mut lp, &mut c, &pn, scale);
        for (cost, lo, hi, entries) in c.cols {
            lp.add_column(cost, lo, hi, entries);
        }
        ForceProgram {
            lp,
            cones: Vec::new(),
            lambda,
            pn,
            pt,
            force_scale: scale,
        }
    }

    /// Solve with the backend of `opts` (the cones, if any, with a backend that takes them).
    pub fn solve(
        &self,
        opts: &crate::lp::SolverOptions,
    ) -> crate::error::Result<crate::lp::LpSolution> {
        if self.cones.is_empty() {
            crate::lp::solve(&self.lp, opts)
        } else {
            crate::lp::solve_with_cones(&self.lp, &self.cones, opts)
        }
    }

    /// Point forces `(p_n, p_t)` from a solution vector (0 where a point has no column); `p_t`
    /// has one value per point and tangent.
    pub fn forces(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let get = |c: &Option<usize>| c.map_or(0.0, |j| x[j]);
        (
            self.pn.iter().map(get).collect(),
            self.pt.iter().map(get).collect(),
        )
    }
}

/// Coulomb: `|p_t| ≤ μ p_n + c` at every point of a joint with finite friction. In 2D (one
/// tangent) the two rows `±p_t ≤ μ p_n + c`; in 3D the pyramid of `map.friction_facets` facets
/// *inscribed* in the cone (conservative): `(cos φ_i, sin φ_i)·p_t ≤ cos(π/K)(μ p_n + c)`,
/// `φ_i = (2i + 1)π/K`, whose vertices lie on the cone.
fn friction_rows(
    map: &KinematicMap,
    lp: &mut LinearProgram,
    c: &mut Columns,
    pn: &[Option<usize>],
    pt: &[Option<usize>],
) {
    let nt = map.tangents_per_point;
    if nt > 1 && map.friction_facets == 0 {
        return; // the exact cone instead ([`friction_cones`])
    }
    let directions: Vec<(Vec<f64>, f64)> = if nt == 1 {
        vec![(vec![1.0], 1.0), (vec![-1.0], 1.0)]
    } else {
        let k = map.friction_facets.max(3);
        let shrink = (std::f64::consts::PI / k as f64).cos();
        (0..k)
            .map(|i| {
                let phi = (2 * i + 1) as f64 * std::f64::consts::PI / k as f64;
                (vec![phi.cos(), phi.sin()], shrink)
            })
            .collect()
    };
    for k in 0..map.num_points() {
        let law = &map.laws[map.points[k].joint];
        let (Some(mu), Some(cn)) = (law.friction, pn[k]) else {
            continue;
        };
        let cts: Option<Vec<usize>> = (k * nt..(k + 1) * nt).map(|r| pt[r]).collect();
        let Some(cts) = cts else {
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
        for (dir, shrink) in &directions {
            let r = lp.add_row(-INF, shrink * bound);
            for (&ct, &e) in cts.iter().zip(dir) {
                c.entry(ct, r, e);
            }
            c.entry(cn, r, -shrink * slope);
        }
    }
}

/// The joints with a crushing domain: finite strength, not bilateral; with their law, largest
/// normal force and range of points.
fn crushing_joints(
    map: &KinematicMap,
) -> impl Iterator<Item = (&crate::discretize::JointLaw, f64, std::ops::Range<usize>)> {
    map.laws.iter().enumerate().filter_map(|(j, law)| {
        let nmax = law.max_normal_force()?;
        let range = map.joint_start[j]..map.joint_start[j + 1];
        (nmax > 0.0 && !range.clone().any(|k| map.bilateral[k])).then_some((law, nmax, range))
    })
}

/// The force scale of a load vector ([`crate::scale::force_scale`]).
fn force_scale(map: &KinematicMap, loads: &[f64]) -> f64 {
    crate::scale::force_scale(map.dofs_per_block, loads)
}

/// Where the vertices of a joint's crushing polygon lie, for `k` facets: at 0 and at forces
/// rising geometrically from `low` to `top = min(f_c w t, reach × scale)` — where the joint
/// forces are (about the loads' force `scale`), not spread evenly to the crushing force, so
/// that as f_c → ∞ the polygon tends to the rigid `|M| ≤ N t/2` at any facet count. Between
/// two vertices in the ratio `r` the chord cuts the eccentricity `t/2 − N/(2 f_c w)` by at
/// most `(√r − 1)²/√r` of the crushing term itself; below `low = max(top / k², scale / 64)` by
/// at most `low / (2 f_c w)`. When `top` is below f_c w t (returned `true`), a cap `N ≤ top`
/// closes the polygon. When `top` is above the peak of the parabola `N = f_c w t / 2` (the
/// largest moment a joint carries), the peak is the top of the geometric part and a quarter of
/// the facets cover `[f_c w t / 2, top]` evenly.
pub fn crushing_vertices(nmax: f64, scale: f64, reach: f64, k: usize) -> (Vec<f64>, bool) {
    let k = k.max(1);
    let capped = scale > 0.0 && reach * scale < nmax;
    let end = if capped { reach * scale } else { nmax };
    let (top, k_hi) = if nmax / 2.0 < end && k > 1 {
        (nmax / 2.0, (k / 4).max(1).min(k - 1))
    } else {
        (end, 0)
    };
    let k_lo = k - k_hi;
    let low = (top / (k_lo * k_lo) as f64)
        .max(scale / 64.0)
        .min(top / k_lo as f64);
    let mut v = vec![0.0];
    if k_lo == 1 {
        v.push(top);
    } else {
        let ratio = (top / low).powf(1.0 / (k_lo - 1) as f64);
        v.extend((0..k_lo).map(|i| {
            if i + 1 == k_lo {
                top
            } else {
                low * ratio.powi(i as i32)
            }
        }));
    }
    v.extend((1..=k_hi).map(|i| top + (end - top) * i as f64 / k_hi as f64));
    (v, capped)
}

/// Finite compressive strength: `|M| ≤ N (t/2 − N / (2 f_c w))` per joint (rectangular stress
/// block), inscribed by `map.facets` chords so that strength is never overestimated.
/// `N = Σ p_n`, `M = Σ s_k p_n,k` with `s_k` the point's position along the joint. The chords'
/// ends lie on the parabola at [`crushing_vertices`] — placed where the forces are, so that as
/// f_c → ∞ the polygon tends to the rigid `|M| ≤ N t/2` at any facet count — and where they stop
/// below f_c·w·t a cap `N ≤ top` closes the polygon (still inscribed).
fn crushing_rows(
    map: &KinematicMap,
    lp: &mut LinearProgram,
    c: &mut Columns,
    pn: &[Option<usize>],
    scale: f64,
) {
    for (law, nmax, range) in crushing_joints(map) {
        let cols: Vec<(usize, f64)> = range
            .clone()
            .filter_map(|k| pn[k].map(|col| (col, map.along[k])))
            .collect();
        let t = law.depth;
        let fw = nmax / t;
        // n·(t/2 − n/(2 f_c w)), not n·t/2 − n²/(2 f_c w): at f_c = 1e-200 kPa n² underflowed
        // to 0 and the chords fell on the rigid |M| ≤ N t/2 (λ of the rigid arch; session 24).
        let m_of = |n: f64| n * (t / 2.0 - n / (2.0 * fw));
        // `facets == 0`: the chords are left to a conic solver (crate::conic).
        if map.facets > 0 {
            let (v, capped) = crushing_vertices(nmax, scale, map.crushing_reach, map.facets);
            for w in v.windows(2) {
                let (n0, n1) = (w[0], w[1]);
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
            if capped {
                let r = lp.add_row(-INF, v[v.len() - 1]);
                for &(col, _) in &cols {
                    c.entry(col, r, 1.0);
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

/// Whether a joint of finite strength carries, in the solution `x` of `fp`, a normal force at
/// the cap of its crushing polygon (so the polygon should reach further: see
/// [`KinematicMap::crushing_reach`]).
pub fn crushing_cap_reached(map: &KinematicMap, fp: &ForceProgram, x: &[f64]) -> bool {
    if map.facets == 0 || fp.lp.num_cols() != x.len() {
        return false;
    }
    let scale = fp.force_scale;
    crushing_joints(map).any(|(_, nmax, range)| {
        let (v, capped) = crushing_vertices(nmax, scale, map.crushing_reach, map.facets);
        let n: f64 = range.filter_map(|k| fp.pn[k].map(|c| x[c])).sum();
        capped && n >= v[v.len() - 1] * (1.0 - 1e-6)
    })
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
    /// The LP dual of [`settlement_force_program`] with dead loads `work`.
    pub fn new(map: &KinematicMap, work: &[f64]) -> crate::error::Result<MotionProgram> {
        let fp = settlement_force_program(map, work);
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

/// The paper's (69)–(71), the force form of a settlement analysis: contact forces in
/// equilibrium with the dead loads `dead` that minimise the work `g_nᵀp_n + g_tᵀp_t` of the
/// forces on the moving supports.
///
/// Points with a gap (existing cracks) take part with their gap (see [`ForceProgram::build`]):
/// the settlement is then a finite motion, and the result no longer scales with its magnitude.
pub fn settlement_force_program(map: &KinematicMap, dead: &[f64]) -> ForceProgram {
    ForceProgram::build(
        map,
        dead,
        None,
        Direction::Minimise,
        |k| map.support_normal[k],
        |r| map.support_tangent[r],
        true,
    )
}

/// The paper's (62)–(66), the motion form of a settlement analysis: the mechanism that
/// maximises the work of the dead loads over admissible motions, formed as the LP dual of
/// [`settlement_force_program`].
pub fn settlement_motion_program(
    map: &KinematicMap,
    dead: &[f64],
) -> crate::error::Result<MotionProgram> {
    MotionProgram::new(map, dead)
}

/// Equilibrium under the dead loads alone: `F_D + Nᵀp_n + Tᵀp_t = 0`, `p_n ≥ 0` (free on
/// bilateral points) and the joint laws, with a zero objective. Feasible iff the structure can
/// carry its dead loads (Heyman's safe theorem: a statically admissible state exists);
/// [`crate::analysis::safety`] asks it of the structure and of its joints shrunk about their
/// centres (the geometric safety factor).
pub fn equilibrium_program(map: &KinematicMap, dead: &[f64]) -> ForceProgram {
    ForceProgram::new(map, dead, None, Direction::Minimise, |_| 0.0, |_| 0.0)
}

/// The extreme of a linear function of the contact forces over the statically admissible
/// states (the constraints of [`equilibrium_program`]): `min` or `max` of
/// `Σ_k c_n[k]·p_n,k + Σ_r c_t[r]·p_t,r`. With `c` the coefficients of a support's reaction
/// component this gives the range of that reaction (the least and the largest thrust of an
/// arch).
pub fn reaction_extreme_program(
    map: &KinematicMap,
    dead: &[f64],
    normal_coefficients: &[f64],
    tangent_coefficients: &[f64],
    direction: Direction,
) -> ForceProgram {
    ForceProgram::new(
        map,
        dead,
        None,
        direction,
        |k| normal_coefficients[k],
        |r| tangent_coefficients[r],
    )
}

/// The static program of limit analysis (the paper's Remark 3): `max λ` subject to
/// `F_D + λ F_L + Nᵀp_n + Tᵀp_t = 0`, `p_n ≥ 0` and the joint laws. Its row duals are the
/// collapse mechanism.
pub fn limit_force_program(map: &KinematicMap, dead: &[f64], live: &[f64]) -> ForceProgram {
    ForceProgram::new(map, dead, Some(live), Direction::Maximise, |_| 0.0, |_| 0.0)
}

/// [`limit_force_program`] with every point a column, those with a gap fixed at zero by their
/// bounds: structures of one topology (a deformation sequence) then give programs of one shape,
/// so the optimal basis of one starts the next. Without joint laws it is the same problem.
pub fn limit_force_program_fixed_topology(
    map: &KinematicMap,
    dead: &[f64],
    live: &[f64],
) -> ForceProgram {
    let mut all = map.clone();
    all.gap.iter_mut().for_each(|g| *g = 0.0);
    let mut fp = limit_force_program(&all, dead, live);
    let nt = map.tangents_per_point;
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 {
            let shear = &fp.pt[k * nt..(k + 1) * nt];
            for &c in std::iter::once(&fp.pn[k]).chain(shear).flatten() {
                fp.lp.col_lower[c] = 0.0;
                fp.lp.col_upper[c] = 0.0;
            }
        }
    }
    fp
}

/// [`limit_force_program`] with the exact crushing domain: no inscribed chords; each joint of
/// finite strength gets the two rotated cones of [`crushing_cones`].
pub fn limit_force_program_conic(map: &KinematicMap, dead: &[f64], live: &[f64]) -> ForceProgram {
    let mut m = map.clone();
    m.facets = 0;
    let mut fp = limit_force_program(&m, dead, live);
    crushing_cones(map, &mut fp);
    fp
}

/// [`settlement_force_program`] with the exact crushing domain of [`limit_force_program_conic`]
/// instead of the inscribed polygon: `min g·p` over forces in equilibrium with the dead loads
/// whose joint resultants lie in `|M| ≤ N (t/2 − N/(2 f_c w))`, and in 3D the exact friction
/// cone `‖p_t‖ ≤ μ p_n + c` instead of the inscribed pyramid (as [`limit_force_program_exact`]).
/// Its mechanism is read from the equilibrium rows' duals (there is no LP dual to build).
pub fn settlement_force_program_conic(map: &KinematicMap, dead: &[f64]) -> ForceProgram {
    let mut m = map.clone();
    m.facets = 0;
    if m.tangents_per_point > 1 {
        m.friction_facets = 0;
    }
    let mut fp = settlement_force_program(&m, dead);
    crushing_cones(map, &mut fp);
    if m.tangents_per_point > 1 {
        friction_cones(&m, &mut fp);
    }
    fp
}

/// The two rotated cones of every joint of finite strength, appended to `fp`:
/// ```text
///   N² ≤ 2 f_c w · (N t/2 ∓ M)   ⇔   ‖(N, (β r − v)/√2)‖ ≤ (β r + v)/√2,
///   r = N t/2 ∓ M,   β = √(2 f_c w / F),   v = f_c w / β
/// ```
/// which is `|M| ≤ N (t/2 − N/(2 f_c w))` exactly (`β r · v = f_c w r`). `F` is the loads'
/// force scale: with `β = 1` the cone's two halves differ by `f_c w t / F` (10⁶ and more for
/// strong masonry) and the interior-point method stalls; the geometric mean halves the spread.
/// (Where it still fails, limit analysis falls back on a fine inscribed polygon:
/// [`crate::analysis::limit::solve_limit_conic`].)
fn crushing_cones(map: &KinematicMap, fp: &mut ForceProgram) {
    let r2 = std::f64::consts::SQRT_2;
    for (law, nmax, range) in crushing_joints(map) {
        let t = law.depth;
        let fw = nmax / t;
        let beta = if fp.force_scale > 0.0 {
            (2.0 * fw / fp.force_scale).sqrt()
        } else {
            1.0
        };
        let v = fw / beta;
        let cols: Vec<(usize, f64)> = range
            .filter_map(|k| fp.pn[k].map(|c| (c, map.along[k])))
            .collect();
        for s in [1.0, -1.0] {
            // r = Σ (t/2 − s·s_k) p_k; slacks b − A x = ((β r + v)/√2, N, (β r − v)/√2).
            let r_row: Vec<(usize, f64)> = cols
                .iter()
                .map(|&(c, a)| (c, -beta * (t / 2.0 - s * a) / r2))
                .collect();
            let n_row: Vec<(usize, f64)> = cols.iter().map(|&(c, _)| (c, -1.0)).collect();
            fp.cones
                .push([(r_row.clone(), v / r2), (n_row, 0.0), (r_row, -v / r2)]);
        }
    }
}

/// [`limit_force_program`] with the exact friction cone `‖p_t‖ ≤ μ p_n + c` at every point of
/// a frictional 3D joint (a second-order cone each, Clarabel) instead of the inscribed
/// pyramid, and the exact crushing domain of [`limit_force_program_conic`] in 2D.
pub fn limit_force_program_exact(map: &KinematicMap, dead: &[f64], live: &[f64]) -> ForceProgram {
    let mut m = map.clone();
    if m.tangents_per_point > 1 {
        m.friction_facets = 0;
    }
    let mut fp = limit_force_program_conic(&m, dead, live);
    if m.tangents_per_point > 1 {
        friction_cones(&m, &mut fp);
    }
    fp
}

/// The exact Coulomb cones of a 3D force program: `‖(p_t1, p_t2)‖ ≤ μ p_n + c`, as the slacks
/// `s = b − a·x` of three rows (see [`crate::lp::Cone3`]).
fn friction_cones(map: &KinematicMap, fp: &mut ForceProgram) {
    let nt = map.tangents_per_point;
    for k in 0..map.num_points() {
        let law = &map.laws[map.points[k].joint];
        let (Some(mu), Some(cn)) = (law.friction, fp.pn[k]) else {
            continue;
        };
        let (Some(t1), Some(t2)) = (fp.pt[k * nt], fp.pt[k * nt + 1]) else {
            continue;
        };
        if map.bilateral[k] {
            continue;
        }
        let (bound, slope) = match &map.shear_limits {
            Some(lim) => (lim[k].max(0.0), 0.0),
            None => (law.cohesion, mu),
        };
        fp.cones.push([
            (vec![(cn, -slope)], bound),
            (vec![(t1, -1.0)], 0.0),
            (vec![(t2, -1.0)], 0.0),
        ]);
    }
}

/// A mechanism on which the live loads do no work and the dead loads do positive work (a ray of
/// the kinematic limit program, which exists when no λ gives equilibrium): `max F_D·d` subject
/// to `F_L·d = 0`, `N d ≥ 0` (`= 0` on bilateral points), `T d = 0`, `−1 ≤ d ≤ 1`, over points
/// without a gap.
pub fn dead_load_ray_program(map: &KinematicMap, dead: &[f64], live: &[f64]) -> LinearProgram {
    let mut lp = LinearProgram::new(Direction::Maximise);
    let mut cols: Vec<Vec<(usize, f64)>> = vec![Vec::new(); map.num_dofs];
    let r = lp.add_row(0.0, 0.0);
    for (c, &v) in live.iter().enumerate() {
        cols[c].push((r, v));
    }
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 {
            continue;
        }
        let r = lp.add_row(0.0, if map.bilateral[k] { 0.0 } else { f64::INFINITY });
        for (c, v) in KinematicMap::row(&map.normal, k) {
            cols[c].push((r, v));
        }
        let nt = map.tangents_per_point;
        for row in k * nt..(k + 1) * nt {
            let r = lp.add_row(0.0, 0.0);
            for (c, v) in KinematicMap::row(&map.tangent, row) {
                cols[c].push((r, v));
            }
        }
    }
    for (c, e) in cols.into_iter().enumerate() {
        lp.add_column(dead[c], -1.0, 1.0, e);
    }
    lp
}

// --- Canonical solutions: programs over an optimal face ------------------------------------
//
// | program | builder |
// |---|---|
// | the kinematic form of any force program (its LP dual; columns `0..num_dofs` are `y = −d`) | [`kinematic_program`] |
// | an LP with its optimal value held as a row, no objective | [`optimal_face`] |
// | the crack area `Σ w_k o_k` as a cost on `y` | [`crack_area_cost`] |
// | the squared crack openings `Σ w_k o_k²` as a quadratic on `y` | [`crack_opening_quadratic`] |
// | a force program with open points unloaded and `|p_t| ≤ μ p_n` on joints without friction | [`physical_force_program`] |
// | the complementary energy `Σ |p_k|² / w_k` as a quadratic on the forces | [`force_energy_quadratic`] |

/// The kinematic form of a force program, formed as its LP dual ([`crate::duality::dual`]): a
/// maximisation whose first `map.num_dofs` columns are `y = −d` (block DOFs with the sign of
/// [`MotionProgram::motion`]), whose optimum equals the force program's.
pub fn kinematic_program(fp: &ForceProgram) -> crate::error::Result<crate::duality::DualProgram> {
    crate::duality::dual(&fp.lp)
}

/// `lp` restricted to its optimal face: its objective `cᵀx` held as the last row,
/// `cᵀx ≥ value − tol·|value|` for a maximisation (`≤ value + tol·|value|` for a
/// minimisation), and no objective (a minimisation with zero costs, to be given one).
pub fn optimal_face(lp: &LinearProgram, value: f64, rel_tol: f64) -> LinearProgram {
    face_row(lp, value, rel_tol, 1.0)
}

/// The band, relative to the largest coefficient of the program's own matrix, within which
/// [`optimal_face_in_band`] leaves the value row as it is: `[FACE_BAND_LOW·a, FACE_BAND_HIGH·a]`.
const FACE_BAND_LOW: f64 = 1e-6;
const FACE_BAND_HIGH: f64 = 10.0;

/// [`optimal_face`] for the canonical force stage ([`physical_force_program`]): the same
/// constraint, but when the row's largest coefficient lies outside a band about the largest
/// coefficient `a` of the program's own matrix (`1e-6·a` to `10·a`), the row is divided
/// through so that its largest coefficient is the band's nearer end. A settlement's costs are
/// its support motions, and far from the structure's own scale the unscaled row was the
/// program's worst-conditioned: on the paper's arch (its matrix's largest coefficient about 1)
/// the least μ came out 0.3906 at `--move right=1e7,0` and 0.3281 at 1e10 m where it is 0.4034
/// (to 3 %) from 1 µm to 1 km, and at 1e-12 m the energy QP failed (session 24). Inside the
/// band nothing changes: dividing every row (session 23) moved the tolerances of ordinary
/// problems (a tilt's certificate, a degenerate face's choice, a search's stated precision).
/// The tolerance stays in the objective's own units.
pub fn optimal_face_in_band(lp: &LinearProgram, value: f64, rel_tol: f64) -> LinearProgram {
    let largest = |v: &[f64]| v.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let (c, a) = (largest(&lp.cost), largest(&lp.value));
    let scale = if c > 0.0 && a > 0.0 {
        c / c.clamp(FACE_BAND_LOW * a, FACE_BAND_HIGH * a)
    } else {
        1.0
    };
    face_row(lp, value, rel_tol, scale)
}

/// The optimal face's row `cᵀx` against `value` within `rel_tol·max(|value|, 1e-12)` (in the
/// objective's own units), divided through by `scale` (1: the row as it is).
fn face_row(lp: &LinearProgram, value: f64, rel_tol: f64, scale: f64) -> LinearProgram {
    let entries: Vec<(usize, f64)> = lp
        .cost
        .iter()
        .copied()
        .enumerate()
        .filter(|&(_, c)| c != 0.0)
        .map(|(j, c)| (j, c / scale))
        .collect();
    let slack = rel_tol * value.abs().max(1e-12) / scale;
    let value = value / scale;
    let (lo, hi) = if lp.maximise {
        (value - slack, INF)
    } else {
        (-INF, value + slack)
    };
    let mut out = lp.with_row(&entries, lo, hi);
    out.maximise = false;
    out.cost.iter_mut().for_each(|c| *c = 0.0);
    out
}

/// [`optimal_face`] made exact by complementary slackness with an optimal dual solution of
/// `lp` (`row_dual`, `col_dual`, as [`crate::lp::LpSolution`] reports them): every row whose
/// dual exceeds `rel_tau` of the largest dual is held at its finite bound, every column whose
/// reduced cost does at its finite bound. A point is optimal exactly when it is feasible and
/// complementary to one optimal dual, so this is the optimal face without a tolerance (the
/// value row of [`optimal_face`] stays, as a guard for interior-point duals).
pub fn optimal_face_exact(
    lp: &LinearProgram,
    value: f64,
    rel_tol: f64,
    row_dual: &[f64],
    col_dual: &[f64],
    rel_tau: f64,
) -> LinearProgram {
    let mut out = optimal_face(lp, value, rel_tol);
    let big = row_dual
        .iter()
        .chain(col_dual)
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let tau = rel_tau * big;
    let hold = |lo: &mut f64, hi: &mut f64| {
        if hi.is_finite() && !lo.is_finite() {
            *lo = *hi;
        } else if lo.is_finite() && !hi.is_finite() {
            *hi = *lo;
        }
    };
    for (i, y) in row_dual.iter().enumerate() {
        if y.abs() > tau {
            let (mut lo, mut hi) = (out.row_lower[i], out.row_upper[i]);
            hold(&mut lo, &mut hi);
            out.row_lower[i] = lo;
            out.row_upper[i] = hi;
        }
    }
    for (j, z) in col_dual.iter().enumerate() {
        if z.abs() > tau {
            let (mut lo, mut hi) = (out.col_lower[j], out.col_upper[j]);
            hold(&mut lo, &mut hi);
            out.col_lower[j] = lo;
            out.col_upper[j] = hi;
        }
    }
    out
}

/// The crack area `Σ_k w_k o_k` over points without a gap, with `o_k = N_k d + g_n,k` and
/// `d = −y`, as a cost vector on the first `map.num_dofs` of `num_cols` columns, and its
/// constant `Σ w_k g_n,k` (so that the area is `cost·x + constant`).
pub fn crack_area_cost(map: &KinematicMap, weights: &[f64], num_cols: usize) -> (Vec<f64>, f64) {
    let mut cost = vec![0.0; num_cols];
    let mut constant = 0.0;
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 || map.bilateral[k] {
            continue;
        }
        constant += weights[k] * map.support_normal[k];
        for (c, a) in KinematicMap::row(&map.normal, k) {
            cost[c] -= weights[k] * a;
        }
    }
    (cost, constant)
}

/// `Σ_k w_k o_k²` (points without a gap, `o_k = g_n,k − N_k y`) as `½ yᵀPy + qᵀy + const`: the
/// upper triangle of `P = 2 Nᵀ W N` and `q = −2 Nᵀ W g_n` (on the first `map.num_dofs` of
/// `num_cols` columns).
pub fn crack_opening_quadratic(
    map: &KinematicMap,
    weights: &[f64],
    num_cols: usize,
) -> (Vec<(usize, usize, f64)>, Vec<f64>) {
    let mut p = Vec::new();
    let mut q = vec![0.0; num_cols];
    for k in 0..map.num_points() {
        if map.gap[k] > 0.0 || map.bilateral[k] {
            continue;
        }
        let row = KinematicMap::row(&map.normal, k);
        let w = weights[k];
        for &(c1, a1) in &row {
            q[c1] -= 2.0 * w * map.support_normal[k] * a1;
            for &(c2, a2) in &row {
                if c1 <= c2 {
                    p.push((c1, c2, 2.0 * w * a1 * a2));
                }
            }
        }
    }
    (p, q)
}

/// A force program of `map` (built by `build`, e.g. [`settlement_force_program`]) restricted to
/// physical optimal fields: its optimal value held ([`optimal_face`], relative `rel_tol`), the
/// points in `open` carrying no force (normal nor shear: their columns fixed at zero), and,
/// with `mu = Some(μ)`, Coulomb's `|p_t| ≤ μ p_n` on every joint without friction of its own
/// (not on bilateral joints). No objective. With `shear_at_open`, open points carry no normal
/// force but may carry shear (the friction rows of those points are dropped): the relaxation
/// for mechanisms that Heyman's no-sliding rule holds at open joints (`docs/canonical.md`).
pub fn physical_force_program(
    map: &KinematicMap,
    build: impl Fn(&KinematicMap) -> ForceProgram,
    value: f64,
    rel_tol: f64,
    open: &[bool],
    mu: Option<f64>,
    shear_at_open: bool,
) -> ForceProgram {
    let rows_before_laws = map.num_dofs;
    let mut fp = match mu {
        Some(mu) => {
            let mut m = map.clone();
            for law in m.laws.iter_mut().filter(|l| l.friction.is_none()) {
                law.friction = Some(mu);
                law.cohesion = 0.0;
            }
            build(&m)
        }
        None => build(map),
    };
    fp.lp = optimal_face_in_band(&fp.lp, value, rel_tol);
    let nt = map.tangents_per_point;
    for (k, _) in open.iter().enumerate().filter(|(_, &o)| o) {
        let shear = &fp.pt[k * nt..(k + 1) * nt];
        if shear_at_open {
            // Normal force zero; the shear free of the friction rows (which would zero it).
            if let Some(c) = fp.pn[k] {
                fp.lp.col_lower[c] = 0.0;
                fp.lp.col_upper[c] = 0.0;
            }
            for &c in shear.iter().flatten() {
                let rows: Vec<usize> = fp.lp.column(c).map(|(i, _)| i).collect();
                for i in rows.into_iter().filter(|&i| i >= rows_before_laws) {
                    fp.lp.row_lower[i] = -INF;
                    fp.lp.row_upper[i] = INF;
                }
            }
            continue;
        }
        for &c in std::iter::once(&fp.pn[k]).chain(shear).flatten() {
            fp.lp.col_lower[c] = 0.0;
            fp.lp.col_upper[c] = 0.0;
        }
    }
    fp
}

/// The complementary energy of springs of equal stiffness per unit joint size,
/// `Σ_k (p_n,k² + |p_t,k|²) / w_k`, as the upper triangle of `P` in `½ xᵀPx` (diagonal).
pub fn force_energy_quadratic(fp: &ForceProgram, weights: &[f64]) -> Vec<(usize, usize, f64)> {
    let nt = if fp.pn.is_empty() {
        1
    } else {
        fp.pt.len() / fp.pn.len()
    };
    let mut p = Vec::new();
    for (k, &w) in weights.iter().enumerate() {
        let shear = &fp.pt[k * nt..(k + 1) * nt];
        for &c in std::iter::once(&fp.pn[k]).chain(shear).flatten() {
            p.push((c, c, 2.0 / w.max(1e-12)));
        }
    }
    p
}
