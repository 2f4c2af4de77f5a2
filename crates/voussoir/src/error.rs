//! The library's one error type. Every message is one line and names what is wrong.

use std::borrow::Cow;
use thiserror::Error;

#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// The model is not a valid structure (bad polygon, overlap, isolated block, …).
    #[error("invalid model: {}", one_line(.0))]
    Model(String),
    /// A request that does not fit the model (unknown support name, bad option value, …).
    #[error("invalid request: {}", one_line(.0))]
    Request(String),
    /// An option of a request out of range or in conflict with another (or with the model),
    /// in the words of the front end that made it (its flag or keyword: `request::Names`):
    /// shown as is.
    #[error("{}", one_line(.0))]
    Invalid(String),
    /// The LP solver failed for a reason other than infeasibility or unboundedness.
    #[error("solver failure: {}", one_line(.0))]
    Solver(String),
    /// A solver ended without deciding whether the program is infeasible or unbounded (HiGHS's
    /// interior point: "unbounded or infeasible"). Not an answer: the fallback chain asks a
    /// method that decides with a certificate (Clarabel) next (`lp::with_fallback`). A variant of
    /// its own so that the chain matches the kind, not the text.
    #[error("solver failure: {}", crate::lp::highs::UNDECIDED)]
    Undecided,
}

/// `s` on one line: control characters (line breaks, tabs, NUL, …) written as escapes (`\n`),
/// so that a name or a value taken from the user's file cannot spread a message over several
/// lines (a support named "a\nb" in JSON, a layer name in a binary DXF).
pub fn one_line(s: &str) -> Cow<'_, str> {
    if !s.chars().any(char::is_control) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

pub type Result<T> = std::result::Result<T, Error>;

pub(crate) fn model_err<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::Model(msg.into()))
}
