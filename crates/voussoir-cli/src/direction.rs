//! `--direction`: one syntax for every command that takes a direction (`tilt`, `incremental`,
//! `gen block`): an axis `+x`, `-x`, `+y`, `-y` (`+z`, `-z`), an angle in degrees from +x
//! towards +y, or a vector `DX,DY[,DZ]` of any length.

/// A direction as written on the command line.
#[derive(Clone, Debug, PartialEq)]
pub enum Direction {
    /// Along axis 0 (x), 1 (y) or 2 (z), sign ±1.
    Axis { axis: usize, sign: f64 },
    /// Degrees from +x towards +y (any finite angle).
    Angle(f64),
    /// Two or three finite components, not all zero.
    Vector(Vec<f64>),
}

/// The help of every `--direction`.
pub const SYNTAX: &str =
    "+x, -x, +y, -y, an angle in degrees from +x towards +y, or a vector DX,DY";

/// clap's value parser of `--direction`.
pub fn parse(s: &str) -> Result<Direction, String> {
    let t = s.trim().replace('−', "-").to_ascii_lowercase();
    let axis = |axis: usize, sign: f64| Ok(Direction::Axis { axis, sign });
    match t.as_str() {
        "+x" | "x" | "right" | "positive" => return axis(0, 1.0),
        "-x" | "left" | "negative" => return axis(0, -1.0),
        "+y" | "y" => return axis(1, 1.0),
        "-y" => return axis(1, -1.0),
        "+z" | "z" => return axis(2, 1.0),
        "-z" => return axis(2, -1.0),
        _ => {}
    }
    let expected = || format!("expected {SYNTAX}, got '{s}'");
    if t.contains(',') {
        let v: Vec<f64> = t
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| expected())?;
        if !(2..=3).contains(&v.len()) || v.iter().any(|x| !x.is_finite()) {
            return Err(format!(
                "a vector direction is two or three finite numbers DX,DY[,DZ], got '{s}'"
            ));
        }
        if v.iter().all(|x| *x == 0.0) {
            return Err(format!("the zero vector '{s}' has no direction"));
        }
        return Ok(Direction::Vector(v));
    }
    match t.parse::<f64>() {
        Ok(a) if a.is_finite() => Ok(Direction::Angle(a)),
        Ok(_) => Err(format!(
            "an angle must be a finite number of degrees, got '{s}'"
        )),
        Err(_) => Err(expected()),
    }
}

impl Direction {
    /// The azimuth in degrees from +x towards +y of a horizontal direction (an angle as given,
    /// not reduced modulo 360°); a vertical one (`+z`, a vector with DZ ≠ 0) is refused.
    pub fn azimuth(&self, flag: &str) -> Result<f64, String> {
        match self {
            Direction::Axis { axis: 0, sign } => Ok(if *sign > 0.0 { 0.0 } else { 180.0 }),
            Direction::Axis { axis: 1, sign } => Ok(if *sign > 0.0 { 90.0 } else { 270.0 }),
            Direction::Axis { .. } => Err(format!(
                "{flag} {}: must be horizontal (+x, -x, +y, -y, an angle or DX,DY)",
                self.text()
            )),
            Direction::Angle(a) => Ok(*a),
            Direction::Vector(v) => {
                if v.len() == 3 && v[2] != 0.0 {
                    return Err(format!(
                        "{flag} {}: must be horizontal (DZ = 0)",
                        self.text()
                    ));
                }
                Ok(match (v[0], v[1]) {
                    (0.0, 0.0) => {
                        return Err(format!("{flag} {}: no horizontal component", self.text()))
                    }
                    // Along an axis: that axis's angle exactly (as `+y` is 90°).
                    (x, 0.0) => {
                        if x > 0.0 {
                            0.0
                        } else {
                            180.0
                        }
                    }
                    (0.0, y) => {
                        if y > 0.0 {
                            90.0
                        } else {
                            270.0
                        }
                    }
                    (x, y) => y.atan2(x).to_degrees(),
                })
            }
        }
    }

    /// The direction in a request: its meaning in the model's dimension is the library's
    /// ([`voussoir::request::Toward::resolve`]).
    pub fn toward(&self) -> voussoir::request::Toward {
        use voussoir::request::Toward;
        match self {
            Direction::Axis { .. } => Toward::Axis(self.text()),
            Direction::Angle(a) => Toward::Angle(*a),
            Direction::Vector(v) => Toward::Vector(v.clone()),
        }
    }

    /// The axis name (`+x`, `−x`, …) of an axis direction.
    pub fn axis_name(&self) -> Option<String> {
        match self {
            Direction::Axis { axis, sign } => Some(format!(
                "{}{}",
                if *sign > 0.0 { "+" } else { "−" },
                ["x", "y", "z"][*axis]
            )),
            _ => None,
        }
    }

    /// As it could be written back on the command line.
    pub fn text(&self) -> String {
        match self {
            Direction::Axis { .. } => self.axis_name().unwrap_or_default().replace('−', "-"),
            Direction::Angle(a) => format!("{a}"),
            Direction::Vector(v) => v
                .iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(","),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_syntax() {
        use voussoir::request::{Names, Toward};
        let planar = |s: &str| {
            parse(s)
                .unwrap()
                .toward()
                .resolve(2, "direction", Names::Flags)
                .unwrap()
        };
        assert_eq!(planar("+x"), [1.0, 0.0]);
        assert_eq!(planar("-y"), [0.0, -1.0]);
        assert_eq!(planar("90"), [0.0, 1.0]);
        assert_eq!(planar("-0.5,2"), [-0.5, 2.0]);
        assert!(matches!(parse("+z").unwrap().toward(), Toward::Axis(_)));
        assert_eq!(parse("-x").unwrap().azimuth("--direction").unwrap(), 180.0);
        assert_eq!(parse("0,1").unwrap().azimuth("--direction").unwrap(), 90.0);
        assert_eq!(parse("-30").unwrap().azimuth("--direction").unwrap(), -30.0);
        assert!(parse("0,0").is_err());
        assert!(parse("inf").is_err());
        assert!(parse("1,2,3,4").is_err());
        assert!(parse("up").is_err());
        assert!(parse("+z").unwrap().azimuth("--direction").is_err());
        assert!(parse("1,0,1").unwrap().azimuth("--direction").is_err());
    }
}
