//! Fill rules: the Yin set covered by arbitrary rings (polygon soup) under a winding-number rule,
//! regularized, built from the arrangement of the rings, the winding numbers of its faces, and the
//! pasting map.
//!
//! Rings are closed polylines of any orientation that may cross, touch, overlap themselves and
//! each other, repeat vertices or have no area at all. The point set they fill is
//! {p off the rings : rule(w(p))} with w the winding number of all rings as given; the result is
//! its regularization (interior of the closure), a Yin set (seed 000 Def. 3.1). Degenerate
//! rings (fewer than 3 distinct points, zero area, spikes) add nothing to it.
//!
//! OGC polygons (exterior and holes in any orientation, rings that touch themselves or each
//! other at points, holes touching the shell) are filled correctly by [`FillRule::EvenOdd`]:
//! a point inside a valid polygon lies inside its exterior ring and in no hole. Multipolygons
//! whose parts overlap (invalid in OGC) are xor-ed by `EvenOdd`; to get their union, orient
//! every exterior counterclockwise and every hole clockwise (as GeoJSON RFC 7946 asks) and use
//! [`FillRule::NonZero`].
//!
//! Float mode (a context with an ε-grid) applies the same rule to the arrangement of the rings
//! snap-rounded to the grid (the `stage` module chooses).
//!
//! Cost: O((n + I) log n) for n ring edges with I contacts (one sweep: the arrangement with the
//! winding numbers of its faces).

use super::error::YinError;
use super::set::YinSet2;
use super::stage::{faces_where, resolve_for};
use crate::kernel::Point;
use crate::num::Num;

/// Which winding numbers are inside.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// Inside where the winding number is not zero.
    NonZero,
    /// Inside where the winding number is odd.
    EvenOdd,
}

impl FillRule {
    /// True if a point of winding number `w` is inside.
    fn inside(self, w: i64) -> bool {
        match self {
            FillRule::NonZero => w != 0,
            FillRule::EvenOdd => w % 2 != 0,
        }
    }
}

impl<N: Num> YinSet2<N> {
    /// The regularized set filled by `rings` under `rule` (see the module documentation), with
    /// the default context (float mode: ε from the input's extent). An error only for a
    /// coordinate that is not finite; no area at all gives 0̂.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::Rational, yin2::{FillRule, YinSet2}};
    /// let p = Point::<Rational>::int;
    /// // A bow-tie: two triangles of area 1 meeting at (1, 1), wound in opposite senses.
    /// let bow = vec![vec![p(0, 0), p(2, 2), p(2, 0), p(0, 2)]];
    /// let y = YinSet2::from_rings_filled(bow, FillRule::NonZero).unwrap();
    /// assert_eq!(y.area(), Some(Rational::from_integer(2.into())));
    /// assert_eq!(y.betti().components, 2);
    /// ```
    pub fn from_rings_filled(
        rings: Vec<Vec<Point<N>>>,
        rule: FillRule,
    ) -> Result<YinSet2<N>, YinError> {
        YinSet2::from_rings_filled_with(rings, rule, N::Ctx::default())
    }

    /// As [`YinSet2::from_rings_filled`], with the given context (float mode: the tolerance ε).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Float, Tolerance}, yin2::{FillRule, YinSet2}};
    /// let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
    /// // Two overlapping squares as polygon soup, in float mode: their union.
    /// let rings = vec![
    ///     vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 2.0), p(0.0, 2.0)],
    ///     vec![p(1.0, 1.0), p(3.0, 1.0), p(3.0, 3.0), p(1.0, 3.0)],
    /// ];
    /// let u = YinSet2::from_rings_filled_with(rings, FillRule::NonZero, Tolerance::new(1e-9))?;
    /// assert_eq!(u.area().unwrap().get(), 7.0);
    /// # Ok::<(), yinset::yin2::YinError>(())
    /// ```
    pub fn from_rings_filled_with(
        rings: Vec<Vec<Point<N>>>,
        rule: FillRule,
        ctx: N::Ctx,
    ) -> Result<YinSet2<N>, YinError> {
        for (c, ring) in rings.iter().enumerate() {
            if let Some(k) = ring
                .iter()
                .position(|p| !p.x.is_finite() || !p.y.is_finite())
            {
                return Err(YinError::NotFinite {
                    curve: c,
                    vertex: k,
                });
            }
        }
        let ctx = resolve_for(&rings, ctx)?;
        let labelled = rings.iter().map(|ring| (&ring[..], 0));
        faces_where(labelled, false, ctx, |w| rule.inside(w[0]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational, Tolerance};
    use proptest::prelude::*;
    use std::cmp::Ordering;

    type Y = YinSet2<Rational>;

    fn ring(c: &[(i64, i64)]) -> Vec<Point<Rational>> {
        c.iter().map(|&(x, y)| Point::int(x, y)).collect()
    }

    fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Vec<Point<Rational>> {
        ring(&[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
    }

    fn rev(mut v: Vec<Point<Rational>>) -> Vec<Point<Rational>> {
        v.reverse();
        v
    }

    fn yin(curves: Vec<Vec<Point<Rational>>>) -> Y {
        YinSet2::from_curves(curves).expect("hand-built expected set is valid")
    }

    /// The filled set, checked by the validator.
    fn fill(rings: Vec<Vec<Point<Rational>>>, rule: FillRule) -> Y {
        let y = YinSet2::from_rings_filled(rings, rule).expect("finite input");
        y.validate().expect("filled set is valid");
        y
    }

    fn area(y: &Y) -> Rational {
        y.area().expect("bounded")
    }

    fn int(v: i64) -> Rational {
        Rational::from_integer(v.into())
    }

    use FillRule::{EvenOdd, NonZero};

    #[test]
    fn bow_tie_is_two_triangles_touching_at_the_crossing() {
        let bow = ring(&[(0, 0), (2, 2), (2, 0), (0, 2)]);
        let expected = yin(vec![
            ring(&[(0, 0), (1, 1), (0, 2)]),
            ring(&[(2, 0), (2, 2), (1, 1)]),
        ]);
        for rule in [NonZero, EvenOdd] {
            let y = fill(vec![bow.clone()], rule);
            assert_eq!(y, expected, "{rule:?}");
            assert_eq!(area(&y), int(2));
            assert_eq!(y.betti().components, 2);
        }
    }

    #[test]
    fn figure_eight_touching_itself_at_a_vertex() {
        // Two unit-2 squares through (2, 2), both counterclockwise, then one lobe clockwise.
        let same = ring(&[
            (0, 0),
            (2, 0),
            (2, 2),
            (4, 2),
            (4, 4),
            (2, 4),
            (2, 2),
            (0, 2),
        ]);
        let twisted = ring(&[
            (0, 0),
            (2, 0),
            (2, 2),
            (2, 4),
            (4, 4),
            (4, 2),
            (2, 2),
            (0, 2),
        ]);
        let expected = yin(vec![rect(0, 0, 2, 2), rect(2, 2, 4, 4)]);
        for rule in [NonZero, EvenOdd] {
            for r in [&same, &twisted] {
                let y = fill(vec![r.clone()], rule);
                assert_eq!(y, expected, "{rule:?}");
                assert_eq!(area(&y), int(8));
            }
        }
    }

    #[test]
    fn overlapping_squares_union_under_nonzero_and_xor_under_evenodd() {
        let (a, b) = (rect(0, 0, 2, 2), rect(1, 1, 3, 3));
        let union = yin(vec![ring(&[
            (0, 0),
            (2, 0),
            (2, 1),
            (3, 1),
            (3, 3),
            (1, 3),
            (1, 2),
            (0, 2),
        ])]);
        let xor = yin(vec![
            ring(&[(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]),
            ring(&[(2, 1), (3, 1), (3, 3), (1, 3), (1, 2), (2, 2)]),
        ]);
        let y = fill(vec![a.clone(), b.clone()], NonZero);
        assert_eq!((y.clone(), area(&y)), (union.clone(), int(7)));
        let y = fill(vec![a.clone(), b.clone()], EvenOdd);
        assert_eq!((y.clone(), area(&y)), (xor.clone(), int(6)));
        // Opposite orientations cancel in the overlap: xor under both rules.
        assert_eq!(fill(vec![a.clone(), rev(b.clone())], NonZero), xor);
        // The kernel's own join and symmetric difference agree.
        let (ya, yb) = (yin(vec![a]), yin(vec![b]));
        assert_eq!(&ya | &yb, union);
        assert_eq!(&ya ^ &yb, xor);
    }

    #[test]
    fn duplicated_ring() {
        let sq = rect(0, 0, 2, 2);
        let twice = vec![sq.clone(), sq.clone()];
        assert_eq!(fill(twice.clone(), NonZero), yin(vec![sq.clone()]));
        assert!(fill(twice, EvenOdd).is_empty());
        for rule in [NonZero, EvenOdd] {
            assert!(fill(vec![sq.clone(), rev(sq.clone())], rule).is_empty());
        }
    }

    #[test]
    fn spikes_add_nothing() {
        // A spike out of the right edge and one into the square from the top edge.
        let spiky = ring(&[
            (0, 0),
            (2, 0),
            (2, 1),
            (4, 1),
            (2, 1),
            (2, 2),
            (1, 2),
            (1, 1),
            (1, 2),
            (0, 2),
        ]);
        for rule in [NonZero, EvenOdd] {
            let y = fill(vec![spiky.clone()], rule);
            assert_eq!(y, yin(vec![rect(0, 0, 2, 2)]), "{rule:?}");
            assert_eq!(area(&y), int(4));
        }
    }

    #[test]
    fn collinear_overlap_back_along_itself() {
        // The top edge runs from x = 4 to 1, back to 3, then on to 0.
        let r = ring(&[(0, 0), (4, 0), (4, 2), (1, 2), (3, 2), (0, 2)]);
        for rule in [NonZero, EvenOdd] {
            assert_eq!(fill(vec![r.clone()], rule), yin(vec![rect(0, 0, 4, 2)]));
        }
    }

    #[test]
    fn ogc_hole_touching_the_shell_at_a_vertex() {
        let shell = rect(0, 0, 4, 4);
        let hole = ring(&[(2, 0), (3, 2), (1, 2)]);
        let expected = yin(vec![shell.clone(), rev(hole.clone())]);
        // Even-odd needs no orientation: the hole as given, or reversed, or the shell reversed.
        for rings in [
            vec![shell.clone(), hole.clone()],
            vec![rev(shell.clone()), rev(hole.clone())],
        ] {
            let y = fill(rings, EvenOdd);
            assert_eq!(y, expected);
            assert_eq!(area(&y), int(14));
            assert_eq!(y.betti().holes, vec![1]);
        }
        assert_eq!(fill(vec![shell, rev(hole)], NonZero), expected);
    }

    #[test]
    fn rings_touching_themselves_make_inverted_holes() {
        // The shell dips to a vertex (2, 4) twice: the triangle between is a hole touching it.
        let top = ring(&[
            (0, 0),
            (4, 0),
            (4, 4),
            (2, 4),
            (3, 2),
            (1, 2),
            (2, 4),
            (0, 4),
        ]);
        let top_hole = ring(&[(2, 4), (3, 2), (1, 2)]);
        // The shell comes back to (0, 2), the middle of its left side, around a triangle.
        let side = ring(&[
            (0, 0),
            (4, 0),
            (4, 4),
            (0, 4),
            (0, 2),
            (2, 3),
            (2, 1),
            (0, 2),
        ]);
        let side_hole = ring(&[(0, 2), (2, 3), (2, 1)]);
        for (shell, hole) in [(top, top_hole), (side, side_hole)] {
            let expected = yin(vec![rect(0, 0, 4, 4), hole]);
            for rule in [NonZero, EvenOdd] {
                let y = fill(vec![shell.clone()], rule);
                assert_eq!(y, expected, "{rule:?}");
                assert_eq!(area(&y), int(14));
                assert_eq!(y.betti().total_holes, 1);
            }
        }
    }

    #[test]
    fn nested_rings_under_both_rules() {
        let rings = vec![rect(0, 0, 10, 10), rect(2, 2, 8, 8), rect(4, 4, 6, 6)];
        assert_eq!(fill(rings.clone(), NonZero), yin(vec![rect(0, 0, 10, 10)]));
        let y = fill(rings, EvenOdd);
        let expected = yin(vec![
            rect(0, 0, 10, 10),
            rev(rect(2, 2, 8, 8)),
            rect(4, 4, 6, 6),
        ]);
        assert_eq!(y, expected);
        assert_eq!(area(&y), int(100 - 36 + 4));
    }

    #[test]
    fn no_area_gives_the_empty_set() {
        let degenerate = vec![
            vec![],
            ring(&[(1, 1)]),
            ring(&[(0, 0), (3, 3)]),
            ring(&[(0, 0), (1, 1), (2, 2)]),
            ring(&[(0, 0), (0, 0), (0, 0)]),
            ring(&[(5, 5), (6, 5), (5, 5), (6, 5)]),
        ];
        for rule in [NonZero, EvenOdd] {
            assert!(fill(vec![], rule).is_empty());
            assert!(fill(degenerate.clone(), rule).is_empty());
        }
        // Degenerate rings next to a real one leave it alone; repeated and closing vertices too.
        let mut rings = degenerate;
        rings.push(ring(&[(0, 0), (0, 0), (2, 0), (2, 2), (0, 2), (0, 0)]));
        assert_eq!(fill(rings, EvenOdd), yin(vec![rect(0, 0, 2, 2)]));
    }

    #[test]
    fn non_finite_coordinates_are_an_error() {
        let f = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
        let rings = vec![
            vec![f(0.0, 0.0), f(1.0, 0.0), f(0.0, 1.0)],
            vec![f(0.0, 0.0), f(1.0, f64::NAN)],
        ];
        let got = YinSet2::from_rings_filled_with(rings, NonZero, Tolerance::new(1e-9));
        assert_eq!(
            got.err(),
            Some(YinError::NotFinite {
                curve: 1,
                vertex: 1
            })
        );
    }

    /// Coordinates k/10 as the nearest floats, as the float proptest makes them.
    fn tenths(c: &[(i64, i64)]) -> Vec<Point<Float>> {
        let f = |k: i64| Float::new(k as f64 * 0.1);
        c.iter().map(|&(x, y)| Point::new(f(x), f(y))).collect()
    }

    #[test]
    fn float_union_of_two_triangles() {
        // Two counterclockwise triangles; A's edge crosses B's vertical edge x = 0.2 at y = 0.25.
        let ctx = Tolerance::new(4e-10);
        let a = YinSet2::from_curves_with(vec![tenths(&[(1, 2), (3, 3), (0, 3)])], ctx).unwrap();
        let b = YinSet2::from_curves_with(vec![tenths(&[(0, 3), (2, 1), (2, 4)])], ctx).unwrap();
        let u = &a | &b;
        assert!(u.validate().is_ok());
        // The same union through the fill (the failing case the float proptest found).
        let rings = vec![
            tenths(&[(1, 2), (0, 3), (3, 3)]),
            tenths(&[(0, 3), (2, 4), (2, 1)]),
        ];
        let y = YinSet2::from_rings_filled_with(rings, NonZero, ctx).unwrap();
        assert!(y.validate().is_ok());
    }

    /// Twice the area of an integer polygon, and its orientation made counterclockwise.
    fn ccw(mut v: Vec<Point<Rational>>) -> Option<Vec<Point<Rational>>> {
        let n = v.len();
        let twice: Rational = (0..n)
            .map(|k| {
                let (p, q) = (&v[k], &v[(k + 1) % n]);
                p.x.clone() * q.y.clone() - q.x.clone() * p.y.clone()
            })
            .sum();
        match twice.sign() {
            Ordering::Equal => None,
            Ordering::Less => {
                v.reverse();
                Some(v)
            }
            Ordering::Greater => Some(v),
        }
    }

    /// The winding number of `p` (on no edge) by an independent oracle: signed crossings of the
    /// horizontal ray to the right, each edge taken half-open in y.
    fn winding(rings: &[Vec<Point<Rational>>], p: &Point<Rational>) -> i64 {
        let mut w = 0;
        for r in rings {
            for k in 0..r.len() {
                let (a, b) = (&r[k], &r[(k + 1) % r.len()]);
                let cross = (b.x.clone() - a.x.clone()) * (p.y.clone() - a.y.clone())
                    - (b.y.clone() - a.y.clone()) * (p.x.clone() - a.x.clone());
                if a.y <= p.y && p.y < b.y && cross.sign() == Ordering::Greater {
                    w += 1;
                } else if b.y <= p.y && p.y < a.y && cross.sign() == Ordering::Less {
                    w -= 1;
                }
            }
        }
        w
    }

    /// True if `p` is on an edge of a ring.
    fn on_rings(rings: &[Vec<Point<Rational>>], p: &Point<Rational>) -> bool {
        rings.iter().any(|r| {
            (0..r.len()).any(|k| {
                let (a, b) = (&r[k], &r[(k + 1) % r.len()]);
                let cross = (b.x.clone() - a.x.clone()) * (p.y.clone() - a.y.clone())
                    - (b.y.clone() - a.y.clone()) * (p.x.clone() - a.x.clone());
                let inside_box = a.x.clone().min(b.x.clone()) <= p.x
                    && p.x <= a.x.clone().max(b.x.clone())
                    && a.y.clone().min(b.y.clone()) <= p.y
                    && p.y <= a.y.clone().max(b.y.clone());
                cross.sign() == Ordering::Equal && inside_box
            })
        })
    }

    fn rings_on_grid(max_rings: usize) -> impl Strategy<Value = Vec<Vec<Point<Rational>>>> {
        let point = (0i64..5, 0i64..5).prop_map(|(x, y)| Point::int(x, y));
        proptest::collection::vec(proptest::collection::vec(point, 1..7), 0..=max_rings)
    }

    /// The rings with coordinates scaled by 1/10 as floats, and the same floats read exactly.
    type Scaled = (Vec<Vec<Point<Float>>>, Vec<Vec<Point<Rational>>>);
    fn scaled(rings: &[Vec<Point<Rational>>]) -> Scaled {
        let f = |v: &Rational| v.to_f64() * 0.1;
        let float = rings
            .iter()
            .map(|r| {
                r.iter()
                    .map(|p| Point::new(Float::new(f(&p.x)), Float::new(f(&p.y))))
                    .collect()
            })
            .collect();
        let exact = rings
            .iter()
            .map(|r| {
                r.iter()
                    .map(|p| {
                        let q = |v: &Rational| Rational::from_f64(f(v)).expect("finite");
                        Point::new(q(&p.x), q(&p.y))
                    })
                    .collect()
            })
            .collect();
        (float, exact)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: yinset_testkit::cases(300), failure_persistence: None, ..ProptestConfig::default() })]

        /// Float mode: the fill is valid and its area within 4 ε (ring length) of the exact
        /// fill of the same numbers.
        #[test]
        fn float_fill_is_valid_and_close_to_exact(rings in rings_on_grid(3)) {
            let (float, exact) = scaled(&rings);
            let eps = 1e-9 * 0.4;
            let length: f64 = float
                .iter()
                .flat_map(|r| (0..r.len()).map(move |k| (r[k].to_f64(), r[(k + 1) % r.len()].to_f64())))
                .map(|([x0, y0], [x1, y1])| (x1 - x0).hypot(y1 - y0))
                .sum();
            for rule in [NonZero, EvenOdd] {
                let y = YinSet2::from_rings_filled_with(float.clone(), rule, Tolerance::new(eps))
                    .expect("finite input");
                prop_assert!(y.validate().is_ok(), "{:?}: {:?}", rule, y.validate());
                let got = y.area().expect("bounded").to_f64();
                let want = area(&fill(exact.clone(), rule)).to_f64();
                prop_assert!((got - want).abs() <= 4.0 * eps * length, "{:?}: {} vs {}", rule, got, want);
            }
        }

        /// Membership on a fine grid of points off the rings agrees with the winding rule.
        #[test]
        fn membership_follows_the_winding_rule(rings in rings_on_grid(3)) {
            let step = Rational::new(1.into(), 3.into());
            let shift = Rational::new(1.into(), 7.into());
            let samples: Vec<Point<Rational>> = (0..15)
                .flat_map(|i| (0..15).map(move |j| (i, j)))
                .map(|(i, j)| Point::new(int(i) * step.clone() + shift.clone(), int(j) * step.clone()))
                .filter(|p| !on_rings(&rings, p))
                .collect();
            for rule in [NonZero, EvenOdd] {
                let y = fill(rings.clone(), rule);
                for (p, loc) in samples.iter().zip(y.locate(&samples)) {
                    let expected = if rule.inside(winding(&rings, p)) {
                        crate::yin2::Location::Inside
                    } else {
                        crate::yin2::Location::Outside
                    };
                    prop_assert_eq!(loc, expected, "{:?} at {}", rule, p);
                }
            }
        }

        /// Counterclockwise triangles: non-zero is the join and even-odd the symmetric
        /// difference of the rings' own fills, as the kernel computes them.
        #[test]
        fn fills_agree_with_the_kernel_algebra(rings in rings_on_grid(3)) {
            let triangles: Vec<Vec<Point<Rational>>> = rings
                .into_iter()
                .filter_map(|r| ccw(r.into_iter().take(3).collect()))
                .collect();
            let sets: Vec<Y> = triangles.iter().map(|t| yin(vec![t.clone()])).collect();
            let join = sets.iter().fold(Y::empty(), |acc, s| &acc | s);
            let xor = sets.iter().fold(Y::empty(), |acc, s| &acc ^ s);
            prop_assert_eq!(fill(triangles.clone(), NonZero), join);
            prop_assert_eq!(fill(triangles, EvenOdd), xor);
        }
    }
}
