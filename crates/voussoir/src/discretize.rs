//! The kinematic map: one sparse assembly shared by every analysis.
//!
//! Blocks carry DOFs `d = (u_i, v_i, θ_i)` at their centroids (`3·i … 3·i+2`). For every
//! collocation point `k` of a joint between bodies `a` and `b` (normal `n` from `a` into `b`,
//! tangent `t = (−n_y, n_x)`), the jump `[u] = u_b(x) − u_a(x)` gives
//!
//! ```text
//!   opening  u_n,k = N_k d + g_n,k      (≥ 0: the paper's (63), with A = −N)
//!   sliding  u_t,k = T_k d + g_t,k      (= 0: the paper's (64))
//! ```
//! where `g` collects the prescribed motions of supports (the paper's (65), `C d = û0`, folded
//! into the joint rows of block–support joints). The transposes are the equilibrium operators:
//! a compressive normal force `p_n,k ≥ 0` on `b` along `+n` and a shear `p_t,k` along `+t` give
//! block resultants `Nᵀ p_n + Tᵀ p_t`, so that equilibrium reads `F + Nᵀ p_n + Tᵀ p_t = 0`.

use crate::dim::Dim;
use serde::{Deserialize, Serialize};
use sprs::CsMat;

/// A body of the structure: a block (3 DOFs) or a support (prescribed motion).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Body {
    Block(usize),
    Support(usize),
}

/// A collocation point in the global numbering: joint index and point index in the joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PointRef {
    pub joint: usize,
    pub index: usize,
}

/// The largest friction coefficient accepted. No masonry joint comes near it; a larger μ is
/// meant as "no sliding", which is Heyman's law (no friction coefficient at all), and it puts
/// rows of scale μ into the programs: on the paper's arch μ = 1e10 gave λ = 0.434623 with 17
/// hinges and μ ≥ 1e15 a "certified" no-equilibrium, where λ = 0.434645 (session 24); on a
/// 2D wall μ = 1e5 was reported uncertified and 1e6 gave 1.999999 for 2. Up to 1e4 both give
/// the no-sliding answer to 1e-6 (`tests/joint_laws.rs`: μ = 1e4 reproduces Heyman to 1e-9).
pub const MAX_FRICTION: f64 = 1e4;

/// Joint law of a joint: Heyman's (no sliding, infinite strength) unless a material says
/// otherwise. A joint takes the weaker of the two blocks' values (block–support: the block's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointLaw {
    /// Coulomb friction coefficient μ (None: no sliding).
    pub friction: Option<f64>,
    /// Cohesive shear capacity per collocation point (kN): c · length · width / points.
    pub cohesion: f64,
    /// Compressive strength f_c (kPa), None: infinite.
    pub strength: Option<f64>,
    /// Joint depth t (m, its original contact length) and out-of-plane width w (m).
    pub depth: f64,
    pub width: f64,
}

impl JointLaw {
    /// The law of a joint between blocks of materials `mats` (one for a block–support joint):
    /// the weakest friction, strength and cohesion of the two; cohesion as a force per point,
    /// `c · area / points`, where `area` is the joint's contact area (2D: length × width).
    pub fn between(
        mats: &[&crate::model::Material],
        depth: f64,
        width: f64,
        area: f64,
        points: usize,
    ) -> JointLaw {
        let min = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(x), Some(y)) => Some(x.min(y)),
            (x, None) => x,
            (None, y) => y,
        };
        let mut law = JointLaw {
            friction: None,
            cohesion: 0.0,
            strength: None,
            depth,
            width,
        };
        let mut cohesion = f64::INFINITY;
        for m in mats {
            law.friction = min(law.friction, m.friction);
            law.strength = min(law.strength, m.compressive_strength);
            cohesion = cohesion.min(m.cohesion);
        }
        if !mats.is_empty() && law.friction.is_some() {
            law.cohesion = cohesion * area / points.max(1) as f64;
        }
        law
    }

    /// Largest normal force a joint can carry, f_c · w · t (kN).
    pub fn max_normal_force(&self) -> Option<f64> {
        self.strength.map(|f| f * self.width * self.depth)
    }
}

/// A joint in contact-frame form: all the kinematic map needs of it, in any dimension.
#[derive(Clone, Debug)]
pub struct ContactJoint<D: Dim> {
    pub a: Body,
    pub b: Body,
    /// Unit normal from `a` into `b`, and the tangents ([`Dim::tangents`]).
    pub normal: D::Vector,
    pub tangents: D::Tangents,
    /// Collocation points and their current gaps.
    pub points: Vec<(D::Vector, f64)>,
    /// Bilateral joint (tied to a `fixed` support).
    pub bilateral: bool,
    pub law: JointLaw,
    /// Position of each point along the joint from its midpoint (m): the lever arm of the
    /// crushing domain (2D; 0 in 3D, where finite strength is not modelled).
    pub along: Vec<f64>,
}

/// The bodies as the kinematic map sees them: reference points of the blocks (where their DOFs
/// act), and of the supports with their prescribed motions (`Dim::DOFS` values each).
#[derive(Clone, Debug)]
pub struct ContactBodies<D: Dim> {
    pub blocks: Vec<D::Vector>,
    pub supports: Vec<(D::Vector, Vec<f64>)>,
}

/// Default [`KinematicMap::crushing_reach`]: the crushing polygon spans forces up to 64 times
/// the total dead load (or up to f_c·w·t, if less).
pub const CRUSHING_REACH: f64 = 64.0;

/// The assembled kinematic map of a structure.
///
/// Rows: one opening row per collocation point `k` (`N`), `tangents_per_point` sliding rows per
/// point (`T`, row `k·tangents_per_point + j` for tangent `j`). Columns: `dofs_per_block` per
/// block (`dofs_per_block·i …`).
#[derive(Clone, Debug)]
pub struct KinematicMap {
    pub num_dofs: usize,
    /// 3 in 2D, 6 in 3D.
    pub dofs_per_block: usize,
    /// 1 in 2D, 2 in 3D.
    pub tangents_per_point: usize,
    pub points: Vec<PointRef>,
    /// Opening rows `N` (points × DOFs), CSR.
    pub normal: CsMat<f64>,
    /// Sliding rows `T` (points·tangents × DOFs), CSR.
    pub tangent: CsMat<f64>,
    /// Opening caused by prescribed support motions at each point.
    pub support_normal: Vec<f64>,
    /// Sliding caused by prescribed support motions at each point and tangent.
    pub support_tangent: Vec<f64>,
    /// Whether each point belongs to a bilateral (fixed-support) joint.
    pub bilateral: Vec<bool>,
    /// Current gap of each point (0 for a point in contact).
    pub gap: Vec<f64>,
    /// First global point of each joint (length `joints + 1`).
    pub joint_start: Vec<usize>,
    /// Joint law of each joint.
    pub laws: Vec<JointLaw>,
    /// Coordinate of each point along its joint's tangent, from the joint's midpoint (m).
    pub along: Vec<f64>,
    /// Facets of the piecewise-linear crushing domain (finite compressive strength).
    pub facets: usize,
    /// How far above the loads' force scale (the total dead load) the crushing polygon
    /// reaches: its vertices lie in `[0, min(f_c·w·t, reach × scale)]`, capped there
    /// ([`crate::programs`]); limit analysis widens it when a joint's force reaches the cap.
    pub crushing_reach: f64,
    /// Facets of the pyramid inscribed in the friction cone (3D; 2D needs none).
    pub friction_facets: usize,
    /// Fixed shear capacities per point, replacing `μ p_n + c` on frictional joints (used by the
    /// non-associative friction iteration: sliding without dilatancy).
    pub shear_limits: Option<Vec<f64>>,
}

impl KinematicMap {
    /// Assemble the opening and sliding rows from contact frames only: each point's position,
    /// its joint's normal and tangents, and the bodies' reference points. The jump
    /// `[u] = u_b(x) − u_a(x)` along a direction `e` is `Σ ± (e·u + (r × e)·ω)` over the two
    /// bodies ([`Dim::dof_row`]); a support contributes its prescribed motion to `g`.
    pub fn assemble<D: Dim>(bodies: &ContactBodies<D>, joints: &[ContactJoint<D>]) -> KinematicMap {
        let (nd, nt) = (D::DOFS, D::TANGENTS);
        let num_dofs = nd * bodies.blocks.len();
        let npts: usize = joints.iter().map(|j| j.points.len()).sum();
        let mut tn = CsrRows::with_capacity(npts, 2 * nd * npts);
        let mut tt = CsrRows::with_capacity(npts * nt, 2 * nd * nt * npts);
        let mut points = Vec::with_capacity(npts);
        let mut support_normal = Vec::with_capacity(npts);
        let mut support_tangent = Vec::with_capacity(npts * nt);
        let mut bilateral = Vec::with_capacity(npts);
        let mut gap = Vec::with_capacity(npts);
        let mut joint_start = Vec::with_capacity(joints.len() + 1);
        let mut laws = Vec::with_capacity(joints.len());
        let mut along = Vec::with_capacity(npts);
        let mut row = [0.0f64; 6];
        for (j, joint) in joints.iter().enumerate() {
            joint_start.push(points.len());
            laws.push(joint.law);
            let n = joint.normal;
            let ts = joint.tangents.as_ref();
            for (k, &(x, g)) in joint.points.iter().enumerate() {
                let mut gn = 0.0;
                let mut gt = [0.0f64; 2];
                let mut nrow: Vec<(usize, f64)> = Vec::with_capacity(2 * nd);
                let mut trows: [Vec<(usize, f64)>; 2] = Default::default();
                for (body, sign) in [(joint.a, -1.0), (joint.b, 1.0)] {
                    match body {
                        Body::Block(i) => {
                            let r = D::sub(x, bodies.blocks[i]);
                            D::dof_row(r, n, &mut row[..nd]);
                            for (c, &v) in row[..nd].iter().enumerate() {
                                nrow.push((nd * i + c, sign * v));
                            }
                            for (m, &t) in ts.iter().enumerate() {
                                D::dof_row(r, t, &mut row[..nd]);
                                for (c, &v) in row[..nd].iter().enumerate() {
                                    trows[m].push((nd * i + c, sign * v));
                                }
                            }
                        }
                        Body::Support(s) => {
                            let (c, motion) = &bodies.supports[s];
                            let u = D::small_displacement(*c, motion, x);
                            gn += sign * D::dot(n, u);
                            for (m, &t) in ts.iter().enumerate() {
                                gt[m] += sign * D::dot(t, u);
                            }
                        }
                    }
                }
                tn.push_row(&mut nrow);
                for row in trows.iter_mut().take(nt) {
                    tt.push_row(row);
                }
                points.push(PointRef { joint: j, index: k });
                support_normal.push(gn);
                support_tangent.extend_from_slice(&gt[..nt]);
                bilateral.push(joint.bilateral);
                gap.push(g);
                along.push(joint.along.get(k).copied().unwrap_or(0.0));
            }
        }
        joint_start.push(points.len());
        KinematicMap {
            num_dofs,
            dofs_per_block: nd,
            tangents_per_point: nt,
            points,
            normal: tn.finish(num_dofs),
            tangent: tt.finish(num_dofs),
            support_normal,
            support_tangent,
            bilateral,
            gap,
            joint_start,
            laws,
            along,
            facets: 16,
            crushing_reach: CRUSHING_REACH,
            friction_facets: 8,
            shear_limits: None,
        }
    }

    /// Whether any joint has friction or finite strength, or the shear capacities of the
    /// non-associative iteration are set: the force program then has rows beyond equilibrium.
    pub fn has_joint_laws(&self) -> bool {
        self.laws
            .iter()
            .any(|l| l.friction.is_some() || l.strength.is_some())
            || self.shear_limits.is_some()
    }

    pub fn num_points(&self) -> usize {
        self.points.len()
    }

    /// Row `k` of `N` (or `T`) as `(dof, value)` pairs.
    pub fn row(m: &CsMat<f64>, k: usize) -> Vec<(usize, f64)> {
        m.outer_view(k)
            .map(|v| v.iter().map(|(c, &x)| (c, x)).collect())
            .unwrap_or_default()
    }

    /// Number of sliding rows (points × tangents).
    pub fn num_tangent_rows(&self) -> usize {
        self.support_tangent.len()
    }

    /// Openings `N d + s·g_n` (one per point) and slidings `T d + s·g_t` (one per point and
    /// tangent) for block DOFs `d`, with the support motions scaled by `s` (1 for the motions
    /// as prescribed, 0 to ignore them).
    pub fn jumps(&self, d: &[f64], s: f64) -> (Vec<f64>, Vec<f64>) {
        let apply = |m: &CsMat<f64>, g: &[f64]| -> Vec<f64> {
            (0..g.len())
                .map(|k| {
                    let mut v = s * g[k];
                    if let Some(row) = m.outer_view(k) {
                        for (c, &x) in row.iter() {
                            v += x * d[c];
                        }
                    }
                    v
                })
                .collect()
        };
        (
            apply(&self.normal, &self.support_normal),
            apply(&self.tangent, &self.support_tangent),
        )
    }

    /// `Nᵀ p_n + Tᵀ p_t`: block resultants of point forces (`p_t` one per point and tangent).
    pub fn resultants(&self, pn: &[f64], pt: &[f64]) -> Vec<f64> {
        let mut f = vec![0.0; self.num_dofs];
        for (m, p) in [(&self.normal, pn), (&self.tangent, pt)] {
            for (k, &pk) in p.iter().enumerate() {
                if pk != 0.0 {
                    if let Some(row) = m.outer_view(k) {
                        for (c, &x) in row.iter() {
                            f[c] += x * pk;
                        }
                    }
                }
            }
        }
        f
    }
}

/// Rows of a CSR matrix built in order (the map's rows come out point by point): no triplet
/// list and no sort of all entries, which at 10⁵ blocks in 3D (3.6 million rows) costs several
/// times the memory and time of writing the rows directly. Hand-written because `sprs`'s
/// `TriMat` has no row-ordered builder.
struct CsrRows {
    indptr: Vec<usize>,
    indices: Vec<usize>,
    data: Vec<f64>,
}

impl CsrRows {
    fn with_capacity(rows: usize, nnz: usize) -> CsrRows {
        let mut indptr = Vec::with_capacity(rows + 1);
        indptr.push(0);
        CsrRows {
            indptr,
            indices: Vec::with_capacity(nnz),
            data: Vec::with_capacity(nnz),
        }
    }

    /// Append one row from unsorted `(column, value)` entries (summing repeated columns),
    /// leaving `entries` empty.
    fn push_row(&mut self, entries: &mut Vec<(usize, f64)>) {
        entries.sort_unstable_by_key(|e| e.0);
        for &(c, v) in entries.iter() {
            if self.indices.len() > *self.indptr.last().unwrap() && self.indices.last() == Some(&c)
            {
                *self.data.last_mut().unwrap() += v;
            } else {
                self.indices.push(c);
                self.data.push(v);
            }
        }
        entries.clear();
        self.indptr.push(self.indices.len());
    }

    fn finish(self, cols: usize) -> CsMat<f64> {
        CsMat::new(
            (self.indptr.len() - 1, cols),
            self.indptr,
            self.indices,
            self.data,
        )
    }
}
