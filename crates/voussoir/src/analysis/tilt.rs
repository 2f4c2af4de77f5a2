//! Tilting-table analysis: the critical tilt of the base at which the structure collapses.
//!
//! Tilting the table by α rotates gravity: every self-weight `W(0, −1)` becomes
//! `W(±sin α, −cos α)`. Dividing by cos α, this is the self-weight plus a horizontal live load
//! `λ·W(±1, 0)` with `λ = tan α`, so the critical tilt is `α = atan λ` with λ the collapse
//! multiplier of that load. The model's own live loads are replaced; its extra dead loads are
//! kept as given (they do not rotate with the table).

use super::limit::{limit_result, solve_limit_checked, LimitStatus};
use crate::discretize::KinematicMap;
use crate::error::{Error, Result};
use crate::lp::SolverOptions;
pub use crate::result::tilt::*;
use crate::structure::{AppliedLoad, Structure};

/// Critical tilt towards `direction` (+1: +x, −1: −x).
pub fn tilt(st: &Structure, direction: f64, opts: &SolverOptions) -> Result<TiltResult> {
    if direction != 1.0 && direction != -1.0 {
        return Err(Error::Request("tilt direction must be +1 or −1".into()));
    }
    let mut s = st.clone();
    s.loads.retain(|l| !l.live);
    let live: Vec<AppliedLoad> = s
        .blocks
        .iter()
        .enumerate()
        .filter(|(_, b)| b.weight > 0.0)
        .map(|(i, b)| AppliedLoad {
            block: i,
            at: b.centroid,
            force: [direction * b.weight, 0.0],
            live: true,
        })
        .collect();
    if live.is_empty() {
        return Err(Error::Request(
            "tilt analysis needs blocks with weight".into(),
        ));
    }
    s.loads.extend(live);
    let map = KinematicMap::new(&s);
    let sol = solve_limit_checked(&s, &map, opts)?;
    let limit = limit_result(&s, &map, &sol);
    let tilt_angle = match (sol.status, sol.lambda) {
        (LimitStatus::Collapse, Some(l)) => Some(l.atan().to_degrees()),
        _ => None,
    };
    Ok(TiltResult {
        tilt_angle,
        direction,
        limit,
    })
}
