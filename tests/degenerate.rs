//! The degenerate configurations of seed 000 (Figures 1, 3, 8, 11) and the classic overlay
//! degeneracies, checked exactly with expected values worked out by hand.

mod common;
use common::*;
use yinset::kernel::Point;
use yinset::yin2::{Homology, Location, YinError, YinSet2};

#[test]
fn two_components_touching_at_one_point() {
    // Fig. 3 / 11(a): two squares sharing the corner (1,1).
    let a = yin(vec![rect(0, 0, 1, 1), rect(1, 1, 2, 2)]);
    let b = a.betti();
    assert_eq!((b.components, b.total_holes), (2, 0));
    assert_eq!(area(&a), q(2, 1));
    // Fig. 11(b): the complement is one unbounded component with two touching holes.
    let c = valid(&a.complement()).clone();
    assert!(!c.is_bounded());
    assert_eq!(c.curves().len(), 2);
    assert_eq!(c.betti().components, 1);
    assert_eq!(c.betti().total_holes, 2);
    assert_eq!(c.complement(), a);
    // Homologically the two touching holes are one: ℝ² minus two closed squares sharing a
    // corner has one independent loop (around both).
    assert_eq!(a.homology(), Homology { b0: 2, b1: 0 });
    assert_eq!(c.homology(), Homology { b0: 1, b1: 1 });
}

#[test]
fn two_components_touching_at_two_points() {
    // Two L-free shapes touching at (1,1) and (1,3): left rect and a right notched polygon.
    let left = rect(0, 0, 1, 4);
    let right = ring(&[(1, 0), (3, 0), (3, 4), (1, 4), (1, 3), (2, 2), (1, 1)]);
    let res = YinSet2::from_curves(vec![left.clone(), right.clone()]);
    // They share the edges x = 1 between y ∈ [0,1] and [3,4]: rejected as shared edges.
    assert!(matches!(res, Err(YinError::SharedEdge { .. })), "{res:?}");
    // Touching only at two points (pocket in between): valid, two components, one pocket.
    let right = ring(&[(2, 0), (3, 0), (3, 4), (2, 4), (1, 3), (2, 2), (1, 1)]);
    let left = ring(&[(0, 0), (1, 1), (1, 3), (0, 4)]);
    let a = yin(vec![left, right]);
    assert_eq!(a.betti().components, 2);
    let c = valid(&a.complement()).clone();
    // Complement: the unbounded part with 2 holes, plus the pocket between the shapes.
    assert_eq!(c.betti().components, 2);
    assert_eq!(c.complement(), a);
}

#[test]
fn hole_touching_its_outer_curve() {
    // Fig. 1: a square with a triangular hole whose vertex touches the outer boundary at (2,0).
    let outer = rect(0, 0, 4, 4);
    let hole = rev(ring(&[(2, 0), (3, 2), (1, 2)]));
    let a = yin(vec![outer, hole]);
    assert_eq!(a.betti().components, 1);
    assert_eq!(a.betti().holes, vec![1]);
    assert_eq!(area(&a), q(16 - 2, 1));
    // The touching point became a vertex of the outer curve.
    assert!(a
        .curves()
        .iter()
        .all(|c| c.vertices().contains(&Point::int(2, 0))));
    // The pinched hole counts for the seed, not for homology: a loop around the triangle
    // must pass through (2,0), which is not in the set.
    assert_eq!(a.homology(), Homology { b0: 1, b1: 0 });
    let c = valid(&a.complement()).clone();
    assert_eq!(c.complement(), a);
    assert_eq!(c.betti().components, 2, "unbounded part + the triangle");
    // The outside of the square (a loop around it) and the open triangle (none).
    assert_eq!(c.homology(), Homology { b0: 2, b1: 1 });
}

#[test]
fn hole_touching_outer_at_two_points_is_not_one_atom() {
    let outer = rect(0, 0, 4, 4);
    let hole = rev(ring(&[(2, 0), (4, 2), (2, 4), (1, 2)]));
    let err = YinSet2::from_curves(vec![outer, hole]).unwrap_err();
    assert!(matches!(err, YinError::DisconnectedAtom { .. }), "{err}");
}

#[test]
fn component_touching_itself_through_a_hole() {
    // Fig. 8(a)-like: one component whose two holes touch each other at (2,2).
    let outer = rect(0, 0, 4, 4);
    let h1 = rev(ring(&[(1, 1), (2, 1), (2, 2)]));
    let h2 = rev(ring(&[(2, 2), (3, 2), (3, 3)]));
    let a = yin(vec![outer, h1, h2]);
    assert_eq!(a.betti().holes, vec![2]);
    assert_eq!(area(&a), q(16, 1) - q(1, 1));
    assert_eq!(valid(&a.complement()).complement(), a);
}

#[test]
fn vertex_on_another_curves_edge() {
    // A triangle whose apex touches the middle of the square's top edge from above.
    let sq = rect(0, 0, 2, 2);
    let tri = ring(&[(1, 2), (2, 3), (0, 3)]);
    let a = yin(vec![sq, tri]);
    assert_eq!(a.betti().components, 2);
    let m = a.meet(&yin(vec![rect(0, 1, 2, 3)]));
    valid(&m);
    assert_eq!(area(&m), q(2, 1) + q(1, 1));
    assert_eq!(m.betti().components, 2);
}

#[test]
fn collinear_overlap_same_direction() {
    // Two squares sharing the bottom edge direction partially: [0,2]² and [1,3]×[0,1].
    let a = yin(vec![rect(0, 0, 2, 2)]);
    let b = yin(vec![rect(1, 0, 3, 1)]);
    let m = valid(&a.meet(&b)).clone();
    assert_eq!(m, yin(vec![rect(1, 0, 2, 1)]));
    let j = valid(&a.join(&b)).clone();
    assert_eq!(
        j,
        yin(vec![ring(&[
            (0, 0),
            (3, 0),
            (3, 1),
            (2, 1),
            (2, 2),
            (0, 2)
        ])])
    );
}

#[test]
fn collinear_overlap_opposite_direction() {
    // Adjacent squares sharing the edge x = 1 with opposite directions.
    let a = yin(vec![rect(0, 0, 1, 1)]);
    let b = yin(vec![rect(1, 0, 2, 1)]);
    assert!(valid(&a.meet(&b)).is_empty());
    assert_eq!(valid(&a.join(&b)).clone(), yin(vec![rect(0, 0, 2, 1)]));
    // Partial overlap of the shared edge, opposite directions.
    let c = yin(vec![rect(1, 0, 2, 3)]);
    let u = valid(&yin(vec![rect(0, 1, 1, 2)]).join(&c)).clone();
    assert_eq!(area(&u), q(4, 1));
    assert_eq!(u.curves().len(), 1);
}

#[test]
fn idempotence_and_complement_laws() {
    let a = yin(vec![
        rect(0, 0, 4, 4),
        rev(rect(1, 1, 2, 2)),
        rect(5, 0, 6, 1),
    ]);
    assert_eq!(a.meet(&a), a);
    assert_eq!(a.join(&a), a);
    assert!(a.meet(&a.complement()).is_empty());
    assert!(a.join(&a.complement()).is_full());
}

#[test]
fn unbounded_yin_sets() {
    // The outside of a square, met with a larger square: an annulus.
    let outside = yin(vec![rev(rect(1, 1, 2, 2))]);
    assert!(!outside.is_bounded());
    assert_eq!(outside.area(), None);
    assert_eq!(outside.betti().holes, vec![1]);
    // ℝ² minus a closed square: a punctured plane, one loop.
    assert_eq!(outside.homology(), Homology { b0: 1, b1: 1 });
    assert_eq!(
        YinSet2::<yinset::num::Rational>::full().homology(),
        Homology { b0: 1, b1: 0 }
    );
    assert_eq!(
        YinSet2::<yinset::num::Rational>::empty().homology(),
        Homology::default()
    );
    let annulus = valid(&outside.meet(&yin(vec![rect(0, 0, 3, 3)]))).clone();
    assert_eq!(area(&annulus), q(8, 1));
    assert_eq!(annulus.betti().holes, vec![1]);
    assert_eq!(annulus.homology(), Homology { b0: 1, b1: 1 });
    // Join of two unbounded sets with overlapping holes: the hole is the intersection.
    let other = yin(vec![rev(rect(0, 0, 2, 2))]);
    let j = valid(&outside.join(&other)).clone();
    assert_eq!(j, yin(vec![rev(rect(1, 1, 2, 2))]));
    let p = [Point::int(10, 10), Point::int(1, 1)];
    assert_eq!(j.locate(&p), vec![Location::Inside, Location::OnBoundary]);
}

#[test]
fn island_inside_a_hole() {
    let a = yin(vec![
        rect(0, 0, 10, 10),
        rev(rect(2, 2, 8, 8)),
        rect(4, 4, 6, 6),
    ]);
    assert_eq!(a.betti().components, 2);
    assert_eq!(a.betti().total_holes, 1);
    assert_eq!(a.homology(), Homology { b0: 2, b1: 1 });
    assert_eq!(a.parents().iter().filter(|p| p.is_some()).count(), 2);
    assert_eq!(area(&a), q(100 - 36 + 4, 1));
    assert_eq!(valid(&a.complement()).complement(), a);
}

#[test]
fn validation_names_curve_and_vertex() {
    let bad = |c| Y::from_curves(c).unwrap_err();
    assert_eq!(
        bad(vec![ring(&[(0, 0), (1, 0)])]),
        YinError::TooFewVertices { curve: 0, count: 2 }
    );
    assert!(matches!(
        bad(vec![
            rect(0, 0, 1, 1),
            ring(&[(0, 0), (1, 0), (1, 0), (0, 1)])
        ]),
        YinError::RepeatedVertex {
            curve: 1,
            vertex: 2,
            ..
        }
    ));
    assert!(matches!(
        bad(vec![ring(&[(0, 0), (2, 2), (2, 0), (0, 2)])]),
        YinError::NotSimple { curve: 0, .. }
    ));
    assert!(matches!(
        bad(vec![rect(0, 0, 2, 2), rect(1, 1, 3, 3)]),
        YinError::ProperCrossing {
            curve_a: 0,
            curve_b: 1,
            ..
        }
    ));
    assert!(matches!(
        bad(vec![rect(0, 0, 2, 2), rect(2, 0, 3, 2)]),
        YinError::SharedEdge { .. }
    ));
    assert!(matches!(
        bad(vec![rect(0, 0, 4, 4), rect(1, 1, 2, 2)]),
        YinError::NestedSameOrientation {
            outer: 0,
            inner: 1,
            ..
        }
    ));
    assert!(matches!(
        bad(vec![rect(0, 0, 1, 1), rev(rect(3, 3, 4, 4))]),
        YinError::MixedOutermost { .. }
    ));
    assert_eq!(bad(vec![]), YinError::NoCurves);
    // A crossing through a shared vertex (no edge overlap): the curves pass through (1,1).
    let x1 = ring(&[(0, 0), (1, 1), (2, 0), (2, 2), (0, 2)]);
    let x2 = rev(ring(&[(1, 1), (3, 3), (-1, 3)]));
    assert!(matches!(bad(vec![x1, x2]), YinError::ProperCrossing { .. }));
}

#[test]
fn canonical_form_ignores_start_order_and_collinear_vertices() {
    let a = yin(vec![rect(0, 0, 2, 2), rect(3, 0, 4, 1)]);
    let b = yin(vec![
        ring(&[(4, 0), (4, 1), (3, 1), (3, 0)]),
        ring(&[(2, 2), (1, 2), (0, 2), (0, 0), (2, 0)]),
    ]);
    assert_eq!(a, b);
    use std::collections::hash_map::DefaultHasher;
    use std::hash::{Hash, Hasher};
    let h = |y: &Y| {
        let mut s = DefaultHasher::new();
        y.hash(&mut s);
        s.finish()
    };
    assert_eq!(h(&a), h(&b));
}
