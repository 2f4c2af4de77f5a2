//! The legend under a structure drawing (2D and 3D): entries (a symbol and its label, the
//! scale bar, plain texts) flowed left to right and wrapped onto new rows so that every entry
//! fits within the figure. Widths are measured conservatively: [`label_width`] adds 10 % to
//! [`text_width`] (which estimates the bundled DejaVu Sans) for a browser that draws the SVG
//! with a wider substitute font; a label wider than the figure on its own is broken into lines.

use super::chrome::wrap;
use super::svg::{esc, human, nice, num, text_width};
use std::fmt::Write as _;

/// Font size of legend texts.
pub(crate) const FS: f64 = 12.5;
/// Distance between rows.
pub(crate) const ROW: f64 = 22.0;
/// Distance between the lines of a wrapped label.
const LINE: f64 = 17.0;
/// Space after an entry.
const GAP: f64 = 24.0;
/// Width of a symbol and the space before its label.
const LEAD: f64 = 28.0;

/// What stands before an entry's label.
#[derive(Clone, Debug)]
pub(crate) enum Lead {
    /// An SVG symbol drawn at the entry's origin (22 × 12 pixels, centred on the row).
    Symbol(String),
    /// A scale bar `px` pixels long; its label is the bar's length.
    Bar { px: f64 },
    /// Text only.
    Text,
}

#[derive(Clone, Debug)]
pub(crate) struct Entry {
    pub lead: Lead,
    /// The label as plain text (measured, wrapped and escaped).
    pub label: String,
    /// SVG content written instead of the escaped label when it is not wrapped (a `tspan`
    /// the report's slider updates).
    pub markup: Option<String>,
    pub colour: &'static str,
    /// Start a new row.
    pub break_before: bool,
}

impl Entry {
    pub fn symbol(symbol: String, label: impl Into<String>) -> Entry {
        Entry {
            lead: Lead::Symbol(symbol),
            label: label.into(),
            markup: None,
            colour: "#333333",
            break_before: false,
        }
    }

    pub fn text(label: impl Into<String>, colour: &'static str) -> Entry {
        Entry {
            lead: Lead::Text,
            label: label.into(),
            markup: None,
            colour,
            break_before: false,
        }
    }

    /// The scale bar of a drawing of a model `size` metres across at `k` pixels per metre: a
    /// round length near 18 % of the size, on a new row.
    pub fn scale_bar(size: f64, k: f64) -> Entry {
        let bar_m = nice(0.18 * size, true);
        let label = if bar_m >= 1.0 {
            format!("{} m", human(bar_m, 3))
        } else {
            format!("{} cm", human(bar_m * 100.0, 3))
        };
        Entry {
            lead: Lead::Bar { px: bar_m * k },
            label,
            markup: None,
            colour: "#333333",
            break_before: true,
        }
    }

    fn lead_width(&self) -> f64 {
        match &self.lead {
            Lead::Symbol(_) => LEAD,
            Lead::Bar { px } => px + 8.0,
            Lead::Text => 0.0,
        }
    }
}

/// The legend of the live-load arrows, which are drawn in proportion to the loads (the largest
/// 9 % of the model's size, none shorter than a quarter of it): the factored load when the
/// analysis gives λ ("live load × λ at collapse: largest 2.302 × 0.288 = 0.663 kN"), the tilt
/// load λ·W with α and its direction on a tilting table, else the load as given ("unfactored").
pub(crate) fn live_load_label(
    lambda: Option<f64>,
    tilt: Option<(f64, String)>,
    largest: f64,
) -> String {
    let q = human(largest, 3);
    match (lambda.filter(|l| l.is_finite()), tilt) {
        (Some(l), Some((alpha, towards))) => format!(
            "tilt load λ·W {towards}, λ = tan α, α = {}°: largest {} × {q} = {} kN",
            human(alpha, 4),
            human(l, 4),
            human(l * largest, 3)
        ),
        (Some(l), None) => format!(
            "live load × λ at collapse: largest {} × {q} = {} kN",
            human(l, 4),
            human(l * largest, 3)
        ),
        (None, _) => format!("live load, unfactored (largest {q} kN)"),
    }
}

/// Width of a legend text at font size `fs`, with 10 % to spare.
pub(crate) fn label_width(s: &str, fs: f64) -> f64 {
    1.1 * text_width(s, fs)
}

/// Where each entry goes: `(x, row offset from the first row, lines of its label)`.
pub(crate) struct Layout {
    pub places: Vec<(f64, f64, Vec<String>)>,
    /// Height of the rows (a wrapped label's lines are [`LINE`] apart).
    pub height: f64,
}

/// Entries flowed between `left` and `right`.
pub(crate) fn layout(entries: &[Entry], left: f64, right: f64) -> Layout {
    let avail = (right - left).max(40.0);
    let (mut x, mut y) = (left, 0.0);
    let mut row_lines = 1usize;
    let mut places = Vec::with_capacity(entries.len());
    for e in entries {
        let lead = e.lead_width();
        let w = lead + label_width(&e.label, FS);
        if x > left && (e.break_before || x + w > right) {
            y += ROW + LINE * (row_lines - 1) as f64;
            x = left;
            row_lines = 1;
        }
        let lines = if lead + label_width(&e.label, FS) > avail {
            wrap(&e.label, FS, ((avail - lead) / 1.1).max(20.0))
        } else {
            vec![e.label.clone()]
        };
        let widest = lines
            .iter()
            .map(|l| label_width(l, FS))
            .fold(0.0f64, f64::max);
        row_lines = row_lines.max(lines.len());
        places.push((x, y, lines));
        x += lead + widest + GAP;
    }
    Layout {
        places,
        height: y + ROW + LINE * (row_lines - 1) as f64,
    }
}

/// Height of a legend whose rows are `rows_height` high (its rule, rows and the space under
/// them).
pub(crate) fn height(rows_height: f64) -> f64 {
    14.0 + rows_height.max(ROW)
}

/// Write the legend: a rule at `top` from `left` to `right`, then the entries.
pub(crate) fn write(o: &mut String, entries: &[Entry], left: f64, right: f64, top: f64) {
    let _ = writeln!(
        o,
        "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#dddddd\" stroke-width=\"1\"/>",
        num(left),
        num(top),
        num(right),
        num(top)
    );
    let l = layout(entries, left, right);
    let _ = writeln!(o, "<g class=\"legend\">");
    for (e, (x, dy, lines)) in entries.iter().zip(&l.places) {
        let y = top + 16.0 + dy;
        match &e.lead {
            Lead::Symbol(s) => {
                let _ = writeln!(
                    o,
                    "<g transform=\"translate({} {})\">{s}</g>",
                    num(*x),
                    num(y)
                );
            }
            Lead::Bar { px } => {
                let _ = writeln!(
                    o,
                    "<g stroke=\"#333333\" stroke-width=\"1.2\"><path d=\"M{x0} {ya}L{x0} {yb}M{x0} {y}L{x1} {y}M{x1} {ya}L{x1} {yb}\" fill=\"none\"/></g>",
                    x0 = num(*x),
                    x1 = num(x + px),
                    y = num(y),
                    ya = num(y - 4.0),
                    yb = num(y + 4.0)
                );
            }
            Lead::Text => {}
        }
        let tx = x + e.lead_width();
        for (i, line) in lines.iter().enumerate() {
            let content = match (&e.markup, lines.len()) {
                (Some(m), 1) => m.clone(),
                _ => esc(line),
            };
            let _ = writeln!(
                o,
                "<text x=\"{}\" y=\"{}\" font-size=\"{FS}\" fill=\"{}\">{content}</text>",
                num(tx),
                num(y + 4.5 + LINE * i as f64),
                e.colour
            );
        }
    }
    o.push_str("</g>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_wrap_within_the_width() {
        let entries: Vec<Entry> = (0..9)
            .map(|i| Entry::text(format!("entry number {i} with a long label"), "#333333"))
            .chain(std::iter::once(Entry::text(
                "a label much longer than the figure is wide, which must be broken into lines",
                "#333333",
            )))
            .collect();
        for right in [200.0, 600.0, 1000.0] {
            let l = layout(&entries, 28.0, right);
            for (x, _, lines) in &l.places {
                for line in lines {
                    assert!(x + label_width(line, FS) <= right + 1e-9, "{line} at {x}");
                }
            }
        }
    }
}
