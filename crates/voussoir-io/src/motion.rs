//! Support motions as the command line writes them: `--move NAME=u,v[,θ]` (2D) or
//! `NAME=u,v,w[,θx,θy,θz]` (3D), `--fixed NAME`, `--split NAME@X[,X…]` and `--profile KIND:NUMBERS`.
//! The parsing is the library's ([`voussoir::request::motion`], one place for every front end);
//! this module gives it the command line's names (`--move`, …) and the `IoError` of the
//! readers, for the commands not yet on the request layer and the fuzz target `motion`.

use crate::IoError;
use voussoir::request::{Move, Names, SupportMotion};
use voussoir::settlement_input::{ModelSupports, Profile, SupportSplit};

pub use voussoir::request::signed_length;

fn io(e: voussoir::Error) -> IoError {
    IoError(e.to_string()).one_line()
}

/// One `--split NAME@X[,X…]`: the support's name and the cuts (m; lengths may carry a unit).
pub fn parse_split(s: &str) -> Result<(String, Vec<f64>), IoError> {
    let sp = voussoir::request::Split::parse(s, Names::Flags).map_err(io)?;
    Ok((sp.support, sp.at))
}

/// One `--move NAME=u,v[,θ]` or `NAME=u,v,w[,θx,θy,θz]`.
pub fn parse_move(m: &str) -> Result<Move, IoError> {
    Move::parse(m, Names::Flags).map_err(io)
}

/// Parse the command-line form of a settlement profile: `uniform:X0,X1,V`,
/// `linear:X0,V0,X1,V1` or `table:X,V;X,V;…` (lengths in m or with a unit).
pub fn parse_profile(s: &str) -> Result<Profile, IoError> {
    voussoir::request::parse_profile(s).map_err(io)
}

/// A support motion resolved from the flags: every value parsed and checked.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Motion(pub SupportMotion);

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
        SupportMotion::parse(moves, fixed, profile, splits, Names::Flags)
            .map(Motion)
            .map_err(io)
    }

    /// Apply the splits, fixed supports, moves and profile to a model of either dimension
    /// ([`SupportMotion::apply`]).
    pub fn apply<M: ModelSupports>(&self, model: &mut M) -> Result<Vec<SupportSplit>, IoError> {
        self.0.apply(model, Names::Flags).map_err(io)
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
        let m = parse_move("right=0, -5mm ,1").unwrap();
        assert_eq!(m.support, "right");
        assert_eq!(m.values, vec![0.0, -5e-3, 1.0]);
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
