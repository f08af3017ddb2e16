//! Point/segment and segment/segment classification, and intersection points.

use super::point::{orient, Point};
use crate::num::Num;
use std::cmp::Ordering;

/// How two closed segments meet.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Contact<N> {
    /// No common point.
    Disjoint,
    /// The interiors cross at one point.
    Crossing(Point<N>),
    /// One common point, an endpoint of at least one segment (end-to-end or end-to-interior).
    Touching(Point<N>),
    /// A common stretch of positive length `[from, to]`, ordered along the first segment.
    Overlap(Point<N>, Point<N>),
}

/// True if `p`, known to be on the line through `a` and `b`, lies on the closed segment `ab`.
pub fn on_closed_segment<N: Num>(a: &Point<N>, b: &Point<N>, p: &Point<N>) -> bool {
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    lo <= p && p <= hi
}

/// Classify the closed segments `ab` and `cd` (each of positive length).
pub fn classify<N: Num>(
    a: &Point<N>,
    b: &Point<N>,
    c: &Point<N>,
    d: &Point<N>,
    ctx: &N::Ctx,
) -> Contact<N> {
    let o1 = orient(a, b, c, ctx);
    let o2 = orient(a, b, d, ctx);
    if o1 == Ordering::Equal && o2 == Ordering::Equal {
        return collinear(a, b, c, d);
    }
    let o3 = orient(c, d, a, ctx);
    let o4 = orient(c, d, b, ctx);
    let candidates = [(o1, a, b, c), (o2, a, b, d), (o3, c, d, a), (o4, c, d, b)];
    for (o, s, t, p) in candidates {
        if o == Ordering::Equal && on_closed_segment(s, t, p) {
            return Contact::Touching(p.clone());
        }
    }
    if apart(o1, o2) && apart(o3, o4) {
        return Contact::Crossing(crossing_point(a, b, c, d));
    }
    Contact::Disjoint
}

/// True if the interiors of the segments `ab` and `cd` cross at one point: the `Crossing` case
/// of [`classify`], decided without constructing the point.
pub fn crosses<N: Num>(
    a: &Point<N>,
    b: &Point<N>,
    c: &Point<N>,
    d: &Point<N>,
    ctx: &N::Ctx,
) -> bool {
    apart(orient(a, b, c, ctx), orient(a, b, d, ctx))
        && apart(orient(c, d, a, ctx), orient(c, d, b, ctx))
}

/// True if two orientations put two points strictly on opposite sides of a line.
fn apart(o: Ordering, p: Ordering) -> bool {
    o != Ordering::Equal && p == o.reverse()
}

/// Collinear segments: disjoint, touching at one point, or overlapping.
fn collinear<N: Num>(a: &Point<N>, b: &Point<N>, c: &Point<N>, d: &Point<N>) -> Contact<N> {
    let (s0, s1) = if a <= b { (a, b) } else { (b, a) };
    let (t0, t1) = if c <= d { (c, d) } else { (d, c) };
    let lo = s0.max(t0);
    let hi = s1.min(t1);
    match lo.cmp(hi) {
        Ordering::Greater => Contact::Disjoint,
        Ordering::Equal => Contact::Touching(lo.clone()),
        Ordering::Less if a <= b => Contact::Overlap(lo.clone(), hi.clone()),
        Ordering::Less => Contact::Overlap(hi.clone(), lo.clone()),
    }
}

/// The intersection of the lines `ab` and `cd` (not parallel), by [`Num::crossing`].
pub(crate) fn crossing_point<N: Num>(
    a: &Point<N>,
    b: &Point<N>,
    c: &Point<N>,
    d: &Point<N>,
) -> Point<N> {
    let [x, y] = N::crossing([&a.x, &a.y], [&b.x, &b.y], [&c.x, &c.y], [&d.x, &d.y]);
    Point::new(x, y)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn p(x: i64, y: i64) -> Point<Rational> {
        Point::int(x, y)
    }

    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn proper_crossing_is_exact() {
        let c = classify(&p(0, 0), &p(3, 1), &p(0, 1), &p(3, 0), &());
        assert_eq!(c, Contact::Crossing(Point::new(r(3, 2), r(1, 2))));
    }

    #[test]
    fn touching_at_endpoint_and_interior() {
        assert_eq!(
            classify(&p(0, 0), &p(2, 0), &p(1, 0), &p(1, 5), &()),
            Contact::Touching(p(1, 0))
        );
        assert_eq!(
            classify(&p(0, 0), &p(2, 0), &p(2, 0), &p(3, 5), &()),
            Contact::Touching(p(2, 0))
        );
    }

    #[test]
    fn collinear_cases() {
        assert_eq!(
            classify(&p(0, 0), &p(2, 0), &p(3, 0), &p(5, 0), &()),
            Contact::Disjoint
        );
        assert_eq!(
            classify(&p(0, 0), &p(2, 0), &p(2, 0), &p(5, 0), &()),
            Contact::Touching(p(2, 0))
        );
        assert_eq!(
            classify(&p(0, 0), &p(4, 0), &p(5, 0), &p(1, 0), &()),
            Contact::Overlap(p(1, 0), p(4, 0))
        );
        assert_eq!(
            classify(&p(4, 0), &p(0, 0), &p(1, 0), &p(5, 0), &()),
            Contact::Overlap(p(4, 0), p(1, 0))
        );
    }

    #[test]
    fn disjoint_near_miss() {
        assert_eq!(
            classify(&p(0, 0), &p(2, 2), &p(2, 0), &p(3, -1), &()),
            Contact::Disjoint
        );
    }
}
