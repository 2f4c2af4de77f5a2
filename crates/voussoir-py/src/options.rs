//! The one-line failure of the native module. The options of every analysis are a request's
//! (`voussoir::request`), built from the keywords by python/voussoir/_options.py.

/// A failure: one line; `Solver` for the solver's own failures, `Option` for an option of a
/// request out of range or in conflict (`voussoir.OptionError`, a `ModelError` and a
/// `ValueError`), `Model` for everything else.
#[derive(Debug)]
pub enum Fail {
    Model(String),
    Solver(String),
    Option(String),
}

impl From<voussoir::Error> for Fail {
    fn from(e: voussoir::Error) -> Self {
        match e {
            voussoir::Error::Solver(_) | voussoir::Error::Undecided => Fail::Solver(e.to_string()),
            voussoir::Error::Invalid(_) => Fail::Option(e.to_string()),
            _ => Fail::Model(e.to_string()),
        }
    }
}
impl From<voussoir_io::IoError> for Fail {
    fn from(e: voussoir_io::IoError) -> Self {
        Fail::Model(e.0)
    }
}
