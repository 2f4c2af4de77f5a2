//! 3D geometry against hand calculations: volumes and centroids of boxes, an L-shaped prism and
//! a tetrahedron; every validation error; interfaces of stacked, bridging, U-shaped and inclined
//! blocks; the overlap check; a running-bond wall's interface count and total area.

use voussoir::geometry3d::{
    bbox3, clean_polyhedron, detect_interfaces3, find_overlap3, Interface3, Solid,
};

const TOL: f64 = 1e-9;

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

fn close3(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|k| close(a[k], b[k], tol))
}

/// The box [lo, hi], faces counter-clockwise seen from outside.
fn cuboid_raw(lo: [f64; 3], hi: [f64; 3]) -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let v = vec![
        [lo[0], lo[1], lo[2]],
        [hi[0], lo[1], lo[2]],
        [hi[0], hi[1], lo[2]],
        [lo[0], hi[1], lo[2]],
        [lo[0], lo[1], hi[2]],
        [hi[0], lo[1], hi[2]],
        [hi[0], hi[1], hi[2]],
        [lo[0], hi[1], hi[2]],
    ];
    let f = vec![
        vec![0, 3, 2, 1], // bottom, −z
        vec![4, 5, 6, 7], // top, +z
        vec![0, 1, 5, 4], // −y
        vec![1, 2, 6, 5], // +x
        vec![2, 3, 7, 6], // +y
        vec![3, 0, 4, 7], // −x
    ];
    (v, f)
}

fn cuboid(lo: [f64; 3], hi: [f64; 3]) -> Solid {
    let (v, f) = cuboid_raw(lo, hi);
    clean_polyhedron("box", &v, &f, TOL).unwrap()
}

/// A prism: the planar polygon `base` (counter-clockwise about `ext`) swept by the vector `ext`.
fn prism_raw(base: &[[f64; 3]], ext: [f64; 3]) -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let n = base.len();
    let mut v = base.to_vec();
    v.extend(
        base.iter()
            .map(|p| [p[0] + ext[0], p[1] + ext[1], p[2] + ext[2]]),
    );
    let mut f = vec![(0..n).rev().collect::<Vec<_>>(), (n..2 * n).collect()];
    for i in 0..n {
        let j = (i + 1) % n;
        f.push(vec![i, j, n + j, n + i]);
    }
    (v, f)
}

fn prism(base: &[[f64; 3]], ext: [f64; 3]) -> Solid {
    let (v, f) = prism_raw(base, ext);
    clean_polyhedron("prism", &v, &f, TOL).unwrap()
}

/// A polygon drawn in the (x, z) plane (counter-clockwise with x right and z up), swept from
/// y = 0 to y = −d: counter-clockwise in (x, z) is counter-clockwise about −y.
fn prism_xz(poly: &[[f64; 2]], d: f64) -> Solid {
    let base: Vec<[f64; 3]> = poly.iter().map(|p| [p[0], 0.0, p[1]]).collect();
    prism(&base, [0.0, -d, 0.0])
}

fn model_error(v: &[[f64; 3]], f: &[Vec<usize>]) -> String {
    match clean_polyhedron("block 7", v, f, TOL) {
        Err(voussoir::Error::Model(m)) => m,
        other => panic!("expected a model error, got {other:?}"),
    }
}

// ---------------------------------------------------------------- mass properties

#[test]
fn unit_cube_volume_and_centroid() {
    let c = cuboid([0.0; 3], [1.0; 3]);
    assert!(close(c.volume, 1.0, 1e-12));
    assert!(close3(c.centroid, [0.5; 3], 1e-12));
}

#[test]
fn box_b_d_h_volume_and_centroid() {
    // b × d × h = 2 × 3 × 0.5 with its low corner at (1, 2, 3): V = 3, centroid at the middle.
    let c = cuboid([1.0, 2.0, 3.0], [3.0, 5.0, 3.5]);
    assert!(close(c.volume, 3.0, 1e-12));
    assert!(close3(c.centroid, [2.0, 3.5, 3.25], 1e-12));
}

#[test]
fn l_shaped_prism_volume_and_centroid() {
    // L = [0,3]×[0,1] ∪ [0,1]×[1,2] (areas 3 and 1, centroids (1.5, 0.5) and (0.5, 1.5)),
    // height 2: V = 4·2 = 8, centroid ((4.5 + 0.5)/4, (1.5 + 1.5)/4, 1) = (1.25, 0.75, 1).
    // Its top and bottom faces are non-convex hexagons.
    let l = prism(
        &[
            [0.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [3.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 2.0, 0.0],
            [0.0, 2.0, 0.0],
        ],
        [0.0, 0.0, 2.0],
    );
    assert!(close(l.volume, 8.0, 1e-12));
    assert!(close3(l.centroid, [1.25, 0.75, 1.0], 1e-12));
}

#[test]
fn tetrahedron_volume_and_centroid() {
    // Corner tetrahedron with legs a, b, c = 1, 2, 3: V = abc/6 = 1, centroid (a, b, c)/4.
    let v = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 2.0, 0.0],
        [0.0, 0.0, 3.0],
    ];
    let f = vec![vec![0, 2, 1], vec![0, 1, 3], vec![0, 3, 2], vec![1, 2, 3]];
    let t = clean_polyhedron("tet", &v, &f, TOL).unwrap();
    assert!(close(t.volume, 1.0, 1e-12));
    assert!(close3(t.centroid, [0.25, 0.5, 0.75], 1e-12));
    assert_eq!(t.faces, f);
}

#[test]
fn inward_cube_is_turned_outward() {
    let (v, f) = cuboid_raw([0.0; 3], [1.0; 3]);
    let inward: Vec<Vec<usize>> = f
        .iter()
        .map(|g| g.iter().rev().copied().collect())
        .collect();
    let c = clean_polyhedron("block 0", &v, &inward, TOL).unwrap();
    assert!(close(c.volume, 1.0, 1e-12));
    assert!(close3(c.centroid, [0.5; 3], 1e-12));
    // Each returned face is the original outward face (up to the starting vertex): the top
    // face's vertices in order 4 → 5 → 6 → 7 cyclically.
    for (got, want) in c.faces.iter().zip(&f) {
        let k = got.iter().position(|&x| x == want[0]).unwrap();
        let mut g = got.clone();
        g.rotate_left(k);
        assert_eq!(&g, want);
    }
}

// ---------------------------------------------------------------- validation errors

#[test]
fn each_validation_error_names_the_block() {
    let (v, f) = cuboid_raw([0.0; 3], [1.0; 3]);

    let m = model_error(&v[..3], &f);
    assert_eq!(m, "block 7: polyhedron has 3 vertices, needs at least 4");

    let m = model_error(&v, &f[..3]);
    assert_eq!(m, "block 7: polyhedron has 3 faces, needs at least 4");

    let mut w = v.clone();
    w[2][1] = f64::NAN;
    let m = model_error(&w, &f);
    assert_eq!(
        m,
        "block 7: vertex 2 has a coordinate that is not a finite number"
    );

    let mut g = f.clone();
    g[1][2] = 9;
    let m = model_error(&v, &g);
    assert_eq!(
        m,
        "block 7: face 1 refers to vertex 9, but there are only 8 vertices"
    );

    let mut g = f.clone();
    g[3] = vec![1, 2];
    let m = model_error(&v, &g);
    assert_eq!(m, "block 7: face 3 has 2 vertices, needs at least 3");

    let mut g = f.clone();
    g[0] = vec![0, 3, 2, 3];
    let m = model_error(&v, &g);
    assert_eq!(m, "block 7: face 0 lists vertex 3 twice");

    // A zero-area face: three collinear vertices (8 is the midpoint of edge 0–1).
    let mut w = v.clone();
    w.push([0.5, 0.0, 0.0]);
    let mut g = f.clone();
    g.push(vec![0, 8, 1]);
    let m = model_error(&w, &g);
    assert_eq!(m, "block 7: face 6 is degenerate (zero area)");

    // Vertex 6 lifted by 0.01: the top face (1) is not planar; Newell's plane passes through
    // the mean of its vertices, so each vertex is 0.01/4 = 2.5e-3 off it (tilt is second order).
    let mut w = v.clone();
    w[6][2] += 0.01;
    let m = model_error(&w, &f);
    assert!(
        m.starts_with("block 7: face 1 is not planar (vertex 4 is 2.500e-3 m off the face's plane"),
        "{m}"
    );

    let m = model_error(&v, &f[..5]);
    assert!(
        m.starts_with("block 7: the surface is open (edge ")
            && m.ends_with("belongs to no other face)"),
        "{m}"
    );

    // A duplicate of the bottom face, turned round: edge 0–1 is in three faces.
    let mut g = f.clone();
    g.push(vec![0, 1, 2, 3]);
    let m = model_error(&v, &g);
    assert_eq!(
        m,
        "block 7: the surface is not manifold (edge 0–1 is shared by faces 0, 2, 6)"
    );

    // One face turned round: it runs along its edges in the same direction as its neighbours.
    let mut g = f.clone();
    g[1].reverse();
    let m = model_error(&v, &g);
    assert_eq!(
        m,
        "block 7: faces 1 and 2 are oriented inconsistently (both run along edge 5→4)"
    );

    // A flat "pillow": a square covered by two triangles on top and two (along the other
    // diagonal) below; closed, manifold, consistently oriented, but of zero volume.
    let sq = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    let g = vec![vec![0, 1, 2], vec![0, 2, 3], vec![0, 3, 1], vec![1, 3, 2]];
    let m = model_error(&sq, &g);
    assert_eq!(m, "block 7: the polyhedron has zero volume");
}

#[test]
fn support_names_appear_too() {
    let (v, f) = cuboid_raw([0.0; 3], [1.0; 3]);
    let e = clean_polyhedron("support 'left'", &v, &f[..5], TOL).unwrap_err();
    let s = e.to_string();
    assert!(
        s.starts_with("invalid model: support 'left': the surface is open"),
        "{s}"
    );
    assert!(!s.contains('\n'));
}

// ---------------------------------------------------------------- interfaces

fn areas(ifs: &[Interface3]) -> Vec<f64> {
    ifs.iter().map(|i| i.area).collect()
}

#[test]
fn stacked_boxes_with_offset_share_the_overlap_rectangle() {
    // A = [0,1]³, B = [0.3,1.5]×[0.4,1.2]×[1,2]: overlap [0.3,1]×[0.4,1], area 0.7·0.6 = 0.42.
    let a = cuboid([0.0; 3], [1.0; 3]);
    let b = cuboid([0.3, 0.4, 1.0], [1.5, 1.2, 2.0]);
    let ifs = detect_interfaces3(&[&a, &b], TOL);
    assert_eq!(ifs.len(), 1);
    let i = &ifs[0];
    assert_eq!((i.a, i.b), (0, 1));
    assert!(close3(i.normal, [0.0, 0.0, 1.0], 1e-12));
    assert!(close(i.area, 0.42, 1e-12));
    // Counter-clockwise about +z from the lexicographically smallest corner.
    let want = [
        [0.3, 0.4, 1.0],
        [1.0, 0.4, 1.0],
        [1.0, 1.0, 1.0],
        [0.3, 1.0, 1.0],
    ];
    assert_eq!(i.polygon.len(), 4);
    for (p, q) in i.polygon.iter().zip(&want) {
        assert!(close3(*p, *q, 1e-12), "{:?}", i.polygon);
    }

    // The other order: a is the upper box, its outward normal is −z, the ring turns the other way.
    let ifs = detect_interfaces3(&[&b, &a], TOL);
    assert_eq!(ifs.len(), 1);
    let i = &ifs[0];
    assert_eq!((i.a, i.b), (0, 1));
    assert!(close3(i.normal, [0.0, 0.0, -1.0], 1e-12));
    assert!(close(i.area, 0.42, 1e-12));
    let want = [
        [0.3, 0.4, 1.0],
        [0.3, 1.0, 1.0],
        [1.0, 1.0, 1.0],
        [1.0, 0.4, 1.0],
    ];
    for (p, q) in i.polygon.iter().zip(&want) {
        assert!(close3(*p, *q, 1e-12), "{:?}", i.polygon);
    }
}

#[test]
fn face_split_into_triangles_gives_one_interface() {
    // A's top split along its diagonal into two triangles; B = [0.2,1.2]×[0.3,1.3]×[1,2] on it:
    // one interface, the rectangle [0.2,1]×[0.3,1] (area 0.8·0.7 = 0.56), the points where the
    // diagonal crosses its sides dropped as collinear.
    let (v, mut f) = cuboid_raw([0.0; 3], [1.0; 3]);
    f[1] = vec![4, 5, 6];
    f.push(vec![4, 6, 7]);
    let a = clean_polyhedron("block 0", &v, &f, TOL).unwrap();
    assert!(close(a.volume, 1.0, 1e-12));
    let b = cuboid([0.2, 0.3, 1.0], [1.2, 1.3, 2.0]);
    let ifs = detect_interfaces3(&[&a, &b], TOL);
    assert_eq!(ifs.len(), 1);
    assert!(close(ifs[0].area, 0.56, 1e-12));
    let want = [
        [0.2, 0.3, 1.0],
        [1.0, 0.3, 1.0],
        [1.0, 1.0, 1.0],
        [0.2, 1.0, 1.0],
    ];
    assert_eq!(ifs[0].polygon.len(), 4, "{:?}", ifs[0].polygon);
    for (p, q) in ifs[0].polygon.iter().zip(&want) {
        assert!(close3(*p, *q, 1e-12), "{:?}", ifs[0].polygon);
    }
}

#[test]
fn block_on_two_supports() {
    // Supports [0,1] and [2,3] in x; the block [0.5,2.5]×[0,1]×[0,0.5] rests on 0.5 m of each.
    let s1 = cuboid([0.0, 0.0, -1.0], [1.0, 1.0, 0.0]);
    let s2 = cuboid([2.0, 0.0, -1.0], [3.0, 1.0, 0.0]);
    let b = cuboid([0.5, 0.0, 0.0], [2.5, 1.0, 0.5]);
    let ifs = detect_interfaces3(&[&s1, &s2, &b], TOL);
    assert_eq!(ifs.len(), 2);
    assert_eq!((ifs[0].a, ifs[0].b, ifs[1].a, ifs[1].b), (0, 2, 1, 2));
    for i in &ifs {
        assert!(close(i.area, 0.5, 1e-12));
        assert!(close3(i.normal, [0.0, 0.0, 1.0], 1e-12));
        assert_eq!(i.polygon.len(), 4);
    }
}

#[test]
fn u_shaped_block_on_one_box_has_two_interfaces() {
    // An upside-down U (feet x ∈ [0,1] and [2,3], opening 1 m high) of depth 1 on the box
    // [0,3]×[−1,0]×[−1,0]: two interfaces with the same pair, 1 m² each.
    let u = prism_xz(
        &[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [3.0, 2.0],
            [0.0, 2.0],
        ],
        1.0,
    );
    // V = 3·2 − 1·1 = 5.
    assert!(close(u.volume, 5.0, 1e-12));
    let base = cuboid([0.0, -1.0, -1.0], [3.0, 0.0, 0.0]);
    let ifs = detect_interfaces3(&[&base, &u], TOL);
    assert_eq!(ifs.len(), 2, "{ifs:?}");
    for i in &ifs {
        assert_eq!((i.a, i.b), (0, 1));
        assert!(close(i.area, 1.0, 1e-12));
        assert!(close3(i.normal, [0.0, 0.0, 1.0], 1e-12));
    }
    // Sorted by polygon: the foot at x ∈ [0,1] first.
    assert!(close3(ifs[0].polygon[0], [0.0, -1.0, 0.0], 1e-12));
    assert!(close3(ifs[1].polygon[0], [2.0, -1.0, 0.0], 1e-12));
}

#[test]
fn non_convex_faces_intersect_exactly() {
    // An L-shaped prism on an L-shaped prism turned by 180° about z: bottom of the upper and
    // top of the lower are non-convex hexagons. L = [0,3]×[0,1] ∪ [0,1]×[0,2]; its image under
    // (x, y) → (3 − x, 2 − y) is [0,3]×[1,2] ∪ [2,3]×[0,2]; the intersection is
    // [0,1]×[1,2] ∪ [2,3]×[0,1]: two unit squares meeting only at no point → two interfaces.
    let l = |p: [f64; 2]| [p[0], p[1], 0.0];
    let lower = prism(
        &[
            [0.0, 0.0],
            [3.0, 0.0],
            [3.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ]
        .map(l),
        [0.0, 0.0, 1.0],
    );
    let upper_base: Vec<[f64; 3]> = [
        [3.0, 2.0],
        [0.0, 2.0],
        [0.0, 1.0],
        [2.0, 1.0],
        [2.0, 0.0],
        [3.0, 0.0],
    ]
    .iter()
    .map(|p| [p[0], p[1], 1.0])
    .collect();
    let upper = prism(&upper_base, [0.0, 0.0, 1.0]);
    let ifs = detect_interfaces3(&[&lower, &upper], TOL);
    assert_eq!(ifs.len(), 2, "{ifs:?}");
    for i in &ifs {
        assert!(close(i.area, 1.0, 1e-12));
        assert_eq!(i.polygon.len(), 4);
    }
}

#[test]
fn inclined_joint_of_a_cube_cut_in_two() {
    // The unit cube cut by the plane x + z = 1 into two triangular prisms: the joint is the
    // diagonal rectangle √2 × 1, normal (1, 0, 1)/√2 from the lower prism.
    let lower = prism_xz(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], 1.0);
    let upper = prism_xz(&[[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], 1.0);
    assert!(close(lower.volume, 0.5, 1e-12) && close(upper.volume, 0.5, 1e-12));
    assert!(close3(lower.centroid, [1.0 / 3.0, -0.5, 1.0 / 3.0], 1e-12));
    let ifs = detect_interfaces3(&[&lower, &upper], TOL);
    assert_eq!(ifs.len(), 1);
    let r = std::f64::consts::FRAC_1_SQRT_2;
    assert!(close3(ifs[0].normal, [r, 0.0, r], 1e-12));
    assert!(close(ifs[0].area, std::f64::consts::SQRT_2, 1e-12));
    assert_eq!(ifs[0].polygon.len(), 4);
    for p in &ifs[0].polygon {
        assert!(close(p[0] + p[2], 1.0, 1e-12));
    }
}

#[test]
fn separated_parallel_faces_and_same_direction_faces_are_not_interfaces() {
    let a = cuboid([0.0; 3], [1.0; 3]);
    // Facing, parallel, 1 mm apart (tol 1e-9 m): no interface.
    let b = cuboid([0.0, 0.0, 1.001], [1.0, 1.0, 2.0]);
    assert!(detect_interfaces3(&[&a, &b], TOL).is_empty());
    // Side by side: the shared side face is an interface, the coplanar tops, bottoms and long
    // sides (same direction) are not.
    let c = cuboid([1.0, 0.0, 0.0], [2.0, 1.0, 1.0]);
    let ifs = detect_interfaces3(&[&a, &c], TOL);
    assert_eq!(ifs.len(), 1);
    assert!(close3(ifs[0].normal, [1.0, 0.0, 0.0], 1e-12));
    assert!(close(ifs[0].area, 1.0, 1e-12));
    // Apart side by side: coplanar faces of the same direction only, nothing.
    let d = cuboid([2.0, 0.0, 0.0], [3.0, 1.0, 1.0]);
    assert!(detect_interfaces3(&[&a, &d], TOL).is_empty());
    // Touching along an edge only (x = 1, z = 1): no area, no interface.
    let e = cuboid([1.0, 0.0, 1.0], [2.0, 1.0, 2.0]);
    assert!(detect_interfaces3(&[&a, &e], TOL).is_empty());
}

#[test]
fn gap_within_tolerance_is_a_contact() {
    // A gap of 0.5 tol between the boxes: still in contact (planes coincide within tol).
    let a = cuboid([0.0; 3], [1.0; 3]);
    let b = cuboid([0.0, 0.0, 1.0 + 0.5 * TOL], [1.0, 1.0, 2.0]);
    let ifs = detect_interfaces3(&[&a, &b], TOL);
    assert_eq!(ifs.len(), 1);
    assert!(close(ifs[0].area, 1.0, 1e-8));
}

// ---------------------------------------------------------------- overlap

#[test]
fn overlap_check() {
    let a = cuboid([0.0; 3], [1.0; 3]);
    let b = cuboid([0.5, 0.5, 0.5], [1.5, 1.5, 1.5]);
    let on_top = cuboid([0.2, 0.3, 1.0], [1.2, 1.3, 2.0]);
    let side = cuboid([1.0, 0.0, 0.0], [2.0, 1.0, 1.0]);
    let small = cuboid([0.4, 0.4, 0.4], [0.6, 0.6, 0.6]);
    let none = |_: usize, _: usize| false;
    assert_eq!(find_overlap3(&[&a, &b], TOL, &none), Some((0, 1)));
    assert_eq!(find_overlap3(&[&a, &on_top, &side], TOL, &none), None);
    assert_eq!(
        find_overlap3(&[&on_top, &a, &small], TOL, &none),
        Some((1, 2))
    );
    // Identical bodies: no vertex, edge midpoint or face point is strictly inside the other;
    // the interior point is.
    assert_eq!(find_overlap3(&[&side, &a, &a], TOL, &none), Some((1, 2)));
    // The caller may skip pairs (support–support).
    assert_eq!(
        find_overlap3(&[&a, &b], TOL, &|i, j| (i, j) == (0, 1)),
        None
    );
    // A cross: two bars through each other, no vertex of either inside the other.
    let bar_x = cuboid([-1.0, 0.4, 0.4], [2.0, 0.6, 0.6]);
    let bar_y = cuboid([0.4, -1.0, 0.45], [0.6, 2.0, 0.55]);
    assert_eq!(find_overlap3(&[&bar_x, &bar_y], TOL, &none), Some((0, 1)));
    // A U-shaped block straddling a bar that passes through its opening: no overlap.
    let u = prism_xz(
        &[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [2.0, 1.0],
            [2.0, 0.0],
            [3.0, 0.0],
            [3.0, 2.0],
            [0.0, 2.0],
        ],
        1.0,
    );
    let through = cuboid([1.0, -2.0, 0.0], [2.0, 1.0, 1.0]);
    assert_eq!(find_overlap3(&[&u, &through], TOL, &none), None);
    let too_tall = cuboid([1.0, -2.0, 0.0], [2.0, 1.0, 1.2]);
    assert_eq!(find_overlap3(&[&u, &too_tall], TOL, &none), Some((0, 1)));
    // Two identical non-convex bodies: the interior point (found through a face's interior
    // point, here by the scanline since the U's vertex mean lies in its opening) is inside.
    assert_eq!(find_overlap3(&[&u, &u], TOL, &none), Some((0, 1)));
}

#[test]
fn touching_non_box_bodies_do_not_overlap() {
    // The cube cut along x + z = 1: bounding boxes overlap, the halves only touch.
    let lower = prism_xz(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], 1.0);
    let upper = prism_xz(&[[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], 1.0);
    let none = |_: usize, _: usize| false;
    assert_eq!(find_overlap3(&[&lower, &upper], TOL, &none), None);
    // The upper half pushed 1 cm into the lower one (along −x): overlap.
    let pushed = prism_xz(&[[0.99, 0.0], [0.99, 1.0], [-0.01, 1.0]], 1.0);
    assert_eq!(find_overlap3(&[&lower, &pushed], TOL, &none), Some((0, 1)));
    // Pulled 1 cm away (along +x): neither overlap nor contact.
    let pulled = prism_xz(&[[1.01, 0.0], [1.01, 1.0], [0.01, 1.0]], 1.0);
    assert_eq!(find_overlap3(&[&lower, &pulled], TOL, &none), None);
    assert!(detect_interfaces3(&[&lower, &pulled], TOL).is_empty());
}

#[test]
fn bbox_of_points() {
    let b = bbox3(&[[1.0, -2.0, 3.0], [-1.0, 5.0, 0.5]]);
    assert_eq!(b, [[-1.0, -2.0, 0.5], [1.0, 5.0, 3.0]]);
}

// ---------------------------------------------------------------- running-bond wall

/// `courses` × `units` bricks `l × d × h`, odd courses shifted by l/2, on a ground slab
/// (body 0) wider than the wall.
fn running_bond(courses: usize, units: usize, [l, d, h]: [f64; 3]) -> Vec<Solid> {
    let mut out = vec![cuboid(
        [-l, -d, -h],
        [(units as f64 + 1.0) * l, 2.0 * d, 0.0],
    )];
    for k in 0..courses {
        let shift = if k % 2 == 1 { 0.5 * l } else { 0.0 };
        for i in 0..units {
            let x = i as f64 * l + shift;
            let z = k as f64 * h;
            out.push(cuboid([x, 0.0, z], [x + l, d, z + h]));
        }
    }
    out
}

#[test]
fn running_bond_wall_interfaces_by_hand() {
    // n courses of m units. Head joints: m − 1 per course, area h·d. Bed joints between two
    // courses: each upper unit overlaps 2 lower ones except at one end, 2m − 1 joints covering
    // the courses' common length (m − 1/2)·l. Ground: m joints of l·d.
    let (n, m) = (7usize, 9usize);
    let [l, d, h] = [0.25, 0.12, 0.055];
    let bodies = running_bond(n, m, [l, d, h]);
    let refs: Vec<&Solid> = bodies.iter().collect();
    let tol = 1e-7 * 3.0;
    let ifs = detect_interfaces3(&refs, tol);
    let (nf, mf) = (n as f64, m as f64);
    let count = n * (m - 1) + (n - 1) * (2 * m - 1) + m;
    let area = nf * (mf - 1.0) * h * d + (nf - 1.0) * (mf - 0.5) * l * d + mf * l * d;
    assert_eq!(ifs.len(), count);
    let total: f64 = areas(&ifs).iter().sum();
    assert!(close(total, area, 1e-12), "{total} vs {area}");
    // Bed joints are l/2 × d (4 corners), head joints h × d, each with 4 vertices.
    for i in &ifs {
        assert_eq!(i.polygon.len(), 4);
        assert!(i.a < i.b);
        let horizontal = close(i.normal[2].abs(), 1.0, 1e-12);
        if horizontal && i.a > 0 {
            assert!(close(i.area, 0.5 * l * d, 1e-12));
        } else if !horizontal {
            assert!(close3(i.normal, [1.0, 0.0, 0.0], 1e-12) && close(i.area, h * d, 1e-12));
        }
    }
    assert_eq!(find_overlap3(&refs, tol, &|_, _| false), None);
}
