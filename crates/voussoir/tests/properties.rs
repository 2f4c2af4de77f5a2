//! Properties of the analyses on random structures (proptest): random stacks of blocks under a
//! horizontal live load, random running-bond walls and random arches (the generators of
//! `voussoir::generate`).
//!
//! (a) the certificate of limit analysis: the static λ (the force program's optimum) equals
//!     the kinematic λ = −F_Dᵀd of its mechanism normalised to F_Lᵀd = 1, and the mechanism is
//!     kinematically admissible;
//! (b) λ, the status and the hinges do not change when the model is scaled by 1e-4 … 1e4
//!     (every force scaled by s², so λ, a ratio of forces, is the same);
//! (c) nor under a rigid motion of the whole model, gravity and the live load rotated along
//!     (the self-weight is written as the dead body load W·(R·[0, −1]), which is what
//!     `self_weight` means for an upright model);
//! (d) nor under a renumbering of the blocks (loads renumbered along);
//! (e) settlement results are linear in the support motion: work, block motions and hinges
//!     scale with its magnitude;
//! (f) `limit`, `settle` and `safety` agree on whether a structure stands: settle with no
//!     support motion finds `cannot_stand`, and safety's `stands` is false, exactly when limit
//!     finds `no_equilibrium`.
//!
//! Reproducible: every property runs a fixed number of cases from a fixed ChaCha seed
//! ([`runner`]); no failure files are written. A failing case is printed shrunk.
//! Results and the cases found are recorded in docs/fuzzing.md ("Properties").

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use std::collections::BTreeMap;
use voussoir::analysis::limit::{limit_result, solve_limit_checked};
use voussoir::analysis::settlement::kinematic_violation;
use voussoir::analysis::{settle, LimitResult, LimitStatus, SettlementStatus};
use voussoir::discretize::KinematicMap;
use voussoir::generate::{arch, wall, ArchShape, ArchSpec, FirstCourse, LiveLoad, WallSpec};
use voussoir::lp::SolverOptions;
use voussoir::model::{Block, Load, Loads, Material, Support};
use voussoir::result::Spatial;
use voussoir::{BuildOptions, Model, Structure};

/// Cases per property: enough to meet stacks that stand, collapse and cannot stand, walls of
/// one to four courses and arches thin and thick; few enough to keep the file well under a
/// minute in release.
const CASES: u32 = 32;

/// Relative tolerance of every comparison of λ and of works.
const REL: f64 = 1e-6;

/// The default solver, with a time limit as a guard: a solve that does not end (one did at
/// scale 1e-4 before the scale-free numerics) fails its case instead of hanging the test.
/// Every solve here takes milliseconds.
fn solver() -> SolverOptions {
    SolverOptions {
        time_limit: Some(60.0),
        ..SolverOptions::default()
    }
}

/// A test runner with a fixed seed: the same cases on every run and every machine.
fn runner(seed: u8) -> TestRunner {
    let config = Config {
        cases: CASES,
        failure_persistence: None,
        max_shrink_iters: 256,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    )
}

/// Run `prop` on `CASES` values of `strategy`; panic with the shrunk case on failure.
fn check<S: Strategy>(
    name: &str,
    seed: u8,
    strategy: S,
    prop: impl Fn(S::Value) -> Result<(), TestCaseError>,
) where
    S::Value: std::fmt::Debug,
{
    if let Err(e) = runner(seed).run(&strategy, prop) {
        panic!("property '{name}' fails: {e}");
    }
}

// ── Random models ──────────────────────────────────────────────────────────────────────────

/// What a random case is built from (printed when a case fails).
#[derive(Clone, Debug)]
enum Case {
    /// Blocks `(width, height, t)`, each resting on the one below; `t ∈ (0, 1)` places it
    /// from just touching the left end of the block below (0) to just touching its right end
    /// (1). A wide slab `base` below. Live load: W·[1, 0] on every block.
    Stack(Vec<(f64, f64, f64)>),
    /// A running-bond wall on segments `f0…`, live load W·[1, 0].
    Wall {
        courses: usize,
        units: usize,
        unit: [f64; 2],
        half: bool,
    },
    /// A semicircular arch on `left` and `right`; live load: a vertical pressure on the left
    /// half (`q > 0`) or W·[1, 0] (`q == 0`).
    Arch {
        radius: f64,
        ratio: f64,
        voussoirs: usize,
        q: f64,
    },
}

fn material() -> BTreeMap<String, Material> {
    BTreeMap::from([(
        "default".to_string(),
        Material {
            unit_weight: 20.0,
            ..Material::default()
        },
    )])
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

impl Case {
    fn model(&self) -> Model {
        match self {
            Case::Stack(blocks) => {
                let mut polys = Vec::new();
                let (mut x, mut y, mut w_below) = (0.0, 0.0, 0.0);
                for (k, &(w, h, t)) in blocks.iter().enumerate() {
                    if k > 0 {
                        // From x − w (touching the left end) to x + w_below (the right end).
                        x += -w + t * (w + w_below);
                    }
                    polys.push(rect(x, y, x + w, y + h));
                    y += h;
                    w_below = w;
                }
                let (w0, _, _) = blocks[0];
                Model {
                    description: "random stack".into(),
                    materials: material(),
                    blocks: polys
                        .into_iter()
                        .map(|polygon| Block {
                            polygon,
                            material: None,
                        })
                        .collect(),
                    supports: vec![Support {
                        name: "base".into(),
                        polygon: rect(-1.0, -0.5, w0 + 1.0, 0.0),
                        motion: [0.0; 3],
                        connection: Default::default(),
                    }],
                    loads: Loads {
                        self_weight: true,
                        dead: vec![],
                        live: vec![Load::Body {
                            coefficients: [1.0, 0.0],
                            blocks: None,
                        }],
                    },
                    tolerance: None,
                    cracks: Vec::new(),
                }
            }
            Case::Wall {
                courses,
                units,
                unit,
                half,
            } => wall(&WallSpec {
                courses: *courses,
                units: *units,
                unit: *unit,
                first_course: if *half {
                    FirstCourse::Half
                } else {
                    FirstCourse::Full
                },
                unit_weight: 20.0,
                width: 1.0,
                live: LiveLoad::Horizontal,
            })
            .expect("valid wall"),
            Case::Arch {
                radius,
                ratio,
                voussoirs,
                q,
            } => arch(&ArchSpec {
                shape: ArchShape::Semicircular,
                radius: *radius,
                thickness: ratio * radius,
                voussoirs: *voussoirs,
                unit_weight: 20.0,
                live: if *q > 0.0 {
                    LiveLoad::Left
                } else {
                    LiveLoad::Horizontal
                },
                live_load: if *q > 0.0 { *q } else { 1.0 },
                ..ArchSpec::default()
            })
            .expect("valid arch"),
        }
    }
}

fn stack() -> impl Strategy<Value = Case> {
    prop::collection::vec((0.3..1.5f64, 0.3..1.5f64, 0.15..0.85f64), 1..=4).prop_map(Case::Stack)
}

fn a_wall() -> impl Strategy<Value = Case> {
    (
        1..=4usize,
        1..=4usize,
        0.2..0.6f64,
        0.1..0.3f64,
        any::<bool>(),
    )
        .prop_map(|(courses, units, l, h, half)| Case::Wall {
            courses,
            units,
            unit: [l, h],
            half,
        })
}

/// Arches with a pressure on the left half (q in kN/m²) or a horizontal load (q = 0); the
/// thickness ratio spans both sides of the least thickness of the semicircular arch
/// (t/R ≈ 0.11), so some cannot stand.
fn an_arch() -> impl Strategy<Value = Case> {
    (
        1.0..5.0f64,
        0.08..0.25f64,
        4..=16usize,
        prop_oneof![Just(0.0), 0.5..5.0f64],
    )
        .prop_map(|(radius, ratio, voussoirs, q)| Case::Arch {
            radius,
            ratio,
            voussoirs,
            q,
        })
}

/// Stacks, walls and arches alike.
fn any_case() -> impl Strategy<Value = Case> {
    prop_oneof![stack(), a_wall(), an_arch()]
}

// ── Analyses ───────────────────────────────────────────────────────────────────────────────

fn structure(m: &Model) -> Structure {
    Structure::new(m, BuildOptions::default()).expect("generated models are valid")
}

/// The bounding-box diagonal of a model's blocks.
fn size(m: &Model) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in m.blocks.iter().flat_map(|b| &b.polygon) {
        for c in 0..2 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// A limit analysis with its raw vectors.
struct Limit {
    result: LimitResult,
    mechanism: Vec<f64>,
    map: KinematicMap,
}

fn limit(m: &Model) -> Limit {
    let st = structure(m);
    let map = KinematicMap::new(&st);
    let s = solve_limit_checked(&st, &map, &solver()).expect("limit solves");
    Limit {
        result: limit_result(&st, &map, &s),
        mechanism: s.mechanism,
        map,
    }
}

fn close(a: f64, b: f64, floor: f64) -> bool {
    (a - b).abs() <= REL * a.abs().max(b.abs()).max(floor)
}

fn close_opt(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => close(a, b, 1e-3),
        (None, None) => true,
        _ => false,
    }
}

/// Hinge positions, mapped by `f` and sorted.
fn hinges(r: &LimitResult, f: impl Fn([f64; 2]) -> [f64; 2]) -> Vec<[f64; 2]> {
    let mut v: Vec<[f64; 2]> = r
        .hinges
        .iter()
        .map(|h| {
            let c = <voussoir::dim::Two as Spatial>::coords(&h.at);
            f([c[0], c[1]])
        })
        .collect();
    v.sort_by(|a, b| a.partial_cmp(b).expect("finite hinge positions"));
    v
}

/// Same status, same λ (both ends of its range) and the same hinges (within `REL` of the
/// model's size `l`) once `map` takes the hinges of `b` back to `a`'s frame.
fn same_limit(
    a: &LimitResult,
    b: &LimitResult,
    l: f64,
    map: impl Fn([f64; 2]) -> [f64; 2],
) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.status, b.status, "status: {} | {}", a.message, b.message);
    prop_assert!(
        close_opt(a.load_multiplier, b.load_multiplier),
        "λ {:?} vs {:?}",
        a.load_multiplier,
        b.load_multiplier
    );
    prop_assert!(
        close_opt(a.least_load_multiplier, b.least_load_multiplier),
        "least λ {:?} vs {:?}",
        a.least_load_multiplier,
        b.least_load_multiplier
    );
    let (ha, hb) = (hinges(a, |p| p), hinges(b, map));
    prop_assert_eq!(ha.len(), hb.len(), "hinges {:?} vs {:?}", ha, hb);
    for (p, q) in ha.iter().zip(&hb) {
        prop_assert!(
            (p[0] - q[0]).hypot(p[1] - q[1]) <= REL * l,
            "hinges {:?} vs {:?}",
            ha,
            hb
        );
    }
    Ok(())
}

// ── Transformations of a model ─────────────────────────────────────────────────────────────

/// Every length times `s`, every force times `s²` (point forces; edge pressures times `s`,
/// acting on edges `s` times longer; body loads follow the weights, which scale with the
/// areas). Support motions: translations times `s`.
fn scaled(m: &Model, s: f64) -> Model {
    let mut m = m.clone();
    let pt = |p: &mut [f64; 2]| {
        p[0] *= s;
        p[1] *= s;
    };
    m.blocks
        .iter_mut()
        .flat_map(|b| &mut b.polygon)
        .for_each(pt);
    for sp in &mut m.supports {
        sp.polygon.iter_mut().for_each(pt);
        sp.motion[0] *= s;
        sp.motion[1] *= s;
    }
    for l in m.loads.dead.iter_mut().chain(&mut m.loads.live) {
        match l {
            Load::Point { at, force, .. } => {
                pt(at);
                force[0] *= s * s;
                force[1] *= s * s;
            }
            Load::Edge { q, .. } => *q *= s,
            Load::Body { .. } => {}
        }
    }
    m
}

/// The rigid motion `p ↦ R(α) p + t`.
#[derive(Clone, Copy, Debug)]
struct Rigid {
    alpha: f64,
    t: [f64; 2],
}

impl Rigid {
    fn rotate(&self, v: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.alpha.sin_cos();
        [c * v[0] - s * v[1], s * v[0] + c * v[1]]
    }
    fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        let r = self.rotate(p);
        [r[0] + self.t[0], r[1] + self.t[1]]
    }
    fn inverse(&self, p: [f64; 2]) -> [f64; 2] {
        let q = [p[0] - self.t[0], p[1] - self.t[1]];
        Rigid {
            alpha: -self.alpha,
            t: [0.0, 0.0],
        }
        .rotate(q)
    }
}

/// The self-weight written as what it is, the dead body load W·[0, −1]; the identity of
/// [`moved`] (a check that the two forms are one load).
fn gravity_as_body_load(m: &Model) -> Model {
    moved(
        m,
        Rigid {
            alpha: 0.0,
            t: [0.0, 0.0],
        },
    )
}

/// The model moved rigidly, its loads along: gravity becomes the dead body load W·R[0, −1];
/// body and point loads are rotated (edge pressures are vertical by definition and cannot be:
/// models with them are not moved).
fn moved(m: &Model, r: Rigid) -> Model {
    let mut m = m.clone();
    let pt = |p: &mut [f64; 2]| *p = r.apply(*p);
    m.blocks
        .iter_mut()
        .flat_map(|b| &mut b.polygon)
        .for_each(pt);
    for sp in &mut m.supports {
        sp.polygon.iter_mut().for_each(pt);
        let [u, v] = r.rotate([sp.motion[0], sp.motion[1]]);
        sp.motion[0] = u;
        sp.motion[1] = v;
    }
    for l in m.loads.dead.iter_mut().chain(&mut m.loads.live) {
        match l {
            Load::Point { at, force, .. } => {
                pt(at);
                *force = r.rotate(*force);
            }
            Load::Edge { .. } => panic!("an edge pressure cannot be moved rigidly"),
            Load::Body { coefficients, .. } => *coefficients = r.rotate(*coefficients),
        }
    }
    if m.loads.self_weight {
        m.loads.self_weight = false;
        m.loads.dead.push(Load::Body {
            coefficients: r.rotate([0.0, -1.0]),
            blocks: None,
        });
    }
    m
}

/// The blocks renumbered: block `i` becomes block `perm[i]`; loads follow.
fn renumbered(m: &Model, perm: &[usize]) -> Model {
    let mut out = m.clone();
    for (i, b) in m.blocks.iter().enumerate() {
        out.blocks[perm[i]] = b.clone();
    }
    for l in out.loads.dead.iter_mut().chain(&mut out.loads.live) {
        match l {
            Load::Point { block, .. } | Load::Edge { block, .. } => *block = perm[*block],
            Load::Body {
                blocks: Some(bs), ..
            } => bs.iter_mut().for_each(|b| *b = perm[*b]),
            Load::Body { blocks: None, .. } => {}
        }
    }
    out
}

/// A permutation of `0..n` from a shuffle seed (a Fisher–Yates shuffle driven by `keys`).
fn permutation(n: usize, keys: &[u32]) -> Vec<usize> {
    let mut p: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        let j = keys[i % keys.len()] as usize % (i + 1);
        p.swap(i, j);
    }
    p
}

// ── (a) the certificate ────────────────────────────────────────────────────────────────────

#[test]
fn static_lambda_equals_kinematic_lambda_and_the_mechanism_is_admissible() {
    check("certificate", 1, any_case(), |case| {
        let m = case.model();
        let l = limit(&m);
        let r = &l.result;
        if r.status != LimitStatus::Collapse {
            return Ok(());
        }
        let lam = r.load_multiplier.expect("collapse has λ");
        let (wd, wl) = (r.work_dead_loads.unwrap(), r.work_live_loads.unwrap());
        prop_assert!(close(wl, 1.0, 1.0), "F_Lᵀd = {wl}, expected 1");
        prop_assert!(
            close(lam, -wd, 1e-3),
            "static λ = {lam}, kinematic λ = −F_Dᵀd = {}",
            -wd
        );
        // Admissible: no interpenetration, no sliding, relative to the mechanism's size.
        let n = m.blocks.len();
        let big = (0..n)
            .map(|i| {
                let d = &l.mechanism[3 * i..3 * i + 3];
                d[0].abs().max(d[1].abs()).max(d[2].abs() * size(&m))
            })
            .fold(0.0f64, f64::max);
        let v = kinematic_violation(&l.map, &l.mechanism, 0.0);
        prop_assert!(
            v <= REL * big,
            "kinematic violation {v} (mechanism size {big})"
        );
        Ok(())
    });
}

// ── (b) scaling ────────────────────────────────────────────────────────────────────────────

fn scale_invariance(case: Case, s: f64) -> Result<(), TestCaseError> {
    let m = case.model();
    let a = limit(&m).result;
    let b = limit(&scaled(&m, s)).result;
    same_limit(&a, &b, size(&m), |p| [p[0] / s, p[1] / s])
}

#[test]
fn lambda_and_hinges_do_not_depend_on_the_scale_1e_2_to_1e2() {
    check(
        "scale 1e-2…1e2",
        2,
        (any_case(), -2.0..2.0f64),
        |(case, e)| scale_invariance(case, 10f64.powf(e)),
    );
}

// Failed before the scale-free numerics of issue 19 item 2 (main at a59f4d2): on 20 random
// cases scale 1e4 changed the status of 7, scale 1e-4 changed 4 and made HiGHS fail on 6, and a
// 4-block stack at 1e-4 did not end (docs/fuzzing.md, "Properties";
// `a_stack_of_tenth_millimetre_blocks_gets_the_answer_of_the_unscaled_stack` below).
#[test]
fn lambda_and_hinges_do_not_depend_on_the_scale_1e_4_and_1e4() {
    check(
        "scale 1e-4, 1e4",
        3,
        (any_case(), prop_oneof![Just(-4.0), Just(4.0)]),
        |(case, e)| scale_invariance(case, 10f64.powf(e)),
    );
}

/// The case found by the extreme-scale property: a 4-block stack scaled by 1e-4 (blocks of
/// 0.1 mm) kept HiGHS's dual simplex in phase 2 for minutes, where the stack at scale 1 takes
/// milliseconds. Both must give the same answer (it cannot stand: its largest multiplier is
/// negative).
#[test]
fn a_stack_of_tenth_millimetre_blocks_gets_the_answer_of_the_unscaled_stack() {
    let read = |name: &str| -> Model {
        let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/property_cases")
            .join(name);
        serde_json::from_str(&std::fs::read_to_string(&p).expect("fixture")).expect("model")
    };
    let small = read("stack_at_1e-4_scale_limit_does_not_end.json");
    let unit = read("stack_at_1e-4_scale_limit_does_not_end.unscaled.json");
    let (a, b) = (limit(&unit).result, limit(&small).result);
    assert_eq!(a.status, LimitStatus::NoEquilibrium, "{}", a.message);
    same_limit(&a, &b, size(&unit), |p| [p[0] * 1e4, p[1] * 1e4]).expect("same result at 1e-4");
}

// ── (c) rigid motion ───────────────────────────────────────────────────────────────────────

/// Cases without edge pressures (which are vertical by definition).
fn movable_case() -> impl Strategy<Value = Case> {
    prop_oneof![
        stack(),
        a_wall(),
        an_arch().prop_map(|c| match c {
            Case::Arch {
                radius,
                ratio,
                voussoirs,
                ..
            } => Case::Arch {
                radius,
                ratio,
                voussoirs,
                q: 0.0,
            },
            c => c,
        })
    ]
}

#[test]
fn self_weight_is_the_dead_body_load_along_minus_y() {
    check("self-weight as a body load", 4, movable_case(), |case| {
        let m = case.model();
        let a = limit(&m).result;
        let b = limit(&gravity_as_body_load(&m)).result;
        same_limit(&a, &b, size(&m), |p| p)
    });
}

#[test]
fn lambda_and_hinges_do_not_change_under_a_rigid_motion_with_gravity_along() {
    check(
        "rigid motion",
        5,
        (
            movable_case(),
            -std::f64::consts::PI..std::f64::consts::PI,
            -100.0..100.0f64,
            -100.0..100.0f64,
        ),
        |(case, alpha, tx, ty)| {
            let m = case.model();
            let r = Rigid { alpha, t: [tx, ty] };
            let a = limit(&m).result;
            let b = limit(&moved(&m, r)).result;
            same_limit(&a, &b, size(&m), |p| r.inverse(p))
        },
    );
}

// ── (d) renumbering ────────────────────────────────────────────────────────────────────────

#[test]
fn lambda_and_hinges_do_not_change_when_the_blocks_are_renumbered() {
    check(
        "renumbering",
        6,
        (any_case(), prop::collection::vec(any::<u32>(), 16)),
        |(case, keys)| {
            let m = case.model();
            let perm = permutation(m.blocks.len(), &keys);
            let a = limit(&m).result;
            let b = limit(&renumbered(&m, &perm)).result;
            same_limit(&a, &b, size(&m), |p| p)
        },
    );
}

// ── (e) settlement is linear in the support motion ─────────────────────────────────────────

/// Walls and arches (several supports) with a motion `[u, v, θ]` of one support (`u = 0` for
/// walls).
fn settlement_case() -> impl Strategy<Value = (Case, usize, [f64; 3])> {
    (
        prop_oneof![a_wall(), an_arch()],
        any::<usize>(),
        -1.0..1.0f64,
        -1.0..1.0f64,
        -1.0..1.0f64,
    )
        .prop_map(|(c, k, u, v, th)| {
            // A wall's bricks do not slide: a horizontal shift of one foundation segment
            // under a wall is mostly incompatible; walls get settlements and rotations.
            let u = if matches!(c, Case::Wall { .. }) {
                0.0
            } else {
                u
            };
            (c, k, [0.01 * u, 0.01 * v, 0.005 * th])
        })
}

#[test]
fn settlement_work_and_mechanism_scale_with_the_support_motion() {
    check(
        "settlement linearity",
        7,
        (
            settlement_case(),
            prop_oneof![Just(1e-3), Just(0.5), Just(1e3)],
        ),
        |((case, k, motion), factor)| {
            let mut m = case.model();
            let i = k % m.supports.len();
            m.supports[i].motion = motion;
            let a = settle(&structure(&m), &solver()).expect("settle solves");
            m.supports[i].motion = motion.map(|x| x * factor);
            let b = settle(&structure(&m), &solver()).expect("settle solves");
            prop_assert_eq!(a.status, b.status, "{} | {}", a.message, b.message);
            if a.status != SettlementStatus::Mechanism {
                return Ok(());
            }
            let (wa, wb) = (a.work_dead_loads.unwrap(), b.work_dead_loads.unwrap());
            let floor = 1e-9 * m.blocks.len() as f64;
            prop_assert!(
                close(wa * factor, wb, floor * factor),
                "work {wa} × {factor} vs {wb}"
            );
            prop_assert!(
                a.certificate.as_ref().is_some_and(|c| c.ok)
                    && b.certificate.as_ref().is_some_and(|c| c.ok),
                "certificates {:?} {:?}",
                a.certificate,
                b.certificate
            );
            // Block motions scale (u, v, θ), within REL of the largest.
            let flat = |r: &voussoir::analysis::SettlementResult| -> Vec<f64> {
                r.blocks
                    .iter()
                    .flat_map(|b| [b.motion.u, b.motion.v, b.motion.theta * size(&m)])
                    .collect()
            };
            let (da, db) = (flat(&a), flat(&b));
            let big = da.iter().fold(0.0f64, |x, y| x.max(y.abs()));
            for (x, y) in da.iter().zip(&db) {
                prop_assert!(
                    (x * factor - y).abs() <= REL * big * factor,
                    "block motions {da:?} × {factor} vs {db:?}"
                );
            }
            Ok(())
        },
    );
}

// ── (f) limit, settle and safety agree on standing────────────────────────────────────────────

#[test]
fn limit_settle_and_safety_agree_on_whether_the_structure_stands() {
    check("limit/settle/safety agree", 8, any_case(), |case| {
        let m = case.model();
        let st = structure(&m);
        let l = limit(&m).result;
        let s = settle(&st, &solver()).expect("settle solves");
        let limit_stands = l.status != LimitStatus::NoEquilibrium;
        let settle_stands = s.status != SettlementStatus::CannotStand;
        let safety_stands = voussoir::analysis::safety::stands(&st, &solver()).expect("stands");
        prop_assert_eq!(
            limit_stands,
            safety_stands,
            "limit: {} | safety: stands = {}",
            l.message,
            safety_stands
        );
        prop_assert_eq!(
            limit_stands,
            settle_stands,
            "limit: {} | settle without motion: {}",
            l.message,
            s.message
        );
        Ok(())
    });
}
