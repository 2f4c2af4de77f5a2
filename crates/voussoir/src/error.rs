//! The library's one error type. Every message is one line and names what is wrong.

use thiserror::Error;

#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// The model is not a valid structure (bad polygon, overlap, isolated block, …).
    #[error("invalid model: {0}")]
    Model(String),
    /// A request that does not fit the model (unknown support name, bad option value, …).
    #[error("invalid request: {0}")]
    Request(String),
    /// The LP solver failed for a reason other than infeasibility or unboundedness.
    #[error("solver failure: {0}")]
    Solver(String),
}

pub type Result<T> = std::result::Result<T, Error>;

pub(crate) fn model_err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Model(msg.into()))
}
