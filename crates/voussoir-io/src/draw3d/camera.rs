//! The camera stage of [`super::draw3d`]: the view (resolved when automatic), the extent of
//! everything drawn in the picture plane, the world → pixel camera once the page is laid out,
//! and the visible faces projected and put in paint order (far to near).

use super::layout::Layout;
use super::{auto_view, newell, paint_order, Camera, Draw3dOptions, Face, View};
use crate::draw::chrome::Bbox;
use crate::result3d::{dot, norm, scale as vscale, sub, Result3d, V3};

/// The view and the extent of the drawing in camera units (before the page's scale).
pub(super) struct Frame {
    pub view: View,
    pub right: V3,
    pub up: V3,
    pub toward: V3,
    /// The extent `[x0, top, x1, bottom]` and its width and height.
    pub bb: Bbox,
    pub bw: f64,
    pub bh: f64,
}

pub(super) fn frame(r: &(impl Result3d + ?Sized), lay: &Layout, opts: &Draw3dOptions) -> Frame {
    let view = match opts.view {
        View::Auto => auto_view(r),
        v => v,
    };
    let cam0 = Camera::of_view(view);
    let (right, up, toward) = (cam0.right, cam0.up, cam0.toward);
    let mut bb = Bbox::new();
    for (i, b) in lay.bodies.iter().enumerate() {
        if !lay.drawn(i) {
            continue;
        }
        for v in b.vertices {
            bb.add(cam0.px(lay.moved(i, *v)));
            if lay.has_motion && opts.undeformed {
                bb.add(cam0.px(*v));
            }
        }
    }
    for (blk, at, d, _) in &lay.loads {
        let t = lay.moved(*blk, *at);
        bb.add(cam0.px(t));
        bb.add(cam0.px(sub(t, *d)));
    }
    if !bb.valid() {
        bb = Bbox([0.0, -1.0, 1.0, 0.0]);
    }
    let (bw, bh) = ((bb.0[2] - bb.0[0]).max(1e-9), (bb.0[3] - bb.0[1]).max(1e-9));
    Frame {
        view,
        right,
        up,
        toward,
        bb,
        bw,
        bh,
    }
}

impl Frame {
    /// The camera of a page of `width` at `k` pixels per metre: the drawing centred, its top at
    /// `top`. (`px` gives (x·right, −x·up) before the offsets: `bb.0[1]` is the top.)
    pub fn camera(&self, k: f64, width: f64, top: f64) -> Camera {
        let draw_w = self.bw * k;
        Camera {
            right: self.right,
            up: self.up,
            toward: self.toward,
            k,
            ox: (width - draw_w) / 2.0 - k * self.bb.0[0],
            oy: top - k * self.bb.0[1],
        }
    }
}

/// The visible faces (deformed: back faces culled), projected, and their paint order.
pub(super) fn visible_faces(lay: &Layout, cam: &Camera) -> (Vec<Face>, Vec<usize>) {
    // Visible faces (deformed), with their depth and picture.
    let mut faces: Vec<Face> = Vec::new();
    for (bi, b) in lay.bodies.iter().enumerate() {
        if !lay.drawn(bi) {
            continue;
        }
        let verts: Vec<V3> = b.vertices.iter().map(|v| lay.moved(bi, *v)).collect();
        for (fi, f) in b.faces.iter().enumerate() {
            let world: Vec<V3> = f.iter().map(|&i| verts[i]).collect();
            faces.extend(Face::project(bi, fi, world, cam));
        }
    }
    let order = paint_order(&faces, 1e-7 * lay.size);
    (faces, order)
}

impl Camera {
    /// The camera of a view at one pixel per metre, unshifted (extents, scores).
    pub(super) fn of_view(view: View) -> Camera {
        let (right, up, toward) = view.basis();
        Camera {
            right,
            up,
            toward,
            k: 1.0,
            ox: 0.0,
            oy: 0.0,
        }
    }
}

impl Face {
    /// Face `index` of body `body` with (deformed) world vertices `world`, projected by `cam`
    /// with its mean depth; `None` for a degenerate face or one turned away from the camera.
    pub(super) fn project(body: usize, index: usize, world: Vec<V3>, cam: &Camera) -> Option<Face> {
        let n = newell(&world);
        let ln = norm(n);
        if !(ln > 0.0) {
            return None;
        }
        let n = vscale(n, 1.0 / ln);
        if dot(n, cam.toward) <= 1e-9 {
            return None;
        }
        let px: Vec<[f64; 2]> = world.iter().map(|p| cam.px(*p)).collect();
        let mut fb = Bbox::new();
        for p in &px {
            fb.add(*p);
        }
        let depth = world.iter().map(|p| cam.depth(*p)).sum::<f64>() / world.len() as f64;
        Some(Face {
            body,
            index,
            world,
            px,
            normal: n,
            depth,
            bbox: fb.0,
        })
    }
}
