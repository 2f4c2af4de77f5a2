//! Clarabel's interior point, then HiGHS's crossover from its duals ([`Method::ClarabelVertex`]):
//! an optimal vertex and its basis, as HiGHS's interior point with crossover gives, without
//! HiGHS's interior point. Clarabel's answer is the centre of the optimal face: where the
//! optimum is not unique the crack pattern would depend on the method; the crossover moves it
//! to a vertex. Measured (docs/performance.md, "Clarabel with crossover (session 19)"): on the
//! 48 × 48 dome's limit program the crossover, not Clarabel, takes the time (about 60–70 CPU s
//! against Clarabel's 5), so it is a method to ask for, not the 3D default. Session 20: the free
//! columns that others span left out first ([`super::free_columns`]), `limit` of that dome
//! 51.6 CPU s at load 9–10 (68.8 in session 19 at load 6), the same vertex.

use super::{Backend, Basis, Cone3, LinearProgram, LpStatus, Method, Solved, SolverOptions};
use crate::error::{Error, Result};

/// The backend of [`Method::ClarabelVertex`].
pub struct ClarabelVertex;

impl Backend for ClarabelVertex {
    fn name(&self) -> &'static str {
        "clarabel+highs"
    }

    fn supports_cones(&self) -> bool {
        false
    }

    /// Clarabel on `lp` (its presolve and settings as [`Method::Clarabel`]'s), then
    /// [`super::highs::crossover`] from its optimal duals. A status other than optimal is
    /// Clarabel's; a crossover that fails is an error (the fallback chain goes on).
    fn solve(
        &self,
        lp: &LinearProgram,
        cones: &[Cone3],
        o: &SolverOptions,
        _start: Option<&Basis>,
    ) -> Result<Solved> {
        if !cones.is_empty() {
            return Err(Error::Solver(
                "clarabel-vertex takes no cone constraints".into(),
            ));
        }
        let trace = std::env::var_os("VOUSSOIR_TRACE").is_some();
        // The free columns that the others span left out first (super::free_columns): the
        // crossover's crash basis pivots every free column in, as IPX's starting basis does.
        if let Some(solved) = super::free_columns::solve_reduced(lp, "clarabel-vertex", |r| {
            self.solve(r, cones, o, None)
        }) {
            return solved;
        }
        let t0 = std::time::Instant::now();
        let clarabel = SolverOptions {
            method: Method::Clarabel,
            ..*o
        };
        let interior = super::clarabel::Clarabel
            .solve(lp, &[], &clarabel, None)?
            .solution;
        let t1 = std::time::Instant::now();
        if interior.status != LpStatus::Optimal {
            let mut solution = interior;
            solution.method = o.method;
            return Ok(Solved {
                solution,
                basis: None,
            });
        }
        let out = super::highs::crossover(lp, &interior, o);
        if trace {
            eprintln!(
                "trace: clarabel-vertex rows {} cols {}: clarabel {:.3} s ({} it, {}), crossover {:.3} s -> {}",
                lp.num_rows(),
                lp.num_cols(),
                (t1 - t0).as_secs_f64(),
                interior.iterations,
                super::policy::check(lp, &interior).unwrap_or_else(|| "certified".into()),
                t1.elapsed().as_secs_f64(),
                match &out {
                    Ok(s) => format!(
                        "{} it, basis {}, {}",
                        s.solution.iterations - interior.iterations,
                        if s.basis.is_some() { "valid" } else { "none" },
                        super::policy::check(lp, &s.solution)
                            .unwrap_or_else(|| "certified".into())
                    ),
                    Err(e) => e.to_string(),
                }
            );
        }
        out
    }
}
