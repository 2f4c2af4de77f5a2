//! What the 3D outputs ([`crate::vtk`], [`crate::draw3d`]) read of a 3D result: the parts that
//! limit and settlement results share ([`Result3d`]), the rigid small motion of a body, volume
//! centroids and the in-plane order of a joint's points.
//!
//! A block's motion `(u, v, w, θx, θy, θz)` is the small motion of its centroid `c`: a point `x`
//! of the block moves by `u + θ × (x − c)`. Supports move by their prescribed motion about their
//! own centroid in a settlement result and stay at rest in a limit result (as in 2D).

use crate::draw::MotionUnits;
use crate::IoError;
use voussoir::analysis::{LimitResult, LimitStatus, SettlementResult};
use voussoir::dim::Three;
use voussoir::result::spatial::SpatialShapes;
use voussoir::result::{BlockMotion, BodyName, Hinge, JointResult, JointState, ThrustPoint};

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

impl Result3d for LimitResult<Three> {
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
        &self.thrust_line
    }
    fn shapes(&self) -> &SpatialShapes {
        &self.geometry
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
}

impl Result3d for SettlementResult<Three> {
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
        &self.thrust_line
    }
    fn shapes(&self) -> &SpatialShapes {
        &self.geometry
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

pub type V3 = [f64; 3];

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}
pub fn finite(a: V3) -> bool {
    a.iter().all(|x| x.is_finite())
}

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
