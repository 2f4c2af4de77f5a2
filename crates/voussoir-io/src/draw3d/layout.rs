//! The layout stage of [`super::draw3d`]: the model's size and centre, the displacement scale,
//! the bodies as drawn (each with its finite rigid motion and its macro-block's colour) and the
//! load arrows, in world coordinates. Nothing here depends on the camera.

use super::{Body, Draw3dOptions, Rigid};
use crate::draw::chrome::{PALETTE, STILL, STONE};
use crate::draw::scene::auto_scale;
use crate::result3d::{norm, scale as vscale, small_displacement, Motions, Result3d, V3};
use std::collections::BTreeMap;
use voussoir::result::spatial::SpatialShapes;

/// What is drawn, in world coordinates.
pub(super) struct Layout<'a> {
    /// Blocks (the first `nb` bodies); supports follow.
    pub nb: usize,
    /// The model's size (m) and the displacement scale (0 when nothing moves).
    pub size: f64,
    pub scale: f64,
    pub has_motion: bool,
    pub show_supports: bool,
    pub bodies: Vec<Body<'a>>,
    /// (block, point, vector in metres of drawing, live).
    pub loads: Vec<(usize, V3, V3, bool)>,
    pub live_max: f64,
    pub dead_max: f64,
    /// The blocks' mean size (m), for the widths of lines and markers.
    pub mean_size: f64,
}

impl Layout<'_> {
    /// Where point `p` of body `body` is drawn.
    pub fn moved(&self, body: usize, p: V3) -> V3 {
        self.bodies[body].motion.apply(p)
    }

    /// Whether body `i` is drawn (supports on request).
    pub fn drawn(&self, i: usize) -> bool {
        self.show_supports || !self.bodies[i].support
    }
}

pub(super) fn layout<'a>(
    r: &(impl Result3d + ?Sized),
    g: &'a SpatialShapes,
    motions: &Motions,
    opts: &Draw3dOptions,
) -> Layout<'a> {
    let nb = g.blocks.len();
    let show_supports = opts.supports;

    // Size of the model.
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let all_vertices = g
        .blocks
        .iter()
        .flat_map(|b| b.vertices.iter())
        .chain(g.supports.iter().flat_map(|s| s.vertices.iter()));
    for v in all_vertices {
        for c in 0..3 {
            lo[c] = lo[c].min(v[c]);
            hi[c] = hi[c].max(v[c]);
        }
    }
    let (size, origin) = if lo[0] <= hi[0] {
        (
            (0..3)
                .map(|c| hi[c] - lo[c])
                .fold(0.0f64, f64::max)
                .max(1e-9),
            [
                (lo[0] + hi[0]) / 2.0,
                (lo[1] + hi[1]) / 2.0,
                (lo[2] + hi[2]) / 2.0,
            ],
        )
    } else {
        (1.0, [0.0; 3])
    };

    // Largest small displacement and rotation.
    type BodyMotion<'b> = (&'b [V3], (V3, [f64; 6]));
    let all_motions: Vec<BodyMotion> = g
        .blocks
        .iter()
        .zip(&motions.blocks)
        .map(|(b, m)| (b.vertices.as_slice(), *m))
        .chain(
            g.supports
                .iter()
                .zip(&motions.supports)
                .map(|(s, m)| (s.vertices.as_slice(), *m)),
        )
        .collect();
    let mut dmax = 0.0f64;
    let mut body_dmax = Vec::with_capacity(all_motions.len());
    for (vs, (c, d)) in &all_motions {
        let m = vs
            .iter()
            .map(|v| norm(small_displacement(*c, d, *v)))
            .fold(0.0f64, f64::max);
        body_dmax.push(m);
        dmax = dmax.max(m);
    }
    let moving: Vec<bool> = body_dmax
        .iter()
        .map(|&m| dmax > 0.0 && m > 1e-9 * dmax)
        .collect();
    let tmax = all_motions
        .iter()
        .zip(&moving)
        .filter(|(_, &mv)| mv)
        .map(|((_, (_, d)), _)| norm([d[3], d[4], d[5]]))
        .fold(0.0f64, f64::max);
    let has_motion = opts.deformed && moving.iter().any(|&m| m);
    let scale = if has_motion {
        match opts.scale {
            Some(s) if s.is_finite() && s >= 0.0 => s,
            _ => auto_scale(dmax, tmax, size),
        }
    } else {
        0.0
    };

    // Colours: one per macro-block (the same rigid field), as in 2D.
    let tq = tmax.max(1e-300);
    let uq = dmax.max(1e-300);
    let mut colour_of: BTreeMap<(i64, i64, i64, i64, i64, i64), usize> = BTreeMap::new();
    let mut bodies: Vec<Body> = Vec::with_capacity(all_motions.len());
    for (i, (_, (c, d))) in all_motions.iter().enumerate() {
        let support = i >= nb;
        let (vertices, faces) = if support {
            let s = &g.supports[i - nb];
            (s.vertices.as_slice(), s.faces.as_slice())
        } else {
            (
                g.blocks[i].vertices.as_slice(),
                g.blocks[i].faces.as_slice(),
            )
        };
        let mv = moving[i] && has_motion;
        let colour = if support {
            STILL
        } else if !has_motion {
            STONE
        } else if !mv {
            STILL
        } else {
            let w = small_displacement(*c, d, origin);
            let q = |x: f64, r: f64| ((x / r) * 1e7).round() as i64;
            let key = (
                q(w[0], uq),
                q(w[1], uq),
                q(w[2], uq),
                q(d[3], tq),
                q(d[4], tq),
                q(d[5], tq),
            );
            let n = colour_of.len();
            PALETTE[*colour_of.entry(key).or_insert(n) % PALETTE.len()]
        };
        bodies.push(Body {
            vertices,
            faces,
            support,
            moving: mv,
            colour,
            motion: Rigid::new(*c, d, if mv { scale } else { 0.0 }),
        });
    }
    // Loads: (block, point, vector in metres of drawing, live).
    let live_max = g
        .loads
        .iter()
        .filter(|l| l.live)
        .fold(0.0f64, |m, l| m.max(norm([l.fx, l.fy, l.fz])));
    let dead_max = g
        .loads
        .iter()
        .filter(|l| !l.live)
        .fold(0.0f64, |m, l| m.max(norm([l.fx, l.fy, l.fz])));
    let arrow_len = 0.09 * size;
    let mut loads: Vec<(usize, V3, V3, bool)> = Vec::new();
    for l in &g.loads {
        let (show, fmax) = if l.live {
            (opts.live_loads && r.live_loads(), live_max)
        } else {
            (opts.dead_loads, dead_max)
        };
        let f = norm([l.fx, l.fy, l.fz]);
        let at = [l.x, l.y, l.z];
        if !show || !(f > 0.0) || !(fmax > 0.0) || l.block >= nb || !crate::result3d::finite(at) {
            continue;
        }
        let len = arrow_len * (f / fmax).max(0.25);
        loads.push((l.block, at, vscale([l.fx, l.fy, l.fz], len / f), l.live));
    }
    // The mean block size (the cube root of the mean bounding-box volume), for pens.
    let mean_size = if nb > 0 {
        let vol: f64 = g
            .blocks
            .iter()
            .map(|b| {
                let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
                for v in &b.vertices {
                    for c in 0..3 {
                        lo[c] = lo[c].min(v[c]);
                        hi[c] = hi[c].max(v[c]);
                    }
                }
                if lo[0] <= hi[0] {
                    (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
                } else {
                    0.0
                }
            })
            .sum();
        (vol / nb as f64).cbrt().max(1e-9)
    } else {
        size / 10.0
    };
    Layout {
        nb,
        size,
        scale,
        has_motion,
        show_supports,
        bodies,
        loads,
        live_max,
        dead_max,
        mean_size,
    }
}
