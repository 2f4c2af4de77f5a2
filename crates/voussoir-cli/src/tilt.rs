//! `voussoir tilt`: critical tilt angle of a tilting-table test.

use crate::common::{Fail, ModelArgs, OutArgs};
use clap::{Args, ValueEnum};
use std::fmt::Write as _;

#[derive(ValueEnum, Clone, Copy, Debug)]
pub enum TiltDirection {
    #[value(name = "+x")]
    PlusX,
    #[value(name = "-x")]
    MinusX,
}

#[derive(Args)]
pub struct TiltArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    /// Direction the table tilts towards (the structure tends to fall that way).
    #[arg(long, value_enum, default_value = "+x", allow_hyphen_values = true)]
    pub direction: TiltDirection,
    #[command(flatten)]
    pub out: OutArgs,
}

pub fn run(a: TiltArgs) -> Result<(), Fail> {
    let (st, opts) = a.model.structure(None)?;
    let dir = match a.direction {
        TiltDirection::PlusX => 1.0,
        TiltDirection::MinusX => -1.0,
    };
    let r = voussoir::analysis::tilt::tilt(&st, dir, &opts)?;
    a.out.emit(&r, || {
        let mut s = String::new();
        let _ = writeln!(s, "blocks {}, joints {}", st.blocks.len(), st.joints.len());
        match r.tilt_angle {
            Some(t) => {
                let _ = writeln!(
                    s,
                    "critical tilt angle {t:.4}° towards {}x (tan α = λ = {:.6})",
                    if dir > 0.0 { "+" } else { "−" },
                    t.to_radians().tan()
                );
            }
            None => {
                let _ = writeln!(s, "{}", r.limit.message);
            }
        }
        s
    })
}
