//! A tiny deterministic SVG writer: fixed number formatting, escaped text, no hash maps.
//!
//! Numbers are written with at most two decimals (pixels), trailing zeros and `-0` removed, so
//! the same input gives the same bytes on every machine.

use std::fmt::Write as _;

/// Format a pixel coordinate: two decimals, trailing zeros trimmed, never `-0`, never `NaN`.
pub fn num(x: f64) -> String {
    fmt_fixed(x, 2)
}

/// Format `x` with at most `decimals` decimals, trimmed.
pub fn fmt_fixed(x: f64, decimals: usize) -> String {
    if !x.is_finite() {
        return "0".to_string();
    }
    let mut s = format!("{x:.decimals$}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".to_string();
    }
    s
}

/// Escape text for XML/HTML content and attribute values.
pub fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&#39;"),
            c if (c as u32) < 0x20 && c != '\n' && c != '\t' => o.push(' '),
            c => o.push(c),
        }
    }
    o
}

/// The font stack written into every drawing. PNGs are rendered with the bundled DejaVu Sans;
/// browsers use it if installed, otherwise a metric-compatible sans-serif.
pub const FONT: &str = "DejaVu Sans, Verdana, Arial, Helvetica, sans-serif";

/// Approximate advance width of `s` in pixels at font size `size` (DejaVu Sans averages about
/// 0.6 em per character); used only for layout of labels and legends.
pub fn text_width(s: &str, size: f64) -> f64 {
    s.chars()
        .map(|c| match c {
            'i' | 'l' | 'j' | '.' | ',' | ':' | ';' | '|' | '\'' | ' ' | '!' | '(' | ')' | '['
            | ']' => 0.32,
            'm' | 'w' | 'M' | 'W' | '—' | '×' => 0.9,
            // Mathematical signs are as wide as digits and more in DejaVu Sans.
            '−' | '=' | '+' | '<' | '>' | '≤' | '≥' | '~' | '#' => 0.84,
            '%' => 0.95,
            '…' | '@' => 1.0,
            c if c.is_ascii_uppercase() => 0.7,
            c if c.is_ascii_digit() => 0.64,
            _ => 0.6,
        })
        .sum::<f64>()
        * size
}

/// Path data of a closed polygon given in pixels: `M x y L x y … Z`.
pub fn polygon_path(out: &mut String, pts: impl IntoIterator<Item = [f64; 2]>) {
    let mut first = true;
    for p in pts {
        let _ = write!(
            out,
            "{}{} {}",
            if first { "M" } else { "L" },
            num(p[0]),
            num(p[1])
        );
        first = false;
    }
    if !first {
        out.push('Z');
    }
}

/// Path data of an open polyline in pixels.
pub fn polyline_path(out: &mut String, pts: impl IntoIterator<Item = [f64; 2]>) {
    let mut first = true;
    for p in pts {
        let _ = write!(
            out,
            "{}{} {}",
            if first { "M" } else { "L" },
            num(p[0]),
            num(p[1])
        );
        first = false;
    }
}

/// `points` attribute value of a polyline/polygon.
pub fn points_attr(pts: &[[f64; 2]]) -> String {
    let mut s = String::with_capacity(pts.len() * 14);
    for (i, p) in pts.iter().enumerate() {
        if i > 0 {
            s.push(' ');
        }
        let _ = write!(s, "{},{}", num(p[0]), num(p[1]));
    }
    s
}

/// An arrow from `tail` to `tip` (pixels) as path data: the shaft and a filled head. Returns the
/// shaft (to be stroked) and the head (to be filled).
pub fn arrow(shaft: &mut String, head: &mut String, tail: [f64; 2], tip: [f64; 2], head_len: f64) {
    let d = [tip[0] - tail[0], tip[1] - tail[1]];
    let len = (d[0] * d[0] + d[1] * d[1]).sqrt();
    if !(len > 1e-9) {
        return;
    }
    let u = [d[0] / len, d[1] / len];
    let hl = head_len.min(0.6 * len);
    let hw = 0.45 * hl;
    let base = [tip[0] - hl * u[0], tip[1] - hl * u[1]];
    polyline_path(
        shaft,
        [tail, [base[0] + 0.2 * hl * u[0], base[1] + 0.2 * hl * u[1]]],
    );
    polygon_path(
        head,
        [
            tip,
            [base[0] - hw * u[1], base[1] + hw * u[0]],
            [base[0] + hw * u[1], base[1] - hw * u[0]],
        ],
    );
}

/// A "nice" number close to `x` (1, 2 or 5 times a power of ten), rounding down if `floor`.
pub fn nice(x: f64, floor: bool) -> f64 {
    if !(x > 0.0) || !x.is_finite() {
        return 1.0;
    }
    let e = x.log10().floor();
    let p = 10f64.powf(e);
    let f = x / p;
    let m = if floor {
        if f >= 5.0 {
            5.0
        } else if f >= 2.0 {
            2.0
        } else {
            1.0
        }
    } else if f < 1.5 {
        1.0
    } else if f < 3.5 {
        2.0
    } else if f < 7.5 {
        5.0
    } else {
        10.0
    };
    m * p
}

/// A number for people: up to `sig` significant digits, no exponent for 1e-4 ≤ |x| < 1e6.
pub fn human(x: f64, sig: usize) -> String {
    if !x.is_finite() {
        return "—".to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let a = x.abs();
    if !(1e-4..1e6).contains(&a) {
        let s = format!("{:.*e}", sig.saturating_sub(1), x);
        return s;
    }
    let digits = (sig as i32 - 1 - a.log10().floor() as i32).max(0) as usize;
    fmt_fixed(x, digits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_trimmed_and_stable() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(12.345), "12.35");
        assert_eq!(num(-3.10), "-3.1");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(human(0.434645, 4), "0.4346");
        assert_eq!(human(50.0, 3), "50");
        assert_eq!(human(0.0125, 3), "0.0125");
    }

    #[test]
    fn nice_numbers() {
        assert_eq!(nice(0.37, true), 0.2);
        assert_eq!(nice(73.0, true), 50.0);
        assert_eq!(nice(0.0031, false), 0.002);
        assert_eq!(nice(8.0, false), 10.0);
    }

    #[test]
    fn escaping() {
        assert_eq!(esc("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
