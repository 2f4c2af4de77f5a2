//! The legend stage of [`super::draw3d`]: what the legend may show (its height is reserved on
//! the page before anything is drawn), then the entries of what was drawn, laid out by the
//! shared [`crate::draw::legend`] (the chrome of 2D and 3D figures alike).

use super::layout::Layout;
use super::{Draw3dOptions, View};
use crate::draw::chrome::{CRACK, EDGE, FAINT, HINGE, LOAD, THRUST};
use crate::draw::legend::{self, Entry};
use crate::draw::svg::{esc, human};
use crate::draw::MotionUnits;
use crate::result3d::Result3d;
use voussoir::result::spatial::SpatialShapes;
use voussoir::result::JointState;

/// The legend's entries that may be drawn (a superset of those drawn: [`LegendLabels::drawn`]).
pub(super) fn labels(
    r: &(impl Result3d + ?Sized),
    g: &SpatialShapes,
    lay: &Layout,
    opts: &Draw3dOptions,
    view: View,
    k: f64,
) -> LegendLabels {
    let n_pressure = r
        .thrust_line()
        .iter()
        .filter(|t| crate::result3d::finite([t.x, t.y, t.z]))
        .count();
    let show_pressure = n_pressure > 0 && opts.pressure_points.lone(n_pressure);
    let labels = LegendLabels {
        show_pressure,
        undeformed: lay.has_motion && opts.undeformed,
        supports: lay.show_supports && !g.supports.is_empty(),
        hinges: opts.hinges && !r.hinges().is_empty(),
        cracks: opts.cracks && r.joints().iter().any(|j| j.state != JointState::Closed),
        pressure: show_pressure,
        live: lay.loads.iter().any(|l| l.3).then(|| {
            crate::draw::legend::live_load_label(r.load_multiplier(), tilt_of(r), lay.live_max)
        }),
        dead: lay
            .loads
            .iter()
            .any(|l| !l.3)
            .then(|| format!("dead load (largest {} kN)", human(lay.dead_max, 3))),
        motion: lay.has_motion.then(|| match r.units() {
            MotionUnits::Metres => format!("displacements drawn × {}", human(lay.scale, 4)),
            MotionUnits::Normalised => format!(
                "mechanism drawn × {} (normalised: live loads do unit work)",
                human(lay.scale, 4)
            ),
        }),
        view: describe_view(&view, &opts.view, lay.has_motion),
        id: esc(&opts.id),
        size: lay.size,
        k,
    };
    labels
}

/// The legend's height on the page (a strip of 8 px without one).
pub(super) fn height(labels: &LegendLabels, opts: &Draw3dOptions, margin: f64, width: f64) -> f64 {
    if opts.legend {
        let l = legend::layout(&labels.entries(), margin, width - margin);
        legend::height(l.height)
    } else {
        8.0
    }
}

/// How many marks each layer drew.
pub(super) struct Drawn {
    pub hinges: usize,
    pub cracks: usize,
    pub thrust: usize,
    pub live: usize,
    pub dead: usize,
}

impl LegendLabels {
    /// Only what was drawn.
    pub(super) fn drawn(mut self, n: &Drawn) -> LegendLabels {
        self.hinges = n.hinges > 0;
        self.cracks = n.cracks > 0;
        self.pressure = n.thrust > 0;
        if n.live == 0 {
            self.live = None;
        }
        if n.dead == 0 {
            self.dead = None;
        }
        self
    }
}

/// The tilt of a tilting-table result for the legend: α and "towards azimuth …°".
pub(super) fn tilt_of(r: &(impl Result3d + ?Sized)) -> Option<(f64, String)> {
    r.tilt()
        .map(|(a, az)| (a, format!("towards azimuth {}°", human(az, 6))))
}

/// The view as the legend states it; an automatic view says that it was chosen.
pub(super) fn describe_view(view: &View, asked: &View, has_motion: bool) -> String {
    let d = view.describe();
    if *asked == View::Auto && has_motion {
        format!("{d} (chosen to show the largest motions)")
    } else {
        d
    }
}

/// The texts and flags of a 3D legend.
pub(super) struct LegendLabels {
    pub(super) show_pressure: bool,
    undeformed: bool,
    supports: bool,
    hinges: bool,
    cracks: bool,
    pressure: bool,
    live: Option<String>,
    dead: Option<String>,
    /// "displacements drawn × …".
    motion: Option<String>,
    view: String,
    /// The figure's id prefix (the hatch pattern).
    id: String,
    /// Model size (m) and pixels per metre, for the scale bar.
    size: f64,
    k: f64,
}

impl LegendLabels {
    pub(super) fn entries(&self) -> Vec<Entry> {
        let id = &self.id;
        let mut e = Vec::new();
        if self.undeformed {
            e.push(Entry::symbol(format!("<rect x=\"0\" y=\"-6\" width=\"22\" height=\"12\" fill=\"none\" stroke=\"{FAINT}\" stroke-dasharray=\"4 3\"/>"), "undeformed"));
        }
        if self.supports {
            e.push(Entry::symbol(format!("<rect x=\"0\" y=\"-6\" width=\"22\" height=\"12\" fill=\"url(#{id}-hatch)\" stroke=\"{EDGE}\" stroke-width=\"0.8\"/>"), "support"));
        }
        if self.hinges {
            e.push(Entry::symbol(format!("<path d=\"M1 4L21 -4\" stroke=\"{HINGE}\" stroke-width=\"2.5\" stroke-linecap=\"round\"/><circle cx=\"11\" cy=\"0\" r=\"4.5\" fill=\"{HINGE}\" stroke=\"#ffffff\" stroke-width=\"1.2\"/>"), "hinge (point, line)"));
        }
        if self.cracks {
            e.push(Entry::symbol(format!("<path d=\"M2 6L22 -6L22 6Z\" fill=\"{CRACK}\" fill-opacity=\"0.55\" stroke=\"{CRACK}\" stroke-width=\"1.5\"/>"), "crack (joint not closed)"));
        }
        if self.pressure {
            e.push(Entry::symbol(
                format!("<circle cx=\"11\" cy=\"0\" r=\"3.5\" fill=\"{THRUST}\"/>"),
                "centre of pressure",
            ));
        }
        let arrow_sym = |c: &str| {
            format!("<path d=\"M1 0L15 0\" stroke=\"{c}\" stroke-width=\"1.6\"/><path d=\"M22 0L13 -4.5L13 4.5Z\" fill=\"{c}\"/>")
        };
        if let Some(l) = &self.live {
            e.push(Entry::symbol(arrow_sym(LOAD), l.clone()));
        }
        if let Some(l) = &self.dead {
            e.push(Entry::symbol(arrow_sym("#555555"), l.clone()));
        }
        // Scale bar (lengths in the picture plane), displacement scale, view.
        e.push(Entry::scale_bar(self.size, self.k));
        if let Some(m) = &self.motion {
            e.push(Entry::text(m.clone(), "#333333"));
        }
        e.push(Entry::text(self.view.clone(), "#777777"));
        e
    }
}
