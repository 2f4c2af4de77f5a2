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
//! keep the unit with e-notation. A length too small for the fixed decimals (it would print as
//! zero) is printed with four significant digits in e-notation, in the same unit, when it is
//! above 1e-9 of the structure's size ([`set_scale`]; below that it is round-off and prints as
//! zero): a structure drawn at micrometre size printed its thickness "0.0000 m" and its crack
//! widths "0.000 mm" (session 25). Rotations keep their fixed decimals.

use std::sync::atomic::{AtomicU64, Ordering};

/// A positive scale held process-wide (the bits of an `f64`, 1 until set), for the summaries
/// of the structure being analysed.
struct Scale(AtomicU64);

impl Scale {
    const fn one() -> Scale {
        Scale(AtomicU64::new(0x3FF0_0000_0000_0000))
    }
    /// Ignored unless finite and positive.
    fn set(&self, v: f64) {
        if v.is_finite() && v > 0.0 {
            self.0.store(v.to_bits(), Ordering::Relaxed);
        }
    }
    fn get(&self) -> f64 {
        f64::from_bits(self.0.load(Ordering::Relaxed))
    }
}

/// The size (m) of the structure whose lengths are printed.
static SIZE: Scale = Scale::one();
/// The total load (kN) of the structure whose forces are printed.
static LOAD: Scale = Scale::one();

/// Lengths below this fraction of the structure's size are its coordinates' round-off: printed
/// as zero when the fixed decimals show zero.
pub const ROUND_OFF: f64 = 1e-9;

/// Forces below this fraction of the structure's load are the solvers' round-off (their
/// feasibility tolerances are relative, about 1e-7 of the loads): printed as zero when the
/// fixed decimals show zero. Larger than [`ROUND_OFF`], which is the coordinates'.
pub const FORCE_ROUND_OFF: f64 = 1e-7;

/// Set the size (m) of the structure whose lengths the summaries print (`request::prepare`
/// calls it once it has built the structure, for the CLI and Python alike; the diagonal of its
/// bounding box). Ignored unless finite and positive.
pub fn set_scale(size: f64) {
    SIZE.set(size)
}

/// The size set by [`set_scale`] (1 m by default).
pub fn scale() -> f64 {
    SIZE.get()
}

/// Set the total load (kN) of the structure whose forces the summaries print
/// (`request::prepare`: its dead loads, or its live loads where it has no weight). Ignored
/// unless finite and positive.
pub fn set_force_scale(load: f64) {
    LOAD.set(load)
}

/// The load set by [`set_force_scale`] (1 kN by default).
pub fn force_scale() -> f64 {
    LOAD.get()
}

/// A force (kN) or a moment (kN·m, `moment`) with `decimals` decimals, as the summaries print
/// reactions and shear: a value the fixed decimals would print as zero gets four significant
/// digits when it is above [`FORCE_ROUND_OFF`] of the structure's load (times its size for a
/// moment); below, round-off, zero. A structure drawn at micrometre size printed every reaction
/// "0.0000 kN" (session 26). No "-0.0000"; e-notation beyond 10⁷ as for lengths.
pub fn force(kn: f64, decimals: usize, moment: bool) -> String {
    force_at(
        kn,
        decimals,
        force_scale() * if moment { scale() } else { 1.0 },
    )
}

/// [`force`] against the scale `scale` (kN or kN·m).
fn force_at(kn: f64, decimals: usize, scale: f64) -> String {
    let s = number(kn, decimals);
    if kn.is_finite()
        && kn.abs() > FORCE_ROUND_OFF * scale
        && s.chars().all(|c| c == '0' || c == '.')
    {
        format!("{kn:.3e}")
    } else {
        s
    }
}

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
        self.number_to(si, self.decimals())
    }

    /// [`Length::number`] with more (or fewer) decimals, for a table that needs them (the
    /// capacity curve's settlements).
    pub fn number_to(self, si: f64, decimals: usize) -> String {
        let x = si * self.factor();
        let s = number(x, decimals);
        // A nonzero length above the round-off that the fixed decimals show as zero.
        if self != Length::Rotation
            && si.is_finite()
            && si.abs() > ROUND_OFF * scale()
            && s.chars().all(|c| c == '0' || c == '.')
        {
            format!("{x:.3e}")
        } else {
            s
        }
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

/// A length (m) printed with `decimals` decimals, or with six significant digits in
/// e-notation below 1 mm (as a load multiplier below 1e-3, `analysis::limit::show_multiplier`):
/// the least thickness of an arch drawn at micrometre size printed as 0.00000031 m (session 25).
pub fn fine(si: f64, decimals: usize) -> String {
    if si != 0.0 && si.abs() < 1e-3 {
        format!("{si:.5e}")
    } else {
        format!("{si:.decimals$}")
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
        // Below the fixed decimals: significant digits above 1e-9 of the size (1 m here),
        // zero below (round-off).
        assert_eq!(Length::Position.show(3.3e-7), "3.300e-7 m");
        assert_eq!(Length::Opening.show(-2.5e-7), "-2.500e-4 mm");
        assert_eq!(Length::Opening.show(6e-7), "0.001 mm");
        assert_eq!(Length::Position.show(1.7e-16), "0.0000 m");
        assert_eq!(Length::Rotation.show(1e-8), "0.0000 mrad");
    }

    #[test]
    fn forces_against_the_load() {
        // A 1 kN structure: fixed decimals, significant digits above 1e-7 kN, zero below.
        assert_eq!(force_at(12.345678, 4, 1.0), "12.3457");
        assert_eq!(force_at(-1e-12, 4, 1.0), "0.0000");
        assert_eq!(force_at(-3.5e-6, 4, 1.0), "-3.500e-6");
        assert_eq!(force_at(5e-8, 4, 1.0), "0.0000");
        assert_eq!(force_at(f64::NAN, 4, 1.0), "—");
        // A 300 kN wall: 3.5e-6 kN is 1.2e-8 of its load, round-off.
        assert_eq!(force_at(3.5e-6, 4, 300.0), "0.0000");
        // A micrometre arch of 2e-11 kN: its reactions in significant digits.
        assert_eq!(force_at(1.04e-11, 4, 2e-11), "1.040e-11");
    }
}
