//! Sequences of solves on one structure: [`WarmLimit`] (a limit LP kept between solves on
//! structures of one topology) and [`SettlementPath`] (the settlement mechanism per unit
//! settlement, from which every deformed structure is made). Capacity curves and the
//! incremental analysis stand on them; they stand on `limit`, `settlement` and
//! `nonassociative`, never the other way round.

use crate::analysis::laws::{Crushing, NonAssociativeOptions, DEFAULT_FACETS};
use crate::analysis::limit::{
    limit_solution, load_vectors, solve_limit, solve_limit_conic, LimitSolution,
};
use crate::analysis::settlement::{
    solve_settlement_crushing, SettlementSolution, SettlementStatus,
};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::{self, SolverOptions};
use crate::programs;
use crate::structure::{Assembly, Structure};

/// A limit LP kept between solves on structures of one topology (same blocks, joints and
/// points): all points are columns, open ones fixed at zero
/// ([`programs::limit_force_program_fixed_topology`]), and the optimal basis of a solve starts
/// the next one, where the backend has bases ([`lp::solve_warm`]).
pub struct WarmLimit {
    solver: SolverOptions,
    hot: bool,
    crushing: Crushing,
    nonassociative: Option<crate::analysis::nonassociative::NonAssociativeOptions>,
    /// Solves whose non-associative friction iteration did not converge.
    pub unconverged: usize,
    basis: Option<lp::Basis>,
    /// The method of a program whose bounds are those of the program before
    /// ([`WarmLimit::with_warm_method`]).
    warm_method: Option<lp::Method>,
    /// The column bounds of the last program solved warm (its open points).
    bounds: Option<[Vec<f64>; 2]>,
    /// LP solves and simplex iterations so far.
    pub solves: usize,
    pub iterations: i64,
}

impl WarmLimit {
    /// `hot = false` solves every LP from scratch with [`solve_limit`].
    pub fn new(solver: &SolverOptions, hot: bool) -> WarmLimit {
        WarmLimit {
            solver: *solver,
            hot,
            crushing: Crushing::Linear,
            nonassociative: None,
            unconverged: 0,
            basis: None,
            warm_method: None,
            bounds: None,
            solves: 0,
            iterations: 0,
        }
    }

    /// Solve with the exact crushing cones ([`solve_limit_conic`], from scratch) instead of
    /// the inscribed polygon.
    pub fn with_crushing(mut self, crushing: Crushing) -> WarmLimit {
        self.crushing = crushing;
        self
    }

    /// Solve a program whose column bounds are those of the program before (a
    /// capacity curve's steps after the first settled one: the same open points, only the
    /// coefficients changed) by `method`, from the basis the one before left; every other
    /// program by the method asked for. `None`: every program by the method asked for (the
    /// solver policy's [`lp::policy::curve_warm_method`]).
    pub fn with_warm_method(mut self, method: Option<lp::Method>) -> WarmLimit {
        self.warm_method = method;
        self
    }

    /// Solve with non-associative friction (the iteration from scratch each time).
    pub fn with_nonassociative(
        mut self,
        o: Option<crate::analysis::nonassociative::NonAssociativeOptions>,
    ) -> WarmLimit {
        self.nonassociative = o;
        self
    }

    /// Limit analysis of `st` (same meaning as [`solve_limit`]).
    pub fn solve<S: Assembly>(&mut self, st: &S, map: &KinematicMap) -> Result<LimitSolution> {
        self.solves += 1;
        if let Some(o) = &self.nonassociative {
            let mut m = map.clone();
            let (_, it) = crate::analysis::nonassociative::solve_limit_nonassociative(
                st,
                &mut m,
                &self.solver,
                o,
            )?;
            self.unconverged += usize::from(!it.converged);
            self.iterations += it.last.iterations;
            return Ok(it.last);
        }
        if self.crushing == Crushing::Conic {
            let sol = solve_limit_conic(st, map, &self.solver)?;
            self.iterations += sol.iterations;
            return Ok(sol);
        }
        // Joint laws (friction, crushing) give gapped points roles of their own in the force
        // program: those structures are solved from scratch.
        let sol = if self.hot && !map.has_joint_laws() {
            let (dead, live) = load_vectors(st)?;
            let fp = programs::limit_force_program_fixed_topology(map, &dead, &live);
            let _kind = lp::ProgramKind::set("steps", "");
            // A program with the column bounds of the one before (the same open points fixed
            // at zero: only coefficients and right-hand sides changed, so that its basis stays
            // dual feasible where the geometry moved little) goes on from that basis by the
            // warm method where one is set; every other one by the method asked for.
            let bounds = [fp.lp.col_lower.clone(), fp.lp.col_upper.clone()];
            // Such a program's kept basis is looked at first: where it is still optimal
            // (certified by the solver layer), no backend runs (`lp::solve_warm_kept`).
            let (o, kept) = match self.warm_method {
                Some(method) if self.basis.is_some() && self.bounds.as_ref() == Some(&bounds) => (
                    SolverOptions {
                        method,
                        ..self.solver
                    },
                    true,
                ),
                _ => (self.solver, false),
            };
            self.bounds = Some(bounds);
            let sol = if kept {
                lp::solve_warm_kept(&fp.lp, &o, &mut self.basis)?
            } else {
                lp::solve_warm(&fp.lp, &o, &mut self.basis)?
            };
            limit_solution(map, &fp, &live, &sol, o.info())
        } else {
            solve_limit(st, map, &self.solver)?
        };
        self.iterations += sol.iterations;
        Ok(sol)
    }
}

/// The settlement path: the structure with unit support motions, its settlement mechanism and
/// openings, from which every deformed structure is made.
///
/// Without existing cracks the settlement LPs are homogeneous in the magnitude: one mechanism
/// per unit settlement, scaled. A structure with existing cracks (gaps) is not: cracks close
/// at some magnitude and the mechanism changes there, so every deformed structure is solved at
/// its own magnitude.
pub struct SettlementPath<S: Assembly = Structure> {
    /// The structure with its support motions divided by `max_settlement`.
    pub unit: S,
    pub max_settlement: f64,
    pub status: SettlementStatus,
    /// Settlement mechanism per unit settlement (empty unless `status` is a mechanism); with
    /// existing cracks, the mechanism of the largest settlement divided by its magnitude.
    pub mechanism: Vec<f64>,
    /// The points (map indices) of existing cracks, with their initial gaps.
    pub existing_cracks: Vec<(usize, f64)>,
    openings: Vec<Vec<f64>>,
    open_tol: f64,
    solver: SolverOptions,
    crushing: Crushing,
    facets: usize,
    nonassociative: Option<NonAssociativeOptions>,
    canonical: Option<crate::analysis::canonical::CanonicalOptions>,
    /// With the canonical selection ([`SettlementPath::with_canonical`]): how the settlement
    /// mechanism was selected; `None` without it, or where it was not reached (the solver's
    /// mechanism then stands).
    pub selection: Option<crate::analysis::canonical::CanonicalMechanism>,
}

impl<S: Assembly> SettlementPath<S> {
    pub fn new(st: &S, solver: &SolverOptions) -> Result<SettlementPath<S>> {
        Self::with_crushing(st, solver, Crushing::Linear, DEFAULT_FACETS)
    }

    /// [`SettlementPath::new`] with a choice of crushing model and facet count.
    pub fn with_crushing(
        st: &S,
        solver: &SolverOptions,
        crushing: Crushing,
        facets: usize,
    ) -> Result<SettlementPath<S>> {
        Self::with_laws(st, solver, crushing, facets, None)
    }

    /// [`SettlementPath::with_crushing`], with non-associative friction when `nonassociative`
    /// is given (every settlement solve is then the iteration's last iterate).
    pub fn with_laws(
        st: &S,
        solver: &SolverOptions,
        crushing: Crushing,
        facets: usize,
        nonassociative: Option<NonAssociativeOptions>,
    ) -> Result<SettlementPath<S>> {
        Self::with_canonical(st, solver, crushing, facets, nonassociative, None)
    }

    /// [`SettlementPath::with_laws`] with the canonical settlement mechanism where `canonical`
    /// is given ([`crate::analysis::canonical::settlement_mechanism`]: least crack area among
    /// the optimal mechanisms, then the generic tie-break), so that the deformed structures do
    /// not depend on the LP method. Only with the inscribed polygons and associative friction
    /// (other laws: the solver's mechanism).
    pub fn with_canonical(
        st: &S,
        solver: &SolverOptions,
        crushing: Crushing,
        facets: usize,
        nonassociative: Option<NonAssociativeOptions>,
        canonical: Option<crate::analysis::canonical::CanonicalOptions>,
    ) -> Result<SettlementPath<S>> {
        let mag = st.settlement_magnitude();
        if !(mag.is_finite() && mag > 0.0) {
            return Err(Error::Request(
                "capacity analysis needs a settlement: no support has a prescribed motion".into(),
            ));
        }
        let motions: Vec<Vec<f64>> = (0..st.num_supports())
            .map(|s| st.support_motion(s).iter().map(|x| x / mag).collect())
            .collect();
        let unit = st.with_support_motions(&motions);
        let mut map = KinematicMap::new(&unit);
        map.facets = facets;
        let existing_cracks: Vec<(usize, f64)> = map
            .gap
            .iter()
            .enumerate()
            .filter(|(_, g)| **g > 0.0)
            .map(|(k, g)| (k, *g))
            .collect();
        let mut path = SettlementPath {
            unit,
            max_settlement: mag,
            status: SettlementStatus::Mechanism,
            mechanism: vec![],
            existing_cracks,
            openings: vec![],
            open_tol: 0.0,
            solver: *solver,
            crushing,
            facets,
            nonassociative,
            canonical,
            selection: None,
        };
        if path.existing_cracks.is_empty() {
            let (sol, selection) = path.solve(&path.unit, &mut map)?;
            path.selection = selection;
            if sol.status == SettlementStatus::Mechanism {
                (path.openings, path.open_tol) =
                    path.unit.joint_openings(&map, &sol.mechanism, 1.0);
            }
            path.status = sol.status;
            path.mechanism = sol.mechanism;
        } else {
            let (at, map, sol, selection) = path.solve_at(mag)?;
            let _ = (at, map);
            path.selection = selection;
            path.status = sol.status;
            path.mechanism = sol.mechanism.iter().map(|x| x / mag).collect();
        }
        Ok(path)
    }

    /// The structure with the support motions of a settlement `s`, its map and its solution.
    #[allow(clippy::type_complexity)]
    fn solve_at(
        &self,
        s: f64,
    ) -> Result<(
        S,
        KinematicMap,
        SettlementSolution,
        Option<crate::analysis::canonical::CanonicalMechanism>,
    )> {
        let motions: Vec<Vec<f64>> = (0..self.unit.num_supports())
            .map(|k| self.unit.support_motion(k).iter().map(|x| x * s).collect())
            .collect();
        let at = self.unit.with_support_motions(&motions);
        let mut map = KinematicMap::new(&at);
        map.facets = self.facets;
        let (sol, selection) = self.solve(&at, &mut map)?;
        Ok((at, map, sol, selection))
    }

    /// One settlement solve under the path's joint laws ([`SettlementPath::solve_selected`]),
    /// its mechanism's round-off set to zero ([`crate::scale::without_round_off`]): the
    /// structures deformed by it then do not depend on the path the solver took to its vertex
    /// (docs/performance.md, "Capacity step round-off and the as-written face extremes
    /// (session 26)").
    fn solve(
        &self,
        st: &S,
        map: &mut KinematicMap,
    ) -> Result<(
        SettlementSolution,
        Option<crate::analysis::canonical::CanonicalMechanism>,
    )> {
        let (mut sol, selection) = self.solve_selected(st, map)?;
        if sol.status == SettlementStatus::Mechanism && sol.mechanism.len() == map.num_dofs {
            sol.mechanism = crate::scale::without_round_off(map, &sol.mechanism, 1.0);
        }
        Ok((sol, selection))
    }

    /// One settlement solve under the path's joint laws; with the canonical selection (the
    /// inscribed polygons, associative friction) its mechanism replaced by the canonical one,
    /// with how it was selected.
    fn solve_selected(
        &self,
        st: &S,
        map: &mut KinematicMap,
    ) -> Result<(
        SettlementSolution,
        Option<crate::analysis::canonical::CanonicalMechanism>,
    )> {
        let mut sol = self.solve_raw(st, map)?;
        let Some(copts) = self
            .canonical
            .filter(|_| self.nonassociative.is_none() && self.crushing == Crushing::Linear)
        else {
            return Ok((sol, None));
        };
        if sol.status != SettlementStatus::Mechanism {
            return Ok((sol, None));
        }
        let _kind = lp::ProgramKind::set(
            "canonical selection",
            "the mechanism stages: least crack area among the optimal mechanisms, then the generic tie-break",
        );
        match crate::analysis::canonical::settlement_mechanism(st, map, &self.solver, &copts)? {
            Some((d, m)) => {
                sol.mechanism = d;
                Ok((sol, Some(m)))
            }
            None => Ok((sol, None)),
        }
    }

    fn solve_raw(&self, st: &S, map: &mut KinematicMap) -> Result<SettlementSolution> {
        match &self.nonassociative {
            Some(o) => Ok(
                crate::analysis::nonassociative::solve_settlement_nonassociative(
                    st,
                    map,
                    &self.solver,
                    self.crushing,
                    o,
                )?
                .1
                .last,
            ),
            None => solve_settlement_crushing(st, map, &self.solver, self.crushing),
        }
    }

    /// The structure after a settlement `s` (m). `s = 0` returns the undeformed structure as is.
    pub fn deformed(&self, s: f64) -> Result<S> {
        let mut st = if s == 0.0 || self.mechanism.is_empty() {
            self.unit.clone()
        } else if self.existing_cracks.is_empty() {
            self.unit
                .deformed(&self.mechanism, s, &self.openings, s.abs() * self.open_tol)
        } else {
            let (at, map, sol, _) = self.solve_at(s)?;
            if sol.status != SettlementStatus::Mechanism {
                return Err(Error::Request(format!(
                    "at a settlement of {s} m: {}",
                    sol.status.sentence()
                )));
            }
            let (openings, tol) = at.joint_openings(&map, &sol.mechanism, 1.0);
            at.deformed(&sol.mechanism, 1.0, &openings, tol)
        };
        let still = vec![0.0; <S::D as crate::dim::Dim>::DOFS];
        for k in 0..st.num_supports() {
            st.set_support_motion(k, &still);
        }
        Ok(st)
    }

    /// How many points of the existing cracks are still open in a deformed structure's map.
    pub fn existing_cracks_open(&self, map: &KinematicMap) -> usize {
        self.existing_cracks
            .iter()
            .filter(|(k, _)| map.gap.get(*k).is_some_and(|g| *g > 0.0))
            .count()
    }
}
