//! Lengths in the printed summaries and messages: one rule for every command (README, "Units in the
//! summaries").
//!
//! - crack openings (joint openings, observed and predicted widths, misfits): **mm**;
//! - support motions, settlements and displacements: **cm**;
//! - positions and dimensions (coordinates, thicknesses): **m**;
//! - rotations of supports: **mrad**.
//!
//! Each kind has a fixed number of decimals (openings and motions to 1 µm, positions to
//! 0.1 mm); the unit is always printed, and a value never comes out in bare e-notation
//! metres. Values too large for fixed notation (≥ 10⁷ in the unit shown, i.e. absurd inputs)
//! keep the unit with e-notation.

/// What a length is, which sets its unit and its decimals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Length {
    /// A crack opening, an observed or predicted width, a misfit: mm.
    Opening,
    /// A support motion, a settlement, a displacement: cm.
    Motion,
    /// A position or a dimension: m.
    Position,
    /// A rotation of a support (given in rad): mrad.
    Rotation,
}

impl Length {
    /// The unit the value is printed in.
    pub fn unit(self) -> &'static str {
        match self {
            Length::Opening => "mm",
            Length::Motion => "cm",
            Length::Position => "m",
            Length::Rotation => "mrad",
        }
    }

    /// The factor from SI (m or rad) to [`Length::unit`].
    pub fn factor(self) -> f64 {
        match self {
            Length::Opening => 1e3,
            Length::Motion => 1e2,
            Length::Position => 1.0,
            Length::Rotation => 1e3,
        }
    }

    /// Decimals printed in [`Length::unit`].
    pub fn decimals(self) -> usize {
        match self {
            Length::Opening => 3,
            Length::Motion => 4,
            Length::Position => 4,
            Length::Rotation => 4,
        }
    }

    /// The number of `si` (m or rad) in this kind's unit, without the unit (for tables whose
    /// heading names it): fixed decimals, no "-0".
    pub fn number(self, si: f64) -> String {
        number(si * self.factor(), self.decimals())
    }

    /// [`Length::number`] with more (or fewer) decimals, for a table that needs them (the
    /// capacity curve's settlements).
    pub fn number_to(self, si: f64, decimals: usize) -> String {
        number(si * self.factor(), decimals)
    }

    /// The value with its unit: `1.250 mm`, `-0.2500 cm`, `3.1900 m`.
    pub fn show(self, si: f64) -> String {
        format!("{} {}", self.number(si), self.unit())
    }

    /// The value with a sign always written (`+0.012 mm`), for misfits.
    pub fn show_signed(self, si: f64) -> String {
        let n = self.number(si);
        if n.starts_with('-') || n.starts_with('—') {
            format!("{n} {}", self.unit())
        } else {
            format!("+{n} {}", self.unit())
        }
    }
}

/// `x` with `decimals` decimals; e-notation only beyond 10⁷; never "-0.000"; "—" if not finite.
fn number(x: f64, decimals: usize) -> String {
    if !x.is_finite() {
        return match x {
            f if f == f64::INFINITY => "∞".into(),
            f if f == f64::NEG_INFINITY => "-∞".into(),
            _ => "—".into(),
        };
    }
    if x.abs() >= 1e7 {
        return format!("{x:.3e}");
    }
    let s = format!("{x:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_and_decimals() {
        assert_eq!(Length::Opening.show(0.00125), "1.250 mm");
        assert_eq!(Length::Motion.show(-0.0025), "-0.2500 cm");
        assert_eq!(Length::Position.show(3.19), "3.1900 m");
        assert_eq!(Length::Rotation.show(0.001), "1.0000 mrad");
        assert_eq!(Length::Opening.show(-1e-12), "0.000 mm");
        assert_eq!(Length::Opening.show_signed(1e-5), "+0.010 mm");
        assert_eq!(Length::Opening.show_signed(-1e-5), "-0.010 mm");
        assert_eq!(Length::Motion.show(1e300), "1.000e302 cm");
        assert_eq!(Length::Motion.number(f64::NAN), "—");
    }
}
