//! The distribution of the capacity after the settlements of a sweep (`voussoir sweep
//! --capacity`): a histogram and an exceedance curve of λ after the settlement, and the HTML
//! report with the quantiles.

use super::plot::{plot, Mark, Plot, PlotSpec, Series};
use super::report::{Report, ReportOptions};
use super::svg::{fmt_fixed, human};
use voussoir::result::sweep::{capacity_summary, CapacitySummary, SweepRecord};

/// λ after the settlement of every record that has a finite one, sorted.
pub fn capacity_values(records: &[SweepRecord]) -> Vec<f64> {
    let mut v: Vec<f64> = records
        .iter()
        .filter_map(|r| r.capacity.as_ref()?.load_multiplier_after)
        .filter(|l| l.is_finite())
        .collect();
    v.sort_by(f64::total_cmp);
    v
}

/// Bin edges and counts of sorted `values`: `bins` equal bins over `[min, max]` (a value on an
/// inner edge goes to the bin above it, the largest to the last bin).
pub fn histogram(sorted: &[f64], bins: usize) -> (Vec<f64>, Vec<usize>) {
    let bins = bins.max(1);
    let (Some(&lo), Some(&hi)) = (sorted.first(), sorted.last()) else {
        return (vec![], vec![]);
    };
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        let d = (1e-3 * lo.abs()).max(1e-9);
        (lo - d, hi + d)
    };
    let w = (hi - lo) / bins as f64;
    let edges: Vec<f64> = (0..=bins).map(|i| lo + w * i as f64).collect();
    let mut counts = vec![0usize; bins];
    for &v in sorted {
        let i = (((v - lo) / w).floor() as usize).min(bins - 1);
        counts[i] += 1;
    }
    (edges, counts)
}

/// Bins for `n` values: 2√n, between 5 and 60.
pub fn default_bins(n: usize) -> usize {
    ((2.0 * (n as f64).sqrt()).ceil() as usize).clamp(5, 60)
}

/// The histogram as one series: its outline, then the bars' inner edges (gaps between
/// segments are non-finite points).
fn histogram_series(edges: &[f64], counts: &[usize]) -> Series {
    let mut pts = Vec::with_capacity(4 * counts.len() + 2);
    if let Some(&e0) = edges.first() {
        pts.push([e0, 0.0]);
    }
    for (i, &c) in counts.iter().enumerate() {
        pts.push([edges[i], c as f64]);
        pts.push([edges[i + 1], c as f64]);
    }
    if let Some(&e) = edges.last() {
        pts.push([e, 0.0]);
    }
    for i in 1..counts.len() {
        let h = counts[i - 1].min(counts[i]) as f64;
        if h > 0.0 {
            pts.push([f64::NAN, f64::NAN]);
            pts.push([edges[i], 0.0]);
            pts.push([edges[i], h]);
        }
    }
    Series {
        colour: Some("#1f5fbf".into()),
        ..Series::new("samples per bin", pts)
    }
}

/// The histogram of λ after the settlement, with λ without settlement as a dashed line.
pub fn capacity_histogram(records: &[SweepRecord], title: &str) -> Plot {
    let v = capacity_values(records);
    let (edges, counts) = histogram(&v, default_bins(v.len()));
    let top = counts.iter().copied().max().unwrap_or(0) as f64;
    let mut series = vec![histogram_series(&edges, &counts)];
    // The samples where limit analysis on the deformed geometry is not valid at the last step,
    // over the same bins.
    let invalid: Vec<f64> = records
        .iter()
        .filter_map(|r| r.capacity.as_ref())
        .filter(|c| !c.valid_after)
        .filter_map(|c| c.load_multiplier_after)
        .filter(|l| l.is_finite())
        .collect();
    if !invalid.is_empty() && edges.len() >= 2 {
        let mut bad = vec![0usize; counts.len()];
        let (lo, w) = (edges[0], edges[1] - edges[0]);
        for l in &invalid {
            bad[(((l - lo) / w).floor().max(0.0) as usize).min(counts.len() - 1)] += 1;
        }
        let mut s = histogram_series(&edges, &bad);
        s.label = "of which not valid (the collapse mechanism closes settlement cracks)".into();
        s.colour = Some("#e08214".into());
        series.push(s.dashed());
    }
    if let Some(l0) = capacity_summary(records).and_then(|s| s.load_multiplier_before) {
        series.push(Series {
            colour: Some("#d7301f".into()),
            ..Series::new(
                format!("λ without settlement = {}", fmt_fixed(l0, 4)),
                vec![[l0, 0.0], [l0, top.max(1.0)]],
            )
            .dashed()
        });
    }
    plot(
        &series,
        &PlotSpec {
            title: title.to_string(),
            x_label: "load multiplier λ after the settlement".into(),
            y_label: "number of samples".into(),
            height: 420.0,
            include_zero: false,
            id: "hist".into(),
            ..PlotSpec::default()
        },
    )
}

/// The empirical exceedance curve `P(Λ > λ)` of sorted values (a right-continuous staircase).
pub fn exceedance_points(sorted: &[f64]) -> Vec<[f64; 2]> {
    let n = sorted.len() as f64;
    let mut pts = Vec::with_capacity(2 * sorted.len());
    for (i, &x) in sorted.iter().enumerate() {
        pts.push([x, (n - i as f64) / n]);
        pts.push([x, (n - i as f64 - 1.0) / n]);
    }
    pts
}

/// The exceedance curve of λ after the settlement, with the 5 % quantile and the median marked.
pub fn capacity_exceedance(records: &[SweepRecord], title: &str) -> Plot {
    let v = capacity_values(records);
    let mut marks = Vec::new();
    if let Some(s) = capacity_summary(records) {
        for q in s
            .quantiles
            .iter()
            .filter(|q| [0.05, 0.5].contains(&q.probability))
        {
            marks.push(Mark::new(
                q.value,
                1.0 - q.probability,
                format!(
                    "{} % quantile λ = {}",
                    human(q.probability * 100.0, 3),
                    fmt_fixed(q.value, 4)
                ),
            ));
        }
    }
    plot(
        &[Series {
            colour: Some("#1a9850".into()),
            ..Series::new("P(Λ > λ)", exceedance_points(&v))
        }],
        &PlotSpec {
            title: title.to_string(),
            x_label: "load multiplier λ after the settlement".into(),
            y_label: "probability of exceedance".into(),
            marks,
            height: 420.0,
            y_range: Some((0.0, 1.0)),
            include_zero: false,
            id: "exc".into(),
            ..PlotSpec::default()
        },
    )
}

/// Both figures stacked in one SVG (for `--svg` and `--png`).
pub fn capacity_distribution_svg(records: &[SweepRecord], title: &str) -> String {
    let h = capacity_histogram(records, title).svg;
    let e = capacity_exceedance(records, "Exceedance curve").svg;
    let size = |svg: &str, attr: &str| -> f64 {
        let key = format!("{attr}=\"");
        svg.find(&key)
            .and_then(|i| {
                let rest = &svg[i + key.len()..];
                rest[..rest.find('"')?].parse().ok()
            })
            .unwrap_or(0.0)
    };
    let (w, h1, h2) = (
        size(&h, "width").max(size(&e, "width")),
        size(&h, "height"),
        size(&e, "height"),
    );
    let nest = |svg: &str, y: f64| svg.replacen("<svg ", &format!("<svg x=\"0\" y=\"{y}\" "), 1);
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{}\" viewBox=\"0 0 {w} {}\">\n{}{}</svg>\n",
        h1 + h2,
        h1 + h2,
        nest(&h, 0.0),
        nest(&e, h1)
    )
}

fn opt(x: Option<f64>, decimals: usize) -> String {
    x.map_or("—".to_string(), |v| fmt_fixed(v, decimals))
}

/// Key numbers of a capacity summary as name–value rows.
pub fn summary_rows(s: &CapacitySummary) -> Vec<(String, String)> {
    vec![
        (
            "analyses (with a finite λ after the settlement)".into(),
            format!("{} ({})", s.analyses, s.with_load_multiplier),
        ),
        (
            "λ without settlement".into(),
            opt(s.load_multiplier_before, 6),
        ),
        ("λ after the settlement: mean".into(), opt(s.mean, 6)),
        (
            "λ after the settlement: least / largest".into(),
            format!("{} / {}", opt(s.min, 6), opt(s.max, 6)),
        ),
        (
            "samples whose settlement exhausts the capacity (λ ≤ 0)".into(),
            format!(
                "{} ({} %)",
                s.exhausted,
                opt(s.exhausted_fraction.map(|f| 100.0 * f), 1)
            ),
        ),
        (
            "samples where limit analysis on the deformed geometry is not valid (at some step / at the last)".into(),
            format!("{} / {}", s.invalid, s.invalid_after),
        ),
        (
            "samples whose capacity analysis failed (see their records)".into(),
            s.failed.to_string(),
        ),
    ]
}

/// The report of a capacity sweep: key numbers, quantiles, histogram, exceedance curve, and
/// every record in a collapsed table.
pub fn sweep_capacity_report(records: &[SweepRecord], opts: &ReportOptions) -> Report {
    let mut rep = Report::new(
        opts.title
            .clone()
            .unwrap_or_else(|| "Capacity after settlement: distribution over a sweep".into()),
    );
    rep.source = opts.source.clone();
    rep.command = "sweep --capacity".into();
    let solver = records.first().map(|r| r.solver.clone());
    rep.sections.extend(crate::report_parts::front_matter(
        None,
        opts.inputs.as_ref(),
        crate::report_parts::Analysis::Sweep,
        &opts.source,
        solver.as_ref(),
        vec![(
            "certified settlements".to_string(),
            format!(
                "{} of {} records",
                records.iter().filter(|r| r.certified).count(),
                records.len()
            ),
        )],
    ));
    let Some(s) = capacity_summary(records) else {
        rep.subtitle = "no record has a capacity analysis".into();
        return rep;
    };
    rep.subtitle = format!(
        "{} analyses of {}; median λ after the settlement {}",
        s.analyses,
        opts.source,
        opt(
            s.quantiles
                .iter()
                .find(|q| q.probability == 0.5)
                .map(|q| q.value),
            4
        )
    );
    let res = rep.section("Results");
    let mut kv = summary_rows(&s);
    let settlements: Vec<f64> = records
        .iter()
        .filter_map(|r| r.capacity.as_ref()?.max_settlement)
        .collect();
    if !settlements.is_empty() {
        let (lo, hi) = settlements
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
                (l.min(x), h.max(x))
            });
        kv.insert(
            1,
            (
                "largest support settlement of a record: least / largest".into(),
                format!(
                    "{} / {}",
                    crate::lengths::Length::Motion.show(lo),
                    crate::lengths::Length::Motion.show(hi)
                ),
            ),
        );
    }
    res.key_values(kv);
    res.table(
        "Quantiles of λ after the settlement (linear interpolation between order statistics)",
        vec!["probability".into(), "λ".into()],
        s.quantiles
            .iter()
            .map(|q| vec![fmt_fixed(q.probability, 2), fmt_fixed(q.value, 6)])
            .collect(),
    );
    let sec = rep.section("Figures");
    sec.figure(
        capacity_histogram(records, "Load multiplier after the settlement").svg,
        "Histogram of λ after the settlement (limit analysis on the deformed geometry), with λ without settlement.",
    );
    sec.figure(
        capacity_exceedance(records, "Exceedance curve").svg,
        "Probability that λ after the settlement exceeds a value, with the 5 % quantile and the median.",
    );
    let rows = records
        .iter()
        .filter_map(|r| {
            let c = r.capacity.as_ref()?;
            Some(vec![
                r.index.to_string(),
                human(r.parameter, 6),
                opt(c.max_settlement.map(|m| m * 100.0), 4),
                opt(c.load_multiplier_after, 6),
                opt(c.zero_capacity_settlement.map(|z| z * 100.0), 4),
                if c.valid { "yes".into() } else { "no".into() },
            ])
        })
        .collect();
    rep.section("Records").collapsed_table(
        "Every analysis",
        [
            "index",
            "parameter",
            "settlement (cm)",
            "λ after",
            "λ = 0 at (cm)",
            "valid",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows,
    );
    rep
}
