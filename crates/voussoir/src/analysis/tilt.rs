//! Tilting-table analysis: the critical tilt of the base at which the structure collapses.
//!
//! Tilting the table by α rotates gravity: every self-weight `W(0, −1)` becomes
//! `W(±sin α, −cos α)`. Dividing by cos α, this is the self-weight plus a horizontal live load
//! `λ·W(±1, 0)` with `λ = tan α`, so the critical tilt is `α = atan λ` with λ the collapse
//! multiplier of that load. The model's own live loads are replaced; its extra dead loads are
//! kept as given (they do not rotate with the table).

use super::limit::{
    limit_result, solve_limit_checked, solve_limit_conic, LimitResult, LimitStatus,
};
use crate::dim::{Dim, Three};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::SolverOptions;
pub use crate::result::tilt::*;
use crate::structure::{Assembly, Structure, Structure3d};

/// Critical tilt towards `direction` (+1: +x, −1: −x) of a 2D structure.
pub fn tilt(st: &Structure, direction: f64, opts: &SolverOptions) -> Result<TiltResult> {
    if direction != 1.0 && direction != -1.0 {
        return Err(Error::Request("tilt direction must be +1 or −1".into()));
    }
    let (tilt_angle, limit) = tilt_along(st, [direction, 0.0], opts, false)?;
    Ok(TiltResult {
        tilt_angle,
        direction,
        azimuth: None,
        limit,
    })
}

/// Critical tilt of a 3D structure towards the azimuth `azimuth` (degrees from x towards y):
/// the table tilts so that gravity gains a horizontal component along `(cos a, sin a, 0)`.
pub fn tilt_azimuth(
    st: &Structure3d,
    azimuth: f64,
    opts: &SolverOptions,
) -> Result<TiltResult<Three>> {
    tilt_3d(st, azimuth, opts, false)
}

/// [`tilt_azimuth`] with the exact friction cone (second-order cones, Clarabel).
pub fn tilt_azimuth_exact(
    st: &Structure3d,
    azimuth: f64,
    opts: &SolverOptions,
) -> Result<TiltResult<Three>> {
    tilt_3d(st, azimuth, opts, true)
}

fn tilt_3d(
    st: &Structure3d,
    azimuth: f64,
    opts: &SolverOptions,
    exact: bool,
) -> Result<TiltResult<Three>> {
    if !azimuth.is_finite() {
        return Err(Error::Request(
            "tilt azimuth must be a finite number".into(),
        ));
    }
    let a = azimuth.to_radians();
    let (tilt_angle, limit) = tilt_along(st, [a.cos(), a.sin(), 0.0], opts, exact)?;
    Ok(TiltResult {
        tilt_angle,
        direction: 1.0,
        azimuth: Some(azimuth),
        limit,
    })
}

/// The tilting table in either dimension: the live loads replaced by the blocks' weights along
/// the unit horizontal `direction`; the critical tilt (degrees) and the limit analysis.
/// `exact` uses the exact cones ([`solve_limit_conic`]) instead of the inscribed polygons.
pub fn tilt_along<S: Assembly>(
    st: &S,
    direction: <S::D as Dim>::Vector,
    opts: &SolverOptions,
    exact: bool,
) -> Result<(Option<f64>, LimitResult<S::D>)> {
    let s = st.with_weight_as_live_load(direction)?;
    let map = KinematicMap::new(&s);
    let sol = if exact {
        solve_limit_conic(&s, &map, opts)?
    } else {
        solve_limit_checked(&s, &map, opts)?
    };
    let limit = limit_result(&s, &map, &sol);
    let tilt_angle = match (sol.status, sol.lambda) {
        (LimitStatus::Collapse, Some(l)) => Some(l.atan().to_degrees()),
        _ => None,
    };
    Ok((tilt_angle, limit))
}

/// [`tilt_along`] with the canonical collapse mechanism (and, with `copts.forces`, forces) of
/// the tilted structure ([`crate::analysis::canonical::limit_canonical`]; docs/canonical.md):
/// the same critical tilt, hinges that do not depend on the LP method. The inscribed polygons
/// only (the exact cones: [`tilt_along`]).
pub fn tilt_along_canonical<S: Assembly>(
    st: &S,
    direction: <S::D as Dim>::Vector,
    opts: &SolverOptions,
    copts: &crate::analysis::canonical::CanonicalOptions,
) -> Result<(Option<f64>, LimitResult<S::D>)> {
    let s = st.with_weight_as_live_load(direction)?;
    let limit =
        crate::analysis::canonical::limit_canonical(&s, opts, super::limit::DEFAULT_FACETS, copts)?;
    let tilt_angle = match (limit.status, limit.load_multiplier) {
        (LimitStatus::Collapse, Some(l)) => Some(l.atan().to_degrees()),
        _ => None,
    };
    Ok((tilt_angle, limit))
}
