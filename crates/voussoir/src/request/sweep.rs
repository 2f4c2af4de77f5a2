//! Sweeps of settlement analyses (magnitudes, angles, Monte Carlo), optionally each followed
//! by the capacity analysis of the same settlement. The engine is [`crate::sweep`].

use super::{invalid, Output, Request};
use crate::analysis::capacity::CapacityOptions;
use crate::analysis::settlement::SettlementForm;
use crate::error::Result;
use crate::lp::SolverOptions;
use crate::result::Spatial;
use crate::structure::Assembly;
use crate::sweep::{self, MotionSize, SweepKind, SweepSpec};
use crate::BuildOptions;
use serde::{Deserialize, Serialize};

/// Options of a sweep. Exactly one of `magnitudes`, `angles`, `samples`. Defaults: coefficient
/// of variation 0.3, seed 1, both settlement programs, no capacity analysis (40 intervals when
/// asked for), every task. The request's support motion is the base settlement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SweepRequest {
    /// N analyses, the base motions scaled by k/N, k = 1 … N.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub magnitudes: Option<usize>,
    /// N analyses, the move vectors (u, v) rotated through 360°·k/N (3D: (u, w) and (θx, θz)
    /// in the vertical x–z plane).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angles: Option<usize>,
    /// N Monte Carlo analyses, random settlement fields around the base motions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub samples: Option<usize>,
    /// Monte Carlo: coefficient of variation of each support's motion (default 0.3; given
    /// without `samples`, refused).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cov: Option<f64>,
    /// Monte Carlo: the random seed (default 1; the same seed gives the same samples anywhere;
    /// given without `samples`, refused).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Which programs each settlement analysis solves (default both).
    pub settlement_form: SettlementForm,
    /// After each settlement, the capacity analysis of the same settlement.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub capacity: bool,
    /// Intervals of each capacity curve (default 40; given without `capacity`, refused).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub capacity_steps: Option<usize>,
    /// Run only the tasks with index ≡ i (mod n): `[i, n]` (default: every task).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shard: Option<[usize; 2]>,
    /// Run only these tasks (indices below the sweep's size; default: every task, or the
    /// shard's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tasks: Option<Vec<usize>>,
    /// Report each settlement's (and capacity curve's) solver's own mechanism instead of the
    /// canonical one (docs/canonical.md).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub raw: bool,
}

impl Default for SweepRequest {
    fn default() -> Self {
        SweepRequest {
            magnitudes: None,
            angles: None,
            samples: None,
            cov: None,
            seed: None,
            settlement_form: SettlementForm::Both,
            capacity: false,
            capacity_steps: None,
            shard: None,
            tasks: None,
            raw: false,
        }
    }
}

/// The Monte Carlo coefficient of variation when none is given.
pub const DEFAULT_COV: f64 = 0.3;
/// The Monte Carlo seed when none is given.
pub const DEFAULT_SEED: u64 = 1;
/// The intervals of each capacity curve when none are given.
pub const DEFAULT_CAPACITY_STEPS: usize = 40;

impl SweepRequest {
    /// The coefficient of variation (given or the default).
    pub fn cov(&self) -> f64 {
        self.cov.unwrap_or(DEFAULT_COV)
    }

    /// The seed (given or the default).
    pub fn seed(&self) -> u64 {
        self.seed.unwrap_or(DEFAULT_SEED)
    }

    /// The intervals of each capacity curve (given or the default).
    pub fn capacity_steps(&self) -> usize {
        self.capacity_steps.unwrap_or(DEFAULT_CAPACITY_STEPS)
    }

    /// What the sweep varies.
    pub fn kind(&self) -> Option<SweepKind> {
        match (self.magnitudes, self.angles, self.samples) {
            (Some(n), None, None) => Some(SweepKind::Scale(n)),
            (None, Some(n), None) => Some(SweepKind::Direction(n)),
            (None, None, Some(n)) => Some(SweepKind::Sample {
                count: n,
                cov: self.cov(),
                seed: self.seed(),
            }),
            _ => None,
        }
    }

    /// The tasks to run: `tasks`, else the shard's, else every one.
    pub fn task_list(&self) -> Vec<usize> {
        let n = self.kind().map_or(0, |k| k.count());
        match (&self.tasks, self.shard) {
            (Some(t), _) => t.clone(),
            (None, Some([i, s])) => sweep::shard_tasks(n, i, s),
            (None, None) => (0..n).collect(),
        }
    }

    /// The sweep's specification for a model of `dims` dimensions (its solver the dimension's
    /// default unless a method is asked for).
    pub fn spec(&self, req: &Request, dims: usize) -> Result<SweepSpec> {
        let Some(kind) = self.kind() else {
            return invalid(self.modes_message(req));
        };
        Ok(SweepSpec {
            kind,
            build: BuildOptions {
                tolerance: req.model.tolerance,
            },
            // The policy's method of the dimension (the sweep's structures are built per task).
            solver: req
                .solver
                .options(&crate::lp::policy::ProblemClass::of_dim(if dims == 3 {
                    3
                } else {
                    2
                })),
            form: self.settlement_form,
            capacity: self.capacity.then_some(CapacityOptions {
                steps: self.capacity_steps(),
                mechanisms: false,
                ..CapacityOptions::default()
            }),
            // The mechanism stages only: a sweep's records hold the hinges, open joints and
            // works, not the forces.
            canonical: (!self.raw).then(super::mechanism_options),
        })
    }

    fn modes_message(&self, req: &Request) -> String {
        let n = req.names;
        format!(
            "give exactly one of {}, {}, {}",
            n.name("magnitudes"),
            n.name("angles"),
            n.name("samples")
        )
    }

    pub(super) fn validate(&self, req: &Request) -> Result<()> {
        let n = req.names;
        let Some(kind) = self.kind() else {
            return invalid(self.modes_message(req));
        };
        if kind.count() == 0 {
            return invalid("the number of analyses must be at least 1".into());
        }
        let cov = self.cov();
        if !(cov.is_finite() && cov >= 0.0) {
            return invalid(format!(
                "{}: must be a finite number ≥ 0",
                n.given("cov", cov)
            ));
        }
        // Options of another mode were accepted and ignored (session 24: `--magnitudes 3
        // --cov 0.2 --seed 5 --capacity-steps 10` wrote the same lines as `--magnitudes 3`).
        // Refused when given, whatever the value (session 25: the default's value, `--seed 1`,
        // passed where `--seed 2` was refused).
        if self.samples.is_none() {
            for (field, value) in [
                ("cov", self.cov.map(|c| c.to_string())),
                ("seed", self.seed.map(|s| s.to_string())),
            ] {
                if let Some(value) = value {
                    return invalid(format!(
                        "{}: applies to the Monte Carlo samples of {} only",
                        n.given(field, value),
                        n.ask("samples", "N")
                    ));
                }
            }
        }
        if let (false, Some(k)) = (self.capacity, self.capacity_steps) {
            return invalid(format!(
                "{}: the intervals of the capacity curves of {}; add it",
                n.given("capacity_steps", k),
                n.name("capacity")
            ));
        }
        if self.capacity && self.capacity_steps() == 0 {
            return invalid(format!(
                "{}: a capacity curve needs at least one interval",
                n.given("capacity_steps", 0)
            ));
        }
        let shards = match self.shard {
            Some([i, s]) => {
                if s == 0 || i >= s {
                    return invalid(format!(
                        "{}: expected I/N with 0 ≤ I < N",
                        n.given("shard", format!("{i}/{s}"))
                    ));
                }
                if self.tasks.is_some() {
                    return invalid(format!(
                        "give {} or {}, not both",
                        n.name("shard"),
                        n.name("tasks")
                    ));
                }
                s
            }
            None => 1,
        };
        sweep::check_size(kind.count(), shards)?;
        req.model.refuse_exact_cone(
            n,
            &format!(
                ": a sweep solves the friction pyramid ({}); the exact cone is solved by settle",
                n.name("friction_facets")
            ),
        )
    }

    /// The sweep's tasks on the structure (its supports carry the base settlement), calling
    /// `progress` after each (on the current rayon pool).
    pub(super) fn solve<S: Assembly>(
        &self,
        st: &S,
        req: &Request,
        dims: usize,
        progress: &(dyn Fn() + Sync),
    ) -> Result<(Output<S::D>, SolverOptions)>
    where
        <S::D as Spatial>::Motion: MotionSize,
    {
        let spec = self.spec(req, dims)?;
        let records = sweep::run_assembly(st, &spec, &self.task_list(), progress)?;
        Ok((Output::Sweep(records), spec.solver))
    }
}
