//! Support motions of a request, parsed in one place for every front end: `move`
//! (`NAME=u,v[,θ]` in 2D, `NAME=u,v,w[,θx,θy,θz]` in 3D; lengths in m or with a unit `mm`, `cm`,
//! `m`; angles in degrees), `fixed`, `split` (`NAME@X[,X…]`) and `profile`
//! (`uniform:X0,X1,V`, `linear:X0,V0,X1,V1`, `table:X,V;X,V;…`; lengths in m or with a unit).
//! The CLI's flags and Python's keywords hand their text to these parsers, so that
//! `right=0,-5mm` means the same everywhere. Every error is one line naming the flag, keyword or
//! field ([`Names`]) and the value given.

use super::Names;
use crate::error::{Error, Result};
use crate::settlement_input::{
    apply_profile_as_drawn, fix_support, move_support, refresh_motions, ModelSupports, Profile,
    SupportSplit,
};
use serde::{Deserialize, Serialize};

fn invalid<T>(msg: String) -> Result<T> {
    Err(Error::Invalid(msg))
}

/// A length in metres: a number in m, or with a unit `mm`, `cm` or `m`.
pub fn signed_length(s: &str) -> Option<f64> {
    let t = s.trim();
    let (num, factor) = if let Some(n) = t.strip_suffix("mm") {
        (n, 1e-3)
    } else if let Some(n) = t.strip_suffix("cm") {
        (n, 1e-2)
    } else if let Some(n) = t.strip_suffix('m') {
        (n, 1.0)
    } else {
        (t, 1.0)
    };
    num.trim().parse::<f64>().ok().map(|x| x * factor)
}

/// The prescribed motion of one support, as given: its name and 2, 3 or 6 values — lengths in
/// m (u, v in 2D; u, v, w in 3D), angles in degrees (θ in 2D; θx, θy, θz in 3D). What the values
/// mean depends on the model's dimension ([`SupportMotion::apply`]).
///
/// In a request's JSON either the text `"right=0,-5mm"` or `{"support": "right", "values":
/// [0, -0.005]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "MoveSpec")]
pub struct Move {
    pub support: String,
    pub values: Vec<f64>,
    /// Of a three-value move: its third value was written with a length unit, so it is a length
    /// (the w of a 3D move) and refused as the θ of a 2D one.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub third_with_unit: bool,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum MoveSpec {
    Text(String),
    Parts {
        support: String,
        values: Vec<f64>,
        #[serde(default)]
        third_with_unit: bool,
    },
}

impl TryFrom<MoveSpec> for Move {
    type Error = String;
    fn try_from(s: MoveSpec) -> std::result::Result<Move, String> {
        match s {
            MoveSpec::Text(t) => Move::parse(&t, Names::Fields).map_err(|e| e.to_string()),
            MoveSpec::Parts {
                support,
                values,
                third_with_unit,
            } => {
                let m = Move {
                    support,
                    values,
                    third_with_unit,
                };
                m.check(Names::Fields).map_err(|e| e.to_string())?;
                Ok(m)
            }
        }
    }
}

const MOVE_FORMS: &str = "NAME=u,v[,θ] (2D) or NAME=u,v,w[,θx,θy,θz] (3D)";

impl Move {
    /// One `NAME=u,v[,θ]` or `NAME=u,v,w[,θx,θy,θz]`: 2, 3 or 6 finite numbers, lengths with
    /// or without a unit, angles in degrees without one.
    pub fn parse(m: &str, names: Names) -> Result<Move> {
        let flag = names.name("move");
        let (name, vals) = m
            .split_once('=')
            .ok_or_else(|| Error::Invalid(format!("{flag} {m}: expected {MOVE_FORMS}")))?;
        // Lengths may carry a unit (`-2.5mm`, `1cm`; bare numbers are metres).
        let nums: Vec<(f64, bool)> = vals
            .split(',')
            .map(|x| {
                let t = x.trim();
                t.parse::<f64>()
                    .ok()
                    .map(|v| (v, false))
                    .or_else(|| signed_length(t).map(|v| (v, true)))
            })
            .collect::<Option<_>>()
            .ok_or_else(|| {
                Error::Invalid(format!(
                    "{flag} {m}: the lengths and angles must be numbers"
                ))
            })?;
        if nums.iter().any(|(x, _)| !x.is_finite()) {
            return invalid(format!("{flag} {m}: every value must be finite"));
        }
        if !matches!(nums.len(), 2 | 3 | 6) {
            return invalid(format!("{flag} {m}: expected {MOVE_FORMS}"));
        }
        // Six values are a 3D move: the last three are angles.
        if nums.len() == 6 {
            if let Some(k) = (3..6).find(|&k| nums[k].1) {
                return invalid(format!(
                    "{flag} {name}: value {} is an angle in degrees and takes no length unit",
                    k + 1
                ));
            }
        }
        Ok(Move {
            support: name.to_string(),
            third_with_unit: nums.len() == 3 && nums[2].1,
            values: nums.into_iter().map(|(v, _)| v).collect(),
        })
    }

    /// The checks of [`Move::parse`] on a move given by its parts.
    pub fn check(&self, names: Names) -> Result<()> {
        let flag = names.name("move");
        if self.values.iter().any(|x| !x.is_finite()) {
            return invalid(format!(
                "{flag} {}: every value must be finite",
                self.support
            ));
        }
        if !matches!(self.values.len(), 2 | 3 | 6) {
            return invalid(format!(
                "{flag} {}: {} values given, expected {MOVE_FORMS}",
                self.support,
                self.values.len()
            ));
        }
        Ok(())
    }

    /// The move in its text form, lengths in m (`right=0,-0.005`).
    pub fn text(&self) -> String {
        let v: Vec<String> = self
            .values
            .iter()
            .enumerate()
            .map(|(k, x)| {
                if k == 2 && self.third_with_unit {
                    format!("{x}m")
                } else {
                    format!("{x}")
                }
            })
            .collect();
        format!("{}={}", self.support, v.join(","))
    }
}

/// Where to cut a support: its name and the x of every cut (m).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "SplitSpec")]
pub struct Split {
    pub support: String,
    pub at: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum SplitSpec {
    Text(String),
    Parts { support: String, at: Vec<f64> },
}

impl TryFrom<SplitSpec> for Split {
    type Error = String;
    fn try_from(s: SplitSpec) -> std::result::Result<Split, String> {
        match s {
            SplitSpec::Text(t) => Split::parse(&t, Names::Fields).map_err(|e| e.to_string()),
            SplitSpec::Parts { support, at } => {
                if support.is_empty() || at.iter().any(|x| !x.is_finite()) {
                    return Err(format!(
                        "split {support}: a support name and finite x values (m)"
                    ));
                }
                Ok(Split { support, at })
            }
        }
    }
}

impl Split {
    /// One `NAME@X[,X…]` (x in m or with a unit).
    pub fn parse(s: &str, names: Names) -> Result<Split> {
        let flag = names.name("split");
        let form = || {
            Error::Invalid(format!("{flag} {s}: expected NAME@X[,X…] (the support's name and where to cut it, x in m or with a unit)"))
        };
        let (name, xs) = s.rsplit_once('@').ok_or_else(form)?;
        if name.is_empty() {
            return Err(form());
        }
        let xs: Vec<f64> = xs
            .split(',')
            .map(signed_length)
            .collect::<Option<_>>()
            .ok_or_else(form)?;
        if xs.iter().any(|x| !x.is_finite()) {
            return invalid(format!("{flag} {s}: every x must be finite"));
        }
        Ok(Split {
            support: name.to_string(),
            at: xs,
        })
    }
}

/// A settlement profile: the library's [`Profile`] JSON or the text form
/// `uniform:X0,X1,V | linear:X0,V0,X1,V1 | table:X,V;X,V;…` (lengths in m or with a unit).
#[derive(Deserialize)]
#[serde(untagged)]
enum ProfileSpec {
    Text(String),
    Profile(Profile),
}

fn profile_of_spec<'de, D: serde::Deserializer<'de>>(
    d: D,
) -> std::result::Result<Option<Profile>, D::Error> {
    let spec = Option::<ProfileSpec>::deserialize(d)?;
    let p = match spec {
        None => return Ok(None),
        Some(ProfileSpec::Text(t)) => parse_profile(&t),
        Some(ProfileSpec::Profile(p)) => p.validate().map(|_| p),
    };
    p.map(Some).map_err(serde::de::Error::custom)
}

/// Parse the text form of a settlement profile (`uniform:X0,X1,V`, `linear:X0,V0,X1,V1` or
/// `table:X,V;X,V;…`; lengths in m or with a unit).
pub fn parse_profile(s: &str) -> Result<Profile> {
    let bad = || {
        Error::Invalid(format!("cannot read settlement profile '{s}': expected uniform:X0,X1,V or linear:X0,V0,X1,V1 or table:X,V;X,V;…"))
    };
    let (kind, rest) = s.split_once(':').ok_or_else(bad)?;
    let nums = |t: &str| -> Result<Vec<f64>> {
        t.split(',')
            .map(|x| signed_length(x).ok_or_else(bad))
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
    p.validate().map_err(passthrough)?;
    Ok(p)
}

/// The support motion of a request: splits, fixed supports, moves and a profile. Default:
/// nothing moves.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SupportMotion {
    /// Prescribed motions, one per support ([`Move`]).
    #[serde(rename = "move", skip_serializing_if = "Vec::is_empty")]
    pub moves: Vec<Move>,
    /// Supports declared `fixed` (bilateral: the blocks on it follow it).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub fixed: Vec<String>,
    /// A vertical settlement profile along x applied to every support.
    #[serde(
        deserialize_with = "profile_of_spec",
        skip_serializing_if = "Option::is_none"
    )]
    pub profile: Option<Profile>,
    /// Supports cut by vertical lines before the moves (which may then name a part).
    #[serde(rename = "split", skip_serializing_if = "Vec::is_empty")]
    pub splits: Vec<Split>,
}

impl SupportMotion {
    /// Parse the text of every `split`, `move` and `profile` (the CLI's flags, Python's strings).
    pub fn parse(
        moves: &[String],
        fixed: &[String],
        profile: Option<&str>,
        splits: &[String],
        names: Names,
    ) -> Result<SupportMotion> {
        let splits = splits
            .iter()
            .map(|s| Split::parse(s, names).map_err(one_line))
            .collect::<Result<Vec<_>>>()?;
        let moves = moves
            .iter()
            .map(|m| Move::parse(m, names).map_err(one_line))
            .collect::<Result<Vec<_>>>()?;
        let profile = match profile {
            Some(p) => Some(parse_profile(p).map_err(one_line)?),
            None => None,
        };
        let m = SupportMotion {
            fixed: fixed.to_vec(),
            moves,
            profile,
            splits,
        };
        m.validate(names)?;
        Ok(m)
    }

    /// Whether anything is asked (a move, a fixed support, a profile or a split).
    pub fn is_empty(&self) -> bool {
        self.moves.is_empty()
            && self.fixed.is_empty()
            && self.profile.is_none()
            && self.splits.is_empty()
    }

    /// One split and one move per support; every move of 2, 3 or 6 finite values.
    pub fn validate(&self, names: Names) -> Result<()> {
        for (k, s) in self.splits.iter().enumerate() {
            let name = &s.support;
            if self.splits[..k].iter().any(|o| &o.support == name) {
                return invalid(format!(
                    "{} {name}@…: support '{name}' is split twice; give all its cuts in one {} ({name}@X1,X2,…)",
                    names.name("split"),
                    names.name("split")
                ));
            }
        }
        for (k, m) in self.moves.iter().enumerate() {
            m.check(names)?;
            let name = &m.support;
            // One motion per support: a second move of the same support would silently win.
            if self.moves[..k].iter().any(|o| &o.support == name) {
                return invalid(format!(
                    "{} {name}=…: support '{name}' is moved twice; give one {} per support",
                    names.name("move"),
                    names.name("move")
                ));
            }
        }
        if let Some(p) = &self.profile {
            p.validate()?;
        }
        Ok(())
    }

    /// Apply the splits, fixed supports, moves and profile to a model of either dimension, in
    /// that order: splits first (so that moves and fixed supports may name a part), then the
    /// profile as drawn (every support spanning one of its breakpoints is cut there, its parts
    /// keeping the motion and connection given to it). In 2D a move is `u, v[, θ]`, in 3D
    /// `u, v, w[, θx, θy, θz]` (lengths in m, angles in degrees). Returns the supports cut, with
    /// their parts' final motions.
    pub fn apply<M: ModelSupports>(
        &self,
        model: &mut M,
        names: Names,
    ) -> Result<Vec<SupportSplit>> {
        self.apply_inner(model, names).map_err(one_line)
    }

    fn apply_inner<M: ModelSupports>(
        &self,
        model: &mut M,
        names: Names,
    ) -> Result<Vec<SupportSplit>> {
        let mut splits = Vec::new();
        for s in &self.splits {
            let name = &s.support;
            let spec =
                s.at.iter()
                    .map(|x| crate::settlement_input::short_number(*x))
                    .collect::<Vec<_>>()
                    .join(",");
            splits.push(
                crate::settlement_input::split_support(model, name, &s.at).map_err(|e| {
                    Error::Invalid(format!(
                        "{} {name}@{spec}: {}",
                        names.name("split"),
                        message(&e)
                    ))
                })?,
            );
        }
        let lengths = M::MOTION / 2 + usize::from(M::MOTION == 3);
        for f in &self.fixed {
            fix_support(model, f).map_err(passthrough)?;
        }
        let flag = names.name("move");
        for m in &self.moves {
            let (name, nums) = (&m.support, &m.values);
            let form = if M::MOTION == 3 {
                "NAME=u,v[,θ] in a 2D model"
            } else {
                "NAME=u,v,w[,θx,θy,θz] in a 3D model"
            };
            if nums.len() != lengths && nums.len() != M::MOTION {
                return invalid(format!(
                    "{flag} {name}: {} values given, expected {form}",
                    nums.len()
                ));
            }
            if M::MOTION == 3 && nums.len() == 3 && m.third_with_unit {
                return invalid(format!(
                    "{flag} {name}: value 3 is an angle in degrees and takes no length unit"
                ));
            }
            let mut motion = vec![0.0; M::MOTION];
            for (k, v) in nums.iter().enumerate() {
                motion[k] = if k < lengths { *v } else { v.to_radians() };
            }
            move_support(model, name, &motion).map_err(passthrough)?;
        }
        if let Some(p) = &self.profile {
            splits.extend(apply_profile_as_drawn(model, p).map_err(|e| {
                Error::Invalid(format!("{}: {}", names.name("profile"), message(&e)))
            })?);
            // A profile that settles no support would be a flag without effect: refused.
            let centres: Vec<f64> = (0..model.support_names().len())
                .filter_map(|i| model.centroid_x(i))
                .collect();
            if centres.iter().all(|&x| {
                let (v, slope) = p.eval(x);
                v == 0.0 && slope == 0.0
            }) {
                let (lo, hi) = centres
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                        (a.min(x), b.max(x))
                    });
                let span = if centres.is_empty() {
                    "the model has no support".to_string()
                } else {
                    format!(
                        "the supports' centres lie at x = {} … {} m",
                        crate::settlement_input::short_number(lo),
                        crate::settlement_input::short_number(hi)
                    )
                };
                return invalid(format!(
                    "{}: the profile moves no support (it is zero at every support's centre; {span})",
                    names.name("profile")
                ));
            }
        }
        refresh_motions(model, &mut splits);
        Ok(splits)
    }
}

/// A library error as the front ends showed it before the request layer: its full text (kind
/// included), shown as is.
fn passthrough(e: Error) -> Error {
    match e {
        Error::Invalid(m) => Error::Invalid(m),
        e => Error::Invalid(e.to_string()),
    }
}

/// The message of a library error without its kind ("invalid request: ").
pub(crate) fn message(e: &Error) -> String {
    match e {
        Error::Request(m) | Error::Model(m) | Error::Invalid(m) => m.clone(),
        e => e.to_string(),
    }
}

fn one_line(e: Error) -> Error {
    match e {
        Error::Invalid(m) => Error::Invalid(crate::error::one_line(&m).into_owned()),
        e => e,
    }
}
