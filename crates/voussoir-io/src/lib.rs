//! File formats and drawings for voussoir: JSON models and results, atomic output files.
//! (DXF import, SVG/PNG drawings and HTML reports live in their own modules.)

pub mod draw;
pub mod dxf;
pub mod files;

pub use files::{read_any_model, read_model, write_all_or_nothing, write_atomic, IoError};
