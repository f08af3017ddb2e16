//! The vertices of the arrangement sweep: ends of input edges, and crossings of two edges held
//! implicitly — as the two edges, with an interval box — so that every predicate on them is
//! first decided by a floating-point filter and computed exactly only where the filter cannot
//! decide (indirect predicates, Attene 2020; the lazy exact kernel of CGAL). A crossing's exact
//! coordinates are made at most once: on a filter failure, or when it ends a piece of a result.

use crate::kernel::{crossing_point, orient, Point};
use crate::num::{Interval, Num};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// A point of the sweep: an end of an input edge or an implicit crossing.
pub(crate) enum Vertex<'a, N: Num> {
    /// An end of an input edge.
    Given(&'a Point<N>),
    /// The crossing of the interiors of two edges.
    Crossing(Crossing<'a, N>),
}

/// The crossing point of the interiors of two edges `(lo, hi)`, held implicitly.
pub(crate) struct Crossing<'a, N: Num> {
    /// The two edges' indices, smaller first: one pair has one crossing.
    edges: (usize, usize),
    /// The ends `lo, hi` of the first edge, then of the second.
    ends: [&'a Point<N>; 4],
    /// Intervals enclosing x and y (exact backends only; float mode makes the point at once).
    area: [Interval; 2],
    exact: OnceCell<Point<N>>,
}

/// The interval enclosing a coordinate (from [`Num::approx`]).
fn around<N: Num>(v: &N) -> Interval {
    Interval::around(v.approx())
}

impl<'a, N: Num> Crossing<'a, N> {
    /// The crossing of edges `i < j` with ends `s` and `t` (their interiors must cross).
    pub fn new(
        (i, j): (usize, usize),
        s: (&'a Point<N>, &'a Point<N>),
        t: (&'a Point<N>, &'a Point<N>),
    ) -> Crossing<'a, N> {
        let ends = [s.0, s.1, t.0, t.1];
        let exact = OnceCell::new();
        if !N::EXACT {
            let _ = exact.set(crossing_point(s.0, s.1, t.0, t.1));
            return Crossing {
                edges: (i, j),
                ends,
                area: [Interval::ENTIRE; 2],
                exact,
            };
        }
        let p = ends.map(|q| [around(&q.x), around(&q.y)]);
        // The point a + t (b − a) on each edge, t = ((c − a) × (d − c)) / ((b − a) × (d − c)),
        // t in [0, 1], inside both edges' boxes.
        let on = |[a, b, c, d]: [[Interval; 2]; 4]| {
            let cross = |u: [Interval; 2], v: [Interval; 2]| u[0] * v[1] - u[1] * v[0];
            let diff = |u: [Interval; 2], v: [Interval; 2]| [u[0] - v[0], u[1] - v[1]];
            let (ab, dc) = (diff(b, a), diff(d, c));
            let t = cross(diff(c, a), dc)
                .div(cross(ab, dc))
                .map_or(Interval::UNIT, |t| t.meet(Interval::UNIT));
            [0, 1].map(|k| {
                (a[k] + t * ab[k])
                    .meet(Interval::span(a[k], b[k]))
                    .meet(Interval::span(c[k], d[k]))
            })
        };
        let (x, y) = (on(p), on([p[2], p[3], p[0], p[1]]));
        Crossing {
            edges: (i, j),
            ends,
            area: [x[0].meet(y[0]), x[1].meet(y[1])],
            exact,
        }
    }

    /// The exact point, made on first use.
    fn exact(&self) -> &Point<N> {
        self.exact.get_or_init(|| {
            let [a, b, c, d] = self.ends;
            crossing_point(a, b, c, d)
        })
    }

    /// The order of points (lexicographic) against a point whose x is enclosed by `qx`, decided
    /// by the boxes where they are apart in x, by `exact` otherwise.
    fn cmp_filtered(&self, qx: Interval, exact: impl FnOnce() -> Ordering) -> Ordering {
        self.area[0].cmp(qx).unwrap_or_else(exact)
    }

    /// The order of points (lexicographic) against the given point `q`.
    pub fn cmp_point(&self, q: &Point<N>) -> Ordering {
        self.cmp_filtered(around(&q.x), || self.exact().cmp(q))
    }
}

impl<N: Num> PartialEq for Crossing<'_, N> {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

impl<N: Num> Eq for Crossing<'_, N> {}

impl<N: Num> PartialOrd for Crossing<'_, N> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

/// The order of points (lexicographic, the sweep's): filtered, exact where the boxes overlap.
impl<N: Num> Ord for Crossing<'_, N> {
    fn cmp(&self, o: &Self) -> Ordering {
        if self.edges == o.edges {
            return Ordering::Equal;
        }
        self.cmp_filtered(o.area[0], || self.exact().cmp(o.exact()))
    }
}

impl<'a, N: Num> Vertex<'a, N> {
    /// The exact point (a crossing's made now if not before).
    #[cfg(test)]
    pub fn point(&self) -> &Point<N> {
        match self {
            Vertex::Given(p) => p,
            Vertex::Crossing(c) => c.exact(),
        }
    }

    /// The exact point, owned (a crossing's made now if not before).
    pub fn into_point(self) -> Point<N> {
        match self {
            Vertex::Given(p) => p.clone(),
            Vertex::Crossing(c) => {
                let [a, b, d, e] = c.ends;
                c.exact
                    .into_inner()
                    .unwrap_or_else(|| crossing_point(a, b, d, e))
            }
        }
    }

    /// The order of points (lexicographic) of `self` against the given point `q`.
    pub fn cmp_point(&self, q: &Point<N>) -> Ordering {
        match self {
            Vertex::Given(p) => (*p).cmp(q),
            Vertex::Crossing(c) => c.cmp_point(q),
        }
    }

    /// The order of points of `self` against the crossing `c`.
    pub fn cmp_crossing(&self, c: &Crossing<'a, N>) -> Ordering {
        match self {
            Vertex::Given(p) => c.cmp_point(p).reverse(),
            Vertex::Crossing(d) => d.cmp(c),
        }
    }

    /// The Left test of `c` against the line from `self` to `to`, for `self` on the segment
    /// `from → to` and not at `to`: `from` is on the same ray, so a crossing is replaced by it
    /// and the test is on input points only (in float mode a given vertex is kept, as it lies
    /// on the segment only within ε).
    pub fn orient_along(
        &self,
        from: &Point<N>,
        to: &Point<N>,
        c: &Point<N>,
        ctx: &N::Ctx,
    ) -> Ordering {
        match self {
            Vertex::Given(p) => orient(p, to, c, ctx),
            Vertex::Crossing(_) => orient(from, to, c, ctx),
        }
    }

    /// The Left test of `self` against edge `e` = `lo → hi` (seed 002 Alg. 1): a crossing lies
    /// on its own edges; otherwise the sign of (hi − lo) × (v − lo) over the box, exact if the
    /// box cannot decide it.
    pub fn side(&self, e: usize, lo: &Point<N>, hi: &Point<N>, ctx: &N::Ctx) -> Ordering {
        let c = match self {
            Vertex::Given(p) => return orient(lo, hi, p, ctx),
            Vertex::Crossing(c) => c,
        };
        if e == c.edges.0 || e == c.edges.1 {
            return Ordering::Equal;
        }
        if N::EXACT {
            let (l, h) = (
                [around(&lo.x), around(&lo.y)],
                [around(&hi.x), around(&hi.y)],
            );
            let det = (h[0] - l[0]) * (c.area[1] - l[1]) - (h[1] - l[1]) * (c.area[0] - l[0]);
            if let Some(o) = det.sign() {
                return o;
            }
        }
        orient(lo, hi, c.exact(), ctx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::crosses;
    use crate::num::Rational;
    use proptest::prelude::*;

    /// `v` moved by `k` ulps.
    fn ulps(v: f64, k: i64) -> f64 {
        f64::from_bits((v.to_bits() as i64 + if v >= 0.0 { k } else { -k }) as u64)
    }

    fn pt(p: [f64; 2]) -> Point<Rational> {
        let q = |v: f64| Rational::from_f64(v).unwrap();
        Point::new(q(p[0]), q(p[1]))
    }

    /// The segment's ends in sweep order.
    fn lo_hi(s: &(Point<Rational>, Point<Rational>)) -> (&Point<Rational>, &Point<Rational>) {
        if s.0 <= s.1 {
            (&s.0, &s.1)
        } else {
            (&s.1, &s.0)
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The filtered predicates on an implicit crossing equal the exact predicates on its
        /// exact point, for crossings of nearly parallel segments (directions a few ulps apart)
        /// tested against points a few ulps from the crossing, lines through points a few ulps
        /// from it, and other crossings: a third segment nearly parallel through a point near
        /// it, one through the exact crossing (the degenerate case: equal points, a third edge
        /// through the vertex), which no filter can decide, and crossings and points far
        /// enough away for the filter to decide.
        #[test]
        fn filtered_crossing_predicates_are_exact_near_degeneracies(
            a in (-1e3f64..1e3, -1e3f64..1e3),
            d in (-1e3f64..1e3, -1e3f64..1e3),
            t in 0.1f64..0.9,
            tilt in (-4i64..=4, -4i64..=4),
            k in (-3i64..=3, -3i64..=3),
            far in (-1e3f64..1e3, -1e3f64..1e3),
            dir in (-5i64..=5, -5i64..=5),
        ) {
            let a = [a.0, a.1];
            let b = [a[0] + d.0, a[1] + d.1];
            let near = [a[0] + t * d.0, a[1] + t * d.1];
            let (d2x, d2y) = (ulps(d.0, tilt.0) / 2.0, ulps(d.1, tilt.1) / 2.0);
            let s1 = (pt(a), pt(b));
            let s2 = (pt([near[0] - d2x, near[1] - d2y]), pt([near[0] + d2x, near[1] + d2y]));
            prop_assume!(s1.0 != s1.1 && crosses(&s1.0, &s1.1, &s2.0, &s2.1, &()));
            let x = crossing_point(&s1.0, &s1.1, &s2.0, &s2.1);
            let c = Crossing::new((0, 1), lo_hi(&s1), lo_hi(&s2));
            let v = Vertex::Crossing(Crossing::new((0, 1), lo_hi(&s1), lo_hi(&s2)));
            // Points a few ulps from the crossing, and the crossing itself.
            let xf = x.to_f64();
            let q = pt([ulps(xf[0], k.0), ulps(xf[1], k.1)]);
            prop_assert_eq!(v.cmp_point(&q), x.cmp(&q));
            prop_assert_eq!(v.cmp_point(&x), Ordering::Equal);
            let r = pt([far.0, far.1]);
            prop_assert_eq!(v.cmp_point(&r), x.cmp(&r));
            // Lines through a point near the crossing, the other edge's line moved an ulp, and
            // lines far enough away for the filter to decide.
            prop_assume!(r != q);
            let moved = pt([ulps(near[0] - d2x, 1), near[1] - d2y]);
            let lines = [(&r, &q), (&q, &r), (&s1.0, &q), (&moved, &s2.1), (&r, &s1.0), (&s2.0, &r)];
            for (lo, hi) in lines {
                prop_assume!(lo != hi);
                prop_assert_eq!(v.side(7, lo, hi, &()), orient(lo, hi, &x, &()));
            }
            prop_assert_eq!(v.side(1, &s2.0, &s2.1, &()), Ordering::Equal);
            // A third edge through the exact crossing, and one nearly parallel near it.
            let step = Point::new(Rational::from_i64(dir.0), Rational::from_i64(dir.1));
            prop_assume!(dir != (0, 0));
            let through = (
                Point::new(x.x.clone() - step.x.clone(), x.y.clone() - step.y.clone()),
                Point::new(x.x.clone() + step.x.clone(), x.y.clone() + step.y.clone()),
            );
            let nearby = (pt([near[0] - d2x, ulps(near[1] - d2y, 2)]), s2.1.clone());
            // And edges across the first one well before and after the crossing.
            let across = |u: f64| {
                let m = [a[0] + u * d.0, a[1] + u * d.1];
                (pt([m[0] - d.1, m[1] + d.0]), pt([m[0] + d.1, m[1] - d.0]))
            };
            for s3 in [&through, &nearby, &across(0.05), &across(0.95)] {
                if crosses(&s1.0, &s1.1, &s3.0, &s3.1, &()) {
                    let y = crossing_point(&s1.0, &s1.1, &s3.0, &s3.1);
                    let e = Crossing::new((0, 2), lo_hi(&s1), lo_hi(s3));
                    prop_assert_eq!(c.cmp(&e), x.cmp(&y));
                    prop_assert_eq!(v.cmp_crossing(&e), x.cmp(&y));
                }
            }
        }
    }
}
