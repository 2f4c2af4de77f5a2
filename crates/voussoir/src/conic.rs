//! Exact finite compressive strength as a second-order cone program (Clarabel).
//!
//! The force program is assembled as usual but without the inscribed chords of the crushing
//! domain; each joint of finite strength instead gets the two rotated cones
//! ```text
//!   N² ≤ 2 f_c w · (N t/2 ∓ M)      ⇔      ‖(N, (r − f_c w)/√2)‖ ≤ (r + f_c w)/√2,  r = N t/2 ∓ M
//! ```
//! which is `|M| ≤ N (t/2 − N/(2 f_c w))` exactly.

use crate::discretize::KinematicMap;
use crate::error::Result;
use crate::lp::{Cone3, Direction, LpSolution, SolverOptions};
use crate::programs::ForceProgram;

/// Solve a force program with the exact crushing cones of `map`'s joints (Clarabel). The
/// LP part is converted by [`crate::lp`]'s Clarabel backend; duals follow HiGHS's convention.
pub fn solve_force_conic(
    map: &KinematicMap,
    fp: &ForceProgram,
    opts: &SolverOptions,
) -> Result<LpSolution> {
    let r2 = std::f64::consts::SQRT_2;
    let mut socs: Vec<Cone3> = Vec::new();
    for (j, law) in map.laws.iter().enumerate() {
        let Some(nmax) = law.max_normal_force() else {
            continue;
        };
        let range = map.joint_start[j]..map.joint_start[j + 1];
        if range.clone().any(|k| map.bilateral[k]) || nmax <= 0.0 {
            continue;
        }
        let t = law.depth;
        let fw = nmax / t;
        let cols: Vec<(usize, f64)> = range
            .filter_map(|k| fp.pn[k].map(|c| (c, map.along[k])))
            .collect();
        for s in [1.0, -1.0] {
            // r = Σ (t/2 − s·s_k) p_k; slacks b − A x = ((r + f w)/√2, N, (r − f w)/√2).
            let r_row: Vec<(usize, f64)> = cols
                .iter()
                .map(|&(c, a)| (c, -(t / 2.0 - s * a) / r2))
                .collect();
            let n_row: Vec<(usize, f64)> = cols.iter().map(|&(c, _)| (c, -1.0)).collect();
            socs.push([(r_row.clone(), fw / r2), (n_row, 0.0), (r_row, -fw / r2)]);
        }
    }
    let o = SolverOptions {
        feasibility_tolerance: opts.feasibility_tolerance.min(1e-10),
        ..*opts
    };
    crate::lp::solve_clarabel_with_cones(&fp.lp, &o, &socs)
}

/// The force program for a limit analysis with the crushing chords left out (the cones
/// replace them).
pub fn limit_force_program(map: &KinematicMap, dead: &[f64], live: &[f64]) -> ForceProgram {
    let mut m = map.clone();
    m.facets = 0;
    ForceProgram::new(&m, dead, Some(live), Direction::Maximise, |_| (0.0, 0.0))
}
