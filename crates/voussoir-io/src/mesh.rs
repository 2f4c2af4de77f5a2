//! Polygon meshes as 3D models: Wavefront OBJ (each object or group is a block) and PLY (each
//! connected closed component is a block) read into a [`Model3d`]; and a 3D model written as
//! OBJ (each block the object `block_i`, each support `support_NAME`), so that generated
//! models round-trip. See docs/import3d.md.
//!
//! Reading a body:
//! 1. coordinates are scaled to metres (`units`);
//! 2. vertices closer than the weld tolerance are merged (`weld`, metres; default 1e-7 of the
//!    model's bounding-box diagonal, the default geometric tolerance of the analyses), and faces
//!    that collapse to fewer than three vertices are dropped;
//! 3. the surface is checked: every edge is shared by exactly two faces (else the body is
//!    *open* or *non-manifold*), the faces can be oriented consistently, the body is one piece
//!    and encloses a volume; faces are turned to point outwards;
//! 4. coplanar faces that share edges (a triangulated rectangle, a fan) are merged back into one
//!    polygon face, because interfaces between blocks are found on whole faces; a vertex left in
//!    the middle of a straight edge between two merged faces is removed;
//! 5. the surface must not intersect itself (an edge through a face it does not touch);
//! 6. the polyhedron is validated by the library's 3D geometry (planarity, degenerate faces,
//!    volume) under the body's own name.
//!
//! Every error is one line naming the OBJ object or PLY part.

use crate::dxf::{ImportLive, Units};
use crate::IoError;
use std::collections::{BTreeMap, HashMap, VecDeque};
use std::path::Path;
use voussoir::model::Material;
use voussoir::model3d::{Block3d, Load3d, Loads3d, Model3d, Point3, Support3d};

/// The default geometric tolerance of the analyses, relative to the bounding-box diagonal.
const DEFAULT_REL_TOLERANCE: f64 = 1e-7;
/// Bodies whose lowest point is within this (relative to the diagonal) of the model's lowest
/// point stand on the ground plane.
const GROUND_REL_TOLERANCE: f64 = 1e-6;
/// Object-name prefix of supports in an OBJ written by [`model_to_obj`].
pub const SUPPORT_PREFIX: &str = "support_";

/// How to read a mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshOptions {
    /// Units of the coordinates (default metres).
    pub units: Units,
    /// Unit weight γ of the blocks, kN/m³.
    pub unit_weight: f64,
    /// Bodies (OBJ object names, PLY `part_K`) that are supports.
    pub supports: Vec<String>,
    /// Bodies whose name starts with this are supports.
    pub support_prefix: Option<String>,
    /// Vertex welding tolerance in metres (None: 1e-7 of the bounding-box diagonal).
    pub weld: Option<f64>,
    pub live: ImportLive,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            units: Units::M,
            unit_weight: Material::default().unit_weight,
            supports: Vec::new(),
            support_prefix: None,
            weld: None,
            live: ImportLive::Horizontal,
        }
    }
}

/// What the import found, beside the model.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshReport {
    /// `OBJ` or `PLY`.
    pub format: &'static str,
    /// The body each block comes from ("OBJ object 'tower_1'"), by block index.
    pub block_sources: Vec<String>,
    /// The body each support comes from, by support index.
    pub support_sources: Vec<String>,
    /// How the supports were chosen.
    pub support_rule: String,
    /// Welding tolerance used (m) and number of vertices merged away.
    pub weld_tolerance: f64,
    pub welded_vertices: usize,
    /// Faces read and faces written after coplanar faces were merged.
    pub faces_read: usize,
    pub faces_written: usize,
    /// Repairs made while reading (one line each).
    pub notes: Vec<String>,
}

impl MeshReport {
    /// `msg` with the source of every "block N" it mentions: "block 3 (OBJ object 'arch_3')".
    pub fn annotate(&self, msg: &str) -> String {
        crate::dxf::annotate_blocks(msg, &self.block_sources)
    }

    /// One line: counts, supports, welding and face merging.
    pub fn summary(&self) -> String {
        format!(
            "{} blocks, {} support(s) [{}] ({}), {} vertices welded within {:.1e} m, {} faces merged into {}",
            self.block_sources.len(),
            self.support_sources.len(),
            self.support_sources.join(", "),
            self.support_rule,
            self.welded_vertices,
            self.weld_tolerance,
            self.faces_read,
            self.faces_written
        )
    }
}

/// Whether `path` is read as a mesh (`.obj` or `.ply`, any case).
pub fn is_mesh(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("obj") || e.eq_ignore_ascii_case("ply"))
}

/// Read an OBJ or PLY file (by extension) as a 3D model.
pub fn read_mesh(path: &Path, opts: &MeshOptions) -> Result<(Model3d, MeshReport), IoError> {
    let bytes =
        std::fs::read(path).map_err(|e| IoError(format!("cannot read {}: {e}", path.display())))?;
    let file = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ply = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("ply"));
    let r = if ply {
        parse_ply(&bytes, opts, &file)
    } else {
        parse_obj(&bytes, opts, &file)
    };
    r.map_err(|e| IoError(format!("{}: {}", path.display(), e.0)).one_line())
}

/// A body as read: a name, vertices and faces (vertex index lists).
#[derive(Clone, Debug)]
struct RawBody {
    name: String,
    vertices: Vec<Point3>,
    faces: Vec<Vec<usize>>,
}

/// Read OBJ text: each object (`o`) or group (`g`) is a body; parts of one name (a `usemtl`
/// splits an object) are joined. A file without any `o`/`g` is split into its connected parts
/// like a PLY.
pub fn parse_obj(
    bytes: &[u8],
    opts: &MeshOptions,
    file: &str,
) -> Result<(Model3d, MeshReport), IoError> {
    parse_obj_inner(bytes, opts, file).map_err(IoError::one_line)
}

fn parse_obj_inner(
    bytes: &[u8],
    opts: &MeshOptions,
    file: &str,
) -> Result<(Model3d, MeshReport), IoError> {
    let load = tobj::LoadOptions {
        single_index: true,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    };
    // Texture coordinates (`vt`) and normals (`vn`) are not used: they are dropped before
    // tobj sees the file, which keeps it away from its unchecked arithmetic on their indices
    // (`f 1/-11` with one `vt` overflows in tobj 4.0.5). A file that is not UTF-8 text fails
    // as tobj would fail it.
    let text = std::str::from_utf8(bytes).map_err(|_| {
        IoError(format!(
            "not a readable OBJ file ({})",
            tobj::LoadError::ReadError
        ))
    })?;
    let geometry: Vec<&str> = text
        .split('\n')
        .map(|l| match l.split_whitespace().next() {
            Some("vt" | "vn") => "",
            _ => l,
        })
        .collect();
    let geometry = geometry.join("\n");
    let mut reader = std::io::Cursor::new(geometry.as_bytes());
    // Materials are not used: the loader for `mtllib` files reports them missing.
    let (models, _) =
        tobj::load_obj_buf(&mut reader, &load, |_| Err(tobj::LoadError::OpenFileFailed))
            .map_err(|e| IoError(format!("not a readable OBJ file ({e})")))?;
    let mut bodies: Vec<RawBody> = Vec::new();
    let mut by_name: BTreeMap<String, usize> = BTreeMap::new();
    for m in &models {
        let mesh = &m.mesh;
        let pos: Vec<Point3> = mesh
            .positions
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect();
        let mut faces = Vec::new();
        let idx: Vec<usize> = mesh.indices.iter().map(|&i| i as usize).collect();
        if mesh.face_arities.is_empty() {
            faces.extend(idx.chunks_exact(3).map(|c| c.to_vec()));
        } else {
            let mut at = 0usize;
            for &n in &mesh.face_arities {
                let n = n as usize;
                if at + n > idx.len() {
                    return Err(IoError(format!(
                        "OBJ object '{}': a face refers past the end of its vertex list",
                        m.name
                    )));
                }
                faces.push(idx[at..at + n].to_vec());
                at += n;
            }
        }
        if faces.is_empty() {
            continue;
        }
        if let Some(&k) = by_name.get(&m.name) {
            let b = &mut bodies[k];
            let off = b.vertices.len();
            b.vertices.extend(pos);
            b.faces.extend(
                faces
                    .into_iter()
                    .map(|f| f.into_iter().map(|i| i + off).collect()),
            );
        } else {
            by_name.insert(m.name.clone(), bodies.len());
            bodies.push(RawBody {
                name: m.name.clone(),
                vertices: pos,
                faces,
            });
        }
    }
    if bodies.is_empty() {
        return Err(IoError("the OBJ file has no faces".into()));
    }
    let unnamed = bodies.len() == 1 && bodies[0].name == "unnamed_object";
    let bodies = if unnamed {
        split_parts(&bodies[0].vertices, &bodies[0].faces)
    } else {
        bodies
    };
    build_model(
        bodies,
        opts,
        if unnamed { "OBJ part" } else { "OBJ object" },
        "OBJ",
        file,
    )
}

/// Read a PLY file (ASCII or binary): the `vertex` element's `x, y, z` and the `face` element's
/// `vertex_indices` (or `vertex_index`). Each set of faces connected through shared vertex
/// indices is a body `part_K` (K from 0, in the order of their first face).
pub fn parse_ply(
    bytes: &[u8],
    opts: &MeshOptions,
    file: &str,
) -> Result<(Model3d, MeshReport), IoError> {
    parse_ply_inner(bytes, opts, file).map_err(IoError::one_line)
}

fn parse_ply_inner(
    bytes: &[u8],
    opts: &MeshOptions,
    file: &str,
) -> Result<(Model3d, MeshReport), IoError> {
    use ply_rs_bw::parser::Parser;
    use ply_rs_bw::ply::{DefaultElement, Property};
    let parser = Parser::<DefaultElement>::new();
    let mut reader = std::io::Cursor::new(bytes);
    let ply = parser.read_ply(&mut reader).map_err(|e| {
        // The parser's message spans several lines (with a dump of the expected tokens).
        let text = e.to_string();
        let first = text.lines().next().unwrap_or("").trim().to_string();
        IoError(format!("not a readable PLY file ({first})"))
    })?;
    let scalar = |p: &Property| -> Option<f64> {
        Some(match *p {
            Property::Char(x) => x as f64,
            Property::UChar(x) => x as f64,
            Property::Short(x) => x as f64,
            Property::UShort(x) => x as f64,
            Property::Int(x) => x as f64,
            Property::UInt(x) => x as f64,
            Property::Float(x) => x as f64,
            Property::Double(x) => x,
            _ => return None,
        })
    };
    let list = |p: &Property| -> Option<Vec<i64>> {
        Some(match p {
            Property::ListChar(v) => v.iter().map(|&x| x as i64).collect(),
            Property::ListUChar(v) => v.iter().map(|&x| x as i64).collect(),
            Property::ListShort(v) => v.iter().map(|&x| x as i64).collect(),
            Property::ListUShort(v) => v.iter().map(|&x| x as i64).collect(),
            Property::ListInt(v) => v.iter().map(|&x| x as i64).collect(),
            Property::ListUInt(v) => v.iter().map(|&x| x as i64).collect(),
            _ => return None,
        })
    };
    let empty = Vec::new();
    let verts = ply.payload.get("vertex").unwrap_or(&empty);
    let mut vertices = Vec::with_capacity(verts.len());
    for (k, v) in verts.iter().enumerate() {
        let mut p = [0.0; 3];
        for (c, key) in ["x", "y", "z"].iter().enumerate() {
            p[c] = v.get(*key).and_then(scalar).ok_or_else(|| {
                IoError(format!("PLY vertex {k} has no numeric property '{key}'"))
            })?;
        }
        vertices.push(p);
    }
    let fs = ply.payload.get("face").unwrap_or(&empty);
    let mut faces = Vec::with_capacity(fs.len());
    for (k, f) in fs.iter().enumerate() {
        let l = f
            .get("vertex_indices")
            .or_else(|| f.get("vertex_index"))
            .and_then(list)
            .ok_or_else(|| {
                IoError(format!(
                    "PLY face {k} has no integer list 'vertex_indices' (or 'vertex_index')"
                ))
            })?;
        let mut face = Vec::with_capacity(l.len());
        for i in l {
            if i < 0 || i as usize >= vertices.len() {
                return Err(IoError(format!(
                    "PLY face {k} refers to vertex {i}, but there are {}",
                    vertices.len()
                )));
            }
            face.push(i as usize);
        }
        faces.push(face);
    }
    if faces.is_empty() {
        return Err(IoError("the PLY file has no faces".into()));
    }
    build_model(
        split_parts(&vertices, &faces),
        opts,
        "PLY part",
        "PLY",
        file,
    )
}

/// Split faces into sets connected through shared vertex indices: bodies `part_K`.
fn split_parts(vertices: &[Point3], faces: &[Vec<usize>]) -> Vec<RawBody> {
    let mut uf = UnionFind::new(vertices.len());
    for f in faces {
        for w in f.windows(2) {
            uf.union(w[0], w[1]);
        }
    }
    // Parts in the order of their first face; vertices in the order of first use.
    let mut part_of_root: HashMap<usize, usize> = HashMap::new();
    // Per part: vertices, faces, and the map from file index to part index.
    type Part = (Vec<Point3>, Vec<Vec<usize>>, HashMap<usize, usize>);
    let mut parts: Vec<Part> = Vec::new();
    for f in faces {
        let Some(&first) = f.first() else { continue };
        let root = uf.find(first);
        let k = *part_of_root.entry(root).or_insert_with(|| {
            parts.push((Vec::new(), Vec::new(), HashMap::new()));
            parts.len() - 1
        });
        let (vs, fs, local) = &mut parts[k];
        let face = f
            .iter()
            .map(|&i| {
                *local.entry(i).or_insert_with(|| {
                    vs.push(vertices[i]);
                    vs.len() - 1
                })
            })
            .collect();
        fs.push(face);
    }
    parts
        .into_iter()
        .enumerate()
        .map(|(k, (vertices, faces, _))| RawBody {
            name: format!("part_{k}"),
            vertices,
            faces,
        })
        .collect()
}

struct UnionFind(Vec<usize>);
impl UnionFind {
    fn new(n: usize) -> Self {
        UnionFind((0..n).collect())
    }
    fn find(&mut self, mut i: usize) -> usize {
        while self.0[i] != i {
            self.0[i] = self.0[self.0[i]];
            i = self.0[i];
        }
        i
    }
    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            let (lo, hi) = (ra.min(rb), ra.max(rb));
            self.0[hi] = lo;
        }
    }
}

use voussoir::vector::{self, cross, dot3 as dot, norm3 as norm, sub3 as sub, V3};

/// Newell's normal of a polygon (length: twice its area).
fn newell(v: &[V3], f: &[usize]) -> V3 {
    vector::newell(f.len(), |k| v[f[k]])
}

/// Six times the signed volume enclosed by the faces (about the first vertex).
fn volume6(v: &[V3], faces: &[Vec<usize>]) -> f64 {
    let o = v.first().copied().unwrap_or([0.0; 3]);
    let mut s = 0.0;
    for f in faces {
        let p0 = sub(v[f[0]], o);
        for k in 1..f.len() - 1 {
            s += dot(p0, cross(sub(v[f[k]], o), sub(v[f[k + 1]], o)));
        }
    }
    s
}

/// Merge vertices closer than `tol` (a grid of cells of size `tol`; each vertex is compared
/// with the representatives in the 27 cells around it; representatives are the first vertex of
/// each cluster in index order, so the result is deterministic). Returns the new vertices and
/// the map old → new.
fn weld(vertices: &[V3], tol: f64) -> (Vec<V3>, Vec<usize>) {
    let cell = |p: V3| -> [i64; 3] {
        let c = |x: f64| (x / tol).floor().clamp(-9e18, 9e18) as i64;
        [c(p[0]), c(p[1]), c(p[2])]
    };
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    let mut out: Vec<V3> = Vec::new();
    let mut map = Vec::with_capacity(vertices.len());
    for &p in vertices {
        let c = cell(p);
        let mut found: Option<usize> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(list) = grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) {
                        for &r in list {
                            if norm(sub(out[r], p)) <= tol && found.is_none_or(|f| r < f) {
                                found = Some(r);
                            }
                        }
                    }
                }
            }
        }
        let r = match found {
            Some(r) => r,
            None => {
                out.push(p);
                grid.entry(c).or_default().push(out.len() - 1);
                out.len() - 1
            }
        };
        map.push(r);
    }
    (out, map)
}

/// A clean body: welded, checked, oriented outwards, coplanar faces merged.
struct CleanBody {
    vertices: Vec<V3>,
    faces: Vec<Vec<usize>>,
    welded: usize,
    faces_read: usize,
    notes: Vec<String>,
}

fn clean_body(
    b: &RawBody,
    what: &str,
    weld_tol: f64,
    plane_tol: f64,
) -> Result<CleanBody, IoError> {
    let err = |m: String| Err(IoError(format!("{what}: {m}")));
    if let Some(k) = b
        .vertices
        .iter()
        .position(|p| p.iter().any(|x| !x.is_finite()))
    {
        return err(format!("vertex {k} is not a finite point"));
    }
    let (verts, map) = weld(&b.vertices, weld_tol);
    let welded = b.vertices.len() - verts.len();
    // Faces on welded vertices, without repeated consecutive vertices.
    let mut faces: Vec<Vec<usize>> = Vec::with_capacity(b.faces.len());
    let mut dropped = 0;
    for f in &b.faces {
        let mut g: Vec<usize> = Vec::with_capacity(f.len());
        for &i in f {
            let j = map[i];
            if g.last() != Some(&j) {
                g.push(j);
            }
        }
        while g.len() > 1 && g.first() == g.last() {
            g.pop();
        }
        if g.len() < 3 {
            dropped += 1;
            continue;
        }
        let mut sorted = g.clone();
        sorted.sort_unstable();
        if sorted.windows(2).any(|w| w[0] == w[1]) {
            return err(format!(
                "a face passes twice through the point {}",
                fmt_point(verts[sorted.windows(2).find(|w| w[0] == w[1]).map_or(0, |w| w[0])])
            ));
        }
        faces.push(g);
    }
    let mut notes = Vec::new();
    if dropped > 0 {
        notes.push(format!(
            "{what}: {dropped} degenerate face(s) (fewer than three distinct vertices after welding) dropped"
        ));
    }
    if faces.len() < 4 {
        return err(format!(
            "{} face(s): a closed body needs at least 4",
            faces.len()
        ));
    }
    // Edges: undirected edge → the faces using it, with the direction.
    let mut edges: BTreeMap<(usize, usize), Vec<(usize, bool)>> = BTreeMap::new();
    for (fi, f) in faces.iter().enumerate() {
        for k in 0..f.len() {
            let (a, c) = (f[k], f[(k + 1) % f.len()]);
            edges
                .entry((a.min(c), a.max(c)))
                .or_default()
                .push((fi, a < c));
        }
    }
    let edge_at = |&(a, c): &(usize, usize)| {
        format!("the edge {}–{}", fmt_point(verts[a]), fmt_point(verts[c]))
    };
    if let Some((e, u)) = edges.iter().find(|(_, u)| u.len() > 2) {
        return err(format!(
            "not a manifold surface: {} is shared by {} faces (a closed block has two at each edge)",
            edge_at(e),
            u.len()
        ));
    }
    if let Some((e, _)) = edges.iter().find(|(_, u)| u.len() == 1) {
        let open = edges.values().filter(|u| u.len() == 1).count();
        return err(format!(
            "the surface is open: {} belongs to one face only ({open} such edge(s)); a block must be closed",
            edge_at(e)
        ));
    }
    // Orient consistently (breadth-first over shared edges) and find the pieces.
    let nf = faces.len();
    let mut adj: Vec<Vec<(usize, bool)>> = vec![Vec::new(); nf];
    for u in edges.values() {
        let ((f, d1), (g, d2)) = (u[0], u[1]);
        // Same direction along the shared edge: their orientations disagree.
        adj[f].push((g, d1 == d2));
        adj[g].push((f, d1 == d2));
    }
    let mut flip = vec![None::<bool>; nf];
    let mut piece_of = vec![0usize; nf];
    let mut pieces = 0;
    for s in 0..nf {
        if flip[s].is_some() {
            continue;
        }
        pieces += 1;
        flip[s] = Some(false);
        piece_of[s] = pieces - 1;
        let mut q = VecDeque::from([s]);
        while let Some(f) = q.pop_front() {
            let ff = flip[f].unwrap_or(false);
            for &(g, disagree) in &adj[f] {
                let want = ff ^ disagree;
                match flip[g] {
                    None => {
                        flip[g] = Some(want);
                        piece_of[g] = pieces - 1;
                        q.push_back(g);
                    }
                    Some(h) if h != want => {
                        return err(
                            "the surface cannot be oriented (a Möbius-like surface): not a closed block"
                                .into(),
                        )
                    }
                    _ => {}
                }
            }
        }
    }
    // Which faces end up turned round (each reversal toggles).
    let mut turned = vec![false; nf];
    for ((f, fl), t) in faces.iter_mut().zip(&flip).zip(turned.iter_mut()) {
        if *fl == Some(true) {
            f.reverse();
            *t = true;
        }
    }
    if pieces > 1 {
        // A block with cavities: the largest piece is the outer surface, every other piece must
        // lie inside it, and is turned to face into its cavity (opposite to the outer surface),
        // so that the volumes add up to the hollow block's. The library checks the rest
        // (strictly inside, no crossing, cavities apart).
        let mut by_piece: Vec<Vec<usize>> = vec![Vec::new(); pieces];
        for (k, &p) in piece_of.iter().enumerate() {
            by_piece[p].push(k);
        }
        let piece_faces = |p: usize| -> Vec<Vec<usize>> {
            by_piece[p].iter().map(|&k| faces[k].clone()).collect()
        };
        let vols: Vec<f64> = (0..pieces)
            .map(|p| volume6(&verts, &piece_faces(p)))
            .collect();
        let outer = (0..pieces)
            .max_by(|&i, &j| vols[i].abs().total_cmp(&vols[j].abs()).then(j.cmp(&i)))
            .unwrap_or(0);
        let outer_faces = piece_faces(outer);
        for p in (0..pieces).filter(|&p| p != outer) {
            let probe = verts[faces[by_piece[p][0]][0]];
            let w = voussoir::geometry3d::winding_number(&verts, &outer_faces, probe);
            if w.abs() < 0.5 {
                return err(format!(
                    "{pieces} separate closed surfaces: a block is one piece (give each piece its own object)"
                ));
            }
            if (vols[p] < 0.0) == (vols[outer] < 0.0) {
                for &k in &by_piece[p] {
                    faces[k].reverse();
                    turned[k] = !turned[k];
                }
            }
        }
        notes.push(format!(
            "{what}: {} closed surface(s) inside the outer one read as cavities",
            pieces - 1
        ));
    }
    let mut vol6 = volume6(&verts, &faces);
    let diag = {
        let [lo, hi] = voussoir::geometry3d::bbox3(&verts);
        norm(sub(hi, lo))
    };
    // Written so that a NaN volume counts as none.
    let encloses = vol6.abs() > 6.0 * (plane_tol * diag * diag).max(f64::MIN_POSITIVE);
    if !encloses {
        return err("encloses no volume".into());
    }
    if vol6 < 0.0 {
        for f in faces.iter_mut() {
            f.reverse();
        }
        vol6 = -vol6;
        for t in turned.iter_mut() {
            *t = !*t;
        }
    }
    debug_assert!(vol6 > 0.0);
    let reoriented = turned.iter().filter(|&&t| t).count();
    if reoriented > 0 && reoriented < nf {
        notes.push(format!(
            "{what}: {reoriented} face(s) turned to face outwards like the others"
        ));
    }
    let faces_read = b.faces.len();
    let (verts, faces) = merge_coplanar(verts, faces, plane_tol);
    if let Some((e, f)) = self_intersection(&verts, &faces, plane_tol) {
        return err(format!(
            "the surface intersects itself: the edge {}–{} passes through the face with corners {} (a block must be a simple closed surface)",
            fmt_point(verts[e.0]),
            fmt_point(verts[e.1]),
            faces[f]
                .iter()
                .take(4)
                .map(|&i| fmt_point(verts[i]))
                .collect::<Vec<_>>()
                .join(", ")
                + if faces[f].len() > 4 { ", …" } else { "" }
        ));
    }
    Ok(CleanBody {
        vertices: verts,
        faces,
        welded,
        faces_read,
        notes,
    })
}

/// An edge that passes through the inside of a face it does not touch, if any: the surface
/// intersects itself. (Two closed polyhedral surfaces' faces intersect improperly only where an
/// edge of one crosses the other; touching and coplanar overlaps within `tol` are not
/// reported.) Broad phase: faces sorted by the low x of their bounding boxes, each edge tested
/// against the faces whose x-range meets its own; exact test: the edge's ends strictly on both
/// sides of the face's plane (beyond `tol`), the crossing point inside the face polygon and
/// farther than `tol` from its outline.
fn self_intersection(v: &[V3], faces: &[Vec<usize>], tol: f64) -> Option<((usize, usize), usize)> {
    struct F {
        lo: V3,
        hi: V3,
        n: V3,
        p0: V3,
        k: usize,
    }
    let mut fs: Vec<F> = faces
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let pts: Vec<V3> = f.iter().map(|&i| v[i]).collect();
            let [lo, hi] = voussoir::geometry3d::bbox3(&pts);
            let n = newell(v, f);
            let l = norm(n);
            F {
                lo,
                hi,
                n: if l > 0.0 {
                    [n[0] / l, n[1] / l, n[2] / l]
                } else {
                    [0.0; 3]
                },
                p0: pts[0],
                k,
            }
        })
        .collect();
    fs.sort_by(|a, b| a.lo[0].total_cmp(&b.lo[0]).then(a.k.cmp(&b.k)));
    let mut edges: Vec<(usize, usize)> = faces
        .iter()
        .flat_map(|f| (0..f.len()).map(move |k| (f[k], f[(k + 1) % f.len()])))
        .filter(|(a, b)| a < b)
        .collect();
    edges.sort_unstable();
    for &(a, b) in &edges {
        let (pa, pb) = (v[a], v[b]);
        let elo = [pa[0].min(pb[0]), pa[1].min(pb[1]), pa[2].min(pb[2])];
        let ehi = [pa[0].max(pb[0]), pa[1].max(pb[1]), pa[2].max(pb[2])];
        let end = fs.partition_point(|f| f.lo[0] <= ehi[0] + tol);
        for f in &fs[..end] {
            if f.hi[0] < elo[0] - tol
                || (0..3).any(|c| f.hi[c] < elo[c] - tol || f.lo[c] > ehi[c] + tol)
            {
                continue;
            }
            let face = &faces[f.k];
            if face.contains(&a) || face.contains(&b) || f.n == [0.0; 3] {
                continue;
            }
            let (da, db) = (dot(sub(pa, f.p0), f.n), dot(sub(pb, f.p0), f.n));
            if !((da > tol && db < -tol) || (da < -tol && db > tol)) {
                continue;
            }
            let t = da / (da - db);
            let x = [
                pa[0] + (pb[0] - pa[0]) * t,
                pa[1] + (pb[1] - pa[1]) * t,
                pa[2] + (pb[2] - pa[2]) * t,
            ];
            if inside_face(v, face, f.n, x, tol) {
                return Some(((a, b), f.k));
            }
        }
    }
    None
}

/// Whether `x` (in the face's plane) is inside the polygon `face` of normal `n`, farther than
/// `tol` from its outline (crossing number in the plane of the two largest components of `n`).
fn inside_face(v: &[V3], face: &[usize], n: V3, x: V3, tol: f64) -> bool {
    let drop = (0..3)
        .max_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs()))
        .unwrap_or(2);
    let (i, j) = match drop {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    };
    let mut inside = false;
    for k in 0..face.len() {
        let (p, q) = (v[face[k]], v[face[(k + 1) % face.len()]]);
        // Distance from x to the edge pq (in 3D).
        let d = sub(q, p);
        let dd = dot(d, d);
        let t = if dd > 0.0 {
            (dot(sub(x, p), d) / dd).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let c = [p[0] + d[0] * t, p[1] + d[1] * t, p[2] + d[2] * t];
        if norm(sub(x, c)) <= tol {
            return false;
        }
        if (p[j] > x[j]) != (q[j] > x[j]) {
            let xi = p[i] + (x[j] - p[j]) / (q[j] - p[j]) * (q[i] - p[i]);
            if x[i] < xi {
                inside = !inside;
            }
        }
    }
    inside
}

fn fmt_point(p: V3) -> String {
    format!("({}, {}, {})", fmt_num(p[0]), fmt_num(p[1]), fmt_num(p[2]))
}
fn fmt_num(x: f64) -> String {
    let s = format!("{:.6}", x);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// Merge faces that share edges and lie in one plane (within `tol`, measured from the plane of
/// the group's first face, so that a gently curved surface is not flattened by drift) into one
/// polygon per group. A group whose outline is not a single simple loop (a ring around a hole,
/// two loops touching at a vertex) is left as it was. Then vertices that lie on a straight edge
/// between exactly two faces are removed from both, and unused vertices are dropped.
///
/// O(n log n) in the number of face corners: one ordered map of directed edges, one
/// breadth-first pass, one pass over each group's outline.
fn merge_coplanar(verts: Vec<V3>, faces: Vec<Vec<usize>>, tol: f64) -> (Vec<V3>, Vec<Vec<usize>>) {
    let nf = faces.len();
    let mut directed: BTreeMap<(usize, usize), usize> = BTreeMap::new();
    for (fi, f) in faces.iter().enumerate() {
        for k in 0..f.len() {
            directed.insert((f[k], f[(k + 1) % f.len()]), fi);
        }
    }
    let unit = |n: V3| {
        let l = norm(n);
        if l > 0.0 {
            [n[0] / l, n[1] / l, n[2] / l]
        } else {
            n
        }
    };
    let normals: Vec<V3> = faces.iter().map(|f| unit(newell(&verts, f))).collect();
    let mut group = vec![usize::MAX; nf];
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for s in 0..nf {
        if group[s] != usize::MAX {
            continue;
        }
        let g = groups.len();
        group[s] = g;
        let (n0, p0) = (normals[s], verts[faces[s][0]]);
        let mut members = vec![s];
        let mut q = VecDeque::from([s]);
        while let Some(f) = q.pop_front() {
            let fv = &faces[f];
            for k in 0..fv.len() {
                let (a, c) = (fv[k], fv[(k + 1) % fv.len()]);
                let Some(&h) = directed.get(&(c, a)) else {
                    continue;
                };
                if group[h] != usize::MAX || dot(normals[h], n0) <= 0.0 {
                    continue;
                }
                if faces[h]
                    .iter()
                    .all(|&i| dot(sub(verts[i], p0), n0).abs() <= tol)
                {
                    group[h] = g;
                    members.push(h);
                    q.push_back(h);
                }
            }
        }
        groups.push(members);
    }
    let mut out: Vec<Vec<usize>> = Vec::with_capacity(groups.len());
    for members in &groups {
        if members.len() == 1 {
            out.push(faces[members[0]].clone());
            continue;
        }
        match outline(&faces, members, &group) {
            Some(poly) => out.push(poly),
            None => out.extend(members.iter().map(|&f| faces[f].clone())),
        }
    }
    // Vertices on a straight edge between exactly two faces.
    let mut uses = vec![0usize; verts.len()];
    for f in &out {
        for &i in f {
            uses[i] += 1;
        }
    }
    let straight = |f: &[usize], k: usize| {
        let n = f.len();
        let (p, x, q) = (
            verts[f[(k + n - 1) % n]],
            verts[f[k]],
            verts[f[(k + 1) % n]],
        );
        let (d1, d2) = (sub(x, p), sub(q, x));
        dot(d1, d2) > 0.0 && norm(cross(d1, d2)) <= tol * norm(sub(q, p))
    };
    let mut removable = vec![true; verts.len()];
    for f in &out {
        for k in 0..f.len() {
            let i = f[k];
            if uses[i] != 2 || !straight(f, k) {
                removable[i] = false;
            }
        }
    }
    for f in out.iter_mut() {
        if f.iter().filter(|&&i| !removable[i] || uses[i] != 2).count() >= 3 {
            f.retain(|&i| !(removable[i] && uses[i] == 2));
        }
    }
    // Renumber the vertices in order of first use.
    let mut new_index = vec![usize::MAX; verts.len()];
    let mut vs = Vec::new();
    for f in out.iter_mut() {
        for i in f.iter_mut() {
            if new_index[*i] == usize::MAX {
                new_index[*i] = vs.len();
                vs.push(verts[*i]);
            }
            *i = new_index[*i];
        }
    }
    (vs, out)
}

/// The outline of a group of faces as one loop (counter-clockwise like the faces), or None if
/// it is not a single simple loop.
fn outline(faces: &[Vec<usize>], members: &[usize], group: &[usize]) -> Option<Vec<usize>> {
    let g = group[members[0]];
    let mut in_group: BTreeMap<(usize, usize), ()> = BTreeMap::new();
    for &f in members {
        let fv = &faces[f];
        for k in 0..fv.len() {
            in_group.insert((fv[k], fv[(k + 1) % fv.len()]), ());
        }
    }
    let _ = g;
    let mut next: BTreeMap<usize, usize> = BTreeMap::new();
    for &(a, c) in in_group.keys() {
        if in_group.contains_key(&(c, a)) {
            continue;
        }
        if next.insert(a, c).is_some() {
            return None; // two outline edges leave one vertex: a pinch
        }
    }
    let (&start, _) = next.iter().next()?;
    let mut poly = vec![start];
    let mut at = start;
    loop {
        at = *next.get(&at)?;
        if at == start {
            break;
        }
        if poly.len() > next.len() {
            return None;
        }
        poly.push(at);
    }
    if poly.len() != next.len() {
        return None; // several loops (a hole)
    }
    // Start at the first vertex of the first face, for a stable, recognisable order.
    let first = faces[members[0]][0];
    if let Some(k) = poly.iter().position(|&i| i == first) {
        poly.rotate_left(k);
    }
    Some(poly)
}

/// Turn the bodies into a model: clean each, choose the supports, add materials and loads.
fn build_model(
    bodies: Vec<RawBody>,
    opts: &MeshOptions,
    kind: &str,
    format: &'static str,
    file: &str,
) -> Result<(Model3d, MeshReport), IoError> {
    let s = opts.units.scale();
    let bodies: Vec<RawBody> = bodies
        .into_iter()
        .map(|b| RawBody {
            vertices: b
                .vertices
                .iter()
                .map(|p| [p[0] * s, p[1] * s, p[2] * s])
                .collect(),
            ..b
        })
        .collect();
    let all: Vec<V3> = bodies
        .iter()
        .flat_map(|b| b.faces.iter().flatten().filter_map(|&i| b.vertices.get(i)))
        .copied()
        .filter(|p| p.iter().all(|x| x.is_finite()))
        .collect();
    let [lo, hi] = voussoir::geometry3d::bbox3(&all);
    let diag = norm(sub(hi, lo));
    if !(diag.is_finite() && diag > 0.0) {
        return Err(IoError("the mesh has no extent".into()));
    }
    let default_tol = DEFAULT_REL_TOLERANCE * diag;
    let weld_tol = match opts.weld {
        Some(w) if w.is_finite() && w > 0.0 => w,
        Some(w) => {
            return Err(IoError(format!(
                "weld tolerance {w}: must be a finite number > 0"
            )))
        }
        None => default_tol,
    };
    // Faces are merged within the tolerance the model will be validated with.
    let plane_tol = weld_tol.max(default_tol);
    let mut cleaned = Vec::with_capacity(bodies.len());
    let mut report = MeshReport {
        format,
        weld_tolerance: weld_tol,
        ..Default::default()
    };
    for b in &bodies {
        let what = format!("{kind} '{}'", b.name);
        let c = clean_body(b, &what, weld_tol, plane_tol)?;
        // The library's own validation (planarity, self-intersection), under the body's name.
        voussoir::geometry3d::clean_polyhedron(&what, &c.vertices, &c.faces, plane_tol)
            .map_err(|e| IoError(e.to_string()))?;
        report.welded_vertices += c.welded;
        report.faces_read += c.faces_read;
        report.faces_written += c.faces.len();
        report.notes.extend(c.notes.iter().cloned());
        cleaned.push(c);
    }
    // Supports.
    let names: Vec<&str> = bodies.iter().map(|b| b.name.as_str()).collect();
    let list = |v: &[&str]| {
        let mut s = v
            .iter()
            .take(8)
            .map(|n| format!("'{n}'"))
            .collect::<Vec<_>>()
            .join(", ");
        if v.len() > 8 {
            s.push_str(", …");
        }
        s
    };
    let mut is_support = vec![false; bodies.len()];
    let mut strip = 0;
    if !opts.supports.is_empty() {
        for n in &opts.supports {
            match names.iter().position(|m| m == n) {
                Some(k) => is_support[k] = true,
                None => {
                    return Err(IoError(format!(
                        "no {kind} is named '{n}' (there are {})",
                        list(&names)
                    )))
                }
            }
        }
        report.support_rule = "named".into();
    }
    if let Some(p) = &opts.support_prefix {
        let mut any = false;
        for (k, n) in names.iter().enumerate() {
            if n.starts_with(p.as_str()) {
                is_support[k] = true;
                any = true;
            }
        }
        if !any {
            return Err(IoError(format!(
                "no {kind} name starts with '{p}' (there are {})",
                list(&names)
            )));
        }
        report.support_rule = if report.support_rule.is_empty() {
            format!("names starting with '{p}'")
        } else {
            format!("named, and names starting with '{p}'")
        };
    }
    if report.support_rule.is_empty() {
        if names.iter().any(|n| n.starts_with(SUPPORT_PREFIX)) {
            for (k, n) in names.iter().enumerate() {
                is_support[k] = n.starts_with(SUPPORT_PREFIX);
            }
            strip = SUPPORT_PREFIX.len();
            report.support_rule = format!("objects named '{SUPPORT_PREFIX}…'");
        } else {
            let zmin = lo[2];
            let ground = GROUND_REL_TOLERANCE * diag;
            for (k, c) in cleaned.iter().enumerate() {
                let low = c
                    .vertices
                    .iter()
                    .map(|p| p[2])
                    .fold(f64::INFINITY, f64::min);
                is_support[k] = low <= zmin + ground;
            }
            report.support_rule = format!("standing on the ground plane z = {}", fmt_num(zmin));
            if is_support.iter().all(|&x| x) {
                return Err(IoError(format!(
                    "every {kind} stands on the ground plane z = {}: name the supports with --supports NAME,… or --support-prefix",
                    fmt_num(zmin)
                )));
            }
        }
    }
    if is_support.iter().all(|&x| x) {
        return Err(IoError(format!(
            "every {kind} is a support: the model has no blocks"
        )));
    }
    let mut blocks = Vec::new();
    let mut supports: Vec<Support3d> = Vec::new();
    for ((b, c), sup) in bodies.iter().zip(cleaned).zip(&is_support) {
        let source = format!("{kind} '{}'", b.name);
        if *sup {
            let name = b.name[strip..].to_string();
            let name = if name.is_empty() {
                b.name.clone()
            } else {
                name
            };
            if supports.iter().any(|s| s.name == name) {
                return Err(IoError(format!(
                    "two supports are named '{name}': support names must be unique"
                )));
            }
            supports.push(Support3d {
                name,
                vertices: c.vertices,
                faces: c.faces,
                motion: [0.0; 6],
                connection: Default::default(),
            });
            report.support_sources.push(source);
        } else {
            blocks.push(Block3d {
                vertices: c.vertices,
                faces: c.faces,
                material: None,
            });
            report.block_sources.push(source);
        }
    }
    let live = match opts.live {
        ImportLive::None => vec![],
        ImportLive::Horizontal => vec![Load3d::Body {
            coefficients: [1.0, 0.0, 0.0],
            blocks: None,
        }],
    };
    let model = Model3d {
        description: format!(
            "imported from {file} ({format}, {} bodies, units {})",
            bodies.len(),
            opts.units.name()
        ),
        materials: BTreeMap::from([(
            "default".to_string(),
            Material {
                unit_weight: opts.unit_weight,
                ..Material::default()
            },
        )]),
        blocks,
        supports,
        loads: Loads3d {
            self_weight: true,
            dead: vec![],
            live,
        },
        // A weld wider than the default tolerance moves vertices by up to that much: the model
        // is then validated with it.
        tolerance: (weld_tol > default_tol).then(|| weld_tol / diag),
    };
    Ok((model, report))
}

/// A 3D model as OBJ text: each block the object `block_i`, each support `support_NAME`
/// (faces as given, outward counter-clockwise; coordinates in metres, written exactly: the
/// shortest decimal that reads back as the same f64). Materials, loads and motions are not
/// written (OBJ has no place for them).
pub fn model_to_obj(m: &Model3d) -> String {
    let mut s = String::new();
    s.push_str("# voussoir 3D model: blocks and supports as closed polyhedra (metres, z up)\n");
    if !m.description.is_empty() {
        s.push_str(&format!("# {}\n", m.description.replace('\n', " ")));
    }
    let mut base = 1usize;
    let mut body = |s: &mut String, name: &str, v: &[Point3], f: &[Vec<usize>]| {
        s.push_str(&format!("o {name}\n"));
        for p in v {
            s.push_str(&format!("v {} {} {}\n", p[0], p[1], p[2]));
        }
        for face in f {
            s.push('f');
            for &i in face {
                s.push_str(&format!(" {}", i + base));
            }
            s.push('\n');
        }
        base += v.len();
    };
    for (i, b) in m.blocks.iter().enumerate() {
        body(&mut s, &format!("block_{i}"), &b.vertices, &b.faces);
    }
    for sp in &m.supports {
        body(&mut s, &support_object(&sp.name), &sp.vertices, &sp.faces);
    }
    s
}

/// The OBJ object name of a support: `support_NAME`, whitespace in NAME written as `_`.
fn support_object(name: &str) -> String {
    let name: String = name
        .chars()
        .map(|c| if c.is_whitespace() { '_' } else { c })
        .collect();
    format!("{SUPPORT_PREFIX}{name}")
}

/// Check a model can be written as OBJ: faces refer to existing vertices, coordinates finite,
/// support object names distinct. (`voussoir export` also builds the model and reads the OBJ
/// back before writing it.)
pub fn check_exportable(m: &Model3d) -> Result<(), IoError> {
    let check = |what: String, v: &[Point3], f: &[Vec<usize>]| -> Result<(), IoError> {
        if let Some(k) = v.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
            return Err(IoError(format!("{what}: vertex {k} is not finite")));
        }
        for (fi, face) in f.iter().enumerate() {
            if face.len() < 3 {
                return Err(IoError(format!(
                    "{what}: face {fi} has fewer than 3 vertices"
                )));
            }
            if let Some(i) = face.iter().find(|&&i| i >= v.len()) {
                return Err(IoError(format!(
                    "{what}: face {fi} refers to vertex {i}, but there are {}",
                    v.len()
                )));
            }
        }
        Ok(())
    };
    for (i, b) in m.blocks.iter().enumerate() {
        check(format!("block {i}"), &b.vertices, &b.faces)?;
    }
    let mut objects: BTreeMap<String, &str> = BTreeMap::new();
    for s in &m.supports {
        check(format!("support '{}'", s.name), &s.vertices, &s.faces)?;
        // Two objects of one name would read back as one body.
        if let Some(other) = objects.insert(support_object(&s.name), &s.name) {
            return Err(IoError(format!(
                "supports '{other}' and '{}' would both be the OBJ object '{}': rename one",
                s.name,
                support_object(&s.name)
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(o: V3, a: f64) -> (Vec<V3>, Vec<Vec<usize>>) {
        let v = (0..8)
            .map(|k| {
                [
                    o[0] + a * (k & 1) as f64,
                    o[1] + a * ((k >> 1) & 1) as f64,
                    o[2] + a * ((k >> 2) & 1) as f64,
                ]
            })
            .collect();
        // Outward quads, each split into two triangles.
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let f = quads
            .iter()
            .flat_map(|q| [vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]])
            .collect();
        (v, f)
    }

    #[test]
    fn triangulated_cube_merges_into_six_quads() {
        let (v, f) = cube([0.0; 3], 2.0);
        let (vs, fs) = merge_coplanar(v.clone(), f, 1e-9);
        assert_eq!(vs.len(), 8);
        assert_eq!(fs.len(), 6);
        assert!(fs.iter().all(|f| f.len() == 4));
        // Volume 8 (6 × signed volume positive: outward orientation kept).
        assert!((volume6(&vs, &fs) / 6.0 - 8.0).abs() < 1e-12);
    }

    #[test]
    fn weld_joins_close_points_only() {
        let v = [[0.0, 0.0, 0.0], [1e-9, 0.0, 0.0], [1e-6, 0.0, 0.0]];
        let (w, map) = weld(&v, 1e-8);
        assert_eq!(w.len(), 2);
        assert_eq!(map, vec![0, 0, 1]);
    }

    #[test]
    fn a_cube_with_a_corner_pushed_through_its_base_intersects_itself() {
        let (mut v, f) = cube([0.0; 3], 1.0);
        let b = RawBody {
            name: "c".into(),
            vertices: v.clone(),
            faces: f.clone(),
        };
        assert!(clean_body(&b, "c", 1e-9, 1e-9).is_ok());
        // Corner 7 (1, 1, 1) moved below the base z = 0: its edges cross the base.
        v[7] = [0.35, 0.4, -0.6];
        let b = RawBody {
            name: "folded".into(),
            vertices: v,
            faces: f,
        };
        let e = clean_body(&b, "OBJ object 'folded'", 1e-9, 1e-9)
            .err()
            .unwrap()
            .0;
        assert!(
            e.starts_with("OBJ object 'folded': the surface intersects itself"),
            "{e}"
        );
    }

    #[test]
    fn inward_cube_is_turned_outwards() {
        let (v, mut f) = cube([0.0; 3], 1.0);
        for face in f.iter_mut() {
            face.reverse();
        }
        let b = RawBody {
            name: "c".into(),
            vertices: v,
            faces: f,
        };
        let c = clean_body(&b, "c", 1e-9, 1e-9).unwrap();
        assert!((volume6(&c.vertices, &c.faces) / 6.0 - 1.0).abs() < 1e-12);
        assert_eq!(c.faces.len(), 6);
    }
}
