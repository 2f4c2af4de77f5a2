//! Model generators: arches, lintels, running-bond walls.

use crate::error::{Error, Result};
use crate::geometry::signed_area;
use crate::model::{Block, Load, Loads, Material, Model, Per, Point, Support};
use std::collections::BTreeMap;
use std::f64::consts::PI;

fn req(ok: bool, msg: &str) -> Result<()> {
    if ok {
        Ok(())
    } else {
        Err(Error::Request(msg.to_string()))
    }
}

/// Where a live load acts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum LiveLoad {
    #[default]
    None,
    Full,
    Left,
    Right,
    /// Horizontal, equal to each block's weight (tilting table).
    Horizontal,
}

/// Where an arch's radius is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum RadiusAt {
    #[default]
    Intrados,
    Centreline,
    Extrados,
}

/// The arch's shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ArchShape {
    /// Half circle, springings on the horizontal diameter.
    Semicircular,
    /// A circular segment subtending `2·half_angle` (radians, < π/2 … π/2).
    Segmental { half_angle: f64 },
    /// Two circular arcs whose centres lie on the springing line at ±`offset` from the middle
    /// (offset as a fraction of the intrados radius; 0.5 is the equilateral arch).
    Pointed { offset: f64 },
}

/// Parameters of `gen arch`.
#[derive(Clone, Debug)]
pub struct ArchSpec {
    pub shape: ArchShape,
    pub radius: f64,
    pub radius_at: RadiusAt,
    pub thickness: f64,
    pub voussoirs: usize,
    pub unit_weight: f64,
    pub width: f64,
    pub live: LiveLoad,
    /// Live load intensity q (kN/m², per unit horizontal projection of the extrados).
    pub live_load: f64,
}

impl Default for ArchSpec {
    fn default() -> Self {
        ArchSpec {
            shape: ArchShape::Semicircular,
            radius: 2.86,
            radius_at: RadiusAt::Intrados,
            thickness: 0.33,
            voussoirs: 64,
            unit_weight: 18.0,
            width: 1.0,
            live: LiveLoad::Full,
            live_load: 1.0,
        }
    }
}

fn polar(c: Point, r: f64, a: f64) -> Point {
    [c[0] + r * a.cos(), c[1] + r * a.sin()]
}

fn material_map(unit_weight: f64, width: f64) -> BTreeMap<String, Material> {
    let mut m = BTreeMap::new();
    m.insert(
        "default".to_string(),
        Material {
            unit_weight,
            width,
            ..Material::default()
        },
    );
    m
}

/// Make a polygon counter-clockwise, returning it.
fn ccw(mut p: Vec<Point>) -> Vec<Point> {
    if signed_area(&p) < 0.0 {
        p.reverse();
    }
    p
}

/// Index of the edge of `p` that runs between `x0` and `x1` (either way).
fn edge_between(p: &[Point], x0: Point, x1: Point) -> usize {
    let n = p.len();
    (0..n)
        .find(|&i| {
            let (a, b) = (p[i], p[(i + 1) % n]);
            (a == x0 && b == x1) || (a == x1 && b == x0)
        })
        .unwrap_or(0)
}

/// A support below/behind a springing joint `p_in`–`p_out`, extending `depth` along `dir`.
fn springing_support(name: &str, p_in: Point, p_out: Point, dir: Point, depth: f64) -> Support {
    let poly = vec![
        p_in,
        p_out,
        [p_out[0] + depth * dir[0], p_out[1] + depth * dir[1]],
        [p_in[0] + depth * dir[0], p_in[1] + depth * dir[1]],
    ];
    Support {
        name: name.into(),
        polygon: ccw(poly),
        motion: [0.0; 3],
        connection: Default::default(),
    }
}

/// The joints of the arch `s` from left to right as (intrados point, extrados point), and the
/// intrados radius, after validating `s` (the 3D vault generator uses them too).
pub(crate) fn arch_joints(s: &ArchSpec) -> Result<(Vec<(Point, Point)>, f64)> {
    req(
        s.radius.is_finite() && s.radius > 0.0,
        "arch radius must be positive",
    )?;
    req(
        s.thickness.is_finite() && s.thickness > 0.0,
        "arch thickness must be positive",
    )?;
    req(s.voussoirs >= 2, "an arch needs at least 2 voussoirs")?;
    req(
        s.unit_weight.is_finite() && s.unit_weight >= 0.0,
        "unit weight must be ≥ 0",
    )?;
    req(
        s.width.is_finite() && s.width > 0.0,
        "width must be positive",
    )?;
    req(s.live_load.is_finite(), "live load must be a finite number")?;
    let ri = match s.radius_at {
        RadiusAt::Intrados => s.radius,
        RadiusAt::Centreline => s.radius - s.thickness / 2.0,
        RadiusAt::Extrados => s.radius - s.thickness,
    };
    req(ri > 0.0, "the thickness is larger than the radius allows")?;
    let re = ri + s.thickness;
    let n = s.voussoirs;
    // Joints: a list of (intrados point, extrados point) from left to right.
    let mut joints: Vec<(Point, Point)> = Vec::with_capacity(n + 1);
    match s.shape {
        ArchShape::Semicircular | ArchShape::Segmental { .. } => {
            let half = match s.shape {
                ArchShape::Segmental { half_angle } => {
                    req(
                        half_angle > 0.0 && half_angle < PI / 2.0 + 1e-12,
                        "segmental half-angle must be in (0°, 90°]",
                    )?;
                    half_angle
                }
                _ => PI / 2.0,
            };
            let a0 = PI / 2.0 + half;
            for k in 0..=n {
                let a = a0 - 2.0 * half * k as f64 / n as f64;
                joints.push((polar([0.0, 0.0], ri, a), polar([0.0, 0.0], re, a)));
            }
            // Keep the crown exactly symmetric.
            for k in 0..=n {
                if 2 * k == n {
                    joints[k].0[0] = 0.0;
                    joints[k].1[0] = 0.0;
                }
            }
        }
        ArchShape::Pointed { offset } => {
            req(
                (0.0..1.0).contains(&offset),
                "pointed-arch offset must be in [0, 1) of the radius",
            )?;
            req(
                n % 2 == 0,
                "a pointed arch needs an even number of voussoirs",
            )?;
            let e = offset * ri;
            // Left half: centre (+e, 0), from angle π to the crown angle where x = 0.
            let top = (-e / ri).acos();
            let half = n / 2;
            for k in 0..=half {
                let a = PI - (PI - top) * k as f64 / half as f64;
                let pi = polar([e, 0.0], ri, a);
                let mut pe = polar([e, 0.0], re, a);
                if k == half {
                    // Vertical crown joint.
                    pe = [0.0, (re * re - e * e).sqrt()];
                }
                joints.push((pi, pe));
            }
            for k in (0..half).rev() {
                let (pi, pe) = joints[k];
                joints.push(([-pi[0], pi[1]], [-pe[0], pe[1]]));
            }
        }
    }
    Ok((joints, ri))
}

/// Generate an arch on two supports named `left` and `right`.
pub fn arch(s: &ArchSpec) -> Result<Model> {
    let (joints, ri) = arch_joints(s)?;
    let n = s.voussoirs;
    let mut blocks = Vec::with_capacity(n);
    let mut live = Vec::new();
    for k in 0..n {
        let (i0, e0) = joints[k];
        let (i1, e1) = joints[k + 1];
        let poly = ccw(vec![i0, i1, e1, e0]);
        let edge = edge_between(&poly, e0, e1);
        let cx = (i0[0] + i1[0] + e0[0] + e1[0]) / 4.0;
        let loaded = match s.live {
            LiveLoad::Full => true,
            LiveLoad::Left => cx < 0.0,
            LiveLoad::Right => cx > 0.0,
            _ => false,
        };
        if loaded && s.live_load != 0.0 {
            live.push(Load::Edge {
                block: k,
                edge,
                q: s.live_load,
                per: Per::Horizontal,
            });
        }
        blocks.push(Block {
            polygon: poly,
            material: None,
        });
    }
    if s.live == LiveLoad::Horizontal {
        live.push(Load::Body {
            coefficients: [1.0, 0.0],
            blocks: None,
        });
    }
    // Supports: extend away from the arch, perpendicular to the springing joint.
    let depth = s.thickness.max(0.1 * ri);
    let (li, le) = joints[0];
    let (ri_, re_) = joints[n];
    let dir_of = |a: Point, b: Point, away: Point| {
        // Unit normal of segment a–b pointing away from `away`.
        let d = [b[0] - a[0], b[1] - a[1]];
        let l = d[0].hypot(d[1]);
        let mut nrm = [d[1] / l, -d[0] / l];
        let m = [(a[0] + b[0]) / 2.0 - away[0], (a[1] + b[1]) / 2.0 - away[1]];
        if nrm[0] * m[0] + nrm[1] * m[1] < 0.0 {
            nrm = [-nrm[0], -nrm[1]];
        }
        nrm
    };
    let c0 = centroid4(&blocks[0].polygon);
    let cn = centroid4(&blocks[n - 1].polygon);
    let supports = vec![
        springing_support("left", li, le, dir_of(li, le, c0), depth),
        springing_support("right", ri_, re_, dir_of(ri_, re_, cn), depth),
    ];
    let shape = match s.shape {
        ArchShape::Semicircular => "semicircular".to_string(),
        ArchShape::Segmental { half_angle } => {
            format!("segmental ({:.1}° half-angle)", half_angle.to_degrees())
        }
        ArchShape::Pointed { offset } => format!("pointed (centres at ±{offset}·R)"),
    };
    Ok(Model {
        description: format!(
            "{shape} arch, intrados radius {ri} m, thickness {} m, {n} voussoirs, γ = {} kN/m³, live load {:?} q = {} kN/m²",
            s.thickness, s.unit_weight, s.live, s.live_load
        ),
        materials: material_map(s.unit_weight, s.width),
        blocks,
        supports,
        loads: Loads { self_weight: true, dead: vec![], live },
        tolerance: None,
        cracks: Vec::new(),
    })
}

fn centroid4(p: &[Point]) -> Point {
    crate::geometry::area_centroid(p).1
}

/// Parameters of `gen lintel`: a single course of bricks between two abutments.
#[derive(Clone, Debug)]
pub struct LintelSpec {
    pub span: f64,
    pub thickness: f64,
    pub bricks: usize,
    pub unit_weight: f64,
    pub width: f64,
    /// Live load on the extrados, kN/m (per unit length, times width 1).
    pub live_load: f64,
    pub compressive_strength: Option<f64>,
}

impl Default for LintelSpec {
    fn default() -> Self {
        LintelSpec {
            span: 1.5,
            thickness: 0.24,
            bricks: 6,
            unit_weight: 18.0,
            width: 1.0,
            live_load: 1.0,
            compressive_strength: None,
        }
    }
}

/// A flat lintel: `bricks` equal bricks spanning between supports `left` and `right` (vertical
/// faces). The live load is a vertical load on the top face of every brick.
pub fn lintel(s: &LintelSpec) -> Result<Model> {
    req(
        s.span > 0.0 && s.thickness > 0.0 && s.bricks >= 1,
        "lintel needs span > 0, thickness > 0, bricks ≥ 1",
    )?;
    req(
        s.unit_weight >= 0.0 && s.width > 0.0,
        "unit weight ≥ 0 and width > 0",
    )?;
    let (h, w) = (s.thickness, s.span / s.bricks as f64);
    let mut blocks = Vec::new();
    let mut live = Vec::new();
    for k in 0..s.bricks {
        let x0 = -s.span / 2.0 + k as f64 * w;
        let x1 = if k + 1 == s.bricks {
            s.span / 2.0
        } else {
            x0 + w
        };
        blocks.push(Block {
            polygon: vec![[x0, 0.0], [x1, 0.0], [x1, h], [x0, h]],
            material: None,
        });
        if s.live_load != 0.0 {
            live.push(Load::Edge {
                block: k,
                edge: 2,
                q: s.live_load / s.width,
                per: Per::Length,
            });
        }
    }
    let a = h; // abutment width
    let (l, r) = (-s.span / 2.0, s.span / 2.0);
    let supports = vec![
        Support {
            name: "left".into(),
            polygon: vec![[l - a, 0.0], [l, 0.0], [l, h], [l - a, h]],
            motion: [0.0; 3],
            connection: Default::default(),
        },
        Support {
            name: "right".into(),
            polygon: vec![[r, 0.0], [r + a, 0.0], [r + a, h], [r, h]],
            motion: [0.0; 3],
            connection: Default::default(),
        },
    ];
    let mut materials = material_map(s.unit_weight, s.width);
    if let Some(m) = materials.get_mut("default") {
        m.compressive_strength = s.compressive_strength;
    }
    Ok(Model {
        description: format!(
            "flat lintel, span {} m, thickness {} m, {} bricks",
            s.span, s.thickness, s.bricks
        ),
        materials,
        blocks,
        supports,
        loads: Loads {
            self_weight: true,
            dead: vec![],
            live,
        },
        tolerance: None,
        cracks: Vec::new(),
    })
}

/// First course of a running-bond wall.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FirstCourse {
    #[default]
    Full,
    Half,
}

/// Parameters of `gen wall`.
#[derive(Clone, Debug)]
pub struct WallSpec {
    pub courses: usize,
    /// Units per full course.
    pub units: usize,
    /// Unit length and height (m).
    pub unit: [f64; 2],
    pub first_course: FirstCourse,
    pub unit_weight: f64,
    pub width: f64,
    pub live: LiveLoad,
}

impl Default for WallSpec {
    fn default() -> Self {
        WallSpec {
            courses: 6,
            units: 5,
            unit: [0.4, 0.175],
            first_course: FirstCourse::Full,
            unit_weight: 18.0,
            width: 1.0,
            live: LiveLoad::None,
        }
    }
}

/// A running-bond wall on a foundation split into one segment per base unit (`f0`, `f1`, …
/// from left to right). A `full` course has `units` whole units; a `half` course has `units − 1`
/// whole units and a half unit at each end. Courses alternate.
pub fn wall(s: &WallSpec) -> Result<Model> {
    req(
        !matches!(s.live, LiveLoad::Left | LiveLoad::Right),
        "a wall's live load is none, full (the top course) or horizontal (left and right are the halves of an arch's span)",
    )?;
    req(
        s.courses >= 1 && s.units >= 1,
        "a wall needs at least one course and one unit",
    )?;
    req(
        s.unit[0] > 0.0 && s.unit[1] > 0.0,
        "unit size must be positive",
    )?;
    req(
        s.unit_weight >= 0.0 && s.width > 0.0,
        "unit weight ≥ 0 and width > 0",
    )?;
    let [l, h] = s.unit;
    let mut blocks = Vec::with_capacity(s.courses * (s.units + 1));
    let mut base_spans: Vec<(f64, f64)> = Vec::new();
    for c in 0..s.courses {
        let full = (c % 2 == 0) == (s.first_course == FirstCourse::Full);
        let (y0, y1) = (c as f64 * h, (c + 1) as f64 * h);
        let mut xs: Vec<f64> = Vec::new();
        if full || s.units == 1 {
            xs.extend((0..=s.units).map(|k| k as f64 * l));
        } else {
            xs.push(0.0);
            xs.extend((0..s.units).map(|k| (k as f64 + 0.5) * l));
            xs.push(s.units as f64 * l);
        }
        for w in xs.windows(2) {
            blocks.push(Block {
                polygon: vec![[w[0], y0], [w[1], y0], [w[1], y1], [w[0], y1]],
                material: None,
            });
            if c == 0 {
                base_spans.push((w[0], w[1]));
            }
        }
    }
    let depth = h;
    let supports = base_spans
        .iter()
        .enumerate()
        .map(|(k, &(x0, x1))| Support {
            name: format!("f{k}"),
            polygon: vec![[x0, -depth], [x1, -depth], [x1, 0.0], [x0, 0.0]],
            motion: [0.0; 3],
            connection: Default::default(),
        })
        .collect();
    let live = match s.live {
        LiveLoad::Horizontal => vec![Load::Body {
            coefficients: [1.0, 0.0],
            blocks: None,
        }],
        LiveLoad::None => vec![],
        _ => {
            // Vertical load on the top course.
            let nb = blocks.len();
            let top_y = s.courses as f64 * h;
            (0..nb)
                .filter(|&i| blocks[i].polygon[2][1] == top_y)
                .map(|i| Load::Edge {
                    block: i,
                    edge: 2,
                    q: 1.0,
                    per: Per::Horizontal,
                })
                .collect()
        }
    };
    Ok(Model {
        description: format!(
            "running-bond wall, {} courses of {} units {}×{} m, first course {:?}",
            s.courses, s.units, l, h, s.first_course
        ),
        materials: material_map(s.unit_weight, s.width),
        blocks,
        supports,
        loads: Loads {
            self_weight: true,
            dead: vec![],
            live,
        },
        tolerance: None,
        cracks: Vec::new(),
    })
}
