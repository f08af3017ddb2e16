//! The pairs of boxes that meet (the broad phase of triangle–triangle tests), by sweep and
//! prune: the boxes sorted by their lower x, each scanned against those that start within its
//! x-range; an R-tree of the boxes where that would scan too many (long boxes side by side).

use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

/// Boxes scanned per box before the sweep gives way to the R-tree: a scan is four comparisons
/// on boxes stored in sweep order, a query of the tree walks a few dozen nodes.
const SCANS_PER_BOX: usize = 64;

/// The boxes, ready to give each box's partners: the boxes after it (in sweep order, or by
/// index in the tree) that meet it.
pub(crate) enum MeetingBoxes {
    /// Sweep order: each box's index, its y- and z-ranges (lower y, lower z, upper y, upper
    /// z, side by side for the scan), and the end of the boxes that start within its x-range.
    Sweep {
        order: Vec<usize>,
        yz: Vec<[f64; 4]>,
        ends: Vec<usize>,
    },
    /// The boxes and their R-tree.
    Tree(
        Vec<AABB<[f64; 3]>>,
        RTree<GeomWithData<Rectangle<[f64; 3]>, usize>>,
    ),
}

impl MeetingBoxes {
    /// The sweep of `boxes`, or their tree past [`SCANS_PER_BOX`] scans per box.
    pub(crate) fn new(boxes: Vec<AABB<[f64; 3]>>) -> MeetingBoxes {
        let n = boxes.len();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_unstable_by(|&i, &j| boxes[i].lower()[0].total_cmp(&boxes[j].lower()[0]));
        let lower_x: Vec<f64> = order.iter().map(|&i| boxes[i].lower()[0]).collect();
        let ends: Vec<usize> = (order.iter())
            .map(|&i| lower_x.partition_point(|&x| x <= boxes[i].upper()[0]))
            .collect();
        // The scans, counted until they pass the budget (each box's own place is in its range).
        let budget = SCANS_PER_BOX * n + 4096;
        let within = (ends.iter().enumerate()).try_fold(0usize, |scans, (k, &e)| {
            Some(scans + e.saturating_sub(k + 1)).filter(|&s| s <= budget)
        });
        if within.is_some() {
            let yz = (order.iter())
                .map(|&i| {
                    let (lo, hi) = (boxes[i].lower(), boxes[i].upper());
                    [lo[1], lo[2], hi[1], hi[2]]
                })
                .collect();
            return MeetingBoxes::Sweep { order, yz, ends };
        }
        let tree = RTree::bulk_load(
            (boxes.iter().enumerate())
                .map(|(i, b)| GeomWithData::new(Rectangle::from_aabb(*b), i))
                .collect(),
        );
        MeetingBoxes::Tree(boxes, tree)
    }

    /// The number of boxes.
    fn len(&self) -> usize {
        match self {
            MeetingBoxes::Sweep { order, .. } => order.len(),
            MeetingBoxes::Tree(boxes, _) => boxes.len(),
        }
    }

    /// True if `f(i, j)` holds for the `k`-th box's partners: `i` is that box's index, `j`
    /// each partner's; stops at the first false. Over k in 0..len(), each pair of distinct
    /// boxes that meet (closed boxes) is asked once, in one of its orders.
    fn partners(&self, k: usize, mut f: impl FnMut(usize, usize) -> bool) -> bool {
        match self {
            MeetingBoxes::Sweep { order, yz, ends } => {
                let [y0, z0, y1, z1] = yz[k];
                (k + 1..ends[k]).all(|m| {
                    // All four comparisons, one branch: most scanned boxes miss in y or z,
                    // unpredictably.
                    let [ly, lz, hy, hz] = yz[m];
                    let meet = (ly <= y1) & (lz <= z1) & (y0 <= hy) & (z0 <= hz);
                    !meet || f(order[k], order[m])
                })
            }
            MeetingBoxes::Tree(boxes, tree) => tree
                .locate_in_envelope_intersecting(&boxes[k])
                .all(|g| g.data <= k || f(k, g.data)),
        }
    }

    /// True if `f(i, j)` holds for every pair of distinct boxes that meet, each asked once in
    /// one of its orders; stops at the first false. On rayon's threads if `parallel`.
    pub(crate) fn all_pairs(
        &self,
        parallel: bool,
        f: impl Fn(usize, usize) -> bool + Sync,
    ) -> bool {
        match parallel {
            true => (0..self.len())
                .into_par_iter()
                .all(|k| self.partners(k, &f)),
            false => (0..self.len()).all(|k| self.partners(k, &f)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::collections::BTreeSet;
    use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
    use std::sync::Mutex;

    /// The pairs `all_pairs` asks for, as (smaller, larger), and whether the tree asked them.
    fn asked(boxes: &[AABB<[f64; 3]>], parallel: bool) -> (Vec<(usize, usize)>, bool) {
        let got = Mutex::new(Vec::new());
        let meeting = MeetingBoxes::new(boxes.to_vec());
        let all = meeting.all_pairs(parallel, |i, j| {
            got.lock().unwrap().push((i.min(j), i.max(j)));
            true
        });
        assert!(all, "every pair held");
        let mut got = got.into_inner().unwrap();
        got.sort_unstable();
        (got, matches!(meeting, MeetingBoxes::Tree(..)))
    }

    /// The pairs whose boxes meet, every pair tested on its own.
    fn brute(boxes: &[AABB<[f64; 3]>]) -> Vec<(usize, usize)> {
        let meet = |a: &AABB<[f64; 3]>, b: &AABB<[f64; 3]>| {
            (0..3).all(|d| a.lower()[d] <= b.upper()[d] && b.lower()[d] <= a.upper()[d])
        };
        let mut out = Vec::new();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if meet(&boxes[i], &boxes[j]) {
                    out.push((i, j));
                }
            }
        }
        out
    }

    /// Boxes with corners on a small lattice (many touching in a face, an edge or a corner,
    /// equal, or degenerate to a point), with −0.0, 0.0 and infinite coordinates among them;
    /// `long`: 300 to 400 boxes all reaching x = −∞, past the sweep's budget.
    fn lattice_boxes(long: bool) -> impl Strategy<Value = Vec<AABB<[f64; 3]>>> {
        let values = [
            f64::NEG_INFINITY,
            -1.0,
            -0.0,
            0.0,
            1.0,
            2.0,
            3.0,
            4.0,
            f64::INFINITY,
        ];
        let corner = || [0..9usize, 0..9usize, 0..9usize];
        let n = if long { 300..400 } else { 0..60 };
        proptest::collection::vec((corner(), corner()), n).prop_map(move |drawn| {
            drawn
                .into_iter()
                .map(|(a, b)| {
                    let (mut a, b) = (a.map(|k| values[k]), b.map(|k| values[k]));
                    if long {
                        a[0] = f64::NEG_INFINITY;
                    }
                    AABB::from_corners(a, b)
                })
                .collect()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Every pair of meeting boxes is asked exactly once and no other pair, by the sweep
        /// and, for boxes all spanning the x-range, by the tree; on one thread and on many.
        #[test]
        fn the_pairs_asked_are_the_pairs_that_meet(
            (boxes, long) in prop_oneof![
                lattice_boxes(false).prop_map(|b| (b, false)),
                lattice_boxes(true).prop_map(|b| (b, true)),
            ],
            parallel in any::<bool>(),
        ) {
            let want = brute(&boxes);
            let (got, by_tree) = asked(&boxes, parallel);
            prop_assert_eq!(by_tree, long, "the tree takes exactly the long boxes");
            prop_assert_eq!(got.iter().collect::<BTreeSet<_>>().len(), got.len(), "a pair asked twice");
            prop_assert_eq!(got, want);
        }
    }

    /// A false answer is returned, by the sweep and by the tree, on one thread and on many;
    /// on one thread nothing more is asked after it.
    #[test]
    fn a_false_pair_is_the_answer() {
        let unit = |x: f64| AABB::from_corners([x, 0.0, 0.0], [x + 1.0, 1.0, 1.0]);
        let short: Vec<_> = (0..10).map(|k| unit(k as f64)).collect();
        let long: Vec<_> = (0..400)
            .map(|k| AABB::from_corners([0.0, k as f64, 0.0], [1000.0, k as f64 + 1.0, 1.0]))
            .collect();
        for (boxes, long) in [(short, false), (long, true)] {
            let meeting = MeetingBoxes::new(boxes);
            assert_eq!(matches!(meeting, MeetingBoxes::Tree(..)), long);
            for parallel in [false, true] {
                let no = |i: usize, j: usize| (i.min(j), i.max(j)) != (3, 4);
                assert!(!meeting.all_pairs(parallel, no));
                assert!(meeting.all_pairs(parallel, |_, _| true));
            }
            let asked = AtomicUsize::new(0);
            assert!(!meeting.all_pairs(false, |_, _| asked.fetch_add(1, Relaxed) > 0));
            assert_eq!(asked.into_inner(), 1, "asked past the first false");
        }
    }
}
