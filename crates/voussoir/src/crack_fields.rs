//! The derived fields of a result's crack record, read where a crack is given as input.
//!
//! A result's `cracks` (length, largest opening, joints, faces, ends, …) can be given back as
//! they are written: as the existing cracks of a model ([`crate::model::ExistingCrack`]) or as
//! the observed cracks of a survey ([`crate::analysis::identify::Crack`]). Both readers take
//! the nine derived fields and ignore them (`points` and `openings` carry the observation).
//! Both deny unknown fields, which `#[serde(flatten)]` does not combine with, so the fields are
//! written into each struct by [`crack_record!`], at the place the struct names, so that the
//! field order — and with it serde's "expected one of …" message — stays as it was.

/// A struct with the nine derived crack-record fields inserted between its two groups of
/// fields: `crack_record! { #[…] pub struct S { { fields before, } { fields after } } }`.
macro_rules! crack_record {
    (
        $(#[$meta:meta])*
        $vis:vis struct $name:ident {
            { $($before:tt)* }
            { $($after:tt)* }
        }
    ) => {
        $(#[$meta])*
        $vis struct $name {
            $($before)*
            /// The derived fields of a result's crack record (`length`, `max_opening`,
            /// `joints`, `faces`, `start`, `end`, `closed_loop`, `rise`, `run`), so that a
            /// result's `cracks` can be given as they are written: read, not used — `points`
            /// and `openings` carry the observation.
            #[serde(default, skip_serializing)]
            pub length: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub max_opening: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub joints: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub faces: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub start: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub end: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub closed_loop: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub rise: Option<serde_json::Value>,
            #[serde(default, skip_serializing)]
            pub run: Option<serde_json::Value>,
            $($after)*
        }
    };
}
