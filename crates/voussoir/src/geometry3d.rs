//! 3D geometry (placeholder until the polyhedral geometry lands: every 3D model is refused).
#[derive(Clone, Debug, PartialEq)]
pub struct Solid {
    pub vertices: Vec<[f64; 3]>,
    pub faces: Vec<Vec<usize>>,
    pub volume: f64,
    pub centroid: [f64; 3],
}
pub fn clean_polyhedron(
    what: &str,
    _vertices: &[[f64; 3]],
    _faces: &[Vec<usize>],
    _tol: f64,
) -> crate::error::Result<Solid> {
    Err(crate::error::Error::Model(format!(
        "{what}: 3D polyhedra are not supported in this build"
    )))
}
#[derive(Clone, Debug, PartialEq)]
pub struct Interface3 {
    pub a: usize,
    pub b: usize,
    pub normal: [f64; 3],
    pub polygon: Vec<[f64; 3]>,
    pub area: f64,
}
pub fn detect_interfaces3(_bodies: &[&Solid], _tol: f64) -> Vec<Interface3> {
    Vec::new()
}
pub fn find_overlap3(
    _bodies: &[&Solid],
    _tol: f64,
    _skip: &dyn Fn(usize, usize) -> bool,
) -> Option<(usize, usize)> {
    None
}
pub fn bbox3(points: &[[f64; 3]]) -> [[f64; 3]; 2] {
    let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
    for p in points {
        for c in 0..3 {
            b[0][c] = b[0][c].min(p[c]);
            b[1][c] = b[1][c].max(p[c]);
        }
    }
    b
}
