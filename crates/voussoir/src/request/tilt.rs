//! The tilting table: the critical tilt of the base towards a horizontal direction.

use super::{invalid, Request};
use crate::analysis::tilt::{tilt_along, tilt_along_canonical, TiltResult};
use crate::dim::Three;
use crate::error::Result;
use crate::lp::SolverOptions;
use crate::structure::{Structure, Structure3d};
use serde::{Deserialize, Serialize};

/// Options of a tilting-table analysis. Default: towards +x (azimuth 0°), the canonical
/// collapse mechanism (docs/canonical.md).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TiltRequest {
    /// The direction the table tilts towards, as an azimuth in degrees from +x towards +y (any
    /// finite angle, taken modulo 360°). A 2D model tilts along x: 0 (+x) or 180 (−x).
    pub azimuth: f64,
    /// How the front end wrote the direction (`+x`, `1,1`), for messages; not part of the JSON.
    #[serde(skip)]
    pub label: Option<String>,
    /// Report the solver's own collapse mechanism instead of the canonical one.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub raw: bool,
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

    /// Whether the canonical selection runs: unless `raw`, and not with the exact friction cone
    /// (a cone program, whose optimum is an interior point: the solver's own is reported, as
    /// `settle` does).
    pub fn canonical(&self, req: &Request) -> bool {
        !self.raw && !req.model.exact_cone()
    }

    /// The canonical selection's options: the mechanism stages only. With the force stage
    /// (the least-μ bisection) the README's vault and dome took 3.6× and 4.8× the raw CPU time
    /// (docs/performance.md, session 16); `limit --canonical` on the tilted model gives the
    /// canonical forces. The forces reported are the solver's optimal field, which is
    /// complementary to every optimal mechanism, the canonical one included.
    fn canonical_options(_dims: usize) -> crate::analysis::canonical::CanonicalOptions {
        super::mechanism_options()
    }

    /// The 2D tilting table (towards +x or −x).
    pub(super) fn solve_2d(
        &self,
        st: &Structure,
        req: &Request,
    ) -> Result<(TiltResult, SolverOptions)> {
        let solver = req.solver.options(&super::class(st, req));
        let direction = self.sign_2d(req)?;
        let (tilt_angle, mut limit) = if self.canonical(req) {
            tilt_along_canonical(st, [direction, 0.0], &solver, &Self::canonical_options(2))?
        } else {
            tilt_along(st, [direction, 0.0], &solver, false)?
        };
        crate::analysis::limit::certify_no_equilibrium(st, &mut limit, &solver, None)?;
        Ok((
            TiltResult {
                tilt_angle,
                direction,
                azimuth: None,
                limit,
            },
            solver,
        ))
    }

    /// The 3D tilting table (towards the azimuth), with the exact friction cone when asked.
    pub(super) fn solve_3d(
        &self,
        st: &Structure3d,
        req: &Request,
    ) -> Result<(TiltResult<Three>, SolverOptions)> {
        let solver = req.solver.options(&super::class(st, req));
        let azimuth = self.normalised();
        let a = azimuth.to_radians();
        let direction = [a.cos(), a.sin(), 0.0];
        let (tilt_angle, mut limit) = if self.canonical(req) {
            tilt_along_canonical(st, direction, &solver, &Self::canonical_options(3))?
        } else {
            tilt_along(st, direction, &solver, req.model.exact_cone())?
        };
        // With the pyramid only: the exact cone's answer is the cone program's.
        if !req.model.exact_cone() {
            crate::analysis::limit::certify_no_equilibrium(st, &mut limit, &solver, None)?;
        }
        Ok((
            TiltResult {
                tilt_angle,
                direction: 1.0,
                azimuth: Some(azimuth),
                limit,
            },
            solver,
        ))
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
