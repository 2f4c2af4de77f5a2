//! Flags shared by the analysis commands, model loading, output and human summaries.

use clap::Args;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;
use voussoir::analysis::{LimitResult, SettlementResult};
use voussoir::lp::{Method, SolverOptions};
use voussoir::settlement_input::{apply_profile, fix_support, move_support, Profile};
use voussoir::{BuildOptions, Model, Structure};

/// A failure: one line for the user.
#[derive(Debug)]
pub struct Fail(pub String);

impl std::fmt::Display for Fail {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl From<voussoir::Error> for Fail {
    fn from(e: voussoir::Error) -> Self {
        Fail(e.to_string())
    }
}
impl From<voussoir_io::IoError> for Fail {
    fn from(e: voussoir_io::IoError) -> Self {
        Fail(e.0)
    }
}

#[derive(Args, Clone, Debug)]
pub struct ModelArgs {
    /// The model: a JSON file (see README, "Model format") or a DXF drawing (`.dxf`).
    pub model: PathBuf,
    /// Geometric tolerance for joint detection, relative to the model's size (default 1e-7).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// LP method: dual-simplex (default; crisp vertex mechanisms), primal-simplex, ipm, choose.
    #[arg(long, value_enum, default_value = "dual-simplex")]
    pub method: MethodArg,
    /// Coulomb friction coefficient μ for every joint (overrides the model's materials;
    /// default: no sliding).
    #[arg(long)]
    pub friction: Option<f64>,
    /// Compressive strength f_c in kPa for every joint (overrides the model's materials;
    /// default: infinite).
    #[arg(long, value_name = "KPA")]
    pub compressive_strength: Option<f64>,
    /// Finite-strength model: `linear` (inscribed polygon, an LP) or `conic` (exact, SOCP via
    /// Clarabel; limit analysis only).
    #[arg(long, value_enum, default_value = "linear")]
    pub crushing: CrushingArg,
    /// Facets of the inscribed crushing polygon.
    #[arg(long, default_value_t = 16)]
    pub facets: usize,
    /// How to read a `.dxf` model.
    #[command(flatten)]
    pub dxf: crate::import::DxfArgs,
    /// Settlement analyses: solve both LPs (default), or only the force LP (`force-only`: 3 rows
    /// per block, the mechanism from its duals, the certificate from both sides; for large
    /// models, with --method clarabel).
    #[arg(long, value_enum, default_value = "both")]
    pub settlement_form: FormArg,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum CrushingArg {
    Linear,
    Conic,
}

/// Which LPs a settlement analysis solves.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default)]
pub enum FormArg {
    #[default]
    Both,
    ForceOnly,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum MethodArg {
    DualSimplex,
    PrimalSimplex,
    Ipm,
    Choose,
    /// Interior point without crossover (HiGHS).
    IpmNoCrossover,
    /// First-order PDLP (HiGHS; low accuracy).
    Pdlp,
    /// Clarabel's interior point: fastest on large models (see docs/performance.md).
    Clarabel,
}

#[derive(Args, Clone, Debug, Default)]
pub struct SettleArgs {
    /// Prescribed motion of a support: NAME=u,v[,θ] with u, v in metres (v up) and θ in
    /// degrees counter-clockwise about the support's centroid. Repeatable.
    #[arg(long = "move", value_name = "NAME=U,V[,THETA]")]
    pub moves: Vec<String>,
    /// Declare a support `fixed` (bilateral: the blocks on it follow it). Repeatable.
    #[arg(long = "fixed", value_name = "NAME")]
    pub fixed: Vec<String>,
    /// Vertical settlement profile along x (m) applied to every support by its centroid:
    /// uniform:X0,X1,V | linear:X0,V0,X1,V1 | table:X,V;X,V;…  (v up, so a settlement is < 0).
    #[arg(long)]
    pub profile: Option<String>,
}

impl SettleArgs {
    /// Apply the moves, fixed supports and profile to a model.
    pub fn apply(&self, model: &mut Model) -> Result<(), Fail> {
        for f in &self.fixed {
            fix_support(model, f)?;
        }
        for m in &self.moves {
            let (name, vals) = m
                .split_once('=')
                .ok_or_else(|| Fail(format!("--move {m}: expected NAME=u,v[,θ]")))?;
            let nums: Vec<f64> = vals
                .split(',')
                .map(|x| x.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|_| Fail(format!("--move {m}: u, v and θ must be numbers")))?;
            let motion = match nums.as_slice() {
                [u, v] => [*u, *v, 0.0],
                [u, v, t] => [*u, *v, t.to_radians()],
                _ => return Err(Fail(format!("--move {m}: expected NAME=u,v[,θ]"))),
            };
            move_support(model, name, motion)?;
        }
        if let Some(p) = &self.profile {
            apply_profile(model, &parse_profile(p)?)?;
        }
        Ok(())
    }
}

impl ModelArgs {
    /// The settlement form chosen by `--settlement-form`.
    pub fn settlement_form(&self) -> voussoir::analysis::settlement::SettlementForm {
        match self.settlement_form {
            FormArg::Both => voussoir::analysis::settlement::SettlementForm::Both,
            FormArg::ForceOnly => voussoir::analysis::settlement::SettlementForm::ForceOnly,
        }
    }

    pub fn solver(&self) -> SolverOptions {
        SolverOptions {
            method: match self.method {
                MethodArg::DualSimplex => Method::DualSimplex,
                MethodArg::PrimalSimplex => Method::PrimalSimplex,
                MethodArg::Ipm => Method::Ipm,
                MethodArg::Choose => Method::Choose,
                MethodArg::IpmNoCrossover => Method::IpmNoCrossover,
                MethodArg::Pdlp => Method::Pdlp,
                MethodArg::Clarabel => Method::Clarabel,
            },
            // Diagnostics: VOUSSOIR_HIGHS_LOG=1 prints the solver's own log on stdout (read here,
            // in the binary; the library takes it as a setting).
            log: std::env::var_os("VOUSSOIR_HIGHS_LOG").is_some_and(|v| v == "1"),
            ..SolverOptions::default()
        }
    }

    pub fn load(&self) -> Result<Model, Fail> {
        let mut m = self.dxf.read(&self.model)?.0;
        self.override_materials(&mut m)?;
        Ok(m)
    }

    /// Apply `--friction` and `--compressive-strength` to every material (the implicit
    /// `default` one included).
    pub fn override_materials(&self, m: &mut Model) -> Result<(), Fail> {
        if let Some(mu) = self.friction {
            if !(mu.is_finite() && mu >= 0.0) {
                return Err(Fail(format!(
                    "--friction {mu}: must be a finite number ≥ 0"
                )));
            }
        }
        if let Some(f) = self.compressive_strength {
            if !(f.is_finite() && f > 0.0) {
                return Err(Fail(format!(
                    "--compressive-strength {f}: must be a finite number > 0 (kPa)"
                )));
            }
        }
        if self.friction.is_none() && self.compressive_strength.is_none() {
            return Ok(());
        }
        m.materials.entry("default".to_string()).or_default();
        for mat in m.materials.values_mut() {
            if self.friction.is_some() {
                mat.friction = self.friction;
            }
            if self.compressive_strength.is_some() {
                mat.compressive_strength = self.compressive_strength;
            }
        }
        Ok(())
    }

    /// Limit analysis with the chosen crushing model.
    pub fn limit(
        &self,
        st: &Structure,
        opts: &SolverOptions,
    ) -> Result<voussoir::analysis::LimitResult, Fail> {
        let crushing = match self.crushing {
            CrushingArg::Linear => voussoir::analysis::limit::Crushing::Linear,
            CrushingArg::Conic => voussoir::analysis::limit::Crushing::Conic,
        };
        Ok(voussoir::analysis::limit::limit_with(
            st,
            opts,
            crushing,
            self.facets,
        )?)
    }

    /// Load, apply settlement flags, validate and discretise.
    pub fn structure(
        &self,
        settle: Option<&SettleArgs>,
    ) -> Result<(Structure, SolverOptions), Fail> {
        let mut model = self.load()?;
        if let Some(s) = settle {
            s.apply(&mut model)?;
        }
        let st = Structure::new(
            &model,
            BuildOptions {
                tolerance: self.tolerance,
            },
        )?;
        Ok((st, self.solver()))
    }
}

#[derive(Args, Clone, Debug)]
pub struct OutArgs {
    /// Print the full result as JSON on stdout (instead of the summary).
    #[arg(long)]
    pub json: bool,
    /// Write the full JSON result to this file (the summary still goes to stdout).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    pub output: Option<PathBuf>,
}

impl OutArgs {
    pub fn emit<T: Serialize>(&self, result: &T, summary: impl Fn() -> String) -> Result<(), Fail> {
        let json = voussoir_io::files::to_json(result)?;
        if let Some(path) = &self.output {
            voussoir_io::write_atomic(path, json.as_bytes())?;
        }
        if self.json && self.output.is_none() {
            out(&json);
        } else {
            out(&summary());
        }
        Ok(())
    }
}

/// Write to stdout; a closed pipe (`voussoir … | head`) ends the output quietly.
pub fn out(text: &str) {
    use std::io::Write;
    let mut o = std::io::stdout().lock();
    let _ = o.write_all(text.as_bytes()).and_then(|_| o.flush());
}

fn hinge_list(st: &Structure, hinges: &[voussoir::result::Hinge]) -> String {
    let mut s = String::new();
    for h in hinges {
        let j = &st.joints[h.joint];
        let _ = writeln!(
            s,
            "  joint {:>4} ({} | {}) at ({:.4}, {:.4})",
            h.joint,
            st.name(j.a),
            st.name(j.b),
            h.x,
            h.y
        );
    }
    s
}

pub fn limit_summary(st: &Structure, r: &LimitResult) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "blocks {}, joints {}, supports {}",
        st.blocks.len(),
        st.joints.len(),
        st.supports.len()
    );
    let _ = writeln!(s, "{}", r.message);
    if !r.hinges.is_empty() {
        let _ = writeln!(s, "hinges of the collapse mechanism ({}):", r.hinges.len());
        s.push_str(&hinge_list(st, &r.hinges));
    }
    s
}

pub fn settle_summary(st: &Structure, r: &SettlementResult) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "blocks {}, joints {}, supports {}",
        st.blocks.len(),
        st.joints.len(),
        st.supports.len()
    );
    let _ = writeln!(s, "{}", r.message);
    if let (Some(p), Some(d), Some(g)) = (r.work_dead_loads, r.work_reactions, r.duality_gap) {
        let _ = writeln!(
            s,
            "work of dead loads {p:.6e} kN·m, work on supports {d:.6e} kN·m, relative gap {g:.2e}"
        );
    }
    if !r.hinges.is_empty() {
        let _ = writeln!(s, "hinges ({}):", r.hinges.len());
        s.push_str(&hinge_list(st, &r.hinges));
    }
    let open = r
        .joints
        .iter()
        .filter(|j| j.state == voussoir::result::JointState::Open)
        .count();
    if open > 0 {
        let _ = writeln!(s, "fully open joints: {open}");
    }
    for re in &r.reactions {
        let _ = writeln!(
            s,
            "reaction {:>8}: fx {:>10.4} kN  fy {:>10.4} kN  m {:>10.4} kN·m",
            re.support, re.fx, re.fy, re.m
        );
    }
    s
}

/// Parse the command-line form: `uniform:X0,X1,V`, `linear:X0,V0,X1,V1` or
/// `table:X,V;X,V;…` (metres).
pub fn parse_profile(s: &str) -> Result<Profile, Fail> {
    let bad = || {
        Fail(format!("cannot read settlement profile '{s}': expected uniform:X0,X1,V or linear:X0,V0,X1,V1 or table:X,V;X,V;…"))
    };
    let (kind, rest) = s.split_once(':').ok_or_else(bad)?;
    let nums = |t: &str| -> Result<Vec<f64>, Fail> {
        t.split(',')
            .map(|x| x.trim().parse::<f64>().map_err(|_| bad()))
            .collect()
    };
    let p = match kind {
        "uniform" => match nums(rest)?.as_slice() {
            [x0, x1, v] => Profile::Uniform {
                x0: *x0,
                x1: *x1,
                v: *v,
            },
            _ => return Err(bad()),
        },
        "linear" => match nums(rest)?.as_slice() {
            [x0, v0, x1, v1] => Profile::Linear {
                x0: *x0,
                v0: *v0,
                x1: *x1,
                v1: *v1,
            },
            _ => return Err(bad()),
        },
        "table" => {
            let mut points = Vec::new();
            for pair in rest.split(';').filter(|t| !t.trim().is_empty()) {
                match nums(pair)?.as_slice() {
                    [x, v] => points.push([*x, *v]),
                    _ => return Err(bad()),
                }
            }
            Profile::Table { points }
        }
        _ => return Err(bad()),
    };
    p.validate().map_err(Fail::from)?;
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn profiles_parse_from_the_command_line_form() {
        assert_eq!(
            parse_profile("uniform:1,2,-0.2").unwrap(),
            Profile::Uniform {
                x0: 1.0,
                x1: 2.0,
                v: -0.2
            }
        );
        assert_eq!(
            parse_profile("table:0,0;1,-0.1").unwrap(),
            Profile::Table {
                points: vec![[0.0, 0.0], [1.0, -0.1]]
            }
        );
        assert!(parse_profile("uniform:2,1,-0.2").is_err());
        assert!(parse_profile("linear:0,0,0,1").is_err());
        assert!(parse_profile("table:0,0;1").is_err());
        assert!(parse_profile("wavy:1").is_err());
    }
}
