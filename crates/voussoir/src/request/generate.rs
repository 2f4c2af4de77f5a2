//! The generators' requests: what `voussoir gen arch`/`gen vault` and Python's
//! `generate.arch`/`generate.vault` (and `least_thickness("arch", …)`) are asked, checked in one
//! place. Each shape's own parameter and the live load's intensity are held as given or not, so
//! that one given where it does nothing is refused whatever its value (session 25: `--half-angle
//! 30` drew the semicircular arch; the refusals were written in the CLI and again in Python).

use super::{invalid, Names};
use crate::error::Result;
use crate::generate::{ArchShape, ArchSpec, LiveLoad, RadiusAt};

/// An arch's shape by name; its own parameter is [`ArchRequest::half_angle`] (segmental) or
/// [`ArchRequest::offset`] (pointed).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ShapeName {
    #[default]
    Semicircular,
    Segmental,
    Pointed,
}

impl ShapeName {
    /// The shape's name as the front ends write it.
    pub fn as_str(self) -> &'static str {
        match self {
            ShapeName::Semicircular => "semicircular",
            ShapeName::Segmental => "segmental",
            ShapeName::Pointed => "pointed",
        }
    }

    /// The shape named `s` (`shape=s` in the message otherwise).
    pub fn parse(s: &str, n: Names) -> Result<ShapeName> {
        match s {
            "semicircular" => Ok(ShapeName::Semicircular),
            "segmental" => Ok(ShapeName::Segmental),
            "pointed" => Ok(ShapeName::Pointed),
            _ => invalid(format!(
                "{}: expected semicircular, segmental or pointed",
                n.given("shape", s)
            )),
        }
    }
}

/// Default half-angle of a segmental arch (degrees).
pub const DEFAULT_HALF_ANGLE: f64 = 60.0;
/// Default centre offset of a pointed arch (a fraction of the intrados radius: equilateral).
pub const DEFAULT_OFFSET: f64 = 0.5;
/// Default live load intensity (kN/m²).
pub const DEFAULT_LIVE_LOAD: f64 = 1.0;

/// What an arch generator is asked. `None`: not given (the default applies where it means
/// something).
#[derive(Clone, Debug, PartialEq)]
pub struct ArchRequest {
    pub shape: ShapeName,
    pub radius: f64,
    pub radius_at: RadiusAt,
    pub thickness: f64,
    pub voussoirs: usize,
    pub unit_weight: f64,
    pub width: f64,
    pub live: LiveLoad,
    /// kN/m² of a vertical live load (full, left, right); default [`DEFAULT_LIVE_LOAD`].
    pub live_load: Option<f64>,
    /// Degrees, segmental only; default [`DEFAULT_HALF_ANGLE`].
    pub half_angle: Option<f64>,
    /// Pointed only; default [`DEFAULT_OFFSET`].
    pub offset: Option<f64>,
}

impl ArchRequest {
    /// The generator's spec, or the one-line refusal of a parameter given where it does
    /// nothing (in the front end's words, [`Names`]).
    pub fn spec(&self, n: Names) -> Result<ArchSpec> {
        if let (Some(q), LiveLoad::None | LiveLoad::Horizontal) = (self.live_load, self.live) {
            let live = if self.live == LiveLoad::None {
                "none"
            } else {
                "horizontal"
            };
            return invalid(format!(
                "{}: applies to a vertical live load ({}, left or right); {} has no intensity",
                n.given("live_load", q),
                n.given("live", "full"),
                n.given("live", live)
            ));
        }
        for (field, given, own) in [
            ("half_angle", self.half_angle, ShapeName::Segmental),
            ("offset", self.offset, ShapeName::Pointed),
        ] {
            if let Some(v) = given {
                if self.shape != own {
                    return invalid(format!(
                        "{}: applies to {} only",
                        n.given(field, v),
                        n.given("shape", own.as_str())
                    ));
                }
            }
        }
        let shape = match self.shape {
            ShapeName::Semicircular => ArchShape::Semicircular,
            ShapeName::Segmental => ArchShape::Segmental {
                half_angle: self.half_angle.unwrap_or(DEFAULT_HALF_ANGLE).to_radians(),
            },
            ShapeName::Pointed => ArchShape::Pointed {
                offset: self.offset.unwrap_or(DEFAULT_OFFSET),
            },
        };
        Ok(ArchSpec {
            shape,
            radius: self.radius,
            radius_at: self.radius_at,
            thickness: self.thickness,
            voussoirs: self.voussoirs,
            unit_weight: self.unit_weight,
            width: self.width,
            live: self.live,
            live_load: self.live_load.unwrap_or(DEFAULT_LIVE_LOAD),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn asked() -> ArchRequest {
        ArchRequest {
            shape: ShapeName::Semicircular,
            radius: 2.86,
            radius_at: RadiusAt::Intrados,
            thickness: 0.33,
            voussoirs: 16,
            unit_weight: 18.0,
            width: 1.0,
            live: LiveLoad::None,
            live_load: None,
            half_angle: None,
            offset: None,
        }
    }

    #[test]
    fn each_shape_parameter_refused_with_another_shape_in_each_front_end_words() {
        let mut r = asked();
        r.half_angle = Some(60.0);
        let e = r.spec(Names::Flags).unwrap_err().to_string();
        assert_eq!(e, "--half-angle 60: applies to --shape segmental only");
        let e = r.spec(Names::Keywords).unwrap_err().to_string();
        assert_eq!(e, "half_angle=60: applies to shape=segmental only");
        r.shape = ShapeName::Segmental;
        match r.spec(Names::Flags).unwrap().shape {
            ArchShape::Segmental { half_angle } => {
                assert!((half_angle - std::f64::consts::FRAC_PI_3).abs() < 1e-15)
            }
            s => panic!("{s:?}"),
        }
        r.offset = Some(0.5);
        let e = r.spec(Names::Flags).unwrap_err().to_string();
        assert_eq!(e, "--offset 0.5: applies to --shape pointed only");
        let mut r = asked();
        r.live_load = Some(2.0);
        let e = r.spec(Names::Flags).unwrap_err().to_string();
        assert_eq!(
            e,
            "--live-load 2: applies to a vertical live load (--live full, left or right); --live none has no intensity"
        );
        r.live = LiveLoad::Left;
        assert_eq!(r.spec(Names::Keywords).unwrap().live_load, 2.0);
        assert!(ShapeName::parse("gothic", Names::Keywords)
            .unwrap_err()
            .to_string()
            .starts_with("shape=gothic: expected"));
    }
}
