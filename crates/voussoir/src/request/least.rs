//! The least thickness of a generated arch or dome: the bisection on the thickness at which it
//! stands under its own weight, regenerating the model each step. It has no model of its own
//! (the generator makes one per step), so its entry is [`least_thickness`], beside [`super::run`].

use super::{invalid, Names, SolverRequest};
use crate::analysis::safety::least_thickness as bisect;
use crate::error::Result;
use crate::generate::{ArchSpec, RadiusAt};
use crate::generate3d::DomeSpec;
use crate::model3d::AnyModel;
pub use crate::result::safety::LeastThicknessResult;
use crate::{BuildOptions, Structure, Structure3d};
use serde::{Deserialize, Serialize};

/// The generated structure whose least thickness is sought (its own thickness is ignored).
#[derive(Clone, Debug)]
pub enum Generator {
    /// An arch of `gen arch` (2D).
    Arch(ArchSpec),
    /// A dome of `gen dome` (3D).
    Dome(DomeSpec),
}

impl Generator {
    fn radius(&self) -> (f64, RadiusAt) {
        match self {
            Generator::Arch(a) => (a.radius, a.radius_at),
            Generator::Dome(d) => (d.radius, d.radius_at),
        }
    }

    fn name(&self) -> &'static str {
        match self {
            Generator::Arch(_) => "arch",
            Generator::Dome(_) => "dome",
        }
    }

    fn dims(&self) -> usize {
        match self {
            Generator::Arch(_) => 2,
            Generator::Dome(_) => 3,
        }
    }

    /// The model at thickness `t`.
    pub fn model(&self, t: f64) -> Result<AnyModel> {
        Ok(match self {
            Generator::Arch(a) => AnyModel::Planar(crate::generate::arch(&ArchSpec {
                thickness: t,
                ..a.clone()
            })?),
            Generator::Dome(d) => AnyModel::Spatial(crate::generate3d::dome(&DomeSpec {
                thickness: t,
                ..d.clone()
            })?),
        })
    }
}

/// Options of the least-thickness bisection. Defaults: the bracket [radius / 1000, radius / 2],
/// a tolerance of 1e-6 × radius.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LeastThicknessRequest {
    /// Thickness (m) at which the structure must not stand (default radius / 1000).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lower: Option<f64>,
    /// Thickness (m) at which the structure must stand (default radius / 2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub upper: Option<f64>,
    /// Tolerance of the bisection, relative to the radius (between 0 and 1; default 1e-6).
    pub bisection_tolerance: f64,
}

impl Default for LeastThicknessRequest {
    fn default() -> Self {
        LeastThicknessRequest {
            lower: None,
            upper: None,
            bisection_tolerance: 1e-6,
        }
    }
}

/// The result and the model at the least thickness.
#[derive(Clone, Debug)]
pub struct LeastThicknessRun {
    pub result: LeastThicknessResult,
    pub model: AnyModel,
}

fn centreline(radius: f64, at: RadiusAt, t: f64) -> f64 {
    match at {
        RadiusAt::Intrados => radius + t / 2.0,
        RadiusAt::Centreline => radius,
        RadiusAt::Extrados => radius - t / 2.0,
    }
}

impl LeastThicknessRequest {
    pub fn validate(&self, generator: &Generator, names: Names) -> Result<()> {
        let (radius, _) = generator.radius();
        if !(radius.is_finite() && radius > 0.0) {
            return invalid(format!(
                "{}: must be a number > 0",
                names.given("radius", radius)
            ));
        }
        let rel = self.bisection_tolerance;
        if !(rel.is_finite() && rel > 0.0 && rel < 1.0) {
            return invalid(format!(
                "{}: must be a number between 0 and 1",
                names.given("bisection_tolerance", rel)
            ));
        }
        if rel < super::MIN_BISECTION_TOLERANCE {
            // Finer than a double resolves in [0, 1]: the bisection never ended (session 24:
            // 1e-300 ran for minutes until killed).
            return invalid(format!(
                "{}: below {:e}, finer than the bisection can resolve (it would never end)",
                names.given("bisection_tolerance", rel),
                super::MIN_BISECTION_TOLERANCE
            ));
        }
        Ok(())
    }
}

/// The least thickness of a generated arch (2D) or dome (3D), with the solver of its dimension
/// (`solver`'s method, else the dimension's default: dual simplex for the arch, interior point
/// for the dome).
pub fn least_thickness(
    generator: &Generator,
    req: &LeastThicknessRequest,
    solver: &SolverRequest,
    names: Names,
) -> Result<LeastThicknessRun> {
    req.validate(generator, names)?;
    let (radius, at) = generator.radius();
    let lo = req.lower.unwrap_or(radius / 1000.0);
    let hi = req.upper.unwrap_or(radius / 2.0);
    let tol = req.bisection_tolerance * radius;
    let build = BuildOptions::default();
    // A yes/no question at each step: the solver policy's method of a feasibility program of
    // the generator's dimension.
    let solver = solver.options(&crate::lp::policy::ProblemClass {
        purpose: crate::lp::policy::Purpose::Feasibility,
        ..crate::lp::policy::ProblemClass::of_dim(if generator.dims() == 3 { 3 } else { 2 })
    });
    // Its many decisions: the result states the method that answered them, every fallback
    // taken and each decision's outcome, as `safety` does.
    let kind = crate::lp::ProgramKind::set("bisection", "");
    let (found, solves) = crate::lp::collecting(|| -> Result<_> {
        Ok(match generator {
            Generator::Arch(a) => bisect(
                |t| {
                    let m = crate::generate::arch(&ArchSpec {
                        thickness: t,
                        ..a.clone()
                    })?;
                    Structure::new(&m, build)
                },
                lo,
                hi,
                tol,
                &solver,
            )?,
            Generator::Dome(d) => bisect(
                |t| {
                    let m = crate::generate3d::dome(&DomeSpec {
                        thickness: t,
                        ..d.clone()
                    })?;
                    Structure3d::new(&m, build)
                },
                lo,
                hi,
                tol,
                &solver,
            )?,
        })
    });
    drop(kind);
    let found = found?;
    let answered = crate::lp::SolverInfo::by_programs(&solver, &solves);
    let certified = crate::lp::answers_certified(&answered);
    let model = generator.model(found.thickness)?;
    let rc = centreline(radius, at, found.thickness);
    Ok(LeastThicknessRun {
        result: LeastThicknessResult {
            generator: generator.name(),
            centreline_radius: rc,
            thickness_over_radius: found.thickness / rc,
            found,
            solver: crate::lp::SolverInfo::of_solves(&solver, &solves),
            answered,
            certified,
        },
        model,
    })
}
