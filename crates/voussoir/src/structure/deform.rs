//! Deforming a structure: a geometry operation. Blocks move by exact finite rigid motions of a
//! mechanism, points that open keep their gap (and carry no force until they close), ties to
//! `fixed` supports are released. Every analysis then runs unchanged on the deformed structure
//! ("limit analysis on the deformed geometry" is `limit(st.deform(d, s))`).

use super::Structure;

/// Relative threshold below which an opening counts as closed (same as the reports').
pub use crate::scale::OPEN_TOLERANCE;

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
