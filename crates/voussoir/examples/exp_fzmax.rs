use std::time::Instant;
use voussoir::analysis::safety::reaction_coefficients;
use voussoir::discretize::KinematicMap;
use voussoir::generate3d::{dome, DomeSpec};
use voussoir::lp::{self, Method, SolverOptions, Direction};
use voussoir::{Assembly, BuildOptions, Structure3d};

fn main() {
    let m = dome(&DomeSpec { courses: 24, segments: 24, ..DomeSpec::default() }).unwrap();
    let st = Structure3d::new(&m, BuildOptions::default()).unwrap();
    let map = KinematicMap::new(&st);
    let dead = st.load_vector(false);
    let base = voussoir::programs::equilibrium_program(&map, &dead);
    let coef = reaction_coefficients(&st, &map);
    let which: Vec<String> = std::env::args().skip(1).collect();
    let (cn, ct) = &coef[0][2];
    let mut p = base.lp.clone();
    for c in p.cost.iter_mut() { *c = 0.0; }
    for (k, col) in base.pn.iter().enumerate() { if let Some(j) = col { p.cost[*j] += cn[k]; } }
    for (r, col) in base.pt.iter().enumerate() { if let Some(j) = col { p.cost[*j] += ct[r]; } }
    p.maximise = true;
    let _ = Direction::Maximise;
    for w in &which {
        let method = match w.as_str() {
            "clarabel" => Method::Clarabel,
            "dual" => Method::DualSimplex,
            "primal" => Method::PrimalSimplex,
            "ipm" => Method::Ipm,
            "ipmnc" => Method::IpmNoCrossover,
            _ => continue,
        };
        let o = SolverOptions { method, ..SolverOptions::default() };
        let t = Instant::now();
        let s = lp::sequence::solve_alone(&p, &o);
        let el = t.elapsed().as_secs_f64();
        match s {
            Ok(s) => println!("{w}: {:?} obj {} it {} cert {:?} {:.3} s", s.status, s.objective, s.iterations, lp::sequence::certify(&p, &s), el),
            Err(e) => println!("{w}: error {e} {:.3} s", el),
        }
    }
}
