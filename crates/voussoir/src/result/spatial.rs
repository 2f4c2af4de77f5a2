//! Results in the dimension of the structure: the components a result reports per block, point
//! and support are vectors of the dimension (the result types are generic over [`Spatial`]).
//! The 2D field names are those voussoir has always written (`u, v, theta`, `x, y`,
//! `fx, fy, m, cx, cy`), so 2D results serialise exactly as before; 3D results write
//! `u, v, w, theta_x, theta_y, theta_z`, `x, y, z`, `fx, fy, fz, mx, my, mz, cx, cy, cz`, and two
//! components (along the joint's two tangents) for slips and shear forces.
//!
//! Every result type derefs to its components, so `block.u` or `hinge.x` read as fields.

use crate::dim::{Dim, Three, Two};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::fmt::Debug;

/// What a result needs of a dimension beyond the kinematics of [`Dim`].
pub trait Spatial: Dim {
    /// Block motion: translation of the reference point and rotation.
    type Motion: Clone + Debug + PartialEq + Serialize + DeserializeOwned + Send + Sync;
    /// A position.
    type Position: Clone + Debug + PartialEq + Serialize + DeserializeOwned + Send + Sync;
    /// A tangential quantity at a contact point: one value per tangent.
    type Tangential: Copy + Clone + Debug + PartialEq + Serialize + DeserializeOwned + Send + Sync;
    /// Force and moment of a support on the structure, with the point the moment is about.
    type Wrench: Clone + Debug + PartialEq + Serialize + DeserializeOwned + Send + Sync;
    /// The shapes a result refers to, so that a saved result can be drawn on its own.
    type Shapes: Clone + Debug + PartialEq + Serialize + DeserializeOwned + Send + Sync;
    /// A crack as results report it: a polyline in 2D ([`super::Crack`]), a record per
    /// cracked joint in 3D ([`super::Crack3d`]).
    type Crack: Clone
        + Debug
        + PartialEq
        + Serialize
        + DeserializeOwned
        + Send
        + Sync
        + super::cracks::CrackText;

    /// `Dim::DOFS` values as a motion.
    fn motion(dofs: &[f64]) -> Self::Motion;
    fn position(x: Self::Vector) -> Self::Position;
    /// `Dim::TANGENTS` values as a tangential quantity.
    fn tangential(values: &[f64]) -> Self::Tangential;
    /// Force `f` and moment `m` (`Dim::DOFS` values: force then moment) about `c`.
    fn wrench(fm: &[f64], c: Self::Vector) -> Self::Wrench;
    /// The coordinates of a position.
    fn coords(p: &Self::Position) -> Vec<f64>;
    /// The components of a wrench with their names and units, for summaries.
    fn wrench_components(w: &Self::Wrench) -> Vec<(&'static str, f64, &'static str)>;
}

/// A 2D block motion: `(u, v)` m and `θ` rad (counter-clockwise).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanarMotion {
    pub u: f64,
    pub v: f64,
    pub theta: f64,
}

/// A 3D block motion: `(u, v, w)` m and the rotation vector `(θx, θy, θz)` rad.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpatialMotion {
    pub u: f64,
    pub v: f64,
    pub w: f64,
    pub theta_x: f64,
    pub theta_y: f64,
    pub theta_z: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanarPoint {
    pub x: f64,
    pub y: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpatialPoint {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

/// Force `(fx, fy)` kN and moment `m` kN·m about `(cx, cy)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanarWrench {
    pub fx: f64,
    pub fy: f64,
    pub m: f64,
    pub cx: f64,
    pub cy: f64,
}

/// Force `(fx, fy, fz)` kN and moment `(mx, my, mz)` kN·m about `(cx, cy, cz)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpatialWrench {
    pub fx: f64,
    pub fy: f64,
    pub fz: f64,
    pub mx: f64,
    pub my: f64,
    pub mz: f64,
    pub cx: f64,
    pub cy: f64,
    pub cz: f64,
}

/// The shapes of a 3D result: block and support polyhedra (vertices and faces, outward
/// counter-clockwise), the supports' names and prescribed motions, and the applied loads.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SpatialShapes {
    pub blocks: Vec<Polyhedron>,
    /// Centroid of each block: the reference point of its motion (`u + θ × (x − c)`).
    pub centroids: Vec<[f64; 3]>,
    pub supports: Vec<SupportSolid>,
    pub loads: Vec<LoadArrow3d>,
}

/// A support of a 3D result.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SupportSolid {
    pub name: String,
    pub vertices: Vec<[f64; 3]>,
    pub faces: Vec<Vec<usize>>,
    /// Prescribed motion `[u, v, w, θx, θy, θz]` about the support's centroid.
    pub motion: [f64; 6],
    pub fixed: bool,
}

/// An applied load of a 3D result: force `(fx, fy, fz)` kN at `(x, y, z)` on `block`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct LoadArrow3d {
    pub block: usize,
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub fx: f64,
    pub fy: f64,
    pub fz: f64,
    pub live: bool,
}

pub use crate::model3d::Polyhedron;

impl Spatial for Two {
    type Motion = PlanarMotion;
    type Position = PlanarPoint;
    type Tangential = f64;
    type Wrench = PlanarWrench;
    type Shapes = super::Geometry;
    type Crack = super::Crack;

    fn motion(d: &[f64]) -> PlanarMotion {
        PlanarMotion {
            u: d[0],
            v: d[1],
            theta: d[2],
        }
    }
    fn position(x: [f64; 2]) -> PlanarPoint {
        PlanarPoint { x: x[0], y: x[1] }
    }
    fn tangential(v: &[f64]) -> f64 {
        v[0]
    }
    fn coords(p: &PlanarPoint) -> Vec<f64> {
        vec![p.x, p.y]
    }
    fn wrench_components(w: &PlanarWrench) -> Vec<(&'static str, f64, &'static str)> {
        vec![("fx", w.fx, "kN"), ("fy", w.fy, "kN"), ("m", w.m, "kN·m")]
    }
    fn wrench(fm: &[f64], c: [f64; 2]) -> PlanarWrench {
        PlanarWrench {
            fx: fm[0],
            fy: fm[1],
            m: fm[2],
            cx: c[0],
            cy: c[1],
        }
    }
}

impl Spatial for Three {
    type Motion = SpatialMotion;
    type Position = SpatialPoint;
    type Tangential = [f64; 2];
    type Wrench = SpatialWrench;
    type Shapes = SpatialShapes;
    type Crack = super::Crack3d;

    fn motion(d: &[f64]) -> SpatialMotion {
        SpatialMotion {
            u: d[0],
            v: d[1],
            w: d[2],
            theta_x: d[3],
            theta_y: d[4],
            theta_z: d[5],
        }
    }
    fn position(x: [f64; 3]) -> SpatialPoint {
        SpatialPoint {
            x: x[0],
            y: x[1],
            z: x[2],
        }
    }
    fn tangential(v: &[f64]) -> [f64; 2] {
        [v[0], v[1]]
    }
    fn coords(p: &SpatialPoint) -> Vec<f64> {
        vec![p.x, p.y, p.z]
    }
    fn wrench_components(w: &SpatialWrench) -> Vec<(&'static str, f64, &'static str)> {
        vec![
            ("fx", w.fx, "kN"),
            ("fy", w.fy, "kN"),
            ("fz", w.fz, "kN"),
            ("mx", w.mx, "kN·m"),
            ("my", w.my, "kN·m"),
            ("mz", w.mz, "kN·m"),
        ]
    }
    fn wrench(fm: &[f64], c: [f64; 3]) -> SpatialWrench {
        SpatialWrench {
            fx: fm[0],
            fy: fm[1],
            fz: fm[2],
            mx: fm[3],
            my: fm[4],
            mz: fm[5],
            cx: c[0],
            cy: c[1],
            cz: c[2],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{BlockMotion, Hinge, PointResult, Reaction};
    use super::*;

    #[test]
    fn results_write_the_components_of_their_dimension() {
        let b2: BlockMotion<Two> = BlockMotion::planar(3, 0.1, -0.2, 0.01);
        assert_eq!(
            serde_json::to_string(&b2).unwrap(),
            r#"{"id":3,"u":0.1,"v":-0.2,"theta":0.01}"#
        );
        let b3 = BlockMotion::<Three> {
            id: 1,
            motion: Three::motion(&[0.1, 0.2, 0.3, 0.01, 0.02, 0.03]),
        };
        let json = serde_json::to_string(&b3).unwrap();
        assert_eq!(
            json,
            r#"{"id":1,"u":0.1,"v":0.2,"w":0.3,"theta_x":0.01,"theta_y":0.02,"theta_z":0.03}"#
        );
        // Read back, and read as fields through the component.
        let back: BlockMotion<Three> = serde_json::from_str(&json).unwrap();
        assert_eq!(back, b3);
        assert_eq!((back.w, back.theta_z), (0.3, 0.03));
        let p = PointResult::<Three> {
            position: Three::position([1.0, 2.0, 3.0]),
            opening: 0.0,
            sliding: Three::tangential(&[0.5, -0.5]),
            normal_force: 4.0,
            shear_force: [1.0, 2.0],
            gap: 0.0,
        };
        assert_eq!(
            serde_json::to_string(&p).unwrap(),
            r#"{"x":1.0,"y":2.0,"z":3.0,"opening":0.0,"sliding":[0.5,-0.5],"normal_force":4.0,"shear_force":[1.0,2.0]}"#
        );
        let r = Reaction::<Three> {
            support: "base".into(),
            wrench: Three::wrench(&[0.0, 0.0, 10.0, 1.0, -1.0, 0.0], [0.5, 0.5, -0.5]),
        };
        assert_eq!((r.fz, r.my, r.cz), (10.0, -1.0, -0.5));
        let h = Hinge::<Two> {
            joint: 2,
            at: Two::position([0.5, 1.0]),
        };
        assert_eq!(
            serde_json::to_string(&h).unwrap(),
            r#"{"joint":2,"x":0.5,"y":1.0}"#
        );
    }
}
