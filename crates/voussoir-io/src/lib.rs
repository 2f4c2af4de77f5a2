//! File formats and drawings for voussoir: JSON models and results, atomic output files.
//! (DXF import, SVG/PNG drawings and HTML reports live in their own modules; 3D results are
//! written to VTK by [`vtk`] and drawn in axonometry by [`draw3d`].)

pub mod draw;
pub mod draw3d;
pub mod dxf;
pub mod files;
/// The summaries' units of length (README, "Units in the summaries"), shared with the library.
pub use voussoir::lengths;
pub mod mesh;
pub mod motion;
pub mod outline;
pub mod report3d;
pub mod report_parts;
pub mod result3d;
pub mod survey;
pub mod vtk;

pub use files::{read_any_model, read_model, write_all_or_nothing, write_atomic, IoError};
