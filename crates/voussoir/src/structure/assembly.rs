//! What every analysis needs of a structure, in any dimension: the [`Assembly`] trait.
//!
//! A 2D [`Structure`](super::Structure) (polygons) and a 3D [`Structure3d`](super::Structure3d)
//! (polyhedra) differ only in their geometry: validation, interface detection, how a finite
//! rigid motion moves a shape, what their loads are. Everything after that — the contact
//! frames handed to the kinematic map, the programs, the solves, the reports, limit,
//! settlement, capacity and tilting-table analyses — is written once over this trait.

use crate::dim::Dim;
use crate::discretize::{ContactBodies, ContactJoint, KinematicMap};
use crate::error::{Error, Result};
use crate::result::{BodyName, Spatial};
use crate::structure::{Body, OPEN_TOLERANCE};

/// A validated structure of rigid blocks and supports in contact, in dimension `Self::D`.
pub trait Assembly: Clone + Send + Sync {
    type D: Spatial;

    fn num_blocks(&self) -> usize;
    fn num_supports(&self) -> usize;
    fn num_joints(&self) -> usize;
    /// The two bodies of joint `j` (the normal points from the first into the second).
    fn joint_bodies(&self, j: usize) -> (Body, Body);
    fn support_name(&self, s: usize) -> &str;
    /// Prescribed motion of support `s` (`D::DOFS` values about its reference point).
    fn support_motion(&self, s: usize) -> &[f64];
    fn set_support_motion(&mut self, s: usize, motion: &[f64]);

    /// Reference points of the bodies and the supports' motions, for the kinematic map.
    fn contact_bodies(&self) -> ContactBodies<Self::D>;
    /// The joints as contact frames with their joint laws.
    fn contact_joints(&self) -> Vec<ContactJoint<Self::D>>;

    /// Load resultants per block (force then moment about the block's reference point).
    fn load_vector(&self, live: bool) -> Vec<f64>;
    fn has_live_loads(&self) -> bool;
    /// A copy whose live loads are replaced by horizontal forces equal to each block's weight
    /// along the unit horizontal `direction` (the tilting table); an error if no block weighs.
    fn with_weight_as_live_load(&self, direction: <Self::D as Dim>::Vector) -> Result<Self>;

    /// The shapes a result refers to.
    fn shapes(&self) -> <Self::D as Spatial>::Shapes;

    /// The cracks of a report's joints (`open[j][k]`: point `k` of joint `j` is open;
    /// `widths[j][k]`: its opening): polylines in 2D, one record per cracked joint in 3D
    /// ([`crate::result::cracks`]).
    fn cracks(
        &self,
        joints: &[crate::result::JointResult<Self::D>],
        open: &[Vec<bool>],
        widths: &[Vec<f64>],
    ) -> Vec<<Self::D as Spatial>::Crack>;

    /// Magnitude of the support motions: the largest translation (or rotation if none).
    fn settlement_magnitude(&self) -> f64;

    /// Move every block by the finite rigid motion `s·d_i` and every support by `s·motion`;
    /// points of each joint take their new position and the gap `s·openings[j][k]` (kept if it
    /// exceeds `gap_tol`, else 0).
    fn deformed(&self, d: &[f64], s: f64, openings: &[Vec<f64>], gap_tol: f64) -> Self;

    /// Turn every `fixed` support into a contact one.
    fn release_fixed(&mut self);

    /// The kinematic map of the structure.
    fn kinematic_map(&self) -> KinematicMap {
        KinematicMap::assemble(&self.contact_bodies(), &self.contact_joints())
    }

    /// How results name a body.
    fn body_name(&self, b: Body) -> BodyName {
        match b {
            Body::Block(i) => BodyName::Block(i),
            Body::Support(s) => BodyName::Support(self.support_name(s).to_string()),
        }
    }

    /// A copy with the supports' prescribed motions replaced.
    fn with_support_motions<M: AsRef<[f64]>>(&self, motions: &[M]) -> Self {
        let mut s = self.clone();
        for (k, m) in motions.iter().enumerate() {
            s.set_support_motion(k, m.as_ref());
        }
        s
    }

    /// Openings of every point per joint for mechanism `d` (with the supports' prescribed
    /// motions scaled by `support_scale`), in the layout [`Assembly::deformed`] takes, and the
    /// closed/open threshold.
    fn joint_openings(
        &self,
        map: &KinematicMap,
        d: &[f64],
        support_scale: f64,
    ) -> (Vec<Vec<f64>>, f64) {
        let (open, _) = map.jumps(d, support_scale);
        let scale = crate::scale::motion_scale(map, d, support_scale);
        let mut out: Vec<Vec<f64>> = map
            .joint_start
            .windows(2)
            .map(|w| vec![0.0; w[1] - w[0]])
            .collect();
        for (k, p) in map.points.iter().enumerate() {
            out[p.joint][p.index] = open[k];
        }
        (out, OPEN_TOLERANCE * scale)
    }

    /// Move the structure by the mechanism `d` scaled by `s`: points whose opening
    /// `s·(N d + g_n)` exceeds `1e-7` of the motion scale ([`crate::scale`]) get that gap and
    /// carry no force.
    fn deform(&self, d: &[f64], s: f64) -> Result<Self> {
        let n = Self::D::DOFS * self.num_blocks();
        if d.len() != n {
            return Err(Error::Request(format!(
                "a mechanism for {} blocks needs {n} values, got {}",
                self.num_blocks(),
                d.len()
            )));
        }
        if !s.is_finite() || d.iter().any(|x| !x.is_finite()) {
            return Err(Error::Request(
                "deformation: the mechanism and its scale must be finite".into(),
            ));
        }
        let map = self.kinematic_map();
        let (openings, tol) = self.joint_openings(&map, d, 1.0);
        Ok(self.deformed(d, s, &openings, (s.abs() * tol).max(0.0)))
    }
}

impl KinematicMap {
    /// The map of a structure (either dimension): its joints in contact-frame form,
    /// assembled by [`KinematicMap::assemble`].
    pub fn new<S: Assembly>(st: &S) -> KinematicMap {
        st.kinematic_map()
    }
}
