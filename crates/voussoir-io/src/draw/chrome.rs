//! The frame every figure of a structure shares, 2D and 3D: page size, the title block, the
//! SVG's head and background, the colours, a bounding box, the "nothing to draw" note. The
//! legend is laid out by [`super::legend`]; the structure itself is drawn by the renderers
//! (`scene` in 2D, `draw3d` in 3D), each in its own stages.

use super::svg::{esc, num, text_width, FONT};
use std::fmt::Write as _;

// Colours: calm, print-friendly, distinguishable in grey scale by shape as well as hue.
pub(crate) const STONE: &str = "#e3dccb";
pub(crate) const STILL: &str = "#d9d6cf";
pub(crate) const EDGE: &str = "#3a3a3a";
pub(crate) const FAINT: &str = "#a8a8a8";
pub(crate) const CRACK: &str = "#d7301f";
pub(crate) const THRUST: &str = "#1f5fbf";
pub(crate) const LOAD: &str = "#7b2d8e";
pub(crate) const FORCE: &str = "#1a9850";
pub(crate) const HINGE: &str = "#111111";
/// Cracks narrower than this fraction of the widest are not drawn as lines (hairlines).
pub(crate) const HAIRLINE: f64 = 0.01;
/// The crack lines (darker than the crack wedges' fill).
pub(crate) const CRACK_LINE: &str = "#7a0177";
/// The fill colours of the rigid parts of a mechanism.
pub(crate) const PALETTE: [&str; 8] = [
    "#f6c97f", "#9ecae1", "#b5dba0", "#f4a582", "#c9b8e0", "#f2e394", "#8fd3c8", "#e7b3cf",
];

/// The page margin (px).
pub(crate) const MARGIN: f64 = 28.0;

/// The page of a figure: its width, the most height the drawing may take, the wrapped info lines
/// under the title and the title block's height.
pub(crate) struct Page {
    pub width: f64,
    pub max_height: f64,
    pub info: Vec<String>,
    pub title_h: f64,
}

impl Page {
    /// `width` and `max_height` as asked (the defaults where not finite or too small), and the
    /// info lines wrapped within the margins.
    pub fn new(width: f64, max_height: f64, default_max_height: f64, info: &[String]) -> Self {
        let width = if width.is_finite() && width >= 200.0 {
            width
        } else {
            1000.0
        };
        let max_height = if max_height.is_finite() && max_height >= 100.0 {
            max_height
        } else {
            default_max_height
        };
        let info: Vec<String> = info
            .iter()
            .flat_map(|l| wrap(l, 13.0, width - 2.0 * MARGIN))
            .collect();
        let title_h = 16.0 + 24.0 + 19.0 * info.len() as f64;
        Page {
            width,
            max_height,
            info,
            title_h,
        }
    }

    /// The SVG's head up to its attributes (the caller adds any and closes the tag).
    pub fn open(&self, o: &mut String, height: f64) {
        let _ = write!(
            o,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"{FONT}\"",
            w = num(self.width),
            h = num(height)
        );
    }

    /// The `<title>`, the support hatch `{id}-hatch`, the white background, the title and the
    /// info lines.
    pub fn head(&self, o: &mut String, id: &str, height: f64, title: &str) {
        let _ = writeln!(o, "<title>{}</title>", esc(title));
        let _ = writeln!(
            o,
            "<defs><pattern id=\"{id}-hatch\" patternUnits=\"userSpaceOnUse\" width=\"7\" height=\"7\" patternTransform=\"rotate(45)\"><rect width=\"7\" height=\"7\" fill=\"#ffffff\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"7\" stroke=\"#444444\" stroke-width=\"1.6\"/></pattern></defs>"
        );
        let _ = writeln!(
            o,
            "<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>",
            num(self.width),
            num(height)
        );
        let _ = writeln!(
            o,
            "<text x=\"{}\" y=\"30\" font-size=\"19\" fill=\"#111111\">{}</text>",
            num(MARGIN),
            esc(title)
        );
        for (i, line) in self.info.iter().enumerate() {
            let _ = writeln!(
                o,
                "<text x=\"{}\" y=\"{}\" font-size=\"13\" fill=\"#444444\">{}</text>",
                num(MARGIN),
                num(52.0 + 19.0 * i as f64),
                esc(line)
            );
        }
    }

    /// "(no blocks to draw)" in the middle of a drawing area of height `draw_h`.
    pub fn nothing_to_draw(&self, o: &mut String, draw_h: f64) {
        let _ = writeln!(
            o,
            "<text x=\"{}\" y=\"{}\" font-size=\"14\" fill=\"#888888\" text-anchor=\"middle\">(no blocks to draw)</text>",
            num(self.width / 2.0),
            num(self.title_h + MARGIN + draw_h / 2.0)
        );
    }
}

/// A line of text broken at spaces into lines at most `max` pixels wide (at font size `size`);
/// a word longer than `max` stays whole.
pub(crate) fn wrap(line: &str, size: f64, max: f64) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    for w in line.split(' ') {
        let candidate = if cur.is_empty() {
            w.to_string()
        } else {
            format!("{cur} {w}")
        };
        if !cur.is_empty() && text_width(&candidate, size) > max {
            out.push(std::mem::take(&mut cur));
            cur = w.to_string();
        } else {
            cur = candidate;
        }
    }
    out.push(cur);
    out
}

/// An axis-aligned box `[xmin, ymin, xmax, ymax]` grown by finite points.
pub(crate) struct Bbox(pub [f64; 4]);

impl Bbox {
    pub fn new() -> Self {
        Bbox([
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ])
    }
    pub fn add(&mut self, p: [f64; 2]) {
        if p[0].is_finite() && p[1].is_finite() {
            self.0[0] = self.0[0].min(p[0]);
            self.0[1] = self.0[1].min(p[1]);
            self.0[2] = self.0[2].max(p[0]);
            self.0[3] = self.0[3].max(p[1]);
        }
    }
    pub fn valid(&self) -> bool {
        self.0[0] <= self.0[2] && self.0[1] <= self.0[3]
    }
}
