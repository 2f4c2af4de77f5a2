//! What a report states beyond the result (issue 32): the materials of the model as analysed
//! (after `--friction` / `--compressive-strength`), the joint laws of every joint of the
//! structure, the friction cone or crushing model, the tolerances and the command's settings.

use crate::common::Input;
use std::collections::BTreeMap;
use voussoir::lp::SolverOptions;
use voussoir::model::Material;
use voussoir::model3d::Model3d;
use voussoir::{Assembly, Model};
use voussoir_io::report_parts::{
    CrushingModel, FrictionCone, JointLaws, MaterialRow, ReportInputs,
};

/// Default relative tolerance of joint detection (docs/tolerances.md, `Model::tolerance`).
const JOINT_TOLERANCE: f64 = 1e-7;

/// The model's materials as used by its blocks, and its own joint-detection tolerance.
#[derive(Clone, Debug, Default)]
pub struct ModelFacts {
    pub materials: Vec<MaterialRow>,
    pub tolerance: Option<f64>,
}

fn material_rows<'a>(
    materials: &BTreeMap<String, Material>,
    names: impl Iterator<Item = Option<&'a str>>,
    planar: bool,
) -> Vec<MaterialRow> {
    let mut count: BTreeMap<String, usize> = BTreeMap::new();
    for n in names {
        *count.entry(n.unwrap_or("default").to_string()).or_default() += 1;
    }
    // Every material the model defines (unused ones with 0 blocks), and a used but undefined
    // "default" as voussoir's built-in one.
    let mut names: Vec<String> = materials.keys().cloned().collect();
    for n in count.keys() {
        if !names.contains(n) {
            names.push(n.clone());
        }
    }
    names
        .into_iter()
        .map(|n| {
            let (m, built_in) = match materials.get(&n) {
                Some(m) => (m.clone(), false),
                None => (Material::default(), true),
            };
            MaterialRow {
                blocks: count.get(&n).copied().unwrap_or(0),
                name: n,
                unit_weight: m.unit_weight,
                width: planar.then_some(m.width),
                compressive_strength: m.compressive_strength,
                friction: m.friction,
                cohesion: m.cohesion,
                built_in,
            }
        })
        .collect()
}

pub fn facts_2d(m: &Model) -> ModelFacts {
    ModelFacts {
        materials: material_rows(
            &m.materials,
            m.blocks.iter().map(|b| b.material.as_deref()),
            true,
        ),
        tolerance: m.tolerance,
    }
}

pub fn facts_3d(m: &Model3d) -> ModelFacts {
    ModelFacts {
        materials: material_rows(
            &m.materials,
            m.blocks.iter().map(|b| b.material.as_deref()),
            false,
        ),
        tolerance: m.tolerance,
    }
}

/// How the joints resist: the friction cone (3D) or the crushing model (2D), and whether
/// friction is non-associative.
#[derive(Clone, Copy, Debug, Default)]
pub struct Laws {
    pub cone: Option<FrictionCone>,
    pub crushing: Option<CrushingModel>,
    pub non_associative: bool,
}

/// The report's inputs of an analysis of `st`.
pub fn report_inputs<S: Assembly>(
    command: &str,
    facts: ModelFacts,
    st: &S,
    input: &Input,
    solver: &SolverOptions,
    laws: Laws,
    settings: Vec<(String, String)>,
) -> ReportInputs {
    let joints = JointLaws::count(
        st.contact_joints()
            .iter()
            .map(|j| (j.law.friction, j.law.strength, j.bilateral)),
    );
    let tol = input
        .build
        .tolerance
        .or(facts.tolerance)
        .unwrap_or(JOINT_TOLERANCE);
    let tolerances = vec![
        (
            "joint detection".to_string(),
            format!(
                "{} × the model's bounding-box diagonal ({})",
                voussoir_io::report_parts::sci(tol),
                if input.build.tolerance.is_some() {
                    "--tolerance"
                } else if facts.tolerance.is_some() {
                    "the model's tolerance"
                } else {
                    "default"
                }
            ),
        ),
        (
            "solver feasibility tolerance".to_string(),
            voussoir_io::report_parts::sci(solver.feasibility_tolerance),
        ),
    ];
    ReportInputs {
        command: command.to_string(),
        materials: facts.materials,
        laws: joints,
        cone: laws.cone,
        crushing: laws.crushing,
        non_associative: laws.non_associative,
        tolerances,
        settings,
    }
}
