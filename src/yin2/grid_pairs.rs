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
/// segments of none); `None` once more than `budget` open boxes have been scanned.
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
    let mut heights: Vec<i64> = boxes.iter().map(|b| b.3 - b.2).collect();
    let low = match heights.len() {
        0 => 0,
        n => *heights.select_nth_unstable(n * 9 / 10).1,
    };
    let mut open: [Open; 3] = Default::default();
    let (mut out, mut work) = (Vec::new(), 0);
    for (step, &b) in boxes.iter().enumerate() {
        // The open boxes of b's own family (index 0 or 1; 2 for none) cannot cross it.
        let own = family(b.4).unwrap_or(2);
        for (f, set) in open.iter_mut().enumerate() {
            if step % 4 == 0 {
                set.prune(b.0);
            }
            if f == own && own != 2 {
                continue;
            }
            work += set.scan(b, low, |c| {
                if cross_properly(segments[b.4], segments[c.4]) {
                    out.push((b.4.min(c.4), b.4.max(c.4)));
                }
            });
            if work > budget {
                return None;
            }
        }
        open[own].insert(b, low);
    }
    Some(out)
}

/// Open boxes of a sweep and prune: those at most `low` high (nine in ten boxes) kept sorted
/// by their bottom, so that the ones that can meet a new box in y are a run of them (starting
/// at most `low` below the new box's bottom), the taller ones all; boxes closed before the
/// current left side are dropped every fourth step and skipped until then.
#[derive(Default)]
struct Open {
    short: Vec<Boxed>,
    tall: Vec<Boxed>,
}

impl Open {
    /// Drops the boxes closed before x.
    fn prune(&mut self, x: i64) {
        self.short.retain(|c| c.1 >= x);
        self.tall.retain(|c| c.1 >= x);
    }

    /// Calls `meet` on every open box that meets `b` (boxes of at most `low` high are short);
    /// returns the number of boxes scanned.
    fn scan(&self, b: Boxed, low: i64, mut meet: impl FnMut(&Boxed)) -> usize {
        let from = self
            .short
            .partition_point(|c| c.2 < b.2.saturating_sub(low));
        let to = self.short.partition_point(|c| c.2 <= b.3);
        for c in self.short[from..to].iter().chain(&self.tall) {
            if c.1 >= b.0 && c.2 <= b.3 && b.2 <= c.3 {
                meet(c);
            }
        }
        to - from + self.tall.len()
    }

    /// Opens `b` (short if at most `low` high).
    fn insert(&mut self, b: Boxed, low: i64) {
        if b.3 - b.2 <= low {
            let at = self.short.partition_point(|c| c.2 < b.2);
            self.short.insert(at, b);
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
        /// Both ways of finding crossing pairs — boxes, and the exact sweep past the budget —
        /// give every pair whose interiors cross and no other, and the boxes every such pair
        /// but those of one family: segments on a 9×9 lattice, many collinear, touching or
        /// through common points, each of family 0, 1 or none.
        #[test]
        fn crossing_pairs_are_the_pairs_that_cross(
            drawn in proptest::collection::vec(
                (((0..=8i64, 0..=8i64), (0..=8i64, 0..=8i64)), 0..3usize), 0..40,
            ),
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
