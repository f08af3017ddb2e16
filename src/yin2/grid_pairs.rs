//! Float mode's crossing pairs of grid segments, from which snap rounding takes the hot pixels of
//! crossings: sweep and prune over the segments' integer boxes, each pair of meeting boxes
//! decided by exact integer orientations; past a budget of box pairs, the Bentley–Ottmann sweep
//! of the segments as exact points (seed 002 §1.3).

use super::grid_arrange::{cross_properly, unit, G};
use super::intersect::exact_image_pairs;

/// The pairs `i < j` of `segments` whose interiors cross at one point, except pairs of one
/// family, given the segments in the order of their left sides (`by_left`) and each one's
/// family (`family`: `Some(0)` or `Some(1)` for a family whose segments are known not to cross
/// each other, `None` for a segment that may cross any): O(n log n + X) for X pairs of boxes
/// whose x-ranges overlap, or, once X passes [`SCANS_PER_SEGMENT`] per segment (long slanted
/// segments side by side, where X grows like n²), O((n + I) log n) for I meeting pairs.
pub(crate) fn grid_crossing_pairs(
    segments: &[(G, G)],
    by_left: &[usize],
    family: impl Fn(usize) -> Option<usize>,
) -> Vec<(usize, usize)> {
    let budget = SCANS_PER_SEGMENT * segments.len() + 4096;
    let mut pairs =
        box_pairs(segments, by_left, &family, budget).unwrap_or_else(|| swept_pairs(segments));
    pairs.retain(|&(i, j)| family(i).is_none() || family(i) != family(j));
    pairs
}

/// The crossing pairs among the meeting pairs that the Bentley–Ottmann sweep finds (a pair
/// meeting at several events is found at each).
fn swept_pairs(segments: &[(G, G)]) -> Vec<(usize, usize)> {
    let edges: Vec<_> = segments.iter().map(|&(a, b)| (unit(a), unit(b))).collect();
    let mut pairs = exact_image_pairs(&edges);
    pairs.sort_unstable();
    pairs.dedup();
    pairs.retain(|&(i, j)| cross_properly(segments[i], segments[j]));
    pairs
}

/// The budget of open boxes scanned per segment before the sweep takes over. A scan is a few
/// integer comparisons and only crossing pairs are kept, while the sweep costs about 12 000
/// instructions per segment on the random stars of the benches (W1, n = 10³): scanning up to
/// 256 per segment is cheaper whenever it finishes (W1 float meet at n = 10³: 5.8 → 4.2 ms
/// against 32), and adds a fraction of the sweep where it does not.
const SCANS_PER_SEGMENT: usize = 256;

/// A segment's box: x from, x to, y from, y to, and the segment.
type Boxed = (i64, i64, i64, i64, usize);

/// The crossing pairs among the pairs of segments whose boxes meet, by sweep and prune: the
/// boxes sorted by their left side (`by_left`), each tested against the boxes still open at it
/// that can meet it in y and are not of its family ([`Open`], one set per family and one for
/// segments of none); `None` once more than `budget` open boxes and strips have been scanned.
fn box_pairs(
    segments: &[(G, G)],
    by_left: &[usize],
    family: impl Fn(usize) -> Option<usize>,
    budget: usize,
) -> Option<Vec<(usize, usize)>> {
    let boxes: Vec<Boxed> = by_left
        .iter()
        .map(|&i| {
            let (a, b) = segments[i];
            (a.0.min(b.0), a.0.max(b.0), a.1.min(b.1), a.1.max(b.1), i)
        })
        .collect();
    let rows = Rows::of(&boxes);
    let mut open: [Open; 3] = std::array::from_fn(|_| Open::new(&rows));
    let (mut out, mut work) = (Vec::new(), 0);
    for (step, &b) in boxes.iter().enumerate() {
        // The open boxes of b's own family (index 0 or 1; 2 for none) cannot cross it.
        let own = family(b.4).unwrap_or(2);
        for (f, set) in open.iter_mut().enumerate() {
            if step % 4 == 0 {
                set.tall.retain(|c| c.1 >= b.0);
            }
            if (f == own && own != 2) || set.empty {
                continue;
            }
            work += set.scan(b, &rows, |c| {
                if cross_properly(segments[b.4], segments[c.4]) {
                    out.push((b.4.min(c.4), b.4.max(c.4)));
                }
            });
            if work > budget {
                return None;
            }
        }
        open[own].insert(b, &rows);
    }
    Some(out)
}

/// Horizontal strips of the boxes' y-range, 2^`shift` high (at least `low`, the height of nine
/// in ten boxes, and at most about as many strips as boxes), in which [`Open`] files the boxes
/// at most `low` high (short) by their bottom: those that can meet a box b in y have their
/// bottom from `low` below b's bottom to b's top.
struct Rows {
    bottom: i64,
    shift: u32,
    count: usize,
    low: i64,
}

impl Rows {
    fn of(boxes: &[Boxed]) -> Rows {
        let mut heights: Vec<i64> = boxes.iter().map(|b| b.3 - b.2).collect();
        let low = match heights.len() {
            0 => 0,
            n => *heights.select_nth_unstable(n * 9 / 10).1,
        };
        let bottom = boxes.iter().map(|b| b.2).min().unwrap_or(0);
        let top = boxes.iter().map(|b| b.3).max().unwrap_or(0);
        let span = (top - bottom) as u64;
        let height = (low as u64).max(span / boxes.len().max(1) as u64).max(1);
        let shift = height.next_power_of_two().trailing_zeros();
        Rows {
            bottom,
            shift,
            count: (span >> shift) as usize + 1,
            low,
        }
    }

    /// The strip holding height `y` (clamped to the range).
    fn of_y(&self, y: i64) -> usize {
        (((y.max(self.bottom) - self.bottom) >> self.shift) as usize).min(self.count - 1)
    }
}

/// Open boxes of a sweep and prune: the short ones filed in [`Rows`] by their bottom, sorted
/// by it in each strip, the tall ones all together. Closed boxes (before the current left
/// side) are dropped from a strip as a box is filed in it, from the tall ones every fourth step
/// by the caller, and skipped until then.
struct Open {
    strips: Vec<Vec<Boxed>>,
    tall: Vec<Boxed>,
    /// No box was ever opened.
    empty: bool,
}

impl Open {
    fn new(rows: &Rows) -> Open {
        Open {
            strips: vec![Vec::new(); rows.count],
            tall: Vec::new(),
            empty: true,
        }
    }

    /// Calls `meet` on every open box that meets `b`; returns the number of boxes and strips
    /// scanned.
    fn scan(&self, b: Boxed, rows: &Rows, mut meet: impl FnMut(&Boxed)) -> usize {
        let least = b.2.saturating_sub(rows.low);
        let (from, to) = (rows.of_y(least), rows.of_y(b.3));
        let mut work = self.tall.len();
        for s in from..=to {
            let strip = &self.strips[s];
            let lo = if s == from {
                strip.partition_point(|c| c.2 < least)
            } else {
                0
            };
            let hi = if s == to {
                strip.partition_point(|c| c.2 <= b.3)
            } else {
                strip.len()
            };
            work += hi - lo + 1;
            for c in &strip[lo..hi] {
                if c.1 >= b.0 && b.2 <= c.3 {
                    meet(c);
                }
            }
        }
        for c in &self.tall {
            if c.1 >= b.0 && c.2 <= b.3 && b.2 <= c.3 {
                meet(c);
            }
        }
        work
    }

    /// Opens `b`, the box with the rightmost left side so far.
    fn insert(&mut self, b: Boxed, rows: &Rows) {
        self.empty = false;
        if b.3 - b.2 <= rows.low {
            let strip = &mut self.strips[rows.of_y(b.2)];
            strip.retain(|c| c.1 >= b.0);
            let at = strip.partition_point(|c| c.2 < b.2);
            strip.insert(at, b);
        } else {
            self.tall.push(b);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{classify, Contact, Point};
    use crate::num::Rational;
    use proptest::prelude::*;

    /// The pairs whose interiors cross by the exact kernel's classification of every pair.
    fn brute(segs: &[(G, G)]) -> Vec<(usize, usize)> {
        let p = |g: G| Point::<Rational>::int(g.0, g.1);
        let mut out = Vec::new();
        for i in 0..segs.len() {
            for j in i + 1..segs.len() {
                let (s, t) = (segs[i], segs[j]);
                if let Contact::Crossing(_) = classify(&p(s.0), &p(s.1), &p(t.0), &p(t.1), &()) {
                    out.push((i, j));
                }
            }
        }
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Both ways of finding crossing pairs — boxes, and the exact sweep past the budget —
        /// give every pair whose interiors cross and no other, and the boxes every such pair
        /// but those of one family: segments on a 9×9 lattice, many collinear, touching or
        /// through common points, each of family 0, 1 or none; or, half the time, on a 9×65
        /// lattice, most of them at most 3 high (filed in many strips, the others tall).
        #[test]
        fn crossing_pairs_are_the_pairs_that_cross(
            drawn in prop_oneof![
                proptest::collection::vec(
                    (((0..=8i64, 0..=8i64), (0..=8i64, 0..=8i64)), 0..3usize), 0..40,
                ),
                proptest::collection::vec(
                    ((0..=8i64, 0..=64i64), (0..=8i64, prop_oneof![9 => -3..=3i64, 1 => -64..=64i64]), 0..3usize)
                        .prop_map(|(a, (x, dy), f)| ((a, (x, (a.1 + dy).clamp(0, 64))), f)),
                    0..60,
                ),
            ],
        ) {
            let (segs, families): (Vec<(G, G)>, Vec<usize>) =
                drawn.into_iter().filter(|s| s.0 .0 != s.0 .1).unzip();
            let want = brute(&segs);
            let mut by_left: Vec<usize> = (0..segs.len()).collect();
            by_left.sort_by_key(|&k| segs[k].0 .0.min(segs[k].1 .0));
            let mut got = grid_crossing_pairs(&segs, &by_left, |_| None);
            got.sort_unstable();
            prop_assert_eq!(&got, &want);
            let family = |k: usize| (families[k] < 2).then_some(families[k]);
            let mut apart = grid_crossing_pairs(&segs, &by_left, family);
            apart.sort_unstable();
            let mut want_apart = want.clone();
            want_apart.retain(|&(i, j)| family(i).is_none() || family(i) != family(j));
            prop_assert_eq!(apart, want_apart);
            let mut fallback = swept_pairs(&segs);
            fallback.sort_unstable();
            prop_assert_eq!(fallback, want);
        }
    }
}
