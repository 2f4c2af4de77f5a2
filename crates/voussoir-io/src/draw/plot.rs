//! Generic x–y line plots: axes with units, grid, several series, labelled points.
//!
//! Used for the λ–settlement capacity curves and the λ–displacement incremental curves (the
//! paper's Figs 7, 10, 12, 14–17):
//! ```
//! use voussoir_io::draw::{plot_curves, Mark, PlotSpec, Series};
//! let svg = plot_curves(
//!     &[Series::new("horizontal settlement", vec![[0.0, 0.429], [1.0, 0.12], [1.4, 0.0]])],
//!     &PlotSpec {
//!         title: "Capacity after settlement".into(),
//!         x_label: "settlement s (cm)".into(),
//!         y_label: "load multiplier λ".into(),
//!         marks: vec![Mark::new(1.4, 0.0, "λ = 0 at s = 1.4 cm")],
//!         ..PlotSpec::default()
//!     },
//! );
//! assert!(svg.starts_with("<svg"));
//! ```
//! A point with a non-finite coordinate breaks a series' line (a gap); a repeated `x` with a
//! new `y` draws a vertical jump.

use super::svg::{esc, fmt_fixed, nice, num, polyline_path, text_width, FONT};
use std::fmt::Write as _;
use voussoir::geometry::segment_meets_box;

/// One curve.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Series {
    pub label: String,
    pub points: Vec<[f64; 2]>,
    /// Draw a marker at every point.
    pub markers: bool,
    pub dashed: bool,
    /// Colour (`#rrggbb`); `None`: the next colour of the palette.
    pub colour: Option<String>,
}

impl Series {
    pub fn new(label: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        Series {
            label: label.into(),
            points,
            ..Series::default()
        }
    }
    pub fn with_markers(mut self) -> Self {
        self.markers = true;
        self
    }
    pub fn dashed(mut self) -> Self {
        self.dashed = true;
        self
    }
}

/// A labelled point (e.g. where λ reaches zero).
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    pub x: f64,
    pub y: f64,
    pub label: String,
}

impl Mark {
    pub fn new(x: f64, y: f64, label: impl Into<String>) -> Self {
        Mark {
            x,
            y,
            label: label.into(),
        }
    }
}

/// Titles, axis labels (with units) and layout of a plot.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotSpec {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub marks: Vec<Mark>,
    /// Figure size in pixels.
    pub width: f64,
    pub height: f64,
    /// Fixed axis ranges; `None`: fitted to the data (and marks) on nice tick values.
    pub x_range: Option<(f64, f64)>,
    pub y_range: Option<(f64, f64)>,
    /// Extend the fitted ranges to include zero.
    pub include_zero: bool,
    /// Prefix for element ids, unique per figure in one HTML page.
    pub id: String,
}

impl Default for PlotSpec {
    fn default() -> Self {
        PlotSpec {
            title: String::new(),
            x_label: String::new(),
            y_label: String::new(),
            marks: Vec::new(),
            width: 820.0,
            height: 520.0,
            x_range: None,
            y_range: None,
            include_zero: true,
            id: "p".to_string(),
        }
    }
}

/// Line colours, distinguishable in print (and with dashes for more than six).
pub const SERIES_COLOURS: [&str; 6] = [
    "#1f5fbf", "#d7301f", "#1a9850", "#e08214", "#7b2d8e", "#4d4d4d",
];

/// An axis: range and ticks.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    pub min: f64,
    pub max: f64,
    pub step: f64,
}

impl Axis {
    /// Fit `[lo, hi]` on nice ticks (about six).
    pub fn fit(lo: f64, hi: f64, fixed: bool) -> Axis {
        let (mut lo, mut hi) = if lo.is_finite() && hi.is_finite() && lo <= hi {
            (lo, hi)
        } else {
            (0.0, 1.0)
        };
        if hi - lo <= 1e-12 * lo.abs().max(hi.abs()).max(1e-300) {
            let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            lo -= d;
            hi += d;
        }
        let step = nice((hi - lo) / 6.0, false);
        if fixed {
            return Axis {
                min: lo,
                max: hi,
                step,
            };
        }
        let min = (lo / step + 1e-9).floor() * step;
        let max = (hi / step - 1e-9).ceil() * step;
        Axis { min, max, step }
    }

    pub fn ticks(&self) -> Vec<f64> {
        let first = (self.min / self.step - 1e-9).ceil();
        let last = (self.max / self.step + 1e-9).floor();
        if !(first.is_finite() && last.is_finite()) || last - first > 100.0 {
            return vec![self.min, self.max];
        }
        (first as i64..=last as i64)
            .map(|i| i as f64 * self.step)
            .collect()
    }

    /// Decimals needed to show the ticks.
    pub fn decimals(&self) -> usize {
        (-(self.step.log10() - 1e-9).floor()).max(0.0) as usize
    }
}

/// The plot frame, its tick labels and the x-axis label below it (shared by the curves and
/// the safety chart).
pub(crate) fn frame(
    o: &mut String,
    [left, top, right, bottom]: [f64; 4],
    ticks: &str,
    x_label: &str,
    h: f64,
) {
    let _ = writeln!(
        o,
        "<rect class=\"frame\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>",
        num(left),
        num(top),
        num(right - left),
        num(bottom - top)
    );
    let _ = writeln!(
        o,
        "<g class=\"ticks\" font-size=\"12\" fill=\"#333333\">\n{ticks}</g>"
    );
    let _ = writeln!(
        o,
        "<text x=\"{}\" y=\"{}\" font-size=\"13.5\" fill=\"#111111\" text-anchor=\"middle\">{}</text>",
        num((left + right) / 2.0),
        num(h - 14.0),
        esc(x_label)
    );
}

fn tick_label(v: f64, decimals: usize) -> String {
    let s = fmt_fixed(v, decimals);
    // A typographic minus reads better on axes.
    if let Some(rest) = s.strip_prefix('-') {
        format!("−{rest}")
    } else {
        s
    }
}

/// A finished plot: the SVG and where data points land.
#[derive(Clone, Debug)]
pub struct Plot {
    pub svg: String,
    pub x_axis: Axis,
    pub y_axis: Axis,
    /// Plot area in pixels: left, top, right, bottom.
    pub area: [f64; 4],
}

impl Plot {
    /// Pixel position of a data point.
    pub fn px(&self, x: f64, y: f64) -> [f64; 2] {
        let [l, t, r, b] = self.area;
        [
            l + (x - self.x_axis.min) / (self.x_axis.max - self.x_axis.min) * (r - l),
            b - (y - self.y_axis.min) / (self.y_axis.max - self.y_axis.min) * (b - t),
        ]
    }
}

/// Draw the series as one SVG plot.
pub fn plot_curves(series: &[Series], spec: &PlotSpec) -> String {
    plot(series, spec).svg
}

/// Draw the series as one SVG plot, keeping the axes. In stages: the layout (page size, axes
/// fitted to the data and marks, the plot area), the axes (grid, zero lines, frame, tick and
/// axis labels), the series, the marks, the legend.
pub fn plot(series: &[Series], spec: &PlotSpec) -> Plot {
    let l = PlotLayout::new(series, spec);
    let id = esc(&spec.id);
    let mut o = String::with_capacity(8192);
    l.head(&mut o, spec, &id);
    l.axes(&mut o, spec);
    let legend_rows = l.series(&mut o, series, &id);
    l.marks(&mut o, series, spec);
    l.legend(&mut o, series, spec, &legend_rows);
    o.push_str("</svg>\n");
    Plot {
        svg: o,
        x_axis: l.xa,
        y_axis: l.ya,
        area: [l.left, l.top, l.right, l.bottom],
    }
}

fn finite(p: &[f64; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// A legend row: label, colour, dashed, markers.
type LegendRow<'a> = (String, &'a str, bool, bool);

/// The page and the plot area of a plot, and its axes.
struct PlotLayout {
    w: f64,
    h: f64,
    xa: Axis,
    ya: Axis,
    xdec: usize,
    ydec: usize,
    left: f64,
    right: f64,
    top: f64,
    bottom: f64,
}

impl PlotLayout {
    fn new(series: &[Series], spec: &PlotSpec) -> PlotLayout {
        let w = if spec.width.is_finite() && spec.width >= 200.0 {
            spec.width
        } else {
            820.0
        };
        let h = if spec.height.is_finite() && spec.height >= 150.0 {
            spec.height
        } else {
            520.0
        };
        let mut xs: Vec<f64> = series
            .iter()
            .flat_map(|s| s.points.iter().filter(|p| finite(p)).map(|p| p[0]))
            .collect();
        let mut ys: Vec<f64> = series
            .iter()
            .flat_map(|s| s.points.iter().filter(|p| finite(p)).map(|p| p[1]))
            .collect();
        for m in spec
            .marks
            .iter()
            .filter(|m| m.x.is_finite() && m.y.is_finite())
        {
            xs.push(m.x);
            ys.push(m.y);
        }
        if spec.include_zero && !xs.is_empty() {
            xs.push(0.0);
            ys.push(0.0);
        }
        let range = |v: &[f64]| {
            v.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                })
        };
        let xa = match spec.x_range {
            Some((a, b)) => Axis::fit(a, b, true),
            None => {
                let (a, b) = range(&xs);
                Axis::fit(a, b, false)
            }
        };
        let ya = match spec.y_range {
            Some((a, b)) => Axis::fit(a, b, true),
            None => {
                let (a, b) = range(&ys);
                Axis::fit(a, b, false)
            }
        };
        let (xdec, ydec) = (xa.decimals(), ya.decimals());
        let ytick_w = ya
            .ticks()
            .iter()
            .map(|t| text_width(&tick_label(*t, ydec), 12.0))
            .fold(0.0f64, f64::max);
        let left = 40.0 + ytick_w + 16.0;
        let right = w - 24.0;
        let top = if spec.title.is_empty() { 24.0 } else { 52.0 };
        let bottom = h - 58.0;
        PlotLayout {
            w,
            h,
            xa,
            ya,
            xdec,
            ydec,
            left,
            right,
            top,
            bottom,
        }
    }

    fn px(&self, x: f64) -> f64 {
        self.left + (x - self.xa.min) / (self.xa.max - self.xa.min) * (self.right - self.left)
    }

    fn py(&self, y: f64) -> f64 {
        self.bottom - (y - self.ya.min) / (self.ya.max - self.ya.min) * (self.bottom - self.top)
    }

    /// The `<svg>` element, title, clip path, background and the plot's title.
    fn head(&self, o: &mut String, spec: &PlotSpec, id: &str) {
        let (w, h, left, top, right, bottom) =
            (self.w, self.h, self.left, self.top, self.right, self.bottom);
        let _ = writeln!(
            *o,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"{FONT}\">",
            w = num(w),
            h = num(h)
        );
        let _ = writeln!(
            *o,
            "<title>{}</title>",
            esc(if spec.title.is_empty() {
                "plot"
            } else {
                &spec.title
            })
        );
        let _ = writeln!(
            *o,
            "<defs><clipPath id=\"{id}-area\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath></defs>",
            num(left),
            num(top - 4.0),
            num(right - left),
            num(bottom - top + 8.0)
        );
        let _ = writeln!(
            *o,
            "<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>",
            num(w),
            num(h)
        );
        if !spec.title.is_empty() {
            let _ = writeln!(
                o,
                "<text x=\"{}\" y=\"30\" font-size=\"17\" fill=\"#111111\">{}</text>",
                num(left),
                esc(&spec.title)
            );
        }
    }

    /// Grid, zero lines, frame, tick labels and the axes' labels.
    fn axes(&self, o: &mut String, spec: &PlotSpec) {
        let (h, left, top, right, bottom) = (self.h, self.left, self.top, self.right, self.bottom);
        let (xa, ya, xdec, ydec) = (&self.xa, &self.ya, self.xdec, self.ydec);
        let px = |x: f64| self.px(x);
        let py = |y: f64| self.py(y);
        // Grid and ticks.
        let mut grid = String::new();
        let mut labels = String::new();
        for t in xa.ticks() {
            let x = px(t);
            let _ = write!(grid, "M{} {}L{} {}", num(x), num(top), num(x), num(bottom));
            let _ = writeln!(
                labels,
                "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
                num(x),
                num(bottom + 18.0),
                tick_label(t, xdec)
            );
        }
        for t in ya.ticks() {
            let y = py(t);
            let _ = write!(grid, "M{} {}L{} {}", num(left), num(y), num(right), num(y));
            let _ = writeln!(
                labels,
                "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
                num(left - 7.0),
                num(y + 4.0),
                tick_label(t, ydec)
            );
        }
        let _ = writeln!(
            *o,
            "<path class=\"grid\" d=\"{grid}\" stroke=\"#e4e4e4\" stroke-width=\"1\" fill=\"none\"/>"
        );
        // Zero lines, a little darker, when inside the range.
        let mut zero = String::new();
        if xa.min < 0.0 && xa.max > 0.0 {
            let _ = write!(
                zero,
                "M{} {}L{} {}",
                num(px(0.0)),
                num(top),
                num(px(0.0)),
                num(bottom)
            );
        }
        if ya.min < 0.0 && ya.max > 0.0 {
            let _ = write!(
                zero,
                "M{} {}L{} {}",
                num(left),
                num(py(0.0)),
                num(right),
                num(py(0.0))
            );
        }
        if !zero.is_empty() {
            let _ = writeln!(
                o,
                "<path d=\"{zero}\" stroke=\"#9a9a9a\" stroke-width=\"1\" fill=\"none\"/>"
            );
        }
        frame(o, [left, top, right, bottom], &labels, &spec.x_label, h);
        let _ = writeln!(
            *o,
            "<text transform=\"translate(20 {}) rotate(-90)\" font-size=\"13.5\" fill=\"#111111\" text-anchor=\"middle\">{}</text>",
            num((top + bottom) / 2.0),
            esc(&spec.y_label)
        );
    }

    /// The series, clipped to the plot area; returns the legend's rows.
    fn series<'s>(&self, o: &mut String, series: &'s [Series], id: &str) -> Vec<LegendRow<'s>> {
        let px = |x: f64| self.px(x);
        let py = |y: f64| self.py(y);
        // Series.
        let mut legend_rows: Vec<LegendRow> = Vec::new();
        for (i, s) in series.iter().enumerate() {
            let colour = s
                .colour
                .as_deref()
                .unwrap_or(SERIES_COLOURS[i % SERIES_COLOURS.len()]);
            let dashed = s.dashed || (i >= SERIES_COLOURS.len() && s.colour.is_none());
            let mut d = String::new();
            let mut run: Vec<[f64; 2]> = Vec::new();
            let flush = |d: &mut String, run: &mut Vec<[f64; 2]>| {
                if run.len() >= 2 {
                    polyline_path(d, run.drain(..));
                }
                run.clear();
            };
            for p in &s.points {
                if finite(p) {
                    run.push([px(p[0]), py(p[1])]);
                } else {
                    flush(&mut d, &mut run);
                }
            }
            flush(&mut d, &mut run);
            let _ = write!(*o, "<g class=\"series\" clip-path=\"url(#{id}-area)\">");
            if !d.is_empty() {
                let _ = write!(
                    *o,
                    "<path d=\"{d}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2.2\" stroke-linejoin=\"round\" stroke-linecap=\"round\"{}/>",
                    esc(colour),
                    if dashed { " stroke-dasharray=\"7 4\"" } else { "" }
                );
            }
            let lone = s.points.iter().filter(|p| finite(p)).count() == 1;
            if s.markers || lone {
                for p in s.points.iter().filter(|p| finite(p)) {
                    let _ = write!(
                        *o,
                        "<circle cx=\"{}\" cy=\"{}\" r=\"3.2\" fill=\"{}\" stroke=\"#ffffff\" stroke-width=\"0.8\"/>",
                        num(px(p[0])),
                        num(py(p[1])),
                        esc(colour)
                    );
                }
            }
            o.push_str("</g>\n");
            if !s.label.is_empty() {
                legend_rows.push((s.label.clone(), colour, dashed, s.markers));
            }
        }
        legend_rows
    }

    /// The marks: a ring and a label beside it, on a white box, placed where the box crosses
    /// no curve, no other label and stays in the plot area (the first of the places around
    /// the ring that does; else the one crossing fewest curve segments).
    fn marks(&self, o: &mut String, series: &[Series], spec: &PlotSpec) {
        let (left, top, right, bottom) = (self.left, self.top, self.right, self.bottom);
        let px = |x: f64| self.px(x);
        let py = |y: f64| self.py(y);
        let segments: Vec<([f64; 2], [f64; 2])> = series
            .iter()
            .flat_map(|s| s.points.windows(2))
            .filter(|w2| finite(&w2[0]) && finite(&w2[1]))
            .map(|w2| ([px(w2[0][0]), py(w2[0][1])], [px(w2[1][0]), py(w2[1][1])]))
            .collect();
        let mut placed: Vec<[f64; 4]> = Vec::new();
        for m in spec
            .marks
            .iter()
            .filter(|m| m.x.is_finite() && m.y.is_finite())
        {
            let (x, y) = (px(m.x), py(m.y));
            if x < left - 1.0 || x > right + 1.0 || y < top - 1.0 || y > bottom + 1.0 {
                continue;
            }
            let (fs, ring) = (12.5, 6.0);
            let tw = mark_label_width(&m.label, fs);
            let place = mark_label_place(
                x,
                y,
                tw,
                fs,
                ring,
                [left, top, right, bottom],
                &segments,
                &placed,
            );
            placed.push(place.bbox);
            let [bx0, by0, bx1, by1] = place.bbox;
            let _ = writeln!(
                *o,
                "<g class=\"mark\"><circle cx=\"{}\" cy=\"{}\" r=\"{ring}\" fill=\"none\" stroke=\"#111111\" stroke-width=\"1.6\"/><rect class=\"mark-box\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#ffffff\" fill-opacity=\"0.9\" rx=\"2\"/><text x=\"{}\" y=\"{}\" font-size=\"{fs}\" fill=\"#111111\" text-anchor=\"{}\">{}</text></g>",
                num(x),
                num(y),
                num(bx0),
                num(by0),
                num(bx1 - bx0),
                num(by1 - by0),
                num(place.x),
                num(place.y),
                place.anchor,
                esc(&m.label)
            );
        }
    }

    /// The legend, in the emptiest corner of the plot area.
    fn legend(
        &self,
        o: &mut String,
        series: &[Series],
        spec: &PlotSpec,
        legend_rows: &[LegendRow],
    ) {
        let (left, top, right, bottom) = (self.left, self.top, self.right, self.bottom);
        let px = |x: f64| self.px(x);
        let py = |y: f64| self.py(y);
        // Legend in the emptiest corner.
        if !legend_rows.is_empty() {
            let fs = 12.5;
            let lw = 44.0
                + legend_rows
                    .iter()
                    .map(|r| text_width(&r.0, fs))
                    .fold(0.0f64, f64::max)
                + 12.0;
            let lh = 10.0 + 20.0 * legend_rows.len() as f64;
            let corners = [
                (right - lw - 10.0, top + 10.0),
                (left + 10.0, top + 10.0),
                (right - lw - 10.0, bottom - lh - 10.0),
                (left + 10.0, bottom - lh - 10.0),
            ];
            let count = |(cx, cy): (f64, f64)| -> usize {
                let mut n = 0;
                for s in series {
                    // Sample along the segments so that lines, not only vertices, count.
                    for w2 in s.points.windows(2) {
                        if !(finite(&w2[0]) && finite(&w2[1])) {
                            continue;
                        }
                        for k in 0..=8 {
                            let t = k as f64 / 8.0;
                            let x = px(w2[0][0] + t * (w2[1][0] - w2[0][0]));
                            let y = py(w2[0][1] + t * (w2[1][1] - w2[0][1]));
                            if x >= cx - 6.0
                                && x <= cx + lw + 6.0
                                && y >= cy - 6.0
                                && y <= cy + lh + 6.0
                            {
                                n += 1;
                            }
                        }
                    }
                }
                for m in &spec.marks {
                    let (x, y) = (px(m.x), py(m.y));
                    if x >= cx - 20.0
                        && x <= cx + lw + 20.0
                        && y >= cy - 20.0
                        && y <= cy + lh + 20.0
                    {
                        n += 50;
                    }
                }
                n
            };
            let mut best = corners[0];
            let mut best_n = usize::MAX;
            for c in corners {
                let n = count(c);
                if n < best_n {
                    best_n = n;
                    best = c;
                }
            }
            let (lx, ly) = best;
            let _ = writeln!(
                *o,
                "<g class=\"legend\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#ffffff\" fill-opacity=\"0.92\" stroke=\"#bbbbbb\" stroke-width=\"1\" rx=\"3\"/>",
                num(lx),
                num(ly),
                num(lw),
                num(lh)
            );
            for (i, (label, colour, dashed, markers)) in legend_rows.iter().enumerate() {
                let y = ly + 15.0 + 20.0 * i as f64;
                let _ = write!(
                    *o,
                    "<path d=\"M{} {}L{} {}\" stroke=\"{}\" stroke-width=\"2.2\"{}/>",
                    num(lx + 8.0),
                    num(y),
                    num(lx + 36.0),
                    num(y),
                    esc(colour),
                    if *dashed {
                        " stroke-dasharray=\"7 4\""
                    } else {
                        ""
                    }
                );
                if *markers {
                    let _ = write!(
                        o,
                        "<circle cx=\"{}\" cy=\"{}\" r=\"3.2\" fill=\"{}\"/>",
                        num(lx + 22.0),
                        num(y),
                        esc(colour)
                    );
                }
                let _ = writeln!(
                    *o,
                    "<text x=\"{}\" y=\"{}\" font-size=\"{fs}\" fill=\"#222222\">{}</text>",
                    num(lx + 44.0),
                    num(y + 4.5),
                    esc(label)
                );
            }
            o.push_str("</g>\n");
        }
    }
}

/// Width of a mark's label with 8 % to spare (for a browser's substitute font).
pub(crate) fn mark_label_width(label: &str, fs: f64) -> f64 {
    1.08 * text_width(label, fs)
}

/// Where a mark's label goes: its text position and anchor, and the box it takes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LabelPlace {
    pub x: f64,
    pub y: f64,
    pub anchor: &'static str,
    /// `[x0, y0, x1, y1]` in pixels.
    pub bbox: [f64; 4],
}

/// The place of a label `tw` pixels wide beside a ring of radius `ring` at `(x, y)` in the
/// plot area `area`: the first of eight places (above right, below right, above left, below
/// left, right, left, then farther above and below) whose box stays in the area and meets no
/// segment and no box in `taken`; else the one meeting fewest segments.
#[allow(clippy::too_many_arguments)]
pub(crate) fn mark_label_place(
    x: f64,
    y: f64,
    tw: f64,
    fs: f64,
    ring: f64,
    area: [f64; 4],
    segments: &[([f64; 2], [f64; 2])],
    taken: &[[f64; 4]],
) -> LabelPlace {
    let pad = 2.0;
    let gap = ring + 4.0;
    let place = |dx: f64, dy: f64, start: bool| {
        let tx = if start { x + dx } else { x - dx };
        let ty = y + dy;
        let (x0, x1) = if start { (tx, tx + tw) } else { (tx - tw, tx) };
        LabelPlace {
            x: tx,
            y: ty,
            anchor: if start { "start" } else { "end" },
            bbox: [
                x0 - pad,
                ty - 0.8 * fs - pad,
                x1 + pad,
                ty + 0.25 * fs + pad,
            ],
        }
    };
    let above = -gap;
    let below = gap + 0.8 * fs;
    let candidates = [
        place(gap, above, true),
        place(gap, below, true),
        place(gap, above, false),
        place(gap, below, false),
        place(gap + 2.0, 0.3 * fs, true),
        place(gap + 2.0, 0.3 * fs, false),
        place(gap, above - fs - 6.0, true),
        place(gap, below + fs + 6.0, true),
        place(gap, above - fs - 6.0, false),
        place(gap, below + fs + 6.0, false),
    ];
    let inside =
        |b: &[f64; 4]| b[0] >= area[0] && b[2] <= area[2] && b[1] >= area[1] && b[3] <= area[3];
    let overlaps =
        |b: &[f64; 4], c: &[f64; 4]| b[0] < c[2] && c[0] < b[2] && b[1] < c[3] && c[1] < b[3];
    // Curves are drawn 2.2 pixels wide: a box within 1.5 pixels of one is struck through.
    let crossings = |b: &[f64; 4]| {
        let g = [b[0] - 1.5, b[1] - 1.5, b[2] + 1.5, b[3] + 1.5];
        segments
            .iter()
            .filter(|(p, q)| segment_meets_box(*p, *q, g))
            .count()
    };
    let ring_box = [
        x - ring - 1.0,
        y - ring - 1.0,
        x + ring + 1.0,
        y + ring + 1.0,
    ];
    let mut best: Option<(usize, LabelPlace)> = None;
    for c in candidates {
        if !inside(&c.bbox) || overlaps(&c.bbox, &ring_box) {
            continue;
        }
        let n = crossings(&c.bbox) + 1000 * taken.iter().filter(|t| overlaps(&c.bbox, t)).count();
        if n == 0 {
            return c;
        }
        if best.as_ref().is_none_or(|(m, _)| n < *m) {
            best = Some((n, c));
        }
    }
    best.map_or(candidates[0], |(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_fits_on_nice_ticks() {
        let a = Axis::fit(0.0, 0.434, false);
        assert_eq!(a.step, 0.05);
        assert!(
            (a.min - 0.0).abs() < 1e-12 && (a.max - 0.45).abs() < 1e-12,
            "{a:?}"
        );
        assert_eq!(a.ticks().len(), 10);
        assert_eq!(a.decimals(), 2);
        let b = Axis::fit(-3.2, 7.9, false);
        assert_eq!(b.step, 2.0);
        assert_eq!((b.min, b.max), (-4.0, 8.0));
        assert_eq!(tick_label(-4.0, b.decimals()), "−4");
    }
}
