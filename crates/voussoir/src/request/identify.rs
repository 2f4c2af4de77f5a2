//! The inverse settlement analysis: which support motions caused the observed cracks
//! (docs/identify.md).

use super::{invalid, parse_profile, Names, Output, Request};
use crate::analysis::identify::{
    identify, Component, IdentifyGeometry, IdentifyOptions, Observations, Unknown,
};
use crate::analysis::settlement::SettlementForm;
use crate::dim::Dim;
use crate::error::{Error, Result};
use crate::lp::SolverOptions;
use crate::settlement_input::{ModelSupports, Profile, SupportSplit};
use serde::{Deserialize, Serialize};

/// One unknown support motion, in either of the front ends' forms.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum UnknownSpec {
    /// The command line's syntax: `NAME=COMP[,COMP…]` (each component one unknown; 2D u, v,
    /// theta; 3D u, v, w, theta_x, theta_y, theta_z), `A..B=COMP` (supports A to B sharing one
    /// value), or a 2D profile with one value written `?` (`uniform:X0,X1,?`,
    /// `linear:X0,V0,X1,?`, `table:X,V;X,?;…`); each component or `?` may carry bounds
    /// `[LO:HI]`. Metres and radians.
    Text(String),
    /// One component shared by the supports named.
    #[serde(rename_all = "snake_case")]
    Supports {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        name: Option<String>,
        supports: Vec<String>,
        component: Component,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        lower: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        upper: Option<f64>,
    },
    /// A profile family (2D): the profile with the unknown set to 0 and to 1.
    Profile {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        name: Option<String>,
        profile: [Profile; 2],
        #[serde(default, skip_serializing_if = "Option::is_none")]
        lower: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        upper: Option<f64>,
    },
}

/// Options of an inverse settlement analysis. Defaults: the identifiability ranges computed,
/// both programs for the forward certificate. The observations and at least one unknown are
/// required; the request's support motion holds the known motions and fixed supports.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct IdentifyRequest {
    /// The observed cracks (docs/identify.md).
    pub observations: Observations,
    /// The unknown support motions.
    pub unknowns: Vec<UnknownSpec>,
    /// Skip the identifiability ranges (two LPs per unknown).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub no_ranges: bool,
    /// Form of the forward settlement analysis (the certificate; default both).
    pub settlement_form: SettlementForm,
}

fn is_profile_text(spec: &str) -> bool {
    matches!(
        spec.trim().split_once(':'),
        Some(("uniform" | "linear" | "table", _))
    )
}

impl IdentifyRequest {
    pub(super) fn validate(&self, req: &Request) -> Result<()> {
        if self.unknowns.is_empty() {
            return invalid(format!(
                "identify needs at least one unknown support motion: give {}",
                req.names.ask("unknown", "SPEC")
            ));
        }
        Ok(())
    }

    pub(super) fn check_dimension(&self, req: &Request, dims: usize) -> Result<()> {
        if dims == 3 {
            for u in &self.unknowns {
                let profile = match u {
                    UnknownSpec::Text(s) if is_profile_text(s) => Some(s.clone()),
                    UnknownSpec::Profile { name, .. } => {
                        Some(name.clone().unwrap_or_else(|| "profile".into()))
                    }
                    _ => None,
                };
                if let Some(p) = profile {
                    return invalid(format!(
                        "{}: a settlement profile as unknown applies to 2D models; on a 3D model give the supports' components (NAME=u,v,w,theta_x,theta_y,theta_z)",
                        req.names.given("unknown", p)
                    ));
                }
            }
        }
        Ok(())
    }

    /// Cut the supports at the breakpoints of the unknown profiles (they act on the
    /// foundations as drawn, as a known profile does): the supports cut.
    pub(super) fn split_profiles<M: ModelSupports>(
        &self,
        model: &mut M,
        names: Names,
    ) -> Result<Vec<SupportSplit>> {
        let xs: Vec<f64> = self
            .unknowns
            .iter()
            .flat_map(|u| match u {
                UnknownSpec::Text(s) => profile_unknown_breakpoints(s),
                UnknownSpec::Profile {
                    profile: [p0, _], ..
                } => p0.breakpoints(),
                UnknownSpec::Supports { .. } => Vec::new(),
            })
            .collect();
        if xs.is_empty() {
            return Ok(Vec::new());
        }
        let mut splits = crate::settlement_input::split_supports_at(model, &xs)
            .map_err(|e| Error::Invalid(format!("{}: {e}", names.name("unknown"))))?;
        crate::settlement_input::refresh_motions(model, &mut splits);
        Ok(splits)
    }

    /// The unknowns on the structure.
    pub fn unknowns<S: IdentifyGeometry>(&self, st: &S, names: Names) -> Result<Vec<Unknown>> {
        let mut out = Vec::new();
        for (i, u) in self.unknowns.iter().enumerate() {
            match u {
                UnknownSpec::Text(s) => out.extend(parse_unknown(s, st, names)?),
                UnknownSpec::Supports {
                    name,
                    supports,
                    component,
                    lower,
                    upper,
                } => {
                    let label = name.clone().unwrap_or_else(|| supports.join(","));
                    out.push(Unknown::supports(
                        st, &label, supports, *component, *lower, *upper,
                    )?);
                }
                UnknownSpec::Profile {
                    name,
                    profile: [p0, p1],
                    lower,
                    upper,
                } => {
                    let name = name.clone().unwrap_or_else(|| format!("profile{i}"));
                    out.push(Unknown::profile(st, &name, p0, p1, *lower, *upper)?);
                }
            }
        }
        Ok(out)
    }

    /// The analysis, with the dimension's default solver.
    pub(super) fn solve<S: IdentifyGeometry>(
        &self,
        st: &S,
        req: &Request,
        _dims: usize,
    ) -> Result<(Output<S::D>, SolverOptions)> {
        // Identify's programs read active sets off vertex solutions: the policy's method for
        // programs that need vertices and bases (as the canonical stages), not an interior
        // point (Clarabel, the 3D default for optimisation, has no crossover).
        let solver = req.solver.options(&crate::lp::policy::ProblemClass {
            purpose: crate::lp::policy::Purpose::CanonicalStage,
            ..super::class(st, req)
        });
        let unknowns = self.unknowns(st, req.names)?;
        let r = identify(
            st,
            &self.observations,
            &unknowns,
            &IdentifyOptions {
                solver,
                ranges: !self.no_ranges,
                form: self.settlement_form,
            },
        )?;
        Ok((Output::Identify(r, unknowns), solver))
    }
}

/// Split `[LO:HI]` bounds (either side may be empty).
fn parse_bounds(s: &str, spec: &str, names: Names) -> Result<(Option<f64>, Option<f64>)> {
    let bad = || {
        Error::Invalid(format!(
            "{}: bounds are written [LO:HI] (either side may be empty)",
            names.given("unknown", spec)
        ))
    };
    let inner = s
        .strip_prefix('[')
        .and_then(|t| t.strip_suffix(']'))
        .ok_or_else(bad)?;
    let (lo, hi) = inner.split_once(':').ok_or_else(bad)?;
    let num = |t: &str| -> Result<Option<f64>> {
        let t = t.trim();
        if t.is_empty() {
            return Ok(None);
        }
        t.parse::<f64>().map(Some).map_err(|_| bad())
    };
    Ok((num(lo)?, num(hi)?))
}

/// `f22` → ("f", 22).
fn split_number(name: &str) -> Option<(&str, u64)> {
    let i = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    if i == name.len() {
        return None;
    }
    Some((&name[..i], name[i..].parse().ok()?))
}

/// One unknown in the command line's syntax ([`UnknownSpec::Text`]).
pub fn parse_unknown<S: IdentifyGeometry>(
    spec: &str,
    st: &S,
    names: Names,
) -> Result<Vec<Unknown>> {
    let spec = spec.trim();
    let bad = |m: String| Error::Invalid(format!("{}: {m}", names.given("unknown", spec)));
    if is_profile_text(spec) {
        return parse_profile_unknown(spec, st, names).map(|u| vec![u]);
    }
    let (label, comps) = spec.split_once('=').ok_or_else(|| {
        bad("expected NAME=u,v,theta, A..B=v or a profile with a '?' (uniform:X0,X1,?)".into())
    })?;
    let label = label.trim();
    let supports: Vec<String> = if let Some((a, b)) = label.split_once("..") {
        let (Some((pa, na)), Some((pb, nb))) = (split_number(a.trim()), split_number(b.trim()))
        else {
            return Err(bad(
                "a range A..B needs numbered names with one prefix, e.g. f22..f43".into(),
            ));
        };
        if pa != pb || na > nb {
            return Err(bad(
                "a range A..B needs one prefix and A's number ≤ B's".into()
            ));
        }
        (na..=nb).map(|n| format!("{pa}{n}")).collect()
    } else {
        vec![label.to_string()]
    };
    let mut out = Vec::new();
    for c in comps.split(',') {
        let c = c.trim();
        let (c, lo, hi) = match c.find('[') {
            Some(i) => {
                let (lo, hi) = parse_bounds(&c[i..], spec, names)?;
                (&c[..i], lo, hi)
            }
            None => (c, None, None),
        };
        let dofs = <S::D as Dim>::DOFS;
        let comp = match Component::parse(c.trim()) {
            Some(comp) if comp.index_in(dofs).is_some() => comp,
            _ if dofs == 3 => {
                return Err(bad(format!(
                    "component '{}' is not u, v or theta",
                    c.trim()
                )))
            }
            _ => {
                return Err(bad(format!(
                    "component '{}' is not u, v, w, theta_x, theta_y or theta_z (a 3D model)",
                    c.trim()
                )))
            }
        };
        out.push(Unknown::supports(st, label, &supports, comp, lo, hi)?);
    }
    Ok(out)
}

/// The breakpoints of an unknown profile (`uniform:X0,X1,?`, …; its positions are known), or
/// none when `spec` is not one or cannot be read (its own parse reports why).
fn profile_unknown_breakpoints(spec: &str) -> Vec<f64> {
    let spec = spec.trim();
    let Some(q) = spec.find('?') else {
        return Vec::new();
    };
    if !is_profile_text(spec) {
        return Vec::new();
    }
    let rest = &spec[q + 1..];
    let tail = match rest.strip_prefix('[') {
        Some(r) => r.find(']').map_or("", |end| &r[end + 1..]),
        None => rest,
    };
    parse_profile(&format!("{}0{tail}", &spec[..q]))
        .map(|p| p.breakpoints())
        .unwrap_or_default()
}

fn parse_profile_unknown<S: IdentifyGeometry>(spec: &str, st: &S, names: Names) -> Result<Unknown> {
    let bad = |m: &str| Error::Invalid(format!("{}: {m}", names.given("unknown", spec)));
    let q = spec
        .find('?')
        .ok_or_else(|| bad("a profile unknown needs one value written '?'"))?;
    if spec[q + 1..].contains('?') {
        return Err(bad("only one '?' per profile"));
    }
    let rest = &spec[q + 1..];
    let (tail, lo, hi) = if rest.starts_with('[') {
        let end = rest.find(']').ok_or_else(|| bad("unclosed bounds"))?;
        let (lo, hi) = parse_bounds(&rest[..=end], spec, names)?;
        (&rest[end + 1..], lo, hi)
    } else {
        (rest, None, None)
    };
    let head = &spec[..q];
    // The '?' must be a value, not a position: count the numbers before it.
    let (kind, nums) = head.split_once(':').unwrap_or((head, ""));
    let before = nums.split([',', ';']).count() - 1;
    let is_value = match kind {
        "uniform" => before == 2,
        "linear" => before == 1 || before == 3,
        "table" => before % 2 == 1,
        _ => false,
    };
    if !is_value {
        return Err(bad(
            "the '?' must stand for a settlement value v, not a position x",
        ));
    }
    let p0 = parse_profile(&format!("{head}0{tail}"))?;
    let p1 = parse_profile(&format!("{head}1{tail}"))?;
    let name = format!("{head}?{tail}");
    Unknown::profile(st, &name, &p0, &p1, lo, hi)
}
