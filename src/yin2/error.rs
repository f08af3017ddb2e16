//! Why user data is not a realizable spadjor (seed 000 Def. 3.15–3.17), naming curve and vertex.

use crate::num::Float;

/// A reason the curves given do not form a Yin set's boundary representation. Curve and vertex
/// indices are 0-based positions in the input as given.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum YinError {
    /// No curve at all (use `YinSet2::empty()` or `YinSet2::full()` for 0̂ and 1̂).
    #[error("no curves given: a spadjor is a non-empty set of Jordan curves (use empty() or full() for 0̂ and 1̂)")]
    NoCurves,
    /// A coordinate is NaN or infinite.
    #[error("curve {curve}, vertex {vertex}: coordinate is not finite")]
    NotFinite {
        /// The curve, counting from 0 in the order given.
        curve: usize,
        /// The vertex in its curve, counting from 0.
        vertex: usize,
    },
    /// A curve with fewer than 3 distinct vertices.
    #[error("curve {curve}: {count} vertices, a Jordan polygon needs at least 3")]
    TooFewVertices {
        /// The curve, counting from 0 in the order given.
        curve: usize,
        /// The number of distinct vertices.
        count: usize,
    },
    /// Two consecutive vertices are equal.
    #[error("curve {curve}, vertex {vertex}: repeats the previous vertex {point}")]
    RepeatedVertex {
        /// The curve, counting from 0 in the order given.
        curve: usize,
        /// The vertex in its curve, counting from 0.
        vertex: usize,
        /// The point where it happens, as text.
        point: String,
    },
    /// A curve meets itself other than at consecutive edges' shared vertex.
    #[error("curve {curve}, edge from vertex {vertex}: the curve is not simple, it meets itself at {point}")]
    NotSimple {
        /// The curve, counting from 0 in the order given.
        curve: usize,
        /// The vertex in its curve, counting from 0.
        vertex: usize,
        /// The point where it happens, as text.
        point: String,
    },
    /// Two curves cross properly.
    #[error("curves {curve_a} and {curve_b} cross at {point} (edges from vertices {vertex_a} and {vertex_b})")]
    ProperCrossing {
        /// The first curve.
        curve_a: usize,
        /// The first curve's edge, by its start vertex.
        vertex_a: usize,
        /// The second curve.
        curve_b: usize,
        /// The second curve's edge, by its start vertex.
        vertex_b: usize,
        /// The point where it happens, as text.
        point: String,
    },
    /// Two curves share a stretch of boundary.
    #[error("curves {curve_a} and {curve_b} share the edge from {from} to {to} (edges from vertices {vertex_a} and {vertex_b})")]
    SharedEdge {
        /// The first curve.
        curve_a: usize,
        /// The first curve's edge, by its start vertex.
        vertex_a: usize,
        /// The second curve.
        curve_b: usize,
        /// The second curve's edge, by its start vertex.
        vertex_b: usize,
        /// The shared edge's start, as text.
        from: String,
        /// The shared edge's end, as text.
        to: String,
    },
    /// A curve directly inside another of the same orientation.
    #[error("curve {inner} lies directly inside curve {outer} and both are {orientation} oriented: orientations must alternate with nesting (seed 000 Def. 3.16)")]
    NestedSameOrientation {
        /// The enclosing curve.
        outer: usize,
        /// The curve directly inside it.
        inner: usize,
        /// Both curves' orientation.
        orientation: &'static str,
    },
    /// Outermost curves of both orientations.
    #[error("outermost curves {positive} (positive) and {negative} (negative) cannot both be outermost: the set would be both bounded and unbounded (seed 000 Lemma 3.18)")]
    MixedOutermost {
        /// An outermost positively oriented curve.
        positive: usize,
        /// An outermost negatively oriented curve.
        negative: usize,
    },
    /// The curves of one atom touch in a cycle, so the atom's interior is not connected.
    #[error("curves {curves:?} of one atom touch each other in a cycle (at {point}), so its interior is not connected (seed 000 Def. 3.16(c))")]
    DisconnectedAtom {
        /// The curves concerned.
        curves: Vec<usize>,
        /// The point where it happens, as text.
        point: String,
    },
    /// Float mode: the grid of the requested ε cannot carry the input's coordinates (every
    /// coordinate must be at most 2⁵¹ grid steps from 0, see `Tolerance`).
    #[error("tolerance {:e} is too fine for these coordinates: the smallest ε whose grid can represent them is {:e}", .requested.get(), .representable.get())]
    ToleranceTooFine {
        /// The ε asked for.
        requested: Float,
        /// The finest ε the coordinates allow.
        representable: Float,
    },
    /// Float mode: the whole input vanishes when snapped to the grid of its ε.
    #[error("the input is thinner than the grid spacing {:e} of its tolerance and vanishes when snapped to it: use a smaller ε", .grid.get())]
    CollapsedOnGrid {
        /// The grid spacing of ε.
        grid: Float,
    },
    /// Pieces to paste that are not a union of closed cycles (an internal invariant).
    #[error("pasting map: the pieces are not closed cycles, one ends at {point}")]
    Unbalanced {
        /// The point where it happens, as text.
        point: String,
    },
    /// Snap rounding found a crossing it cannot resolve (an internal invariant).
    #[error("snap rounding made no progress on a crossing near grid point {point}")]
    SnapStalled {
        /// The point where it happens, as text.
        point: String,
    },
    /// The sweep for winding numbers found pieces stacked in a cycle (an internal invariant).
    #[error("winding sweep: the pieces above the one starting at {point} form a cycle")]
    SweepCycle {
        /// The point where it happens, as text.
        point: String,
    },
    /// `validate` found a set whose stored form is not the canonical one (an internal bug).
    #[error("the stored curves are not in canonical form")]
    NotCanonical,
}
