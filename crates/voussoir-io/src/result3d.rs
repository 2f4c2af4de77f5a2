//! What the 3D outputs ([`crate::vtk`], [`crate::draw3d`]) read of a 3D result: the parts that
//! limit and settlement results share ([`Result3d`]), the rigid small motion of a body, volume
//! centroids and the in-plane order of a joint's points.
//!
//! A block's motion `(u, v, w, θx, θy, θz)` is the small motion of its centroid `c`: a point `x`
//! of the block moves by `u + θ × (x − c)`. Supports move by their prescribed motion about their
//! own centroid in a settlement result and stay at rest in a limit result (as in 2D).

use crate::draw::MotionUnits;
use crate::IoError;
use voussoir::dim::Three;
use voussoir::lp::SolverInfo;
use voussoir::result::spatial::{SpatialMotion, SpatialShapes};
use voussoir::result::TiltResult;
use voussoir::result::{
    BlockMotion, BodyName, FrictionIteration, Hinge, JointResult, JointState, Reaction, ThrustPoint,
};
use voussoir::result::{CapacityResult, LimitResult, LimitStatus, SettlementResult};

/// A 3D result that can be written to VTK or drawn: a limit or a settlement result.
pub trait Result3d {
    fn blocks(&self) -> &[BlockMotion<Three>];
    fn joints(&self) -> &[JointResult<Three>];
    fn hinges(&self) -> &[Hinge<Three>];
    fn thrust_line(&self) -> &[ThrustPoint<Three>];
    fn shapes(&self) -> &SpatialShapes;
    /// What the motions mean: normalised (limit analyses) or metres (settlements).
    fn units(&self) -> MotionUnits;
    /// Whether live loads are part of the analysis (λ multiplies them): limit analyses only.
    fn live_loads(&self) -> bool;
    /// Whether supports move by their prescribed motion (settlements with a mechanism).
    fn supports_move(&self) -> bool;
    /// Title of a drawing.
    fn title(&self) -> String;
    /// Key numbers, one line each, printed under the title.
    fn info(&self) -> Vec<String>;
    /// Key numbers as (name, value) rows for reports: status, λ or the settlement certificate
    /// (primal, dual, gap). Default: the [`Result3d::info`] lines.
    fn key_numbers(&self) -> Vec<(String, String)> {
        self.info()
            .into_iter()
            .map(|l| (String::new(), l))
            .collect()
    }
    /// Support reactions (none where the result has no forces).
    fn reactions(&self) -> &[Reaction<Three>] {
        &[]
    }
    /// The cracks as the summary lists them (widest first); none where the result has none.
    fn cracks(&self) -> &[voussoir::result::Crack3d] {
        &[]
    }
    /// The solver and method that produced the result.
    fn solver(&self) -> Option<&SolverInfo> {
        None
    }
    /// The non-associative friction iteration, when one was run.
    fn friction_iteration(&self) -> Option<&FrictionIteration> {
        None
    }
    /// The collapse load multiplier λ that the drawn live loads are multiplied by (a limit
    /// analysis that found a mechanism); `None`: the live loads are drawn unfactored.
    fn load_multiplier(&self) -> Option<f64> {
        None
    }
    /// A tilting-table result: the critical tilt angle α and the azimuth of the tilt, degrees.
    fn tilt(&self) -> Option<(f64, f64)> {
        None
    }
    /// The certificate as (name, value) rows for a report's inputs.
    fn certificate_rows(&self) -> Vec<(String, String)> {
        Vec::new()
    }
}

fn limit_certificate_rows(r: &LimitResult<Three>) -> Vec<(String, String)> {
    vec![(
        "certificate of λ".to_string(),
        match &r.certificate {
            Some(c) => format!(
                "gap |λ − λ_kin|/|λ| = {}, admissibility {} — {}",
                crate::draw::svg::human(c.gap, 3),
                crate::draw::svg::human(c.admissibility, 3),
                if c.ok {
                    "certified (≤ 1e-6)"
                } else {
                    "NOT certified"
                }
            ),
            None => "not computed for this outcome or joint law".to_string(),
        },
    )]
}

/// A number for a report table: up to 6 significant digits, or "—" when absent or not finite.
fn num6(x: Option<f64>) -> String {
    match x {
        Some(v) if v.is_finite() => crate::draw::svg::human(v, 6),
        _ => "—".to_string(),
    }
}

fn plural(n: usize, what: &str) -> String {
    format!("{n} {what}{}", if n == 1 { "" } else { "s" })
}

/// "2 hinge lines, 1 open joint" for the cracked joints of a result.
fn crack_summary(joints: &[JointResult<Three>]) -> String {
    let count = |s: JointState| joints.iter().filter(|j| j.state == s).count();
    let mut parts = vec![plural(count(JointState::Hinge), "hinged joint")];
    let open = count(JointState::Open);
    if open > 0 {
        parts.push(plural(open, "open joint"));
    }
    let sliding = count(JointState::Sliding);
    if sliding > 0 {
        parts.push(plural(sliding, "sliding joint"));
    }
    parts.join(", ")
}

/// The parts of [`Result3d`] that a limit, settlement or tilt result reads from its fields
/// (`result3d_parts!(limit)`: from its field `limit`).
macro_rules! result3d_parts {
    ($($f:ident).*) => {
        fn cracks(&self) -> &[voussoir::result::Crack3d] {
            &self$(.$f)*.cracks
        }
        fn reactions(&self) -> &[Reaction<Three>] {
            &self$(.$f)*.reactions
        }
        fn solver(&self) -> Option<&SolverInfo> {
            Some(&self$(.$f)*.solver)
        }
        fn friction_iteration(&self) -> Option<&FrictionIteration> {
            self$(.$f)*.friction_iteration.as_ref()
        }
        fn blocks(&self) -> &[BlockMotion<Three>] {
            &self$(.$f)*.blocks
        }
        fn joints(&self) -> &[JointResult<Three>] {
            &self$(.$f)*.joints
        }
        fn hinges(&self) -> &[Hinge<Three>] {
            &self$(.$f)*.hinges
        }
        fn thrust_line(&self) -> &[ThrustPoint<Three>] {
            &self$(.$f)*.thrust_line
        }
        fn shapes(&self) -> &SpatialShapes {
            &self$(.$f)*.geometry
        }
    };
}

impl Result3d for LimitResult<Three> {
    result3d_parts!();
    fn certificate_rows(&self) -> Vec<(String, String)> {
        limit_certificate_rows(self)
    }
    fn units(&self) -> MotionUnits {
        MotionUnits::Normalised
    }
    fn live_loads(&self) -> bool {
        true
    }
    fn supports_move(&self) -> bool {
        false
    }
    fn title(&self) -> String {
        match self.status {
            LimitStatus::Collapse => "Collapse mechanism",
            LimitStatus::Locked => "No collapse: locked",
            LimitStatus::NoEquilibrium => "No equilibrium under the dead loads",
        }
        .to_string()
    }
    fn info(&self) -> Vec<String> {
        match self.load_multiplier {
            Some(l) if self.status == LimitStatus::Collapse => vec![format!(
                "collapse load multiplier λ = {l:.4}   ·   {}",
                crack_summary(&self.joints)
            )],
            _ => vec![self.message.clone()],
        }
    }
    fn key_numbers(&self) -> Vec<(String, String)> {
        let mut k = vec![
            ("status".to_string(), self.status.sentence().to_string()),
            (
                "collapse load multiplier λ".to_string(),
                num6(self.load_multiplier),
            ),
        ];
        if self.least_load_multiplier.is_some() {
            k.push((
                "least multiplier in equilibrium (≤ 0: stands under the dead loads)".to_string(),
                num6(self.least_load_multiplier),
            ));
        }
        k.push((
            "work of the dead loads (normalised mechanism)".to_string(),
            num6(self.work_dead_loads),
        ));
        k.push((
            "work of the live loads (normalised mechanism)".to_string(),
            num6(self.work_live_loads),
        ));
        k.push(("cracked joints".to_string(), crack_summary(&self.joints)));
        k
    }
    fn load_multiplier(&self) -> Option<f64> {
        self.load_multiplier
            .filter(|l| l.is_finite() && self.status == LimitStatus::Collapse)
    }
}

impl Result3d for SettlementResult<Three> {
    result3d_parts!();
    fn certificate_rows(&self) -> Vec<(String, String)> {
        vec![(
            "duality certificate".to_string(),
            match &self.certificate {
                Some(c) => format!(
                    "relative gap {} — {}",
                    crate::draw::svg::human(c.relative_gap, 3),
                    if c.ok {
                        "certified (≤ 1e-7)"
                    } else {
                        "NOT certified"
                    }
                ),
                None => "none (no mechanism)".to_string(),
            },
        )]
    }
    fn units(&self) -> MotionUnits {
        MotionUnits::Metres
    }
    fn live_loads(&self) -> bool {
        false
    }
    fn supports_move(&self) -> bool {
        !self.blocks.is_empty()
    }
    fn title(&self) -> String {
        "Settlement mechanism".to_string()
    }
    fn info(&self) -> Vec<String> {
        let mut info = Vec::new();
        if let Some(m) = support_motion_text(&self.geometry) {
            info.push(m);
        }
        let mut line = crack_summary(&self.joints);
        if let Some(c) = &self.certificate {
            line.push_str(&format!(
                "   ·   duality gap {} ({})",
                crate::draw::svg::human(c.relative_gap, 2),
                if c.ok { "certified" } else { "NOT certified" }
            ));
        } else {
            line = self.message.clone();
        }
        info.push(line);
        info
    }
    fn key_numbers(&self) -> Vec<(String, String)> {
        let mut k = vec![("status".to_string(), self.status.sentence().to_string())];
        if let Some(m) = support_motion_text(&self.geometry) {
            k.push((
                "support motion".to_string(),
                m.replace("prescribed support motion: ", ""),
            ));
        }
        match &self.certificate {
            Some(c) => {
                k.push((
                    "primal (work of the dead loads, kN·m)".to_string(),
                    num6(Some(c.primal)),
                ));
                k.push((
                    "dual (work of the reactions, kN·m)".to_string(),
                    num6(Some(c.dual)),
                ));
                k.push((
                    "relative duality gap".to_string(),
                    num6(Some(c.relative_gap)),
                ));
                k.push(("complementarity".to_string(), num6(Some(c.complementarity))));
                k.push((
                    "equilibrium residual".to_string(),
                    num6(Some(c.equilibrium_residual)),
                ));
                k.push((
                    "certificate".to_string(),
                    if c.ok { "certified" } else { "NOT certified" }.to_string(),
                ));
            }
            None => k.push(("certificate".to_string(), self.message.clone())),
        }
        k.push(("cracked joints".to_string(), crack_summary(&self.joints)));
        k
    }
}

/// The tilting-table result: its limit analysis, titled and summed up by the tilt angle.
impl Result3d for TiltResult<Three> {
    result3d_parts!(limit);
    fn certificate_rows(&self) -> Vec<(String, String)> {
        limit_certificate_rows(&self.limit)
    }
    fn units(&self) -> MotionUnits {
        self.limit.units()
    }
    fn live_loads(&self) -> bool {
        true
    }
    fn supports_move(&self) -> bool {
        false
    }
    fn title(&self) -> String {
        match self.tilt_angle {
            Some(_) => format!(
                "Tilting table: collapse mechanism towards azimuth {}°",
                crate::draw::svg::human(self.azimuth.unwrap_or(0.0), 6)
            ),
            None => self.limit.title(),
        }
    }
    fn info(&self) -> Vec<String> {
        let mut info = self.limit.info();
        if let Some(a) = self.tilt_angle {
            info.insert(
                0,
                format!("critical tilt angle α = {a:.3}°   ·   live load: horizontal, λ = tan α"),
            );
        }
        info
    }
    fn key_numbers(&self) -> Vec<(String, String)> {
        let mut k = vec![(
            "critical tilt angle α (degrees)".to_string(),
            num6(self.tilt_angle),
        )];
        k.push((
            "azimuth of the tilt (degrees from x towards y)".to_string(),
            num6(Some(self.azimuth.unwrap_or(0.0))),
        ));
        k.extend(self.limit.key_numbers());
        k
    }
    fn load_multiplier(&self) -> Option<f64> {
        self.limit.load_multiplier()
    }
    fn tilt(&self) -> Option<(f64, f64)> {
        self.tilt_angle
            .filter(|a| a.is_finite())
            .map(|a| (a, self.azimuth.unwrap_or(0.0)))
    }
}

/// A 3D figure assembled from parts, drawn and reported as a result is: a model with its loads
/// (nothing moves) or the settlement mechanism of a capacity analysis (no joint results).
#[derive(Clone, Debug)]
pub struct Figure3d {
    pub shapes: SpatialShapes,
    pub blocks: Vec<BlockMotion<Three>>,
    /// Joints, only to say which body carries each hinge (closed, without points).
    pub joints: Vec<JointResult<Three>>,
    pub hinges: Vec<Hinge<Three>>,
    pub units: MotionUnits,
    pub live_loads: bool,
    pub supports_move: bool,
    pub title: String,
    pub info: Vec<String>,
}

impl Figure3d {
    /// A model with its loads.
    pub fn model(shapes: SpatialShapes) -> Figure3d {
        let live = shapes.loads.iter().filter(|l| l.live).count();
        let info = vec![format!(
            "{}, {}; {}",
            plural(shapes.blocks.len(), "block"),
            plural(shapes.supports.len(), "support"),
            if live == 0 {
                "no live loads".to_string()
            } else {
                format!("{} (arrows)", plural(live, "live load"))
            }
        )];
        Figure3d {
            shapes,
            blocks: vec![],
            joints: vec![],
            hinges: vec![],
            units: MotionUnits::Normalised,
            live_loads: true,
            supports_move: false,
            title: "Model and loads".to_string(),
            info,
        }
    }

    /// The settlement mechanism of a capacity analysis at its largest settlement (metres).
    pub fn capacity_settlement(r: &CapacityResult<Three>) -> Figure3d {
        let s = if r.max_settlement.is_finite() {
            r.max_settlement
        } else {
            0.0
        };
        let blocks = r
            .settlement_mechanism
            .iter()
            .map(|b| BlockMotion {
                id: b.id,
                motion: SpatialMotion {
                    u: b.u * s,
                    v: b.v * s,
                    w: b.w * s,
                    theta_x: b.theta_x * s,
                    theta_y: b.theta_y * s,
                    theta_z: b.theta_z * s,
                },
            })
            .collect();
        let mut info: Vec<String> = support_motion_text(&r.geometry).into_iter().collect();
        let mut ids: Vec<usize> = r.settlement_hinges.iter().map(|h| h.joint).collect();
        ids.sort_unstable();
        ids.dedup();
        info.push(format!(
            "hinges opened by the settlement on {}",
            plural(ids.len(), "joint")
        ));
        // The result lists no joints: each hinged joint is given the block its first hinge
        // point lies on, so that the drawing carries the hinge with that block (at a hinge
        // both sides move alike, so either side does).
        let joints = ids
            .iter()
            .map(|&id| {
                let h = r.settlement_hinges.iter().find(|h| h.joint == id);
                let body = h
                    .and_then(|h| block_on(&r.geometry, [h.x, h.y, h.z]))
                    .map_or(BodyName::Block(usize::MAX), BodyName::Block);
                JointResult {
                    id,
                    a: body.clone(),
                    b: body,
                    normal: [0.0, 0.0, 1.0],
                    points: vec![],
                    normal_force: 0.0,
                    shear_force: [0.0, 0.0],
                    eccentricity: None,
                    state: JointState::Closed,
                    compressed_depth: None,
                }
            })
            .collect();
        Figure3d {
            shapes: r.geometry.clone(),
            blocks,
            joints,
            hinges: r.settlement_hinges.clone(),
            units: MotionUnits::Metres,
            live_loads: false,
            supports_move: true,
            title: "Settlement mechanism at the largest settlement".to_string(),
            info,
        }
    }
}

impl Result3d for Figure3d {
    fn blocks(&self) -> &[BlockMotion<Three>] {
        &self.blocks
    }
    fn joints(&self) -> &[JointResult<Three>] {
        &self.joints
    }
    fn hinges(&self) -> &[Hinge<Three>] {
        &self.hinges
    }
    fn thrust_line(&self) -> &[ThrustPoint<Three>] {
        &[]
    }
    fn shapes(&self) -> &SpatialShapes {
        &self.shapes
    }
    fn units(&self) -> MotionUnits {
        self.units
    }
    fn live_loads(&self) -> bool {
        self.live_loads
    }
    fn supports_move(&self) -> bool {
        self.supports_move
    }
    fn title(&self) -> String {
        self.title.clone()
    }
    fn info(&self) -> Vec<String> {
        self.info.clone()
    }
}

/// The first block with a face through `p` (within 1e-6 of the model's size of the face's
/// plane, and inside the face's bounding box so enlarged); None if there is none.
fn block_on(g: &SpatialShapes, p: V3) -> Option<usize> {
    if !finite(p) {
        return None;
    }
    let size = g
        .blocks
        .iter()
        .flat_map(|b| b.vertices.iter())
        .fold(0.0f64, |m, v| m.max(norm(sub(*v, p))))
        .max(1e-300);
    let tol = 1e-6 * size;
    g.blocks.iter().position(|b| {
        b.faces.iter().any(|f| {
            let pts: Vec<V3> = f
                .iter()
                .filter_map(|&i| b.vertices.get(i).copied())
                .collect();
            if pts.len() < 3 {
                return false;
            }
            let n = (1..pts.len() - 1).fold([0.0; 3], |a, k| {
                add(a, cross(sub(pts[k], pts[0]), sub(pts[k + 1], pts[0])))
            });
            let l = norm(n);
            if l.is_nan() || l <= 0.0 {
                return false;
            }
            let inside = (0..3).all(|c| {
                let lo = pts.iter().fold(f64::INFINITY, |m, q| m.min(q[c]));
                let hi = pts.iter().fold(f64::NEG_INFINITY, |m, q| m.max(q[c]));
                p[c] >= lo - tol && p[c] <= hi + tol
            });
            inside && (dot(sub(p, pts[0]), n) / l).abs() <= tol
        })
    })
}

/// A 3D model's key numbers for a report: blocks, supports, size, total dead and live loads.
pub fn model_rows_3d(g: &SpatialShapes, source: &str) -> Vec<(String, String)> {
    use crate::draw::svg::human;
    let mut kv = Vec::new();
    if !source.is_empty() {
        kv.push(("model".to_string(), source.to_string()));
    }
    kv.push(("blocks".into(), g.blocks.len().to_string()));
    let sup: Vec<String> = g
        .supports
        .iter()
        .map(|s| {
            format!(
                "{}{}",
                s.name,
                if s.fixed { " (fixed)" } else { " (contact)" }
            )
        })
        .collect();
    kv.push(("supports".into(), sup.join(", ")));
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for v in g
        .blocks
        .iter()
        .flat_map(|b| b.vertices.iter())
        .chain(g.supports.iter().flat_map(|s| s.vertices.iter()))
        .filter(|v| finite(**v))
    {
        for c in 0..3 {
            lo[c] = lo[c].min(v[c]);
            hi[c] = hi[c].max(v[c]);
        }
    }
    if lo[0] <= hi[0] {
        kv.push((
            "extent x × y × z (m)".into(),
            format!(
                "{} × {} × {}",
                human(hi[0] - lo[0], 4),
                human(hi[1] - lo[1], 4),
                human(hi[2] - lo[2], 4)
            ),
        ));
    }
    let total = |live: bool| {
        g.loads
            .iter()
            .filter(|l| l.live == live)
            .fold([0.0; 3], |a, l| add(a, [l.fx, l.fy, l.fz]))
    };
    let show = |f: V3| {
        format!(
            "({}, {}, {}) kN",
            human(f[0], 4),
            human(f[1], 4),
            human(f[2], 4)
        )
    };
    kv.push(("total dead load (fx, fy, fz)".into(), show(total(false))));
    kv.push(("total live load (fx, fy, fz)".into(), show(total(true))));
    kv
}

/// "prescribed support motion: right w = −10 mm" for the supports that move (at most three
/// listed; more are counted).
pub fn support_motion_text(g: &SpatialShapes) -> Option<String> {
    use crate::draw::svg::human;
    let moving: Vec<_> = g
        .supports
        .iter()
        .filter(|s| s.motion.iter().any(|&x| x != 0.0 && x.is_finite()))
        .collect();
    if moving.is_empty() {
        return None;
    }
    if moving.len() > 3 {
        return Some(format!(
            "prescribed support motion on {} supports ({} … {})",
            moving.len(),
            moving[0].name,
            moving[moving.len() - 1].name
        ));
    }
    let parts: Vec<String> = moving
        .iter()
        .map(|s| {
            let names = ["u", "v", "w"];
            let mut t = s.name.clone();
            let mut first = true;
            for (k, n) in names.iter().enumerate() {
                if s.motion[k] != 0.0 {
                    t.push_str(if first { " " } else { ", " });
                    t.push_str(&format!("{n} = {} mm", human(s.motion[k] * 1000.0, 3)));
                    first = false;
                }
            }
            for (k, n) in ["θx", "θy", "θz"].iter().enumerate() {
                if s.motion[3 + k] != 0.0 {
                    t.push_str(if first { " " } else { ", " });
                    t.push_str(&format!(
                        "{n} = {}°",
                        human(s.motion[3 + k].to_degrees(), 3)
                    ));
                    first = false;
                }
            }
            if s.fixed {
                t.push_str(" (fixed)");
            }
            t
        })
        .collect();
    Some(format!("prescribed support motion: {}", parts.join("; ")))
}

/// Vector operations under their short names (defined once, in `voussoir::vector`).
pub use voussoir::vector::{
    add3 as add, cross, dot3 as dot, finite3 as finite, norm3 as norm, scale3 as scale,
    sub3 as sub, V3,
};

/// Small rigid motion of point `x` of a body moving by `m = [u, v, w, θx, θy, θz]` about `c`:
/// `u + θ × (x − c)`.
pub fn small_displacement(c: V3, m: &[f64; 6], x: V3) -> V3 {
    let r = sub(x, c);
    add([m[0], m[1], m[2]], cross([m[3], m[4], m[5]], r))
}

/// Volume centroid of a closed polyhedron (divergence theorem over a fan triangulation of each
/// face); the mean of the vertices when the volume vanishes.
pub fn polyhedron_centroid(vertices: &[V3], faces: &[Vec<usize>]) -> V3 {
    let mean = {
        let n = vertices.len().max(1) as f64;
        let s = vertices.iter().fold([0.0; 3], |a, v| add(a, *v));
        scale(s, 1.0 / n)
    };
    // Relative to the mean, for accuracy far from the origin.
    let (mut vol, mut m) = (0.0, [0.0; 3]);
    for f in faces {
        if f.len() < 3 || f.iter().any(|&i| i >= vertices.len()) {
            continue;
        }
        let p0 = sub(vertices[f[0]], mean);
        for k in 1..f.len() - 1 {
            let p1 = sub(vertices[f[k]], mean);
            let p2 = sub(vertices[f[k + 1]], mean);
            let v6 = dot(p0, cross(p1, p2));
            vol += v6;
            m = add(m, scale(add(add(p0, p1), p2), v6 / 4.0));
        }
    }
    if vol.abs() > 1e-14 && finite(m) {
        add(mean, scale(m, 1.0 / vol))
    } else {
        mean
    }
}

/// Check that a result's shapes can be written and drawn: finite vertices, faces of at least
/// three vertices that exist. Returns a one-line error naming the offending body otherwise.
pub fn validate(r: &(impl Result3d + ?Sized)) -> Result<(), IoError> {
    let g = r.shapes();
    let check = |what: &str, vertices: &[V3], faces: &[Vec<usize>]| -> Result<(), IoError> {
        if let Some(k) = vertices.iter().position(|v| !finite(*v)) {
            return Err(IoError(format!("{what}: vertex {k} is not finite")));
        }
        for (fi, f) in faces.iter().enumerate() {
            if f.len() < 3 {
                return Err(IoError(format!(
                    "{what}: face {fi} has {} vertices (at least 3 needed)",
                    f.len()
                )));
            }
            if let Some(&i) = f.iter().find(|&&i| i >= vertices.len()) {
                return Err(IoError(format!(
                    "{what}: face {fi} refers to vertex {i}, but there are {}",
                    vertices.len()
                )));
            }
        }
        Ok(())
    };
    for (i, b) in g.blocks.iter().enumerate() {
        check(&format!("block {i}"), &b.vertices, &b.faces)?;
    }
    for s in &g.supports {
        check(&format!("support {}", s.name), &s.vertices, &s.faces)?;
    }
    Ok(())
}

/// A body's reference point and small motion, for every block and support of a result.
pub struct Motions {
    /// Block centroids and motions, by block id (blocks the result does not list are at rest).
    pub blocks: Vec<(V3, [f64; 6])>,
    /// Support centroids and motions (the prescribed motion when supports move, else zero).
    pub supports: Vec<(V3, [f64; 6])>,
}

impl Motions {
    pub fn of(r: &(impl Result3d + ?Sized)) -> Motions {
        let g = r.shapes();
        let mut blocks: Vec<(V3, [f64; 6])> = g
            .blocks
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let c = match g.centroids.get(i) {
                    Some(c) if finite(*c) => *c,
                    _ => polyhedron_centroid(&b.vertices, &b.faces),
                };
                (c, [0.0; 6])
            })
            .collect();
        for m in r.blocks() {
            if let Some(b) = blocks.get_mut(m.id) {
                let d = [m.u, m.v, m.w, m.theta_x, m.theta_y, m.theta_z];
                if d.iter().all(|x| x.is_finite()) {
                    b.1 = d;
                }
            }
        }
        let supports = g
            .supports
            .iter()
            .map(|s| {
                let c = polyhedron_centroid(&s.vertices, &s.faces);
                let d = if r.supports_move() && s.motion.iter().all(|x| x.is_finite()) {
                    s.motion
                } else {
                    [0.0; 6]
                };
                (c, d)
            })
            .collect();
        Motions { blocks, supports }
    }

    /// The reference point and motion of a body named in a joint.
    pub fn of_body(&self, g: &SpatialShapes, b: &BodyName) -> Option<(V3, [f64; 6])> {
        match b {
            BodyName::Block(i) => self.blocks.get(*i).copied(),
            BodyName::Support(name) => g
                .supports
                .iter()
                .position(|s| &s.name == name)
                .map(|k| self.supports[k]),
        }
    }

    /// Small displacement of point `x` moving with body `b` (zero for an unknown body).
    pub fn displacement(&self, g: &SpatialShapes, b: &BodyName, x: V3) -> V3 {
        match self.of_body(g, b) {
            Some((c, m)) => small_displacement(c, &m, x),
            None => [0.0; 3],
        }
    }
}

/// Two unit tangents `(t1, t2)` of the unit normal `n` (any orthonormal pair with `t1 × t2 = n`;
/// deterministic).
pub fn tangents(n: V3) -> (V3, V3) {
    let l = norm(n);
    let n = if l > 0.0 && l.is_finite() {
        scale(n, 1.0 / l)
    } else {
        [0.0, 0.0, 1.0]
    };
    // The coordinate axis least aligned with n.
    let a = if n[0].abs() <= n[1].abs() && n[0].abs() <= n[2].abs() {
        [1.0, 0.0, 0.0]
    } else if n[1].abs() <= n[2].abs() {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let t1 = cross(a, n);
    let t1 = scale(t1, 1.0 / norm(t1));
    let t2 = cross(n, t1);
    (t1, t2)
}

/// The order of points `pts` around their mean in the plane of normal `n`: counter-clockwise
/// about `n` (ties broken by index, so the order is deterministic).
pub fn polygon_order(pts: &[V3], n: V3) -> Vec<usize> {
    if pts.is_empty() {
        return Vec::new();
    }
    let (t1, t2) = tangents(n);
    let m = scale(
        pts.iter().fold([0.0; 3], |a, p| add(a, *p)),
        1.0 / pts.len() as f64,
    );
    let angle: Vec<f64> = pts
        .iter()
        .map(|p| {
            let r = sub(*p, m);
            dot(r, t2).atan2(dot(r, t1))
        })
        .collect();
    let mut idx: Vec<usize> = (0..pts.len()).collect();
    idx.sort_by(|&a, &b| angle[a].total_cmp(&angle[b]).then(a.cmp(&b)));
    idx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centroid_of_a_shifted_box() {
        // Box [1,3]×[0,1]×[2,5].
        let v = vec![
            [1.0, 0.0, 2.0],
            [3.0, 0.0, 2.0],
            [3.0, 1.0, 2.0],
            [1.0, 1.0, 2.0],
            [1.0, 0.0, 5.0],
            [3.0, 0.0, 5.0],
            [3.0, 1.0, 5.0],
            [1.0, 1.0, 5.0],
        ];
        let f = vec![
            vec![0, 3, 2, 1],
            vec![4, 5, 6, 7],
            vec![0, 1, 5, 4],
            vec![1, 2, 6, 5],
            vec![2, 3, 7, 6],
            vec![3, 0, 4, 7],
        ];
        let c = polyhedron_centroid(&v, &f);
        for (a, b) in c.iter().zip([2.0, 0.5, 3.5]) {
            assert!((a - b).abs() < 1e-12, "{c:?}");
        }
    }

    #[test]
    fn tangents_are_orthonormal_and_right_handed() {
        for n in [
            [0.0, 0.0, 1.0],
            [0.0, 0.0, -1.0],
            [0.6, 0.0, 0.8],
            [1.0, 2.0, -2.0],
        ] {
            let (t1, t2) = tangents(n);
            let nn = scale(n, 1.0 / norm(n));
            let c = cross(t1, t2);
            assert!(dot(t1, nn).abs() < 1e-12 && dot(t2, nn).abs() < 1e-12);
            assert!((norm(t1) - 1.0).abs() < 1e-12 && (norm(t2) - 1.0).abs() < 1e-12);
            assert!(norm(sub(c, nn)) < 1e-12);
        }
    }
}
