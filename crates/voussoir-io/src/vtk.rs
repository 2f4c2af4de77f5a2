//! VTK output of 3D results (XML UnstructuredGrid `.vtu` pieces and a `.vtm` multiblock), for
//! ParaView. Layout, arrays and units: `docs/vtk.md`.
//!
//! - [`blocks_vtu`]: the blocks. Each block is written as its **faces, one polygon cell each**
//!   (VTK_POLYGON), with a cell array `block` naming the block. vtkio (0.7) writes the XML
//!   `Cells` element as connectivity/offsets/types only and has no `faces`/`faceoffsets` arrays,
//!   so VTK_POLYHEDRON cells cannot be written through it; polygon faces render the same, and
//!   `Threshold` on `block` picks blocks out. Each block has its own copy of its vertices (blocks
//!   move differently), with point data `displacement` = `u + θ × (x − c)` so that ParaView's
//!   *Warp By Vector* shows the mechanism; cell data `block`, `translation`, `rotation`.
//! - [`contacts_vtu`]: the contact points, one VTK_VERTEX cell each.
//! - [`cracks_vtu`]: the joints that are not closed, one polygon each (the joint's points in
//!   order around the joint).
//! - [`supports_vtu`]: the supports' faces as polygons.
//! - [`multiblock`]: a `.vtm` naming those pieces, and the pieces, as `(file name, bytes)` so the
//!   caller writes them all or nothing ([`crate::write_all_or_nothing`]); an empty `cracks`
//!   block is listed without a file.
//!
//! Arrays are written in binary (base64, little endian, UInt64 headers, no compression), so the
//! values read back are the values written, bit for bit, and the bytes are the same on every run.
//! Cell connectivity and offsets are `Int64` and cell types `UInt8`, as VTK's own writers use
//! them (and as meshio reads them), in every piece.

use crate::result3d::{polygon_order, validate, Motions, Result3d, V3};
use crate::IoError;
use std::fmt::Write as _;
use voussoir::result::JointState;
use vtkio::model::{
    Attribute, Attributes, ByteOrder, CellType, Cells, DataArray, DataSet, ElementType,
    UnstructuredGridPiece, Version, VertexNumbers, Vtk,
};

/// The numeric code of a joint state in the `state` arrays (documented in `docs/vtk.md`).
pub fn state_code(s: JointState) -> i32 {
    match s {
        JointState::Closed => 0,
        JointState::Hinge => 1,
        JointState::Open => 2,
        JointState::Sliding => 3,
    }
}

/// An unstructured grid being assembled.
#[derive(Default)]
struct Grid {
    points: Vec<f64>,
    connectivity: Vec<u64>,
    offsets: Vec<u64>,
    types: Vec<CellType>,
    point_data: Vec<Attribute>,
    cell_data: Vec<Attribute>,
}

impl Grid {
    fn add_point(&mut self, p: V3) -> u64 {
        self.points.extend_from_slice(&p);
        (self.points.len() / 3 - 1) as u64
    }
    fn add_cell(&mut self, kind: CellType, pts: impl IntoIterator<Item = u64>) {
        self.connectivity.extend(pts);
        self.offsets.push(self.connectivity.len() as u64);
        self.types.push(kind);
    }
    fn point_f64(&mut self, name: &str, comps: u32, data: Vec<f64>) {
        self.point_data.push(array(name, comps, data));
    }
    fn cell_f64(&mut self, name: &str, comps: u32, data: Vec<f64>) {
        self.cell_data.push(array(name, comps, data));
    }
    fn cell_i32(&mut self, name: &str, data: Vec<i32>) {
        self.cell_data.push(Attribute::DataArray(DataArray {
            name: name.to_string(),
            elem: ElementType::Scalars {
                num_comp: 1,
                lookup_table: None,
            },
            data: data.into(),
        }));
    }
    fn point_i32(&mut self, name: &str, data: Vec<i32>) {
        self.point_data.push(Attribute::DataArray(DataArray {
            name: name.to_string(),
            elem: ElementType::Scalars {
                num_comp: 1,
                lookup_table: None,
            },
            data: data.into(),
        }));
    }

    /// The `.vtu` bytes.
    fn into_bytes(self, title: &str) -> Result<Vec<u8>, IoError> {
        let (points, cells) = (self.points.len() / 3, self.types.len());
        let vtk = Vtk {
            version: Version::new_xml(1, 0),
            title: title.to_string(),
            byte_order: ByteOrder::LittleEndian,
            file_path: None,
            data: DataSet::inline(UnstructuredGridPiece {
                points: self.points.into(),
                cells: Cells {
                    cell_verts: VertexNumbers::XML {
                        connectivity: self.connectivity,
                        offsets: self.offsets,
                    },
                    types: self.types,
                },
                data: Attributes {
                    point: self.point_data,
                    cell: self.cell_data,
                },
            }),
        };
        let mut out = Vec::new();
        vtk.write_xml(&mut out)
            .map_err(|e| IoError(format!("cannot write VTK ({title}): {e}")))?;
        let mut out = as_vtk_writes(out, points, cells, title)?;
        if !out.ends_with(b"\n") {
            out.push(b'\n');
        }
        Ok(out)
    }
}

/// vtkio's XML made to read as VTK's own writers write it, in two attributes:
///
/// - the cells' `connectivity` and `offsets` are declared `Int64`. vtkio 0.7 holds them as
///   `u64` and declares them `UInt64`, which ParaView reads but meshio (and numpy code mixing
///   them with signed indices) does not: meshio fails with `UFuncTypeError`. Every value is a
///   point index or a count, far below 2⁶³, so its eight little-endian bytes are an `Int64`'s
///   too: only the declared type changes, the binary data and their headers stay as written;
/// - the piece states `NumberOfPoints` and `NumberOfCells` even when they are 0 (vtkio leaves
///   a zero out; the format requires both, and readers such as meshio need them).
///
/// Each is expected exactly where vtkio writes it; anything else is an error rather than a
/// file that half follows the convention.
fn as_vtk_writes(
    xml: Vec<u8>,
    points: usize,
    cells: usize,
    title: &str,
) -> Result<Vec<u8>, IoError> {
    let fail = |what: &str| IoError(format!("cannot write VTK ({title}): {what}"));
    let mut text = String::from_utf8(xml).map_err(|_| fail("not UTF-8"))?;
    for name in ["connectivity", "offsets"] {
        let from = format!("<DataArray type=\"UInt64\" Name=\"{name}\"");
        let to = format!("<DataArray type=\"Int64\" Name=\"{name}\"");
        if text.matches(&from).count() != 1 {
            return Err(fail(&format!(
                "the {name} array is not where vtkio writes it"
            )));
        }
        text = text.replacen(&from, &to, 1);
    }
    let piece = format!("<Piece NumberOfPoints=\"{points}\" NumberOfCells=\"{cells}\">");
    let written = [
        "<Piece>".to_string(),
        format!("<Piece NumberOfPoints=\"{points}\">"),
        format!("<Piece NumberOfCells=\"{cells}\">"),
        piece.clone(),
    ];
    let Some(tag) = written
        .iter()
        .find(|t| text.matches(t.as_str()).count() == 1)
    else {
        return Err(fail("the piece is not where vtkio writes it"));
    };
    text = text.replacen(tag.as_str(), &piece, 1);
    Ok(text.into_bytes())
}

/// A float array: 1 component as scalars, 3 as vectors, others generic.
fn array(name: &str, comps: u32, data: Vec<f64>) -> Attribute {
    let elem = match comps {
        3 => ElementType::Vectors,
        n => ElementType::Scalars {
            num_comp: n,
            lookup_table: None,
        },
    };
    Attribute::DataArray(DataArray {
        name: name.to_string(),
        elem,
        data: data.into(),
    })
}

/// The blocks as polygon faces: point data `displacement` (m, or normalised for limit
/// results), cell data `block` (id), `translation` `(u, v, w)` and `rotation` `(θx, θy, θz)`
/// (rad) of the block the face belongs to.
pub fn blocks_vtu(r: &(impl Result3d + ?Sized)) -> Result<Vec<u8>, IoError> {
    validate(r)?;
    let g = r.shapes();
    let m = Motions::of(r);
    let mut grid = Grid::default();
    let (mut disp, mut block, mut tr, mut rot) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (i, b) in g.blocks.iter().enumerate() {
        let (c, d) = m.blocks[i];
        let first = grid.points.len() as u64 / 3;
        for v in &b.vertices {
            grid.add_point(*v);
            disp.extend_from_slice(&crate::result3d::small_displacement(c, &d, *v));
        }
        for f in &b.faces {
            grid.add_cell(CellType::Polygon, f.iter().map(|&k| first + k as u64));
            block.push(i as i32);
            tr.extend_from_slice(&d[..3]);
            rot.extend_from_slice(&d[3..]);
        }
    }
    grid.point_f64("displacement", 3, disp);
    grid.cell_i32("block", block);
    grid.cell_f64("translation", 3, tr);
    grid.cell_f64("rotation", 3, rot);
    grid.into_bytes("voussoir blocks")
}

/// The contact points, one vertex cell each, with point data `opening` (m), `sliding` (2
/// components, m, along the joint's two tangents), `normal_force` (kN, compression positive),
/// `shear_force` (2 components, kN), `normal` (unit, from body `a` into body `b`),
/// `displacement` (with body `a`) and `joint` (id); cell data `joint` and `state`.
pub fn contacts_vtu(r: &(impl Result3d + ?Sized)) -> Result<Vec<u8>, IoError> {
    validate(r)?;
    let g = r.shapes();
    let m = Motions::of(r);
    let mut grid = Grid::default();
    let (mut opening, mut sliding, mut nf, mut sf, mut normal, mut disp, mut joint, mut state) = (
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
    );
    for j in r.joints() {
        for p in &j.points {
            let x = [p.x, p.y, p.z];
            let k = grid.add_point(x);
            grid.add_cell(CellType::Vertex, [k]);
            opening.push(p.opening);
            sliding.extend_from_slice(&p.sliding);
            nf.push(p.normal_force);
            sf.extend_from_slice(&p.shear_force);
            normal.extend_from_slice(&j.normal);
            disp.extend_from_slice(&m.displacement(g, &j.a, x));
            joint.push(j.id as i32);
            state.push(state_code(j.state));
        }
    }
    grid.point_f64("opening", 1, opening);
    grid.point_f64("sliding", 2, sliding);
    grid.point_f64("normal_force", 1, nf);
    grid.point_f64("shear_force", 2, sf);
    grid.point_f64("normal", 3, normal);
    grid.point_f64("displacement", 3, disp);
    grid.point_i32("joint", joint.clone());
    grid.cell_i32("joint", joint);
    grid.cell_i32("state", state);
    grid.into_bytes("voussoir contact points")
}

/// The cracked interfaces: every joint whose state is not closed, as one polygon through its
/// points (ordered around their mean in the joint's plane). Cell data `joint`, `state`
/// (1 hinge, 2 open, 3 sliding), `max_opening` (m), `normal_force` (kN); point data `opening`
/// and `displacement` (with body `a`).
pub fn cracks_vtu(r: &(impl Result3d + ?Sized)) -> Result<Vec<u8>, IoError> {
    validate(r)?;
    let g = r.shapes();
    let m = Motions::of(r);
    let mut grid = Grid::default();
    let (mut joint, mut state, mut maxo, mut nf, mut opening, mut disp) = (
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
        Vec::new(),
    );
    for j in r.joints() {
        if j.state == JointState::Closed || j.points.is_empty() {
            continue;
        }
        let pts: Vec<V3> = j.points.iter().map(|p| [p.x, p.y, p.z]).collect();
        if pts.iter().any(|p| !crate::result3d::finite(*p)) {
            return Err(IoError(format!("joint {}: a point is not finite", j.id)));
        }
        let order = polygon_order(&pts, j.normal);
        let mut ids = Vec::with_capacity(order.len());
        for &k in &order {
            ids.push(grid.add_point(pts[k]));
            opening.push(j.points[k].opening);
            disp.extend_from_slice(&m.displacement(g, &j.a, pts[k]));
        }
        let kind = match ids.len() {
            1 => CellType::Vertex,
            2 => CellType::Line,
            _ => CellType::Polygon,
        };
        grid.add_cell(kind, ids);
        joint.push(j.id as i32);
        state.push(state_code(j.state));
        maxo.push(j.points.iter().fold(0.0f64, |a, p| a.max(p.opening)));
        nf.push(j.normal_force);
    }
    grid.point_f64("opening", 1, opening);
    grid.point_f64("displacement", 3, disp);
    grid.cell_i32("joint", joint);
    grid.cell_i32("state", state);
    grid.cell_f64("max_opening", 1, maxo);
    grid.cell_f64("normal_force", 1, nf);
    grid.into_bytes("voussoir cracked interfaces")
}

/// The supports as polygon faces: cell data `support` (index in the result's list of supports)
/// and `fixed` (1 for a fixed connection); point data `displacement` (the prescribed motion in
/// a settlement result, zero in a limit result).
pub fn supports_vtu(r: &(impl Result3d + ?Sized)) -> Result<Vec<u8>, IoError> {
    validate(r)?;
    let g = r.shapes();
    let m = Motions::of(r);
    let mut grid = Grid::default();
    let (mut disp, mut support, mut fixed) = (Vec::new(), Vec::new(), Vec::new());
    for (i, s) in g.supports.iter().enumerate() {
        let (c, d) = m.supports[i];
        let first = grid.points.len() as u64 / 3;
        for v in &s.vertices {
            grid.add_point(*v);
            disp.extend_from_slice(&crate::result3d::small_displacement(c, &d, *v));
        }
        for f in &s.faces {
            grid.add_cell(CellType::Polygon, f.iter().map(|&k| first + k as u64));
            support.push(i as i32);
            fixed.push(i32::from(s.fixed));
        }
    }
    grid.point_f64("displacement", 3, disp);
    grid.cell_i32("support", support);
    grid.cell_i32("fixed", fixed);
    grid.into_bytes("voussoir supports")
}

/// The parts of a multiblock file, in order.
pub const PARTS: [&str; 4] = ["blocks", "contacts", "cracks", "supports"];

/// A `.vtm` multiblock and its pieces: `[(vtm_name, …), (stem_blocks.vtu, …),
/// (stem_contacts.vtu, …), (stem_cracks.vtu, …), (stem_supports.vtu, …)]` where `stem` is
/// `vtm_name` without its `.vtm` extension; the supports only when `supports` is true. The
/// pieces are named relative to the `.vtm`: write them all into the directory of the `.vtm`.
/// `vtm_name` must be a plain file name (no directory).
///
/// When no joint is cracked, the `cracks` block is listed without a file (`<DataSet index="2"
/// name="cracks"/>`, as VTK's own writer lists an empty block) and no `_cracks.vtu` is written:
/// every file the `.vtm` names holds cells (meshio cannot read a grid of zero cells).
pub fn multiblock(
    r: &(impl Result3d + ?Sized),
    vtm_name: &str,
    supports: bool,
) -> Result<Vec<(String, Vec<u8>)>, IoError> {
    if vtm_name.is_empty()
        || vtm_name.contains(['/', '\\'])
        || vtm_name == "."
        || vtm_name == ".."
        || vtm_name.chars().any(|c| c.is_control())
    {
        return Err(IoError(format!(
            "the multiblock name must be a plain file name, got {vtm_name:?}"
        )));
    }
    let stem = vtm_name.strip_suffix(".vtm").unwrap_or(vtm_name);
    let cracked = r
        .joints()
        .iter()
        .any(|j| j.state != JointState::Closed && !j.points.is_empty());
    // (part, file and bytes; None for an empty block).
    type Part<'a> = (&'a str, Option<(String, Vec<u8>)>);
    let mut parts: Vec<Part> = vec![
        (
            PARTS[0],
            Some((format!("{stem}_blocks.vtu"), blocks_vtu(r)?)),
        ),
        (
            PARTS[1],
            Some((format!("{stem}_contacts.vtu"), contacts_vtu(r)?)),
        ),
        (
            PARTS[2],
            if cracked {
                Some((format!("{stem}_cracks.vtu"), cracks_vtu(r)?))
            } else {
                None
            },
        ),
    ];
    if supports {
        parts.push((
            PARTS[3],
            Some((format!("{stem}_supports.vtu"), supports_vtu(r)?)),
        ));
    }
    let mut vtm = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <vtkMultiBlockDataSet>\n",
    );
    for (i, (part, piece)) in parts.iter().enumerate() {
        match piece {
            Some((file, _)) => {
                let _ = writeln!(
                    vtm,
                    "    <DataSet index=\"{i}\" name=\"{part}\" file=\"{}\"/>",
                    crate::draw::svg::esc(file)
                );
            }
            None => {
                let _ = writeln!(vtm, "    <DataSet index=\"{i}\" name=\"{part}\"/>");
            }
        }
    }
    vtm.push_str("  </vtkMultiBlockDataSet>\n</VTKFile>\n");
    let mut out = vec![(vtm_name.to_string(), vtm.into_bytes())];
    out.extend(parts.into_iter().filter_map(|(_, piece)| piece));
    Ok(out)
}
