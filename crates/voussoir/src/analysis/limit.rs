//! Classic limit analysis (the paper's Remark 3).
//!
//! Static: `max λ  s.t.  F_D + λ F_L + Nᵀ p_n + Tᵀ p_t = 0,  p_n ≥ 0`.
//! Kinematic (its dual, read from the equilibrium rows' duals): the collapse mechanism `d`,
//! normalised so that the live loads do unit work, `F_Lᵀ d = 1`; then `λ = −F_Dᵀ d`.

use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, Direction, LpStatus, SolverOptions};
use crate::programs::ForceProgram;
use crate::result::{report, BlockMotion, Geometry, Hinge, JointResult, Reaction, ThrustPoint};
use crate::structure::Structure;
use serde::{Deserialize, Serialize};

/// Outcome of a limit analysis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LimitStatus {
    /// A finite collapse multiplier λ ≥ 0 and its mechanism.
    Collapse,
    /// No finite collapse load: equilibrium holds for every λ ("locked").
    Locked,
    /// No equilibrium under the dead loads alone (λ would have to be negative, or no λ works).
    NoEquilibrium,
}

impl LimitStatus {
    pub fn sentence(&self) -> &'static str {
        match self {
            LimitStatus::Collapse => "collapse: finite load multiplier with its mechanism",
            LimitStatus::Locked => "no finite collapse load: the structure is locked (equilibrium for every load multiplier)",
            LimitStatus::NoEquilibrium => "no equilibrium under the dead loads: the structure cannot stand even without live load",
        }
    }
}

/// Result of a limit analysis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LimitResult {
    pub status: LimitStatus,
    pub message: String,
    /// λ: the collapse multiplier (negative when the dead loads alone cannot be carried and the
    /// live load, reversed, would be needed; `null` when locked or infeasible).
    pub load_multiplier: Option<f64>,
    /// Work of the dead loads and of the live loads on the mechanism (−λ and 1 at collapse).
    pub work_dead_loads: Option<f64>,
    pub work_live_loads: Option<f64>,
    /// The collapse mechanism (normalised: unit work of the live loads).
    pub blocks: Vec<BlockMotion>,
    pub joints: Vec<JointResult>,
    pub hinges: Vec<Hinge>,
    pub thrust_line: Vec<ThrustPoint>,
    pub reactions: Vec<Reaction>,
    /// Simplex iterations spent.
    pub iterations: i64,
    /// The geometry analysed (for drawing a saved result).
    pub geometry: Geometry,
}

/// The raw vectors of a limit analysis, for the analyses built on top of it.
#[derive(Clone, Debug)]
pub struct LimitSolution {
    pub status: LimitStatus,
    pub lambda: Option<f64>,
    /// Mechanism (block DOFs), empty unless a collapse was found.
    pub mechanism: Vec<f64>,
    pub pn: Vec<f64>,
    pub pt: Vec<f64>,
    pub iterations: i64,
}

/// Solve the static LP of `st` and read the mechanism from its duals.
pub fn solve_limit(
    st: &Structure,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<LimitSolution> {
    let (dead, live) = load_vectors(st)?;
    let fp = ForceProgram::new(map, &dead, Some(&live), Direction::Maximise, |_| (0.0, 0.0));
    let sol = lp::solve(&fp.lp, opts)?;
    Ok(finish(
        map,
        &fp,
        &live,
        sol.status,
        &sol.x,
        &sol.row_dual,
        sol.iterations,
    ))
}

/// Dead and live load vectors; an error if there is no live load.
fn load_vectors(st: &Structure) -> Result<(Vec<f64>, Vec<f64>)> {
    if !st.has_live_loads() {
        return Err(Error::Request(
            "limit analysis needs live loads (the model has none)".into(),
        ));
    }
    Ok((st.load_vector(false), st.load_vector(true)))
}

/// Limit analysis with the exact crushing domain (second-order cones, Clarabel) instead of
/// its inscribed polygon. Without finite compressive strength this is the same problem.
pub fn solve_limit_conic(
    st: &Structure,
    map: &KinematicMap,
    opts: &SolverOptions,
) -> Result<LimitSolution> {
    let (dead, live) = load_vectors(st)?;
    let fp = crate::conic::limit_force_program(map, &dead, &live);
    let sol = crate::conic::solve_force_conic(map, &fp, opts)?;
    Ok(finish(
        map,
        &fp,
        &live,
        sol.status,
        &sol.x,
        &sol.row_dual,
        sol.iterations,
    ))
}

/// λ, forces and the mechanism (duals of the equilibrium rows, normalised to unit live-load
/// work) from a solved force program.
fn finish(
    map: &KinematicMap,
    fp: &ForceProgram,
    live: &[f64],
    status: LpStatus,
    x: &[f64],
    row_dual: &[f64],
    iterations: i64,
) -> LimitSolution {
    let none = |status| LimitSolution {
        status,
        lambda: None,
        mechanism: vec![],
        pn: vec![0.0; map.num_points()],
        pt: vec![0.0; map.num_points()],
        iterations,
    };
    match status {
        LpStatus::Unbounded => return none(LimitStatus::Locked),
        LpStatus::Infeasible => return none(LimitStatus::NoEquilibrium),
        LpStatus::Optimal => {}
    }
    let lambda = x[fp.lambda.expect("program has λ")];
    let (pn, pt) = fp.forces(x);
    let y = &row_dual[..map.num_dofs];
    let wl: f64 = live.iter().zip(y).map(|(a, b)| a * b).sum();
    let mechanism = if wl.abs() > 0.0 {
        y.iter().map(|v| v / wl).collect()
    } else {
        vec![0.0; y.len()]
    };
    LimitSolution {
        status: if lambda >= 0.0 {
            LimitStatus::Collapse
        } else {
            LimitStatus::NoEquilibrium
        },
        lambda: Some(lambda),
        mechanism,
        pn,
        pt,
        iterations,
    }
}

/// How finite compressive strength enters the limit analysis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Crushing {
    /// Inscribed polygon with `facets` chords: an LP (HiGHS). The default.
    #[default]
    Linear,
    /// The exact parabola as second-order cones (Clarabel).
    Conic,
}

/// Limit analysis with a choice of crushing model and number of facets.
pub fn limit_with(
    st: &Structure,
    opts: &SolverOptions,
    crushing: Crushing,
    facets: usize,
) -> Result<LimitResult> {
    let mut map = KinematicMap::new(st);
    map.facets = facets.max(1);
    let s = match crushing {
        Crushing::Linear => solve_limit(st, &map, opts)?,
        Crushing::Conic => solve_limit_conic(st, &map, opts)?,
    };
    Ok(limit_result(st, &map, &s))
}

/// Limit analysis of a structure: collapse multiplier, mechanism, forces, thrust line.
pub fn limit(st: &Structure, opts: &SolverOptions) -> Result<LimitResult> {
    let map = KinematicMap::new(st);
    let s = solve_limit(st, &map, opts)?;
    Ok(limit_result(st, &map, &s))
}

/// Turn raw vectors into the reported result.
pub fn limit_result(st: &Structure, map: &KinematicMap, s: &LimitSolution) -> LimitResult {
    let d = if s.mechanism.is_empty() {
        vec![0.0; map.num_dofs]
    } else {
        s.mechanism.clone()
    };
    let rep = report(st, map, &d, 0.0, &s.pn, &s.pt);
    let (wd, wl) = if s.mechanism.is_empty() {
        (None, None)
    } else {
        let dot = |f: Vec<f64>| f.iter().zip(&d).map(|(a, b)| a * b).sum::<f64>();
        (
            Some(dot(st.load_vector(false))),
            Some(dot(st.load_vector(true))),
        )
    };
    let message = match (s.status, s.lambda) {
        (LimitStatus::Collapse, Some(l)) => format!("collapse load multiplier λ = {l:.6}"),
        (LimitStatus::NoEquilibrium, Some(l)) => format!(
            "{} (the largest multiplier in equilibrium is λ = {l:.6} < 0)",
            s.status.sentence()
        ),
        (st_, _) => st_.sentence().to_string(),
    };
    LimitResult {
        status: s.status,
        message,
        load_multiplier: s.lambda,
        work_dead_loads: wd,
        work_live_loads: wl,
        blocks: if s.mechanism.is_empty() {
            vec![]
        } else {
            rep.blocks
        },
        joints: rep.joints,
        hinges: if s.mechanism.is_empty() {
            vec![]
        } else {
            rep.hinges
        },
        thrust_line: rep.thrust_line,
        reactions: rep.reactions,
        iterations: s.iterations,
        geometry: Geometry::of(st),
    }
}
