//! Why user data is not the boundary of a 3D Yin set (seed 003 Def. 7.1–7.8; yin3 docs:
//! *Data model*, invariants I1–I4), naming the face or edge at fault.

use crate::kernel::Point3;
use crate::num::{short_f64, Float, Num, Rational};
use std::fmt;

/// A reason the faces given do not bound a 3D Yin set. Face and vertex indices are 0-based
/// positions in the input as given.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Yin3Error {
    /// No face at all (use `YinSet3::empty()` or `YinSet3::full()` for 0̂ and 1̂).
    #[error("no faces given: a boundary representation needs triangles (use empty() or full() for 0̂ and 1̂)")]
    NoFaces,
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex}: coordinate is not finite")]
    NotFinite {
        /// The vertex, counting from 0 in the order given.
        vertex: usize,
    },
    /// A face names a vertex that does not exist.
    #[error("face {face}: vertex index {index} is out of range (there are {count} vertices)")]
    IndexOutOfRange {
        /// The face, counting from 0 in the order given.
        face: usize,
        /// The vertex index the face names.
        index: usize,
        /// The number counted (vertices or faces).
        count: usize,
    },
    /// A face with fewer than 3 vertices or a repeated vertex.
    #[error("face {face}: {reason}")]
    DegenerateFace {
        /// The face, counting from 0 in the order given.
        face: usize,
        /// Why, in words.
        reason: String,
    },
    /// A face whose vertices are not coplanar.
    #[error("face {face}: its {count} vertices are not coplanar (vertex {vertex} is off the plane of the first three that span one)")]
    NonPlanarFace {
        /// The face, counting from 0 in the order given.
        face: usize,
        /// The number counted (vertices or faces).
        count: usize,
        /// The vertex, counting from 0 in the order given.
        vertex: usize,
    },
    /// Two faces cross each other.
    #[error(
        "faces {a} and {b} cross each other (their interiors meet along a segment through {point})"
    )]
    Crossing {
        /// The first face.
        a: usize,
        /// The second face.
        b: usize,
        /// A point where it happens.
        point: Spot,
    },
    /// Two coplanar faces overlap in an area.
    #[error("faces {a} and {b} are coplanar and overlap in an area around {point}")]
    Overlap {
        /// The first face.
        a: usize,
        /// The second face.
        b: usize,
        /// A point where it happens.
        point: Spot,
    },
    /// An edge with an odd number of faces: the surface is open there.
    #[error("the edge from {from} to {to} has {count} faces (face {face} among them): the surface is open there, every edge needs an even number")]
    OpenEdge {
        /// The edge's start.
        from: Spot,
        /// The edge's end.
        to: Spot,
        /// The number counted (vertices or faces).
        count: usize,
        /// The face, counting from 0 in the order given.
        face: usize,
    },
    /// Faces around an edge whose orientations do not alternate (invariant I3 of the yin3 docs,
    /// seed 003 Lemma 5.5(c)).
    #[error("faces {a} and {b} are neighbours around the edge from {from} to {to} with inconsistent orientations: around an edge, faces must alternate between bounding the set from one side and from the other")]
    Inconsistent {
        /// The edge's start.
        from: Spot,
        /// The edge's end.
        to: Spot,
        /// The first face.
        a: usize,
        /// The second face.
        b: usize,
    },
    /// A closed surface whose normals point the wrong way relative to the rest (invariant I4 of the
    /// yin3 docs).
    #[error("the closed surface through face {face} is oriented against the rest: the winding number on the side its normals point to is {winding}, not {expected} (normals must point out of the set, by the right-hand rule)")]
    Orientation {
        /// The face, counting from 0 in the order given.
        face: usize,
        /// The winding number found.
        winding: i64,
        /// The winding number a valid set has there.
        expected: i64,
    },
    /// Float mode: ε is too fine for the coordinates (as in 2D, `Tolerance`).
    #[error("tolerance {:e} is too fine for coordinates of this magnitude: the smallest usable is {:e}", .requested.get(), .representable.get())]
    ToleranceTooFine {
        /// The ε asked for.
        requested: Float,
        /// The finest ε the coordinates allow.
        representable: Float,
    },
    /// Float mode: the result has no valid representation with `f64` vertices (the exact
    /// result, rounded to the nearest `f64`s, is not a valid boundary or has another topology).
    #[error("the float result is not representable: the exact result rounded to f64 is not a valid boundary with its topology ({0}); use exact mode")]
    Unrepresentable(String),
    /// `validate` found a stored set that breaks an invariant (an internal bug).
    #[error("internal invariant broken: {0}")]
    Internal(String),
}

/// A point named in an error, shown exactly, or in float mode as its nearest `f64`s (shortest,
/// in scientific notation when very large or small; `≈` where rounded), its exact value kept
/// in [`Spot::exact`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Spot {
    exact: Box<Point3<Rational>>,
    rounded: bool,
}

impl Spot {
    /// The point `p`, shown exactly.
    pub(crate) fn new<N: Num>(p: &Point3<N>) -> Spot {
        let r = |v: &N| {
            let (n, d) = v.fraction();
            Rational::new(n, d)
        };
        Spot {
            exact: Box::new(Point3::new(r(&p.x), r(&p.y), r(&p.z))),
            rounded: false,
        }
    }

    /// The exact point.
    pub fn exact(&self) -> &Point3<Rational> {
        &self.exact
    }

    /// The point shown as its nearest `f64`s if `rounded` (a point of a float-mode input, whose
    /// validity is decided on its exact values), else exactly.
    pub(crate) fn shown(self, rounded: bool) -> Spot {
        Spot { rounded, ..self }
    }
}

impl fmt::Display for Spot {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let near = self.exact.to_f64();
        if !self.rounded || near.iter().any(|v| !v.is_finite()) {
            return write!(f, "{}", self.exact);
        }
        let off = self
            .exact
            .coords()
            .iter()
            .zip(near)
            .any(|(x, v)| Rational::from_float(v).as_ref() != Some(*x));
        let [x, y, z] = near.map(short_f64);
        write!(f, "{}({x}, {y}, {z})", if off { "≈ " } else { "" })
    }
}
