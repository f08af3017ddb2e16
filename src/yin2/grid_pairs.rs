//! Float mode's crossing pairs of grid segments, from which snap rounding takes the hot pixels of
//! crossings: sweep and prune over the segments' integer boxes, each pair of meeting boxes
//! decided by exact integer orientations; past a budget of box pairs, the Bentley–Ottmann sweep
//! of the segments as exact points (seed 002 §1.3).

use super::grid_arrange::{cross_properly, unit, G};
use super::intersect::exact_image_pairs;

/// The pairs `i < j` of `segments` whose interiors cross at one point, given the segments in
/// the order of their left sides (`by_left`): O(n + X) for X pairs of boxes whose x-ranges
/// overlap, or, once X passes [`SCANS_PER_SEGMENT`] per segment (long slanted segments side by
/// side, where X grows like n²), O((n + I) log n) for I meeting pairs.
pub(crate) fn grid_crossing_pairs(segments: &[(G, G)], by_left: &[usize]) -> Vec<(usize, usize)> {
    let budget = SCANS_PER_SEGMENT * segments.len() + 4096;
    box_pairs(segments, by_left, budget).unwrap_or_else(|| swept_pairs(segments))
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

/// The crossing pairs among the pairs of segments whose boxes meet, by sweep and prune: the
/// boxes sorted by their left side, each tested against the boxes still open at it that can
/// meet it in y — the open boxes at most as high as nine in ten boxes kept sorted by their
/// bottom (those that meet start at most that height below the new box's bottom), the taller
/// ones all; `None` once more than `budget` open boxes have been scanned. The segments come
/// `by_left`, in the order of their boxes' left sides.
fn box_pairs(segments: &[(G, G)], by_left: &[usize], budget: usize) -> Option<Vec<(usize, usize)>> {
    // (x from, x to, y from, y to, segment), by x from.
    let boxes: Vec<(i64, i64, i64, i64, usize)> = by_left
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
    // Open boxes: those at most `low` high by bottom, the others as they come; boxes closed
    // before the current left side are dropped every fourth step and skipped until then.
    let mut short: Vec<(i64, i64, i64, i64, usize)> = Vec::new();
    let mut tall: Vec<(i64, i64, i64, i64, usize)> = Vec::new();
    let (mut out, mut work) = (Vec::new(), 0);
    for (step, &b) in boxes.iter().enumerate() {
        if step % 4 == 0 {
            short.retain(|c| c.1 >= b.0);
            tall.retain(|c| c.1 >= b.0);
        }
        let from = short.partition_point(|c| c.2 < b.2.saturating_sub(low));
        let to = short.partition_point(|c| c.2 <= b.3);
        work += to - from + tall.len();
        if work > budget {
            return None;
        }
        for c in short[from..to].iter().chain(&tall) {
            if c.1 >= b.0
                && c.2 <= b.3
                && b.2 <= c.3
                && cross_properly(segments[b.4], segments[c.4])
            {
                out.push((b.4.min(c.4), b.4.max(c.4)));
            }
        }
        if b.3 - b.2 <= low {
            let at = short.partition_point(|c| c.2 < b.2);
            short.insert(at, b);
        } else {
            tall.push(b);
        }
    }
    Some(out)
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
        /// give every pair whose interiors cross and no other:
        /// segments on a 9×9 lattice, many collinear, touching or through common points.
        #[test]
        fn crossing_pairs_are_the_pairs_that_cross(
            drawn in proptest::collection::vec(((0..=8i64, 0..=8i64), (0..=8i64, 0..=8i64)), 0..40),
        ) {
            let segs: Vec<(G, G)> = drawn.into_iter().filter(|s| s.0 != s.1).collect();
            let want = brute(&segs);
            let mut by_left: Vec<usize> = (0..segs.len()).collect();
            by_left.sort_by_key(|&k| segs[k].0 .0.min(segs[k].1 .0));
            let mut got = grid_crossing_pairs(&segs, &by_left);
            got.sort_unstable();
            prop_assert_eq!(&got, &want);
            let mut fallback = swept_pairs(&segs);
            fallback.sort_unstable();
            prop_assert_eq!(fallback, want);
        }
    }
}
