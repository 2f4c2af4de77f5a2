//! The tilting table: the critical tilt of the base towards a horizontal direction.

use super::{invalid, Request};
use crate::error::Result;
use serde::{Deserialize, Serialize};

/// Options of a tilting-table analysis. Default: towards +x (azimuth 0°).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TiltRequest {
    /// The direction the table tilts towards, as an azimuth in degrees from +x towards +y (any
    /// finite angle, taken modulo 360°). A 2D model tilts along x: 0 (+x) or 180 (−x).
    pub azimuth: f64,
    /// How the front end wrote the direction (`+x`, `1,1`), for messages; not part of the JSON.
    #[serde(skip)]
    pub label: Option<String>,
}

impl TiltRequest {
    /// The azimuth in [0, 360).
    pub fn normalised(&self) -> f64 {
        let r = self.azimuth.rem_euclid(360.0);
        // rem_euclid rounds a tiny negative angle up to 360 itself; -0 prints as "-0".
        if r >= 360.0 || r == 0.0 {
            0.0
        } else {
            r
        }
    }

    fn label(&self) -> String {
        self.label
            .clone()
            .unwrap_or_else(|| crate::settlement_input::short_number(self.azimuth))
    }

    pub(super) fn validate(&self, req: &Request) -> Result<()> {
        if !self.azimuth.is_finite() {
            return invalid(format!(
                "{}: must be a finite number of degrees",
                req.names.given("direction", self.azimuth)
            ));
        }
        Ok(())
    }

    /// 2D: +1 (+x) or −1 (−x).
    pub(super) fn sign_2d(&self, req: &Request) -> Result<f64> {
        let a = self.normalised();
        if a == 0.0 {
            Ok(1.0)
        } else if a == 180.0 {
            Ok(-1.0)
        } else {
            invalid(format!(
                "{}: a 2D model tilts along x: +x or -x (azimuth 0 or 180)",
                req.names.given("direction", self.label())
            ))
        }
    }
}
