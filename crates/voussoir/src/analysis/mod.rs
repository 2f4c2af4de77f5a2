//! Analyses: each is a composition of the structure, the kinematic map and the two LP forms.

pub mod adapt;
pub mod canonical;
pub mod canonical_friction;
pub mod laws;
pub mod limit;
pub mod nonassociative;
pub mod paths;
pub mod safety;
pub mod settlement;
pub mod tilt;

pub use limit::{limit, Crushing, LimitResult, LimitStatus};
pub use settlement::{settle, SettlementResult, SettlementStatus};
pub mod capacity;
pub mod identify;
pub use capacity::{capacity, CapacityOptions, CapacityResult};
pub mod incremental;
pub use incremental::{incremental, IncrementalOptions, IncrementalResult};
