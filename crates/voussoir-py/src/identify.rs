//! `voussoir.identify`: the inverse settlement analysis (which support motions caused the
//! observed cracks), over the library's [`voussoir::analysis::identify`] as `voussoir identify`
//! runs it. Unknowns come as JSON objects instead of the CLI's `--unknown` syntax:
//! `{"supports": ["right"], "component": "u"}` (one component shared by the supports named) or
//! `{"name": "slope", "profile": [P0, P1]}` (a profile family: the profile with the unknown set
//! to 0 and to 1, as `Profile` JSON), each with optional `"lower"`/`"upper"` bounds.

use crate::options::{Common, Fail, Settle};
use pyo3::prelude::*;
use serde::Deserialize;
use voussoir::analysis::identify::{
    identify as identify_motions, Component, IdentifyOptions, Observations, Unknown,
};
use voussoir::settlement_input::Profile;
use voussoir::{BuildOptions, Structure};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct UnknownSpec {
    #[serde(default)]
    name: Option<String>,
    #[serde(default)]
    supports: Vec<String>,
    #[serde(default)]
    component: Option<Component>,
    #[serde(default)]
    profile: Option<[Profile; 2]>,
    #[serde(default)]
    lower: Option<f64>,
    #[serde(default)]
    upper: Option<f64>,
}

/// The breakpoints of the unknown profiles (none if the text cannot be read: [`unknowns`]
/// says why).
fn profile_breakpoints(text: &str) -> Vec<f64> {
    serde_json::from_str::<Vec<UnknownSpec>>(text)
        .map(|specs| {
            specs
                .iter()
                .filter_map(|s| s.profile.as_ref())
                .flat_map(|[p0, _]| p0.breakpoints())
                .collect()
        })
        .unwrap_or_default()
}

fn unknowns(st: &Structure, text: &str) -> Result<Vec<Unknown>, Fail> {
    let specs: Vec<UnknownSpec> =
        serde_json::from_str(text).map_err(|e| Fail::Model(format!("unknowns: {e}")))?;
    let mut out = Vec::with_capacity(specs.len());
    for (i, s) in specs.iter().enumerate() {
        let u = match (&s.profile, s.component) {
            (Some([p0, p1]), None) if s.supports.is_empty() => {
                let name = s.name.clone().unwrap_or_else(|| format!("profile{i}"));
                Unknown::profile(st, &name, p0, p1, s.lower, s.upper)?
            }
            (None, Some(c)) => {
                let label = s.name.clone().unwrap_or_else(|| s.supports.join(","));
                Unknown::supports(st, &label, &s.supports, c, s.lower, s.upper)?
            }
            _ => {
                return Err(Fail::Model(format!(
                    "unknown {i}: give supports and a component (u, v or theta), or a profile pair"
                )))
            }
        };
        out.push(u);
    }
    Ok(out)
}

/// Identify the unknown support motions of `model` from the observed cracks `cracks`
/// (observation JSON, docs/identify.md); the known motions come from `settle`.
#[pyfunction]
pub fn identify(
    py: Python<'_>,
    model: String,
    common: Common,
    settle: Settle,
    cracks: String,
    unknown: String,
    ranges: bool,
) -> PyResult<String> {
    crate::detached(py, || {
        let (mut m, mut splits) = common.model_split(&model, Some(&settle))?;
        // Unknown profiles act on the foundations as drawn, as in the CLI: a support spanning
        // one of their breakpoints is cut there first.
        let xs = profile_breakpoints(&unknown);
        if !xs.is_empty() {
            splits.extend(voussoir::settlement_input::split_supports_at(&mut m, &xs)?);
            voussoir::settlement_input::refresh_motions(&m, &mut splits);
        }
        let st = Structure::new(
            &m,
            BuildOptions {
                tolerance: common.tolerance,
            },
        )?;
        let obs: Observations = serde_json::from_str(&cracks)
            .map_err(|e| Fail::Model(format!("cracks: not an observation file: {e}")))?;
        let us = unknowns(&st, &unknown)?;
        let opts = IdentifyOptions {
            solver: common.solver()?,
            ranges,
            form: common.settlement_form()?,
        };
        crate::json_split(&identify_motions(&st, &obs, &us, &opts)?, &splits)
    })
}
