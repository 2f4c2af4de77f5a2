//! Deforming a structure: a geometry operation. Blocks move by exact finite rigid motions of a
//! mechanism, points that open keep their gap (and carry no force until they close), ties to
//! `fixed` supports are released. Every analysis then runs unchanged on the deformed structure
//! ("limit analysis on the deformed geometry" is `limit(st.deform(d, s))`).

use super::Structure;
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};

/// Relative threshold below which an opening counts as closed (same as the reports').
pub const OPEN_TOLERANCE: f64 = 1e-7;

impl Structure {
    /// Magnitude of a set of support motions: the largest translation (or rotation if none).
    pub fn settlement_magnitude(&self) -> f64 {
        let st = self;
        let t = st
            .supports
            .iter()
            .fold(0.0f64, |m, s| m.max(s.motion[0].hypot(s.motion[1])));
        if t > 0.0 {
            t
        } else {
            st.supports
                .iter()
                .fold(0.0f64, |m, s| m.max(s.motion[2].abs()))
        }
    }

    /// Openings of every point per joint for mechanism `d` (with the supports' prescribed motions),
    /// in the layout [`Structure::deformed`] takes, and the closed/open threshold.
    pub fn joint_openings(
        &self,
        map: &KinematicMap,
        d: &[f64],
        support_scale: f64,
    ) -> (Vec<Vec<f64>>, f64) {
        let st = self;
        let (open, _) = map.jumps(d, support_scale);
        let scale = open.iter().fold(0.0f64, |m, o| m.max(o.abs()));
        let mut out: Vec<Vec<f64>> = st
            .joints
            .iter()
            .map(|j| vec![0.0; j.points.len()])
            .collect();
        for (k, p) in map.points.iter().enumerate() {
            out[p.joint][p.index] = open[k];
        }
        (out, OPEN_TOLERANCE * scale)
    }

    /// Move `st` by the mechanism `d` scaled by `s` (blocks by exact finite rigid motions, supports
    /// by `s·motion`): points whose opening `s·(N d + g_n)` exceeds `1e-7` of the largest opening
    /// get that gap (added to any gap they had) and carry no force; the others stay in contact.
    pub fn deform(&self, d: &[f64], s: f64) -> Result<Structure> {
        let st = self;
        if d.len() != 3 * st.blocks.len() {
            return Err(Error::Request(format!(
                "a mechanism for {} blocks needs {} values, got {}",
                st.blocks.len(),
                3 * st.blocks.len(),
                d.len()
            )));
        }
        if !s.is_finite() || d.iter().any(|x| !x.is_finite()) {
            return Err(Error::Request(
                "deformation: the mechanism and its scale must be finite".into(),
            ));
        }
        let map = KinematicMap::new(st);
        let (openings, tol) = st.joint_openings(&map, d, 1.0);
        Ok(st.deformed(d, s, &openings, (s.abs() * tol).max(0.0)))
    }

    /// Turn every `fixed` support into a contact one: its joints become unilateral (no tension).
    pub fn release_fixed(&mut self) {
        let st = self;
        use crate::model::Connection;
        use crate::structure::Body;
        let fixed: Vec<bool> = st
            .supports
            .iter()
            .map(|s| s.connection == Connection::Fixed)
            .collect();
        for j in st.joints.iter_mut() {
            if [j.a, j.b]
                .iter()
                .any(|b| matches!(b, Body::Support(k) if fixed[*k]))
            {
                j.bilateral = false;
            }
        }
        for sp in st.supports.iter_mut() {
            sp.connection = Connection::Contact;
        }
    }
}
