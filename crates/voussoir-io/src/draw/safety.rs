//! Pictures of the safety assessment (`voussoir safety`): the range of every support reaction
//! component over the statically admissible states, as one bar per component on a common force
//! axis (kN), with whether the structure stands and its geometric safety factor in the title
//! block; and the report. A safety result has no geometry, so the figure is this chart (2D and
//! 3D alike: 3D adds `fz`).

use super::plot::Axis;
use super::report::{Report, ReportOptions};
use super::svg::{esc, fmt_fixed, human, num, text_width, FONT};
use std::fmt::Write as _;
use voussoir::result::SafetyResult;

/// The default title of the figure.
pub fn safety_title(r: &SafetyResult) -> String {
    if r.stands {
        "Safety: the structure stands under its dead loads".to_string()
    } else {
        "Safety: the structure does not stand under its dead loads".to_string()
    }
}

/// The line of key numbers under the title.
pub fn safety_info(r: &SafetyResult) -> String {
    match (r.geometric_safety_factor, r.least_joint_fraction) {
        (Some(g), Some(f)) => format!(
            "geometric safety factor {}   ·   least joint fraction {} %",
            fmt_fixed(g, 4),
            fmt_fixed(100.0 * f, 2)
        ),
        (None, Some(f)) => format!(
            "geometric safety factor unbounded   ·   least joint fraction {} %",
            fmt_fixed(100.0 * f, 2)
        ),
        _ => r.message.clone(),
    }
}

/// "[11.07, 11.23] kN", with "−∞"/"+∞" for an unbounded side.
pub fn range_text(min: Option<f64>, max: Option<f64>) -> String {
    let show = |x: f64| {
        let t = human(x, 5);
        t.strip_prefix('-').map_or(t.clone(), |r| format!("−{r}"))
    };
    let lo = min.map_or("−∞".to_string(), show);
    let hi = max.map_or("+∞".to_string(), show);
    format!("[{lo}, {hi}] kN")
}

/// The chart of the admissible reaction ranges (SVG), one row per support and component: a bar
/// from the least to the largest value (an arrow where a side is unbounded), the values beside.
pub fn safety_figure(r: &SafetyResult, title: &str) -> String {
    let rows: Vec<(String, Option<f64>, Option<f64>)> = r
        .reactions
        .iter()
        .flat_map(|s| {
            s.components
                .iter()
                .map(|c| (format!("{} {}", s.support, c.component), c.min, c.max))
        })
        .collect();
    let finite: Vec<f64> = rows
        .iter()
        .flat_map(|(_, a, b)| [*a, *b])
        .flatten()
        .filter(|x| x.is_finite())
        .chain([0.0])
        .collect();
    let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let axis = Axis::fit(lo, hi, false);
    let w = 820.0;
    let fs = 12.5;
    let label_w = rows
        .iter()
        .map(|(l, _, _)| text_width(l, fs))
        .fold(60.0f64, f64::max);
    let value_w = rows
        .iter()
        .map(|(_, a, b)| text_width(&range_text(*a, *b), fs))
        .fold(80.0f64, f64::max);
    let left = 24.0 + label_w + 14.0;
    let right = w - 24.0 - value_w - 14.0;
    let info = safety_info(r);
    let top = 86.0;
    let row_h = 26.0;
    let bottom = top + row_h * rows.len().max(1) as f64;
    let h = bottom + 62.0;
    let px = |x: f64| left + (x - axis.min) / (axis.max - axis.min) * (right - left);

    let mut o = String::with_capacity(4096);
    let _ = writeln!(
        o,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"{FONT}\">",
        w = num(w),
        h = num(h)
    );
    let _ = writeln!(o, "<title>{}</title>", esc(title));
    let _ = writeln!(
        o,
        "<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>",
        num(w),
        num(h)
    );
    let _ = writeln!(
        o,
        "<text x=\"24\" y=\"30\" font-size=\"17\" fill=\"#111111\">{}</text>",
        esc(title)
    );
    let _ = writeln!(
        o,
        "<text class=\"info\" x=\"24\" y=\"52\" font-size=\"13\" fill=\"#333333\">{}</text>",
        esc(&info)
    );
    if rows.is_empty() {
        let _ = writeln!(
            o,
            "<text x=\"24\" y=\"{}\" font-size=\"13\" fill=\"#333333\">no reaction ranges in this result</text>",
            num(top + 16.0)
        );
        o.push_str("</svg>\n");
        return o;
    }
    let _ = writeln!(
        o,
        "<text x=\"{}\" y=\"74\" font-size=\"12.5\" fill=\"#333333\" text-anchor=\"middle\">admissible range of each support reaction component (kN, the force on the structure)</text>",
        num((left + right) / 2.0)
    );
    // Grid, ticks and the zero line.
    let mut grid = String::new();
    let mut ticks = String::new();
    let dec = axis.decimals();
    for t in axis.ticks() {
        let x = px(t);
        let _ = write!(grid, "M{} {}L{} {}", num(x), num(top), num(x), num(bottom));
        let label = fmt_fixed(t, dec);
        let label = label
            .strip_prefix('-')
            .map_or(label.clone(), |r| format!("−{r}"));
        let _ = writeln!(
            ticks,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            num(x),
            num(bottom + 18.0),
            label
        );
    }
    let _ = writeln!(
        o,
        "<path class=\"grid\" d=\"{grid}\" stroke=\"#e4e4e4\" stroke-width=\"1\" fill=\"none\"/>"
    );
    if axis.min < 0.0 && axis.max > 0.0 {
        let _ = writeln!(
            o,
            "<path d=\"M{} {}L{} {}\" stroke=\"#9a9a9a\" stroke-width=\"1\" fill=\"none\"/>",
            num(px(0.0)),
            num(top),
            num(px(0.0)),
            num(bottom)
        );
    }
    super::plot::frame(
        &mut o,
        [left, top, right, bottom],
        &ticks,
        "reaction force (kN)",
        h,
    );
    // The bars.
    let colour = "#1f5fbf";
    let _ = writeln!(
        o,
        "<g class=\"ranges\" font-size=\"{fs}\" fill=\"#222222\">"
    );
    for (i, (label, a, b)) in rows.iter().enumerate() {
        let y = top + row_h * (i as f64 + 0.5);
        let _ = write!(
            o,
            "<g class=\"range\"><text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            num(left - 10.0),
            num(y + 4.5),
            esc(label)
        );
        let x0 = a.filter(|x| x.is_finite()).map_or(left, px);
        let x1 = b.filter(|x| x.is_finite()).map_or(right, px);
        // A range narrower than a few pixels is a dot at its middle.
        if (x1 - x0).abs() < 4.0 {
            let _ = write!(
                o,
                "<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"{colour}\"/>",
                num((x0 + x1) / 2.0),
                num(y)
            );
        } else {
            let _ = write!(
                o,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"10\" fill=\"{colour}\" fill-opacity=\"0.75\"/>",
                num(x0.min(x1)),
                num(y - 5.0),
                num((x1 - x0).abs())
            );
        }
        // Unbounded sides: an arrow head at the frame.
        if a.is_none() {
            let _ = write!(
                o,
                "<path class=\"unbounded\" d=\"M{} {}L{} {}L{} {}Z\" fill=\"{colour}\"/>",
                num(left - 1.0),
                num(y),
                num(left + 9.0),
                num(y - 8.0),
                num(left + 9.0),
                num(y + 8.0)
            );
        }
        if b.is_none() {
            let _ = write!(
                o,
                "<path class=\"unbounded\" d=\"M{} {}L{} {}L{} {}Z\" fill=\"{colour}\"/>",
                num(right + 1.0),
                num(y),
                num(right - 9.0),
                num(y - 8.0),
                num(right - 9.0),
                num(y + 8.0)
            );
        }
        let _ = writeln!(
            o,
            "<text class=\"value\" x=\"{}\" y=\"{}\">{}</text></g>",
            num(right + 12.0),
            num(y + 4.5),
            esc(&range_text(*a, *b))
        );
    }
    o.push_str("</g>\n</svg>\n");
    o
}

/// Report of a safety assessment: hypotheses and inputs (`opts.inputs`, with the model as the
/// command built it: a safety result carries no geometry), then the results — whether the
/// structure stands, the safety factors computed with their definitions, the admissible ranges
/// of the support reactions (table and chart).
pub fn safety_report(r: &SafetyResult, opts: &ReportOptions) -> Report {
    use crate::report_parts::{self as rp, Analysis};
    let title = opts
        .title
        .clone()
        .unwrap_or_else(|| "Safety assessment".to_string());
    let mut rep = Report::new(title);
    rep.subtitle = r.message.clone();
    rep.source = opts.source.clone();
    rep.command = opts
        .inputs
        .as_ref()
        .map(|i| i.command.clone())
        .filter(|c| !c.is_empty())
        .unwrap_or_else(|| "safety".into());
    let cert = vec![
        (
            "bisection on the joint fraction".to_string(),
            format!("to {} (absolute)", human(r.tolerance, 3)),
        ),
        ("LP solves".to_string(), r.solves.to_string()),
    ];
    rep.sections.extend(rp::front_matter(
        None,
        opts.inputs.as_ref(),
        Analysis::Safety,
        &opts.source,
        Some(&r.solver),
        cert,
    ));
    let mut kv = vec![(
        "stands under its dead loads".to_string(),
        if r.stands { "yes" } else { "no" }.to_string(),
    )];
    kv.push((
        "geometric safety factor (Heyman) = 1 / least joint fraction".into(),
        match (r.geometric_safety_factor, r.least_joint_fraction) {
            (Some(g), _) => fmt_fixed(g, 6),
            (None, Some(_)) => "unbounded (the dead loads pass through the joints' centres)".into(),
            _ => "not computed (the structure does not stand)".into(),
        },
    ));
    kv.push((
        "least joint fraction".into(),
        r.least_joint_fraction
            .map_or("not computed (the structure does not stand)".into(), |f| {
                format!("{} %", fmt_fixed(100.0 * f, 4))
            }),
    ));
    let res = rep.section("Results");
    res.key_values(kv);
    res.items.push(super::report::Item::List(vec![
        "Geometric safety factor: every joint is shrunk about its centre to the same fraction f of its extent (thickness); the least f at which contact forces still balance the dead loads within the shrunk joints is found by bisection, and the factor is 1 / f (Heyman: the thickness of the structure over the least thickness that carries its weight; 1 means just standing).".to_string(),
        "Reaction ranges: the least and largest value of each support reaction component over every statically admissible state of the full joints (two LPs per component); the actual reactions lie between them, and a settlement moves them to an end (for an arch, the least and largest horizontal thrust).".to_string(),
    ]));
    if r.reactions.is_empty() {
        res.text(if r.stands {
            "Reaction ranges: not computed (--no-ranges)."
        } else {
            "Reaction ranges: none (no admissible state)."
        });
    } else {
        let rows = r
            .reactions
            .iter()
            .flat_map(|s| {
                s.components.iter().map(|c| {
                    vec![
                        s.support.clone(),
                        c.component.clone(),
                        c.min.map_or("unbounded".into(), |x| fmt_fixed(x, 6)),
                        c.max.map_or("unbounded".into(), |x| fmt_fixed(x, 6)),
                    ]
                })
            })
            .collect();
        res.table(
            "Admissible support reactions (force of each support on the structure)",
            ["support", "component", "least (kN)", "largest (kN)"]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            rows,
        );
        rep.section("Figures").figure(
            safety_figure(r, &safety_title(r)),
            "The range of every support reaction component over the statically admissible states (kN); an arrow: unbounded on that side.",
        );
    }
    rep
}
