//! Support motions as the command line writes them: `--move NAME=u,v[,θ]` (2D) or
//! `NAME=u,v,w[,θx,θy,θz]` (3D), `--fixed NAME`, `--split NAME@X[,X…]` and `--profile KIND:NUMBERS`. Pure text parsing
//! (no files, no flags framework), so that the front ends and the fuzz target `motion` share it.
//! Every error is one line naming the flag and the value given.

use crate::IoError;
use voussoir::settlement_input::{
    apply_profile_as_drawn, fix_support, move_support, refresh_motions, split_support,
    ModelSupports, Profile, SupportSplit,
};

/// A length in metres from the command line: a number in m, or with a unit `mm`, `cm` or `m`.
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

/// A support motion resolved from the flags: every value parsed and checked.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Motion {
    pub fixed: Vec<String>,
    /// (support, values, whether each value carried a length unit) as given; lengths in m,
    /// angles in degrees. Their meaning depends on the model's dimension ([`Motion::apply`]).
    pub moves: Vec<(String, Vec<(f64, bool)>)>,
    pub profile: Option<Profile>,
    /// `--split NAME@X[,X…]`: a support and where to cut it (m).
    pub splits: Vec<(String, Vec<f64>)>,
}

/// One `--split NAME@X[,X…]`: the support's name and the cuts (m; lengths may carry a unit).
pub fn parse_split(s: &str) -> Result<(String, Vec<f64>), IoError> {
    parse_split_inner(s).map_err(IoError::one_line)
}

fn parse_split_inner(s: &str) -> Result<(String, Vec<f64>), IoError> {
    let form = || {
        IoError(format!("--split {s}: expected NAME@X[,X…] (the support's name and where to cut it, x in m or with a unit)"))
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
        return Err(IoError(format!("--split {s}: every x must be finite")));
    }
    Ok((name.to_string(), xs))
}

/// One `--move NAME=u,v[,θ]` or `NAME=u,v,w[,θx,θy,θz]`: the support's name and the values
/// (with whether each carried a length unit), 2, 3 or 6 finite numbers.
pub fn parse_move(m: &str) -> Result<(String, Vec<(f64, bool)>), IoError> {
    parse_move_inner(m).map_err(IoError::one_line)
}

fn parse_move_inner(m: &str) -> Result<(String, Vec<(f64, bool)>), IoError> {
    let (name, vals) = m.split_once('=').ok_or_else(|| {
        IoError(format!(
            "--move {m}: expected NAME=u,v[,θ] (2D) or NAME=u,v,w[,θx,θy,θz] (3D)"
        ))
    })?;
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
            IoError(format!(
                "--move {m}: the lengths and angles must be numbers"
            ))
        })?;
    if nums.iter().any(|(x, _)| !x.is_finite()) {
        return Err(IoError(format!("--move {m}: every value must be finite")));
    }
    if !matches!(nums.len(), 2 | 3 | 6) {
        return Err(IoError(format!(
            "--move {m}: expected NAME=u,v[,θ] (2D) or NAME=u,v,w[,θx,θy,θz] (3D)"
        )));
    }
    Ok((name.to_string(), nums))
}

/// Parse the command-line form of a settlement profile: `uniform:X0,X1,V`,
/// `linear:X0,V0,X1,V1` or `table:X,V;X,V;…` (metres).
pub fn parse_profile(s: &str) -> Result<Profile, IoError> {
    parse_profile_inner(s).map_err(IoError::one_line)
}

fn parse_profile_inner(s: &str) -> Result<Profile, IoError> {
    let bad = || {
        IoError(format!("cannot read settlement profile '{s}': expected uniform:X0,X1,V or linear:X0,V0,X1,V1 or table:X,V;X,V;…"))
    };
    let (kind, rest) = s.split_once(':').ok_or_else(bad)?;
    let nums = |t: &str| -> Result<Vec<f64>, IoError> {
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
    p.validate()?;
    Ok(p)
}

impl Motion {
    /// Parse every `--move`, the `--fixed` names and the `--profile` (before any work).
    pub fn parse(
        moves: &[String],
        fixed: &[String],
        profile: Option<&str>,
    ) -> Result<Motion, IoError> {
        Self::parse_with_splits(moves, fixed, profile, &[])
    }

    /// [`Motion::parse`] with the `--split` values.
    pub fn parse_with_splits(
        moves: &[String],
        fixed: &[String],
        profile: Option<&str>,
        splits: &[String],
    ) -> Result<Motion, IoError> {
        let splits = splits
            .iter()
            .map(|s| parse_split(s))
            .collect::<Result<Vec<_>, _>>()?;
        for (k, (name, _)) in splits.iter().enumerate() {
            if splits[..k].iter().any(|(n, _)| n == name) {
                return Err(IoError(format!(
                    "--split {name}@…: support '{name}' is split twice; give all its cuts in one --split ({name}@X1,X2,…)"
                )));
            }
        }
        let moves = moves
            .iter()
            .map(|m| parse_move(m))
            .collect::<Result<Vec<_>, _>>()?;
        // One motion per support: a second `--move` of the same support would silently win.
        for (k, (name, _)) in moves.iter().enumerate() {
            if moves[..k].iter().any(|(n, _)| n == name) {
                return Err(IoError(format!(
                    "--move {name}=…: support '{name}' is moved twice; give one --move per support"
                )));
            }
        }
        let profile = match profile {
            Some(p) => Some(parse_profile(p)?),
            None => None,
        };
        Ok(Motion {
            fixed: fixed.to_vec(),
            moves,
            profile,
            splits,
        })
    }

    /// Apply the splits, fixed supports, moves and profile to a model of either dimension, in
    /// that order: `--split` first (so that `--move` and `--fixed` may name a part), then the
    /// profile as drawn (every support spanning one of its breakpoints is cut there, its parts
    /// keeping the motion and connection given to it). In 2D a move is `u, v[, θ]`, in 3D
    /// `u, v, w[, θx, θy, θz]` (lengths in m or with a unit, angles in degrees). Returns the
    /// supports cut, with their parts' final motions.
    pub fn apply<M: ModelSupports>(&self, model: &mut M) -> Result<Vec<SupportSplit>, IoError> {
        self.apply_inner(model).map_err(IoError::one_line)
    }

    fn apply_inner<M: ModelSupports>(&self, model: &mut M) -> Result<Vec<SupportSplit>, IoError> {
        let mut splits = Vec::new();
        for (name, xs) in &self.splits {
            let spec = xs
                .iter()
                .map(|x| voussoir::settlement_input::short_number(*x))
                .collect::<Vec<_>>()
                .join(",");
            splits.push(
                split_support(model, name, xs)
                    .map_err(|e| IoError(format!("--split {name}@{spec}: {}", request(&e))))?,
            );
        }
        let lengths = M::MOTION / 2 + usize::from(M::MOTION == 3);
        for f in &self.fixed {
            fix_support(model, f)?;
        }
        for (name, nums) in &self.moves {
            let form = if M::MOTION == 3 {
                "NAME=u,v[,θ] in a 2D model"
            } else {
                "NAME=u,v,w[,θx,θy,θz] in a 3D model"
            };
            if nums.len() != lengths && nums.len() != M::MOTION {
                return Err(IoError(format!(
                    "--move {name}: {} values given, expected {form}",
                    nums.len()
                )));
            }
            if let Some(k) = (lengths..nums.len()).find(|&k| nums[k].1) {
                return Err(IoError(format!(
                    "--move {name}: value {} is an angle in degrees and takes no length unit",
                    k + 1
                )));
            }
            let mut motion = vec![0.0; M::MOTION];
            for (k, (v, _)) in nums.iter().enumerate() {
                motion[k] = if k < lengths { *v } else { v.to_radians() };
            }
            move_support(model, name, &motion)?;
        }
        if let Some(p) = &self.profile {
            splits.extend(
                apply_profile_as_drawn(model, p)
                    .map_err(|e| IoError(format!("--profile: {}", request(&e))))?,
            );
        }
        refresh_motions(model, &mut splits);
        Ok(splits)
    }
}

/// A result with the supports cut for it: the result's fields, then `split_supports` (the
/// CLI's and the Python package's JSON, byte for byte the same).
#[derive(serde::Serialize)]
pub struct WithSplits<'a, T> {
    #[serde(flatten)]
    pub result: &'a T,
    pub split_supports: &'a [SupportSplit],
}

/// The message of a library error without its "invalid request: " kind.
fn request(e: &voussoir::Error) -> String {
    match e {
        voussoir::Error::Request(m) | voussoir::Error::Model(m) => m.clone(),
        e => e.to_string(),
    }
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

    #[test]
    fn moves_parse_with_units_and_refuse_what_is_not_a_motion() {
        let (name, v) = parse_move("right=0, -5mm ,1").unwrap();
        assert_eq!(name, "right");
        assert_eq!(v, vec![(0.0, false), (-5e-3, true), (1.0, false)]);
        assert_eq!(signed_length("2.5cm"), Some(0.025));
        for bad in [
            "right",
            "right=1",
            "right=1,2,3,4",
            "right=1,x",
            "right=1e400,0",
        ] {
            let e = parse_move(bad).unwrap_err().0;
            assert!(e.starts_with("--move ") && !e.contains('\n'), "{e}");
        }
    }
}
