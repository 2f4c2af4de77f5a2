//! The parts every report shares, 2D and 3D (issue 32, "a report to sign"): the hypotheses and
//! joint laws in force, the echo of the inputs (geometry, materials, loads, supports and their
//! motions, solver, tolerances, certificate), the crack and reaction tables, the title block and
//! the sign-off lines, and the print stylesheet (A4, no interactive controls).
//!
//! What the result holds (geometry, loads, support motions, solver, certificate) is read from
//! it; what only the model and the command know (materials, the joint laws of every joint, the
//! friction cone, the crushing model, tolerances) comes in [`ReportInputs`], filled by the
//! command line. A report made without it says that the joint laws were not recorded.
//!
//! Deterministic: no clock is read. The date and the signatures are blank lines to fill in on
//! the printed page.

use crate::draw::report::Section;
use crate::draw::svg::{esc, human};
use crate::result3d::{self, polygon_order, tangents, V3};
use voussoir::dim::{Three, Two};
use voussoir::lp::SolverInfo;
use voussoir::result::spatial::SpatialShapes;
use voussoir::result::FrictionIteration;
use voussoir::result::{BodyName, Geometry, JointResult, JointState};

/// A material as the model gives it (after `--friction` / `--compressive-strength`).
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialRow {
    pub name: String,
    /// Blocks made of it.
    pub blocks: usize,
    /// γ, kN/m³.
    pub unit_weight: f64,
    /// Out-of-plane width, m (2D only).
    pub width: Option<f64>,
    /// f_c, kPa (`None`: infinite).
    pub compressive_strength: Option<f64>,
    /// μ (`None`: no sliding).
    pub friction: Option<f64>,
    /// c, kPa.
    pub cohesion: f64,
    /// Not defined by the model: voussoir's built-in default.
    pub built_in: bool,
}

/// The friction cone of a 3D joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionCone {
    /// The pyramid of this many facets inscribed in the cone (an LP).
    Pyramid(usize),
    /// The exact cone (a second-order cone program).
    Exact,
}

/// The crushing model where a compressive strength is given (2D).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CrushingModel {
    /// Inscribed polygon of the crushing domain with this many chords (an LP).
    Linear(usize),
    /// The exact crushing cone (a second-order cone program).
    Conic,
}

/// The joint laws in force, counted over the structure's joints.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JointLaws {
    pub joints: usize,
    /// Distinct friction coefficients μ with the number of joints having each.
    pub friction: Vec<(f64, usize)>,
    /// Joints without friction coefficient: no sliding.
    pub no_sliding: usize,
    /// Distinct compressive strengths f_c (kPa) with their joint counts.
    pub strength: Vec<(f64, usize)>,
    /// Joints tied to a `fixed` support (bilateral: they carry tension).
    pub bilateral: usize,
}

impl JointLaws {
    /// Count the laws of joints given as (μ, f_c, bilateral).
    pub fn count(laws: impl IntoIterator<Item = (Option<f64>, Option<f64>, bool)>) -> JointLaws {
        let mut j = JointLaws::default();
        let add = |v: &mut Vec<(f64, usize)>, x: f64| match v.iter_mut().find(|(y, _)| *y == x) {
            Some(e) => e.1 += 1,
            None => v.push((x, 1)),
        };
        for (mu, fc, bilateral) in laws {
            j.joints += 1;
            match mu {
                Some(m) => add(&mut j.friction, m),
                None => j.no_sliding += 1,
            }
            if let Some(f) = fc {
                add(&mut j.strength, f);
            }
            if bilateral {
                j.bilateral += 1;
            }
        }
        j.friction.sort_by(|a, b| a.0.total_cmp(&b.0));
        j.strength.sort_by(|a, b| a.0.total_cmp(&b.0));
        j
    }
}

/// What the model and the command contribute to a report beyond the result.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ReportInputs {
    /// The analysis as run (`settle`, `limit`, …).
    pub command: String,
    pub materials: Vec<MaterialRow>,
    pub laws: JointLaws,
    /// 3D: the friction cone (where friction is given).
    pub cone: Option<FrictionCone>,
    /// 2D: the crushing model (where a compressive strength is given).
    pub crushing: Option<CrushingModel>,
    /// Non-associative friction (sliding without dilatancy).
    pub non_associative: bool,
    /// Tolerances set by the model or the command (name, value with its meaning).
    pub tolerances: Vec<(String, String)>,
    /// Other settings of the command, as given (name, value with unit).
    pub settings: Vec<(String, String)>,
    /// The model as the command built it, for results that carry no geometry (`safety`, a
    /// sweep's records): what the inputs section echoes.
    pub model: Option<ModelEcho>,
    /// `identify`: the kind of length of each unknown (a motion in cm, a rotation in mrad).
    pub unknown_lengths: Vec<voussoir::lengths::Length>,
}

/// What kind of analysis a report is about.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Analysis {
    /// A limit analysis: live loads × λ (`Some(λ)` at collapse).
    Limit(Option<f64>),
    /// A settlement: dead loads only, prescribed support motions.
    Settlement,
    /// Capacity after settlement: limit analyses on the geometry deformed by a settlement.
    Capacity,
    /// Safety assessment: statically admissible states under the dead loads (lower bound).
    Safety,
    /// Incremental (finite-displacement) analysis: λ along the path of a control point.
    Incremental,
    /// Inverse settlement analysis: the support motions that reproduce observed cracks.
    Identify,
    /// A sweep of settlements, each followed by the capacity analysis.
    Sweep,
}

/// A support as echoed: its name, whether it is fixed, and its prescribed motion
/// (2D `[u, v, θ]`, 3D `[u, v, w, θx, θy, θz]`; m and rad).
#[derive(Clone, Debug, PartialEq)]
pub struct SupportEcho {
    pub name: String,
    pub fixed: bool,
    pub motion: Vec<f64>,
}

/// The geometry and loads a result carries, in either dimension.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelEcho {
    /// 2 or 3.
    pub dim: usize,
    pub blocks: usize,
    pub joints: usize,
    /// Bounding box of blocks and supports (m).
    pub lo: Vec<f64>,
    pub hi: Vec<f64>,
    /// Dead and live loads: count and resultant (kN).
    pub dead: (usize, Vec<f64>),
    pub live: (usize, Vec<f64>),
    pub supports: Vec<SupportEcho>,
}

impl ModelEcho {
    pub fn of_2d(g: &Geometry, joints: usize) -> ModelEcho {
        let pts = g
            .blocks
            .iter()
            .flatten()
            .chain(g.supports.iter().flat_map(|s| s.polygon.iter()))
            .map(|p| p.to_vec());
        let loads = g.loads.iter().map(|l| (l.live, vec![l.fx, l.fy]));
        let supports = g.supports.iter().map(|s| (&s.name, s.fixed, &s.motion[..]));
        ModelEcho::new(2, g.blocks.len(), joints, pts, loads, supports)
    }

    pub fn of_3d(g: &SpatialShapes, joints: usize) -> ModelEcho {
        let pts = g
            .blocks
            .iter()
            .flat_map(|b| b.vertices.iter())
            .chain(g.supports.iter().flat_map(|s| s.vertices.iter()))
            .map(|p| p.to_vec());
        let loads = g.loads.iter().map(|l| (l.live, vec![l.fx, l.fy, l.fz]));
        let supports = g.supports.iter().map(|s| (&s.name, s.fixed, &s.motion[..]));
        ModelEcho::new(3, g.blocks.len(), joints, pts, loads, supports)
    }

    /// The echo of either dimension: the points of the blocks and supports (for the bounding
    /// box), each load as (live, force components), each support as (name, fixed, motion).
    fn new<'a>(
        dim: usize,
        blocks: usize,
        joints: usize,
        pts: impl Iterator<Item = Vec<f64>>,
        loads: impl Iterator<Item = (bool, Vec<f64>)>,
        supports: impl Iterator<Item = (&'a String, bool, &'a [f64])>,
    ) -> ModelEcho {
        let (lo, hi) = bounds(pts, dim);
        let mut dead = (0, vec![0.0; dim]);
        let mut live = (0, vec![0.0; dim]);
        for (is_live, f) in loads {
            let t = if is_live { &mut live } else { &mut dead };
            t.0 += 1;
            for (k, fk) in f.iter().enumerate() {
                t.1[k] += fk;
            }
        }
        ModelEcho {
            dim,
            blocks,
            joints,
            lo,
            hi,
            dead,
            live,
            supports: supports
                .map(|(name, fixed, motion)| SupportEcho {
                    name: name.clone(),
                    fixed,
                    motion: motion.to_vec(),
                })
                .collect(),
        }
    }

    /// The total vertical dead load W (kN, positive downwards): −Σ of the dead loads' vertical
    /// components (y in 2D, z in 3D).
    pub fn total_weight(&self) -> f64 {
        -self.dead.1[self.dim - 1]
    }

    fn axes(&self) -> &'static [&'static str] {
        if self.dim == 2 {
            &["x", "y"]
        } else {
            &["x", "y", "z"]
        }
    }
}

fn bounds(pts: impl Iterator<Item = Vec<f64>>, dim: usize) -> (Vec<f64>, Vec<f64>) {
    let mut lo = vec![f64::INFINITY; dim];
    let mut hi = vec![f64::NEG_INFINITY; dim];
    for p in pts {
        for k in 0..dim {
            if p[k].is_finite() {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    (lo, hi)
}

/// A tolerance as written in the docs: `1e-7`, `2.5e-8`.
pub fn sci(x: f64) -> String {
    format!("{x:e}")
}

/// A number with up to `sig` significant digits; round-off below 1e-12 of `scale` is 0.
fn num(x: f64, sig: usize, scale: f64) -> String {
    if x.abs() <= 1e-12 * scale.abs() {
        return "0".into();
    }
    human(x, sig)
}

fn vector(v: &[f64], sig: usize) -> String {
    let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    format!(
        "({})",
        v.iter()
            .map(|&x| num(x, sig, scale))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// The hypotheses of the analysis: Heyman's, and the joint laws actually in force.
pub fn hypotheses(
    echo: &ModelEcho,
    inputs: Option<&ReportInputs>,
    analysis: Analysis,
    iteration: Option<&FrictionIteration>,
) -> Section {
    let mut s = Section {
        heading: "Hypotheses".into(),
        items: Vec::new(),
    };
    let mut h = vec![
        "Rigid blocks: the blocks do not deform; every motion is a relative rigid motion at the joints (Heyman).".to_string(),
        "No tension: a joint transmits compression only and opens (cracks) at no cost.".to_string(),
    ];
    match inputs {
        None => h.push(
            "Joint laws (friction, compressive strength): not recorded with this result; the report written by the analysis command states them.".into(),
        ),
        Some(i) => {
            let l = &i.laws;
            // Sliding.
            if l.friction.is_empty() {
                h.push(format!(
                    "No sliding: no friction coefficient is given, so every joint ({}) resists any shear (infinite friction, Heyman).",
                    l.joints
                ));
            } else {
                let mus: Vec<String> = l
                    .friction
                    .iter()
                    .map(|(m, n)| format!("μ = {} ({})", human(*m, 4), plural(*n, "joint", "joints")))
                    .collect();
                let mut t = format!("Coulomb friction: {}", mus.join(", "));
                if l.no_sliding > 0 {
                    t.push_str(&format!(
                        "; no sliding at {} without a friction coefficient",
                        plural(l.no_sliding, "joint", "joints")
                    ));
                }
                t.push_str(if analysis == Analysis::Safety {
                    ". The contact forces stay within the friction cone (|V| ≤ μ N); the static theorem holds for associative friction, so with real joints that slide without dilatancy an admissible state proves less (Drucker)"
                } else if i.non_associative {
                    ". Non-associative: joints slide without opening (no dilatancy), solved by the fixed-point iteration on the normal forces"
                } else {
                    ". Associative (normality): sliding comes with an opening of μ times the slip (dilatancy), the rule of limit analysis"
                });
                if i.non_associative {
                    if let Some(it) = iteration {
                        t.push_str(&format!(
                            " ({} after {})",
                            if it.converged { "converged" } else { "NOT converged" },
                            plural(it.history.len(), "iteration", "iterations")
                        ));
                    }
                }
                t.push('.');
                if echo.dim == 3 {
                    t.push_str(&match i.cone {
                        Some(FrictionCone::Exact) => {
                            " Friction cone: the exact circular cone (second-order cone program).".to_string()
                        }
                        Some(FrictionCone::Pyramid(k)) => format!(
                            " Friction cone: the pyramid of {k} facets inscribed in the cone (linear program; the sliding resistance is between μ·cos(π/{k}) = {} μ and μ, on the safe side).",
                            human((std::f64::consts::PI / k as f64).cos(), 4)
                        ),
                        None => String::new(),
                    });
                }
                h.push(t);
            }
            let cohesive: Vec<String> = i
                .materials
                .iter()
                .filter(|m| m.cohesion > 0.0 && m.blocks > 0)
                .map(|m| format!("c = {} kPa ({})", human(m.cohesion, 4), m.name))
                .collect();
            if !cohesive.is_empty() {
                h.push(format!(
                    "Cohesion (shear resistance at zero compression): {}.",
                    cohesive.join(", ")
                ));
            }
            // Compression.
            if l.strength.is_empty() {
                h.push("Infinite compressive strength: no crushing (Heyman).".into());
            } else {
                let fc: Vec<String> = l
                    .strength
                    .iter()
                    .map(|(f, n)| {
                        format!(
                            "f_c = {} kPa ({})",
                            human(*f, 4),
                            plural(*n, "joint", "joints")
                        )
                    })
                    .collect();
                let model = match i.crushing {
                    Some(CrushingModel::Linear(k)) => format!(
                        "; crushing domain: the inscribed polygon of {k} chords (linear program, slightly safe)"
                    ),
                    Some(CrushingModel::Conic) => {
                        "; crushing domain: the exact cone (second-order cone program)".into()
                    }
                    None => String::new(),
                };
                h.push(format!(
                    "Finite compressive strength: {}{model}.",
                    fc.join(", ")
                ));
            }
            if l.bilateral > 0 {
                let fixed: Vec<&str> = echo
                    .supports
                    .iter()
                    .filter(|s| s.fixed)
                    .map(|s| s.name.as_str())
                    .collect();
                h.push(format!(
                    "Fixed supports ({}): their {} are bilateral (they carry tension and do not open).",
                    fixed.join(", "),
                    plural(l.bilateral, "joint", "joints")
                ));
            }
        }
    }
    h.push(match analysis {
        Analysis::Limit(_) => "Small displacements: the collapse mechanism is a rate, found on the undeformed geometry; the dead loads are constant and the live loads grow with the load multiplier λ until collapse.".into(),
        Analysis::Capacity => "The settlement deforms the geometry: its mechanism (found as by a settlement analysis, under the dead loads alone) is applied as a finite rigid motion of every block, opening its cracks; at each step a limit analysis of the deformed geometry gives λ (standard limit analysis, valid while the collapse mechanism does not close settlement cracks: the report marks the steps where it would).".into(),
        Analysis::Settlement => "Small displacements: the mechanism that accommodates the prescribed support motions is found on the undeformed geometry, under the dead loads alone (no live load, no λ); it is the one of least work of the dead loads (minimum potential energy).".into(),
        Analysis::Safety => "Static (lower-bound, safe) theorem: the structure stands if one set of contact forces balances the dead loads and respects the joint laws above; no mechanism is computed and the live loads are not applied. The geometric safety factor shrinks every joint about its centre by one common fraction and finds, by bisection, the least fraction that still carries the dead loads; the reaction ranges are the extreme values of each support reaction over all such states.".into(),
        Analysis::Incremental => "Finite displacements: the live loads grow with λ while a control point is pushed step by step; at each step a limit analysis of the current (moved) geometry gives λ and the mechanism, so hinges may open and close and λ may fall (path following; the dead loads are constant).".into(),
        Analysis::Identify => "Inverse settlement analysis: the unknown support motions are those whose settlement mechanism (small displacements, dead loads only, least work, as `settle`) best reproduces the observed crack widths, with the other joint points closed (least total misfit, each width within its tolerance where possible).".into(),
        Analysis::Sweep => "Each analysis of the sweep is a settlement (small displacements, dead loads only, least work) followed, with --capacity, by limit analyses of the geometry deformed by it (as `capacity`); the records differ only in the support motions.".into(),
    });
    s.items.push(crate::draw::report::Item::List(h));
    s
}

/// The inputs: geometry, materials, loads, supports and their motions, solver, tolerances and
/// certificate (`certificate`: rows made by the caller from the result).
pub fn inputs(
    echo: &ModelEcho,
    inputs: Option<&ReportInputs>,
    analysis: Analysis,
    source: &str,
    solver: Option<&SolverInfo>,
    certificate: Vec<(String, String)>,
) -> Section {
    use crate::draw::report::Item;
    let mut s = Section {
        heading: "Inputs".into(),
        items: Vec::new(),
    };
    let ax = echo.axes();
    // Geometry.
    s.items.push(Item::Heading("Geometry".into()));
    let mut kv = Vec::new();
    if !source.is_empty() {
        kv.push(("model file".to_string(), source.to_string()));
    }
    if let Some(i) = inputs {
        if !i.command.is_empty() {
            kv.push(("analysis".into(), i.command.clone()));
        }
    }
    // A result without joint results (capacity) counts its joints from the joint laws.
    let joints = match (echo.joints, inputs) {
        (0, Some(i)) => i.laws.joints,
        (n, _) => n,
    };
    kv.push((
        "size".into(),
        if joints > 0 {
            format!(
                "{}, {}, {} ({}D)",
                plural(echo.blocks, "block", "blocks"),
                plural(joints, "joint", "joints"),
                plural(echo.supports.len(), "support", "supports"),
                echo.dim
            )
        } else {
            format!(
                "{}, {} ({}D)",
                plural(echo.blocks, "block", "blocks"),
                plural(echo.supports.len(), "support", "supports"),
                echo.dim
            )
        },
    ));
    if echo.lo.iter().all(|x| x.is_finite()) {
        let sizes: Vec<String> = (0..echo.dim)
            .map(|k| format!("{} m", human(echo.hi[k] - echo.lo[k], 5)))
            .collect();
        let ranges: Vec<String> = (0..echo.dim)
            .map(|k| {
                format!(
                    "{} {} … {}",
                    ax[k],
                    human(echo.lo[k], 5),
                    human(echo.hi[k], 5)
                )
            })
            .collect();
        kv.push((
            "extent".into(),
            format!("{} ({} m)", sizes.join(" × "), ranges.join(", ")),
        ));
    }
    kv.push((
        "total weight W (vertical dead load)".into(),
        format!("{} kN", human(echo.total_weight(), 7)),
    ));
    s.items.push(Item::KeyValues(kv));

    // Materials.
    s.items.push(Item::Heading("Materials".into()));
    match inputs {
        Some(i) if !i.materials.is_empty() => {
            let mut head = vec!["material", "blocks", "unit weight γ (kN/m³)"];
            if echo.dim == 2 {
                head.push("width (m)");
            }
            head.extend([
                "compressive strength f_c (kPa)",
                "friction μ (–)",
                "cohesion c (kPa)",
            ]);
            let rows = i
                .materials
                .iter()
                .map(|m| {
                    let mut r = vec![
                        if m.built_in {
                            format!("{} (built-in)", m.name)
                        } else {
                            m.name.clone()
                        },
                        m.blocks.to_string(),
                        human(m.unit_weight, 6),
                    ];
                    if echo.dim == 2 {
                        r.push(human(m.width.unwrap_or(1.0), 6));
                    }
                    r.push(
                        m.compressive_strength
                            .map(|f| human(f, 6))
                            .unwrap_or_else(|| "∞ (not given)".into()),
                    );
                    r.push(
                        m.friction
                            .map(|f| human(f, 6))
                            .unwrap_or_else(|| "∞ (no sliding)".into()),
                    );
                    r.push(human(m.cohesion, 6));
                    r
                })
                .collect();
            s.items.push(Item::table(
                "",
                head.iter().map(|h| h.to_string()).collect(),
                rows,
            ));
        }
        _ => s.items.push(Item::Text(
            "Not recorded with this result (the weights are in the loads below).".into(),
        )),
    }

    // Loads.
    s.items.push(Item::Heading("Loads".into()));
    let unit = |v: &[f64]| format!("{} kN", vector(v, 6));
    let mut kv = vec![(
        "dead loads (self-weight and given dead loads)".to_string(),
        format!(
            "{}, resultant {}",
            plural(echo.dead.0, "force", "forces"),
            unit(&echo.dead.1)
        ),
    )];
    let live = if echo.live.0 == 0 {
        "none".to_string()
    } else {
        format!(
            "{}, resultant {}",
            plural(echo.live.0, "force", "forces"),
            unit(&echo.live.1)
        )
    };
    match analysis {
        Analysis::Capacity | Analysis::Incremental | Analysis::Sweep => {
            kv.push(("live loads (multiplied by λ)".into(), live))
        }
        Analysis::Safety | Analysis::Identify => kv.push((
            "live loads".into(),
            if echo.live.0 == 0 {
                live
            } else {
                format!("{live}; not applied (dead loads only)")
            },
        )),
        Analysis::Limit(l) => {
            kv.push(("live loads (multiplied by λ)".into(), live));
            if let (Some(l), true) = (l, echo.live.0 > 0) {
                let f: Vec<f64> = echo.live.1.iter().map(|x| x * l).collect();
                kv.push((
                    "live loads at collapse (× λ)".into(),
                    format!("λ = {}: resultant {}", human(l, 6), unit(&f)),
                ));
            }
        }
        Analysis::Settlement => kv.push((
            "live loads".into(),
            if echo.live.0 == 0 {
                live
            } else {
                format!("{live}; not applied (a settlement analysis has no λ)")
            },
        )),
    }
    s.items.push(Item::KeyValues(kv));

    // Supports and their motions.
    s.items
        .push(Item::Heading("Supports and prescribed motions".into()));
    let (t_names, r_names): (&[&str], &[&str]) = if echo.dim == 2 {
        (&["u", "v"], &["θ"])
    } else {
        (&["u", "v", "w"], &["θx", "θy", "θz"])
    };
    let mut head = vec!["support".to_string(), "connection".to_string()];
    head.extend(t_names.iter().map(|n| format!("{n} (mm)")));
    head.extend(r_names.iter().map(|n| format!("{n} (°)")));
    let rows = echo
        .supports
        .iter()
        .map(|sp| {
            let mut r = vec![
                sp.name.clone(),
                if sp.fixed { "fixed" } else { "contact" }.to_string(),
            ];
            let n = t_names.len();
            r.extend(sp.motion[..n].iter().map(|x| human(x * 1000.0, 6)));
            r.extend(sp.motion[n..].iter().map(|x| human(x.to_degrees(), 6)));
            r
        })
        .collect();
    s.items.push(Item::table("", head, rows));
    s.items.push(Item::Text(if echo.dim == 2 {
        "Prescribed motion of each support's centroid: u along x, v along y (up), in mm; θ about the centroid, in degrees counter-clockwise.".to_string()
    } else {
        "Prescribed motion of each support's centroid: u, v, w along x, y, z (z up), in mm; rotations θx, θy, θz about axes through the centroid, in degrees, right-handed.".to_string()
    }));
    if let Some(i) = inputs {
        if !i.settings.is_empty() {
            s.items
                .push(Item::Heading("Settings of the analysis".into()));
            s.items.push(Item::KeyValues(i.settings.clone()));
        }
    }

    // Solver, tolerances, certificate.
    s.items
        .push(Item::Heading("Solver, tolerances and certificate".into()));
    let mut kv = Vec::new();
    if let Some(si) = solver {
        kv.push((
            "solver".to_string(),
            format!("{} ({})", si.solver, si.method.name()),
        ));
        kv.push((
            "fallback".to_string(),
            si.fallback_note()
                .unwrap_or_else(|| "none: the requested method answered".into()),
        ));
    }
    if let Some(i) = inputs {
        kv.extend(i.tolerances.iter().cloned());
    }
    kv.extend(fixed_tolerances(analysis));
    kv.extend(certificate);
    s.items.push(Item::KeyValues(kv));
    s
}

/// The front matter of a report, Hypotheses then Inputs. The model echoed: `inputs.model` (as
/// the command built it), else `echo` (from the result); without either the
/// inputs section says they were not recorded (a report made from a saved result file).
pub fn front_matter(
    echo: Option<&ModelEcho>,
    inputs: Option<&ReportInputs>,
    analysis: Analysis,
    source: &str,
    solver: Option<&SolverInfo>,
    certificate: Vec<(String, String)>,
) -> Vec<Section> {
    // The model as the command built it (with the settlement it applied) comes first.
    let echo = inputs.and_then(|i| i.model.as_ref()).or(echo);
    match echo {
        Some(e) => vec![
            hypotheses(e, inputs, analysis, None),
            self::inputs(e, inputs, analysis, source, solver, certificate),
        ],
        None => {
            let empty = ModelEcho {
                dim: 2,
                blocks: 0,
                joints: 0,
                lo: vec![f64::NAN; 2],
                hi: vec![f64::NAN; 2],
                dead: (0, vec![0.0; 2]),
                live: (0, vec![0.0; 2]),
                supports: Vec::new(),
            };
            let mut s = Section {
                heading: "Inputs".into(),
                items: Vec::new(),
            };
            let mut kv = Vec::new();
            if !source.is_empty() {
                kv.push(("model file".to_string(), source.to_string()));
            }
            if let Some(si) = solver {
                kv.push((
                    "solver".to_string(),
                    format!("{} ({})", si.solver, si.method.name()),
                ));
            }
            kv.extend(certificate);
            s.items.push(crate::draw::report::Item::Text(
                "The model (geometry, materials, loads, supports) is not recorded with this result: the report written by the analysis command (--report) echoes it.".into(),
            ));
            if !kv.is_empty() {
                s.items.push(crate::draw::report::Item::KeyValues(kv));
            }
            vec![hypotheses(&empty, None, analysis, None), s]
        }
    }
}

/// The tolerances every analysis applies (docs/tolerances.md; `voussoir::scale`).
fn fixed_tolerances(analysis: Analysis) -> Vec<(String, String)> {
    use voussoir::scale::{LAMBDA_ZERO, OPEN_TOLERANCE, WORK_FLOOR};
    let mut kv = vec![(
        "open / sliding".to_string(),
        format!(
            "a point opens or slides when its relative motion exceeds {} × the motion scale (the largest displacement of a contact point)",
            sci(OPEN_TOLERANCE)
        ),
    )];
    match analysis {
        Analysis::Safety => {
            kv.clear();
            kv.push((
                "stands".to_string(),
                "an equilibrium state is found when the solver reports the program feasible (its feasibility tolerance above)".to_string(),
            ));
        }
        Analysis::Settlement | Analysis::Identify | Analysis::Sweep => kv.push((
            "certified".into(),
            format!(
                "relative duality gap ≤ {} (relative to max(|primal|, |dual|, {} W·u)); mechanism admissible to 1e-6 of the motion scale",
                sci(voussoir::result::GAP_TOLERANCE),
                sci(WORK_FLOOR)
            ),
        )),
        Analysis::Incremental => {}
        Analysis::Limit(_) | Analysis::Capacity => kv.push((
            "certified".into(),
            format!(
                "|λ − λ_kin| ≤ {} max(|λ|, 1e-3 λ_unit), mechanism admissible to 1e-6; a negative λ within {} λ_unit is 0",
                sci(voussoir::result::CERTIFICATE_TOLERANCE),
                sci(LAMBDA_ZERO)
            ),
        )),
    }
    kv
}

/// One row of the crack table: a joint that is not closed.
#[derive(Clone, Debug, PartialEq)]
pub struct CrackRow {
    pub joint: usize,
    pub a: String,
    pub b: String,
    pub state: &'static str,
    /// Centroid of the opened part of the joint (m).
    pub position: Vec<f64>,
    /// Largest opening (m).
    pub width: f64,
    /// Length of the opened part (m): along the joint in 2D; in 3D along the crack's line (the
    /// direction of constant opening), else the opened part's largest extent.
    pub length: f64,
}

pub fn body_name(b: &BodyName) -> String {
    match b {
        BodyName::Block(i) => format!("block {i}"),
        BodyName::Support(s) => s.clone(),
    }
}

pub fn state_name(s: JointState) -> &'static str {
    match s {
        JointState::Closed => "closed",
        JointState::Hinge => "hinge",
        JointState::Open => "open",
        JointState::Sliding => "sliding",
    }
}

/// The threshold below which an opening is round-off: 1e-7 of the largest opening of all
/// joints (the joints' states are decided on the motion scale, docs/tolerances.md).
fn opening_threshold(openings: impl Iterator<Item = f64>) -> f64 {
    voussoir::scale::OPEN_TOLERANCE * openings.filter(|x| x.is_finite()).fold(0.0, f64::max)
}

/// The crack rows of a 2D result: every joint that is not closed. The opening varies linearly
/// between the joint's points (a relative rigid motion); the opened part is where it exceeds
/// round-off.
pub fn crack_rows_2d(joints: &[JointResult<Two>]) -> Vec<CrackRow> {
    let thr = opening_threshold(
        joints
            .iter()
            .flat_map(|j| j.points.iter().map(|p| p.opening)),
    );
    joints
        .iter()
        .filter(|j| j.state != JointState::Closed)
        .map(|j| {
            let t = [-j.normal[1], j.normal[0]];
            let mut pts: Vec<([f64; 2], f64)> = j
                .points
                .iter()
                .map(|p| {
                    (
                        [p.x, p.y],
                        if p.opening.is_finite() {
                            p.opening
                        } else {
                            0.0
                        },
                    )
                })
                .collect();
            pts.sort_by(|a, b| {
                (a.0[0] * t[0] + a.0[1] * t[1]).total_cmp(&(b.0[0] * t[0] + b.0[1] * t[1]))
            });
            let width = pts.iter().map(|p| p.1).fold(0.0, f64::max);
            let (mut len, mut cx, mut cy) = (0.0, 0.0, 0.0);
            for w in pts.windows(2) {
                let ((p, wp), (q, wq)) = (w[0], w[1]);
                let l = (q[0] - p[0]).hypot(q[1] - p[1]);
                // The part of [p, q] where the opening exceeds the threshold.
                let at = |s: f64| [p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])];
                let (s0, s1) = match (wp > thr, wq > thr) {
                    (true, true) => (0.0, 1.0),
                    (false, false) => continue,
                    (true, false) => (0.0, (wp - thr) / (wp - wq)),
                    (false, true) => ((thr - wp) / (wq - wp), 1.0),
                };
                let (a, b) = (at(s0), at(s1));
                let part = l * (s1 - s0);
                len += part;
                cx += part * (a[0] + b[0]) / 2.0;
                cy += part * (a[1] + b[1]) / 2.0;
            }
            let position = if len > 0.0 {
                vec![cx / len, cy / len]
            } else {
                // Nothing open (a sliding joint, or one point): the joint's middle.
                let n = pts.len().max(1) as f64;
                vec![
                    pts.iter().map(|p| p.0[0]).sum::<f64>() / n,
                    pts.iter().map(|p| p.0[1]).sum::<f64>() / n,
                ]
            };
            CrackRow {
                joint: j.id,
                a: body_name(&j.a),
                b: body_name(&j.b),
                state: state_name(j.state),
                position,
                width,
                length: len,
            }
        })
        .collect()
}

/// The crack rows of a 3D result: every joint that is not closed. The opening is affine over
/// the joint's polygon (a relative rigid motion); the opened part is the polygon clipped where
/// it exceeds round-off, its length measured along the line of constant opening (the hinge
/// line's direction).
pub fn crack_rows_3d(joints: &[JointResult<Three>]) -> Vec<CrackRow> {
    use result3d::{cross, dot, norm, sub};
    let thr = opening_threshold(
        joints
            .iter()
            .flat_map(|j| j.points.iter().map(|p| p.opening)),
    );
    joints
        .iter()
        .filter(|j| j.state != JointState::Closed)
        .map(|j| {
            let n: V3 = [j.normal[0], j.normal[1], j.normal[2]];
            let raw: Vec<V3> = j.points.iter().map(|p| [p.x, p.y, p.z]).collect();
            let order = polygon_order(&raw, n);
            let poly: Vec<(V3, f64)> = order
                .iter()
                .map(|&k| {
                    let w = j.points[k].opening;
                    (raw[k], if w.is_finite() { w } else { 0.0 })
                })
                .collect();
            let width = poly.iter().map(|p| p.1).fold(0.0, f64::max);
            // Clip the polygon to w > thr (Sutherland–Hodgman; exact for an affine w).
            let mut open: Vec<V3> = Vec::new();
            let m = poly.len();
            for k in 0..m {
                let (p, wp) = poly[k];
                let (q, wq) = poly[(k + 1) % m];
                if wp > thr {
                    open.push(p);
                }
                if (wp > thr) != (wq > thr) {
                    let s = (thr - wp) / (wq - wp);
                    open.push([
                        p[0] + s * (q[0] - p[0]),
                        p[1] + s * (q[1] - p[1]),
                        p[2] + s * (q[2] - p[2]),
                    ]);
                }
            }
            // Centroid of the opened polygon (area-weighted fan), or of its points if flat.
            let mean = |v: &[V3]| -> V3 {
                let k = v.len().max(1) as f64;
                let mut c = [0.0; 3];
                for p in v {
                    for i in 0..3 {
                        c[i] += p[i] / k;
                    }
                }
                c
            };
            let position = if open.len() >= 3 {
                let o = open[0];
                let (mut area, mut c) = (0.0, [0.0; 3]);
                for k in 1..open.len() - 1 {
                    let a = norm(cross(sub(open[k], o), sub(open[k + 1], o))) / 2.0;
                    area += a;
                    for i in 0..3 {
                        c[i] += a * (o[i] + open[k][i] + open[k + 1][i]) / 3.0;
                    }
                }
                if area > 0.0 {
                    c.map(|x| x / area)
                } else {
                    mean(&open)
                }
            } else if open.is_empty() {
                mean(&poly.iter().map(|p| p.0).collect::<Vec<_>>())
            } else {
                mean(&open)
            };
            // The opening's gradient in the joint's plane (least squares in the tangents).
            let (t1, t2) = tangents(n);
            let grad = {
                let (mut a, mut r) = ([[0.0; 3]; 3], [0.0; 3]);
                for (p, w) in &poly {
                    let row = [1.0, dot(*p, t1), dot(*p, t2)];
                    for i in 0..3 {
                        r[i] += row[i] * w;
                        for k in 0..3 {
                            a[i][k] += row[i] * row[k];
                        }
                    }
                }
                solve3(a, r).map(|x| [x[1], x[2]])
            };
            let extent = |d: V3| -> f64 {
                let s = open.iter().map(|p| dot(*p, d));
                let (lo, hi) = s.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                    (l.min(x), h.max(x))
                });
                if hi >= lo {
                    hi - lo
                } else {
                    0.0
                }
            };
            let length = match grad {
                Some(g) if g[0].hypot(g[1]) * diameter(&open) > thr.max(1e-300) => {
                    // Along the lines of constant opening: perpendicular to the gradient.
                    let gd = [
                        g[0] * t1[0] + g[1] * t2[0],
                        g[0] * t1[1] + g[1] * t2[1],
                        g[0] * t1[2] + g[1] * t2[2],
                    ];
                    let d = cross(n, gd);
                    let l = norm(d);
                    extent([d[0] / l, d[1] / l, d[2] / l])
                }
                _ => diameter(&open),
            };
            CrackRow {
                joint: j.id,
                a: body_name(&j.a),
                b: body_name(&j.b),
                state: state_name(j.state),
                position: position.to_vec(),
                width,
                length: if open.len() < 2 { 0.0 } else { length },
            }
        })
        .collect()
}

fn diameter(v: &[V3]) -> f64 {
    let mut d = 0.0f64;
    for (i, p) in v.iter().enumerate() {
        for q in &v[i + 1..] {
            d = d.max(result3d::norm(result3d::sub(*p, *q)));
        }
    }
    d
}

/// Solve a 3 × 3 system by Cramer's rule; `None` when singular.
fn solve3(a: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    let scale = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if d.is_nan() || d.abs() <= 1e-12 * scale.powi(3) {
        return None;
    }
    let mut x = [0.0; 3];
    for k in 0..3 {
        let mut m = a;
        for i in 0..3 {
            m[i][k] = r[i];
        }
        x[k] = det(m) / d;
    }
    Some(x)
}

/// The cracks as the summary and the drawings show them (polylines through consecutive open
/// joints in 2D, connected coplanar cracked joints in 3D), widest first, one row each with the
/// summary's own words: the report, the terminal and the JSON's `cracks` tell the same story.
/// `widths`: a settlement's widths in mm; otherwise openings relative to the largest.
pub fn crack_polyline_table<C: voussoir::result::CrackText>(
    cracks: &[C],
    widths: bool,
) -> (Vec<String>, Vec<Vec<String>>) {
    let largest = cracks.iter().fold(0.0f64, |m, c| m.max(c.max_opening()));
    let head = vec!["crack".to_string(), "description".to_string()];
    let rows = cracks
        .iter()
        .enumerate()
        .map(|(i, c)| vec![(i + 1).to_string(), c.describe(widths, largest)])
        .collect();
    (head, rows)
}

/// The caption of [`crack_polyline_table`].
pub const CRACK_POLYLINES_CAPTION: &str =
    "Cracks, widest first, as in the summary and the drawings (the result's \"cracks\")";

/// The crack table's header and rows: position in m, width and length in mm.
pub fn crack_table(rows: &[CrackRow], dim: usize) -> (Vec<String>, Vec<Vec<String>>) {
    let mut head = vec![
        "joint".to_string(),
        "between".to_string(),
        "state".to_string(),
    ];
    head.extend(
        ["x (m)", "y (m)", "z (m)"][..dim]
            .iter()
            .map(|s| s.to_string()),
    );
    head.push("width (mm)".into());
    head.push("length (mm)".into());
    let body = rows
        .iter()
        .map(|c| {
            let mut r = vec![
                c.joint.to_string(),
                format!("{} | {}", c.a, c.b),
                c.state.to_string(),
            ];
            let scale = c.position.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            r.extend(c.position.iter().map(|&x| num(x, 5, scale.max(1e-300))));
            r.push(human(c.width * 1000.0, 4));
            r.push(human(c.length * 1000.0, 4));
            r
        })
        .collect();
    (head, body)
}

/// A support's reaction: its name, force (kN), moment (kN·m) and the point it is about (m).
pub type ReactionRow = (String, Vec<f64>, Vec<f64>, Vec<f64>);

/// The reactions table: force (kN) and moment (kN·m) of each support on the structure, about
/// the point given (m), and a last row with the total force. `rows`: (support, force, moment,
/// about).
pub fn reaction_table(
    rows: &[ReactionRow],
    dim: usize,
) -> (Vec<String>, Vec<Vec<String>>, Vec<Vec<String>>) {
    let (f, m, c): (&[&str], &[&str], &[&str]) = if dim == 2 {
        (&["Fx", "Fy"], &["M"], &["x", "y"])
    } else {
        (&["Fx", "Fy", "Fz"], &["Mx", "My", "Mz"], &["x", "y", "z"])
    };
    let mut head = vec!["support".to_string()];
    head.extend(f.iter().map(|n| format!("{n} (kN)")));
    head.extend(m.iter().map(|n| format!("{n} (kN·m)")));
    head.push(format!("M about ({}) (m)", c.join(", ")));
    let scale = rows
        .iter()
        .flat_map(|r| r.1.iter())
        .fold(0.0f64, |s, x| s.max(x.abs()));
    let body = rows
        .iter()
        .map(|(name, force, moment, about)| {
            let mut r = vec![name.clone()];
            r.extend(force.iter().map(|&x| num(x, 7, scale)));
            r.extend(moment.iter().map(|&x| num(x, 5, scale)));
            r.push(vector(about, 5));
            r
        })
        .collect();
    let mut total = vec!["total".to_string()];
    for k in 0..dim {
        let s: f64 = rows.iter().map(|r| r.1[k]).sum();
        total.push(num(s, 7, scale));
    }
    total.extend(m.iter().map(|_| "—".to_string()));
    total.push(String::new());
    (head, body, vec![total])
}

/// The title block under the title: model, analysis, program; the date and checker to fill in.
pub fn title_block(source: &str, command: &str) -> String {
    let mut o = String::from("<table class=\"titleblock\">\n<tr>");
    o.push_str(&format!(
        "<th>model</th><td>{}</td><th>date</th><td class=\"blank\"></td></tr>\n<tr>",
        if source.is_empty() {
            "—".to_string()
        } else {
            esc(source)
        }
    ));
    o.push_str(&format!(
        "<th>analysis</th><td>{}</td><th>checked by</th><td class=\"blank\"></td></tr>\n<tr>",
        if command.is_empty() {
            "—".to_string()
        } else {
            esc(command)
        }
    ));
    o.push_str(&format!(
        "<th>program</th><td>voussoir {}</td><th>signature</th><td class=\"blank\"></td></tr>\n</table>\n",
        env!("CARGO_PKG_VERSION")
    ));
    o
}

/// The sign-off lines at the end of the report.
pub fn sign_off() -> &'static str {
    "<section class=\"signoff\">\n<h2>Sign-off</h2>\n<table class=\"sign\">\n\
     <tr><th>prepared by</th><td class=\"blank\"></td><th>date</th><td class=\"blank\"></td></tr>\n\
     <tr><th>checked by</th><td class=\"blank\"></td><th>date</th><td class=\"blank\"></td></tr>\n\
     </table>\n<p class=\"note\">The date is left blank on purpose: the file is the same, byte for byte, for the same input, and is dated and signed on paper.</p>\n</section>\n"
}

/// A CSS string literal of `s` (inside `<style>`: `<` is escaped too).
fn css_string(s: &str) -> String {
    let mut o = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => o.push_str("\\22 "),
            '\\' => o.push_str("\\5c "),
            '<' => o.push_str("\\3c "),
            '\n' | '\r' => o.push(' '),
            c => o.push(c),
        }
    }
    o.push('"');
    o
}

/// The stylesheet shared by the reports for the title block, sign-off and print: A4 pages
/// with the title and model in the running footer and page numbers, no interactive controls,
/// tables and figures kept whole where they fit on a page.
pub fn print_css(title: &str, source: &str) -> String {
    let left = if source.is_empty() {
        title.to_string()
    } else {
        format!("{title} — {source}")
    };
    format!(
        r#"table.titleblock{{margin:6px 0 14px;border:1px solid #bbb;font-size:13px;width:100%;table-layout:fixed;box-sizing:border-box}}
table.titleblock th{{width:13%;text-align:left;font-weight:normal;color:#555;padding:3px 8px;border:1px solid #ddd;background:#f7f6f2;white-space:nowrap}}
table.titleblock td{{width:37%;padding:3px 8px;border:1px solid #ddd;overflow-wrap:anywhere}}
table.sign{{margin:10px 0;font-size:14px}}
table.sign th{{text-align:left;font-weight:normal;color:#555;padding:14px 10px 2px 0}}
table.sign td.blank{{border-bottom:1px solid #333;min-width:200px;padding:14px 24px 2px 0}}
ul.hyp{{margin:6px 0;padding-left:22px}}
ul.hyp li{{margin:3px 0}}
p.note{{color:#666;font-size:13px}}
tfoot td{{font-weight:600;background:#faf9f5}}
figure svg,table.grid{{box-sizing:border-box}}
table.kv td{{overflow-wrap:anywhere}}
.print-only{{display:none}}
@page{{size:A4;margin:16mm 14mm 18mm 14mm;@bottom-left{{content:{};font:8pt "DejaVu Sans",Arial,sans-serif;color:#666}}@bottom-right{{content:"page " counter(page) " of " counter(pages);font:8pt "DejaVu Sans",Arial,sans-serif;color:#666}}}}
@media print{{
body{{background:#fff;font-size:10pt}}
main{{max-width:none;margin:0;padding:0;box-shadow:none}}
nav,.slider,.controls,.hint,.viewer,details,button,input,.screen-only,main>footer{{display:none!important}}
.print-only{{display:block}}
h1,h2,h3{{break-after:avoid;page-break-after:avoid;break-inside:avoid;page-break-inside:avoid}}
h2{{margin-top:18px}}
figure,table.kv,table.titleblock,.signoff,tr,ul.hyp li{{break-inside:avoid;page-break-inside:avoid}}
.scroll{{overflow:visible}}
.scroll.keep{{break-inside:avoid;page-break-inside:avoid}}
thead{{display:table-header-group}}
figure svg{{max-height:235mm;width:auto;max-width:100%;margin:0 auto}}
table.grid{{font-size:8.5pt}}
table.grid th,table.grid td{{padding:2px 5px}}
table.kv{{font-size:9.5pt}}
a{{color:inherit;text-decoration:none}}
}}
"#,
        css_string(&left)
    )
}
