//! # voussoir: rigid no-tension blocks in unilateral contact
//!
//! A masonry structure is a set of rigid 2D blocks resting on foundations (supports), under
//! Heyman's hypotheses: no tensile strength, no sliding, infinite compressive strength (finite
//! strength and friction are optional joint laws). Each block has three DOFs
//! `d_i = (u_i, v_i, θ_i)` at its centroid. Joints between touching bodies are discretised by
//! collocation points (the two ends of the contact segment), where the opening `N d + g_n ≥ 0`
//! and the sliding `T d + g_t = 0` are linear in `d` ([`discretize::KinematicMap`]).
//!
//! ## The linear programs (Tralli, Chiozzi, Grillanda, Milani 2020, Section 5)
//!
//! **Settlement, primal (62)–(66)**: the mechanism caused by prescribed support motions
//! ```text
//!   max  F_Dᵀ d   s.t.  N d + g_n ≥ 0,  T d + g_t = 0      (g: the settlement at each point)
//! ```
//! **Settlement, dual (69)–(71)**: contact forces and reactions
//! ```text
//!   min  g_nᵀ p_n + g_tᵀ p_t   s.t.  F_D + Nᵀ p_n + Tᵀ p_t = 0,  p_n ≥ 0
//! ```
//! Their optima coincide (strong duality); [`analysis::settlement`] solves both and reports the
//! gap as a certificate.
//!
//! **Limit analysis (Remark 3)**, static: `max λ  s.t.  F_D + λ F_L + Nᵀ p_n + Tᵀ p_t = 0,
//! p_n ≥ 0`; kinematic: its dual, the collapse mechanism with `F_Lᵀ d = 1`.
//!
//! Sign conventions: `n` points from body `a` into body `b`; opening ≥ 0; `p_n ≥ 0` is the
//! compressive force on `b` along `+n`. Units: m, kN, kN/m³, kPa, radians.
//!
//! ## Pipeline
//! [`model::Model`] (JSON, generators) → [`structure::Structure`] (validated, joints found) →
//! [`discretize::KinematicMap`] → [`programs`] (force and motion LPs) → [`lp`] (HiGHS) →
//! [`analysis`] → [`result`].

#[macro_use]
mod crack_fields;
pub mod analysis;
pub mod bench;
pub mod dim;
pub mod discretize;
pub mod duality;
pub mod error;
pub mod generate;
pub mod generate3d;
pub mod generate_facade;
pub mod geometry;
pub mod geometry3d;
pub mod lengths;
pub mod lp;
pub mod model;
pub mod model3d;
pub mod outline_mesh;
pub mod programs;
pub mod programs_identify;
pub mod reporting;
pub mod request;
pub mod result;
pub mod scale;
pub mod settlement_input;
pub mod structure;
pub mod support_split;
pub mod sweep;
pub mod vector;

pub use error::{Error, Result};
pub use model::Model;
pub use structure::{Assembly, BuildOptions, Structure, Structure3d};
