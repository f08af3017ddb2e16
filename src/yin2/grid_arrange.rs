//! Float mode's arrangement of snapped grid fragments: the sweep of seed 002 §1.3 that
//! [`super::intersect::arrange`] runs on any number type, specialised to segments with integer
//! ends that should not cross — events at segment ends only, exact `i128` orientations, no
//! implicit vertex, no filter, no construction. A pair found crossing is reported
//! ([`Arrangement::crossed`]) for the snap rounding to resolve.

use super::arrangement::{Arrangement, Recorder};
use super::buckets::Buckets;
use super::status::{Status, NIL};
use crate::kernel::Point;
use crate::num::Float;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{CheckedAdd, CheckedMul, CheckedSub, Signed, ToPrimitive};
use std::cmp::Ordering;

/// A grid point: integer multiples of the grid spacing, relative to the local origin (below
/// 2⁵² in magnitude, so that every orientation below is exact in `i128`).
pub(crate) type G = (i64, i64);

/// The point of grid coordinates `k` in grid units: integers below 2⁵², exact `f64`s, on which
/// the `f64` predicates are exact.
pub(crate) fn unit(k: G) -> Point<Float> {
    Point::new(Float::new(k.0 as f64), Float::new(k.1 as f64))
}

/// The sign of (b − a) × (c − a), exactly (coordinates below 2⁶² in magnitude).
pub(crate) fn orient_g(a: G, b: G, c: G) -> Ordering {
    let d = |p: G, q: G| ((q.0 - p.0) as i128, (q.1 - p.1) as i128);
    let (u, v) = (d(a, b), d(a, c));
    (u.0 * v.1).cmp(&(u.1 * v.0))
}

/// True if the interiors of segments `s` and `t` cross at one point that is inside both.
pub(crate) fn cross_properly(s: (G, G), t: (G, G)) -> bool {
    let opposite = |x: Ordering, y: Ordering| x != Ordering::Equal && x == y.reverse();
    opposite(orient_g(s.0, s.1, t.0), orient_g(s.0, s.1, t.1))
        && opposite(orient_g(t.0, t.1, s.0), orient_g(t.0, t.1, s.1))
}

/// The pixel (nearest grid point, ties up) of the crossing of the lines `ab` and `cd`, exactly:
/// read off a horizontal and a vertical line, else in `i128` when it cannot overflow, else in
/// big integers (coordinates below 2⁵² need up to 160 bits).
pub(crate) fn crossing_pixel(s: (G, G), t: (G, G)) -> G {
    // A horizontal and a vertical segment (rectilinear input) cross at a grid point.
    let (vertical, horizontal) = (|(a, b): (G, G)| a.0 == b.0, |(a, b): (G, G)| a.1 == b.1);
    if horizontal(s) && vertical(t) {
        return (t.0 .0, s.0 .1);
    }
    if vertical(s) && horizontal(t) {
        return (s.0 .0, t.0 .1);
    }
    pixel_in::<i128>(s, t)
        .or_else(|| pixel_in::<BigInt>(s, t))
        .expect("the pixel of a crossing of two grid segments is a grid point")
}

/// [`crossing_pixel`] in the integer type `T`, `None` on overflow.
fn pixel_in<T>(s: (G, G), t: (G, G)) -> Option<G>
where
    T: Integer + Signed + Clone + From<i64> + CheckedMul + CheckedAdd + CheckedSub + ToPrimitive,
{
    let ((a, b), (c, d)) = (s, t);
    let w = |p: G| (T::from(p.0), T::from(p.1));
    let (a, b, c, d) = (w(a), w(b), w(c), w(d));
    let sub = |x: &T, y: &T| x.checked_sub(y);
    let cross = |u: (T, T), v: (T, T)| u.0.checked_mul(&v.1)?.checked_sub(&u.1.checked_mul(&v.0)?);
    let ab = (sub(&b.0, &a.0)?, sub(&b.1, &a.1)?);
    let cd = (sub(&d.0, &c.0)?, sub(&d.1, &c.1)?);
    let ca = (sub(&c.0, &a.0)?, sub(&c.1, &a.1)?);
    let mut den = cross(ab.clone(), cd.clone())?;
    let mut num = cross(ca, cd)?;
    if den.is_negative() {
        den = -den;
        num = -num;
    }
    // coordinate = a + num/den · ab;
    // pixel = floor(coordinate + 1/2) = floor((2(a·den + num·ab) + den) / 2den).
    let two = T::from(2);
    let round = |a0: &T, ab0: &T| -> Option<i64> {
        let top = a0.checked_mul(&den)?.checked_add(&num.checked_mul(ab0)?)?;
        let top = top.checked_mul(&two)?.checked_add(&den)?;
        top.div_floor(&den.checked_mul(&two)?).to_i64()
    };
    Some((round(&a.0, &ab.0)?, round(&a.1, &ab.1)?))
}

/// The arrangement of the grid segments `spans` (each of positive length, given by the indices
/// of its ends in `points`, which are sorted and distinct; seed 002 §1.3): every segment cut at
/// every segment end inside it, collinear stretches grouped, and for each piece the piece
/// directly below it, as [`super::intersect::arrange`] records them. Segments whose interiors
/// cross are reported in [`Arrangement::crossed`] (the sweep finds one if there is any; past the
/// first, the rest of the arrangement is not valid). O(n log n + m) for n segments and m points.
pub(crate) fn arrange_grid(
    points: &[G],
    spans: impl Iterator<Item = (usize, usize)> + Clone,
) -> Arrangement<G> {
    // Each segment lo → hi in the sweep order (lexicographic: the sweep line is tilted
    // infinitesimally, and a vertical segment runs from its lower end to its upper one), as
    // indices of `points`, whose order is the sweep's.
    let span = spans.map(|(i, j)| (i.min(j), i.max(j)));
    // The segment ends at each point: 2·segment + 1 for an upper end.
    let ends = span
        .clone()
        .enumerate()
        .flat_map(|(e, (i, j))| [(i, 2 * e), (j, 2 * e + 1)]);
    let at = Buckets::new(points.len(), ends);
    let seg: Vec<(G, G)> = span.map(|(i, j)| (points[i], points[j])).collect();
    let mut sweep = GridSweep {
        seg: &seg,
        points,
        at: &at,
        status: Status::new(seg.len()),
        record: Recorder::new(seg.len()),
    };
    let (mut old, mut next, mut stamp) = (Vec::new(), Vec::new(), 0);
    for (k, &p) in points.iter().enumerate() {
        let codes = at.get(k);
        if codes.is_empty() {
            continue;
        }
        old.clear();
        next.clear();
        for &code in codes {
            if code % 2 == 1 {
                old.push(code / 2);
            } else {
                next.push(code / 2);
            }
        }
        if old.len() == next.len()
            && old.len() <= PASS_MOST
            && sweep.pass(p, stamp, &old, &mut next)
        {
            stamp += 1;
            continue;
        }
        for &e in &old {
            sweep.status.remove(e);
        }
        sweep.event(p, stamp, &mut old, &mut next);
        stamp += 1;
    }
    sweep.record.finish()
}

/// The most segments that may end (and start) at an event for [`GridSweep::pass`] to try
/// replacing them in place.
const PASS_MOST: usize = 4;

/// The state of [`arrange_grid`]'s sweep.
struct GridSweep<'a> {
    seg: &'a [(G, G)],
    points: &'a [G],
    /// The segment ends at each point of `points` (2·segment + 1 for an upper end).
    at: &'a Buckets,
    status: Status,
    record: Recorder<G>,
}

impl GridSweep<'_> {
    /// Event `p`, numbered `stamp`: the segments `old` end here (out of the status already),
    /// the segments `next` start here. Takes the segments through `p` out of the status, ends
    /// their pieces, and puts every segment going on past `p` back by its direction after `p`.
    fn event(&mut self, p: G, stamp: usize, old: &mut Vec<usize>, next: &mut Vec<usize>) {
        let seg = self.seg;
        let status = &mut self.status;
        // The segments with p inside form the middle of the status.
        let side = |t: usize| orient_g(seg[t].0, seg[t].1, p);
        let (below, rest) = status.split(status.root, |t| side(t) != Ordering::Greater);
        let (on, above) = status.split(rest, |t| side(t) == Ordering::Less);
        let ended = old.len();
        status.collect(on, old);
        for &s in old.iter() {
            status.reset(s);
            status.live[s] = false;
        }
        self.record.close(old, stamp);
        next.extend(&old[ended..]);
        // Bottom to top by direction after p (every direction points into the half-plane after
        // p in sweep order, where orientation orders them), ties by index.
        let turn = |a: usize, b: usize| orient_g(p, seg[a].1, seg[b].1);
        next.sort_unstable_by(|&a, &b| turn(a, b).reverse().then(a.cmp(&b)));
        let (lower, upper) = status.rejoin(below, next, above);
        match (next.first(), next.last()) {
            (Some(&f), Some(&l)) => {
                self.check(lower, f);
                self.check(l, upper);
            }
            _ => self.check(lower, upper),
        }
        let same = |k: usize| turn(next[k - 1], next[k]) == Ordering::Equal;
        self.record.open(p, next, lower, same);
    }

    /// Event `p`, numbered `stamp`, where the segments `ended` end and as many segments
    /// `started` start (a vertex of one curve, or where curves touch, the common cases): if the
    /// ended ones are neighbours in the status and no other segment passes through `p`, the
    /// started ones take their places in the status in the order of [`GridSweep::event`]
    /// (without searching it), and true; else nothing is done and false.
    fn pass(&mut self, p: G, stamp: usize, ended: &[usize], started: &mut [usize]) -> bool {
        let (seg, status) = (self.seg, &self.status);
        let ends_here = |t: usize| t != NIL && ended.contains(&t);
        let (mut low, mut lower) = (ended[0], status.before(ended[0]));
        while ends_here(lower) {
            (low, lower) = (lower, status.before(lower));
        }
        // The ended segments bottom to top.
        let mut order = [NIL; PASS_MOST];
        order[0] = low;
        let mut upper = status.after(low);
        for slot in order.iter_mut().take(ended.len()).skip(1) {
            if !ends_here(upper) {
                return false;
            }
            *slot = upper;
            upper = status.after(upper);
        }
        // The segments through p are neighbours in the status, and the ended ones are among them.
        let through = |t: usize| t != NIL && orient_g(seg[t].0, seg[t].1, p) == Ordering::Equal;
        if through(lower) || through(upper) {
            return false;
        }
        let turn = |a: usize, b: usize| orient_g(p, seg[a].1, seg[b].1);
        if started.len() > 1 {
            started.sort_unstable_by(|&a, &b| turn(a, b).reverse().then(a.cmp(&b)));
        }
        for (&old, &new) in order.iter().zip(started.iter()) {
            self.status.replace(old, new);
        }
        self.record.close(ended, stamp);
        self.check(lower, started[0]);
        self.check(started[started.len() - 1], upper);
        let same = |k: usize| turn(started[k - 1], started[k]) == Ordering::Equal;
        self.record.open(p, started, lower, same);
        true
    }

    /// Report neighbours `s` and `t` if their interiors cross away from every event (at an
    /// event, both are cut: the crossing is a vertex of the arrangement).
    fn check(&mut self, s: usize, t: usize) {
        if s == NIL || t == NIL {
            return;
        }
        // Neighbours apart in y (the common case) cannot cross.
        let ys = |(a, b): (G, G)| (a.1.min(b.1), a.1.max(b.1));
        let ((s0, s1), (t0, t1)) = (ys(self.seg[s]), ys(self.seg[t]));
        if s1 <= t0 || t1 <= s0 || !cross_properly(self.seg[s], self.seg[t]) {
            return;
        }
        // The crossing is a grid point exactly when its pixel's centre lies on both segments.
        let c = crossing_pixel(self.seg[s], self.seg[t]);
        let on = |(a, b): (G, G)| orient_g(a, b, c) == Ordering::Equal;
        let event = self
            .points
            .binary_search(&c)
            .is_ok_and(|k| !self.at.get(k).is_empty());
        if !(event && on(self.seg[s]) && on(self.seg[t])) {
            self.record.cross(s.min(t), s.max(t));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{classify, Contact, Point};
    use crate::num::Rational;
    use crate::yin2::intersect::{arrange, lattice_segment};
    use proptest::prelude::*;

    fn point<N: crate::num::Num>(g: G) -> Point<N> {
        Point::int(g.0, g.1)
    }

    /// True if the interiors of `s` and `t` cross, by the exact kernel's classification, at a
    /// point that is none of the `ends` (a crossing at a segment end is a vertex of the
    /// arrangement like any other).
    fn crossing(s: (G, G), t: (G, G), ends: &[G]) -> bool {
        let p = point::<Rational>;
        match classify(&p(s.0), &p(s.1), &p(t.0), &p(t.1), &()) {
            Contact::Crossing(x) => !ends.iter().any(|&e| p(e) == x),
            _ => false,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: yinset_testkit::cases(2000), failure_persistence: None, ..ProptestConfig::default() })]

        /// The grid sweep reports a crossing exactly when two segments cross away from every
        /// segment end (the exact kernel's classification of every pair), and otherwise
        /// records the arrangement that the exact sweep of `arrange` records on the same
        /// segments as rationals (which cuts them at their crossings, all at segment ends
        /// here): the same events, pieces, pieces below and edges of every piece. Half the
        /// cases keep only segments that cross none kept before them (touching, overlapping,
        /// T-junctions and repeats stay); the points given hold some that no segment ends at,
        /// where a crossing is still one.
        #[test]
        fn grid_sweep_records_the_exact_sweeps_arrangement(
            drawn in proptest::collection::vec(lattice_segment(6), 0..30),
            uncrossed in any::<bool>(),
            unused in proptest::collection::vec((0..=6i64, 0..=6i64), 0..6),
        ) {
            let mut segs: Vec<(G, G)> = Vec::new();
            for s in drawn.into_iter().filter(|s| s.0 != s.1) {
                if !uncrossed || segs.iter().all(|&t| !crossing(s, t, &[])) {
                    segs.push(s);
                }
            }
            let ends: Vec<G> = segs.iter().flat_map(|&(a, b)| [a, b]).collect();
            let any_crossing = (0..segs.len())
                .any(|i| (0..i).any(|j| crossing(segs[i], segs[j], &ends)));
            let mut points = ends.clone();
            points.extend(unused);
            points.sort_unstable();
            points.dedup();
            let index = |g: G| points.binary_search(&g).unwrap();
            let got = arrange_grid(&points, segs.iter().map(|&(a, b)| (index(a), index(b))));
            prop_assert_eq!(!got.crossed.is_empty(), any_crossing);
            for &(i, j) in &got.crossed {
                prop_assert!(i < j && crossing(segs[i], segs[j], &ends));
            }
            if any_crossing {
                return Ok(());
            }
            let q = point::<Rational>;
            let edges: Vec<_> = segs.iter().map(|&(a, b)| (q(a), q(b))).collect();
            let want = arrange(&edges, &());
            let points: Vec<Point<Rational>> = got.points.iter().map(|&g| q(g)).collect();
            let want_points: Vec<_> = want.points.iter().map(|v| v.point().clone()).collect();
            prop_assert_eq!(points, want_points);
            prop_assert_eq!(groups(&got), groups(&want));
        }
    }

    /// A grid point at one of three scales: a small lattice (where segments run parallel to
    /// the axes and cross at pixel centres and edges), 2³⁹ and 2⁵⁰ (where `i128` overflows and
    /// big integers take over).
    fn scaled_point() -> impl Strategy<Value = G> {
        prop_oneof![
            (0..8i64, 0..8i64),
            (-(1i64 << 39)..1 << 39, -(1i64 << 39)..1 << 39),
            (-(1i64 << 50)..1 << 50, -(1i64 << 50)..1 << 50),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: yinset_testkit::cases(3000), failure_persistence: None, ..ProptestConfig::default() })]

        /// The pixel of a crossing is its exact rational crossing point rounded to the nearest
        /// grid point, ties up. The second segment is drawn anywhere, near the first (so that
        /// pairs at large coordinates cross often), or parallel to an axis through the
        /// middle of the first's box; the first is flattened onto an axis a third of the time.
        #[test]
        fn crossing_pixels_round_the_exact_crossing(
            s in (scaled_point(), scaled_point()),
            t in (scaled_point(), scaled_point()),
            how in 0..4u8,
            flat in 0..3u8,
        ) {
            let s = match flat {
                0 => (s.0, (s.1.0, s.0.1)),
                _ => s,
            };
            let (lo, hi) = ((s.0.0.min(s.1.0), s.0.1.min(s.1.1)), (s.0.0.max(s.1.0), s.0.1.max(s.1.1)));
            let mid = ((lo.0 + hi.0) / 2, (lo.1 + hi.1) / 2);
            let t = match how {
                0 => t,
                1 => ((s.0.0 + t.0.0 % 8, s.1.1 - t.0.1 % 8), (s.1.0 - t.1.0 % 8, s.0.1 + t.1.1 % 8)),
                2 => ((mid.0, lo.1 - 1), (mid.0, hi.1 + 1)),
                _ => ((lo.0 - 1, mid.1), (hi.0 + 1, mid.1)),
            };
            let p = point::<Rational>;
            let Contact::Crossing(x) = classify(&p(s.0), &p(s.1), &p(t.0), &p(t.1), &()) else {
                return Ok(());
            };
            let round = |v: &Rational| {
                let twice = BigInt::from(2) * v.numer() + v.denom();
                twice.div_floor(&(BigInt::from(2) * v.denom())).to_i64().expect("a grid point")
            };
            prop_assert_eq!(crossing_pixel(s, t), (round(&x.x), round(&x.y)));
        }
    }

    /// The pieces of `a` as (lower end, upper end, piece below, edges).
    fn groups<P>(a: &Arrangement<P>) -> Vec<(usize, usize, Option<usize>, Vec<usize>)> {
        a.groups
            .iter()
            .map(|g| (g.from, g.to, g.below, a.members[g.members.clone()].to_vec()))
            .collect()
    }
}
