//! The pairs of boxes that meet (the broad phase of triangle–triangle tests), by sweep and
//! prune: the boxes sorted by their lower x, each scanned against those that start within its
//! x-range; an R-tree of the boxes where that would scan too many (long boxes side by side).

use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

/// Boxes scanned per box before the sweep gives way to the R-tree: a scan is six comparisons
/// on boxes stored in sweep order, a query of the tree walks a few dozen nodes.
const SCANS_PER_BOX: usize = 64;

/// The boxes, ready to give each box's partners: the boxes after it (in sweep order, or by
/// index in the tree) that meet it.
pub(crate) enum MeetingBoxes {
    /// Sweep order: each box's index, lower and upper corners, and the end of the boxes that
    /// start within its x-range.
    Sweep {
        order: Vec<usize>,
        lo: Vec<[f64; 3]>,
        hi: Vec<[f64; 3]>,
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
        let lo: Vec<[f64; 3]> = order.iter().map(|&i| boxes[i].lower()).collect();
        let hi: Vec<[f64; 3]> = order.iter().map(|&i| boxes[i].upper()).collect();
        let ends: Vec<usize> = hi
            .iter()
            .map(|h| lo.partition_point(|l| l[0] <= h[0]))
            .collect();
        let scans: usize = ends.iter().enumerate().map(|(k, &e)| e - k - 1).sum();
        if scans <= SCANS_PER_BOX * n + 4096 {
            return MeetingBoxes::Sweep {
                order,
                lo,
                hi,
                ends,
            };
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
            MeetingBoxes::Sweep {
                order,
                lo,
                hi,
                ends,
            } => (k + 1..ends[k]).all(|m| {
                let meet = (1..3).all(|d| lo[m][d] <= hi[k][d] && lo[k][d] <= hi[m][d]);
                !meet || f(order[k], order[m])
            }),
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
    use std::sync::Mutex;

    /// The pairs `all_pairs` asks for, as (smaller, larger).
    fn asked(boxes: &[AABB<[f64; 3]>], parallel: bool) -> Vec<(usize, usize)> {
        let got = Mutex::new(Vec::new());
        let all = MeetingBoxes::new(boxes.to_vec()).all_pairs(parallel, |i, j| {
            got.lock().unwrap().push((i.min(j), i.max(j)));
            true
        });
        assert!(all, "every pair held");
        let mut got = got.into_inner().unwrap();
        got.sort_unstable();
        got
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

    /// Boxes on a small lattice (many touching in a face, an edge or a corner, equal, or
    /// degenerate to a point), or long in x, so that the sweep gives way to the tree.
    fn lattice_boxes(long: bool) -> impl Strategy<Value = Vec<AABB<[f64; 3]>>> {
        let corner = || [0..6i32, 0..6i32, 0..6i32];
        let n = if long { 200..400 } else { 0..60 };
        proptest::collection::vec((corner(), corner()), n).prop_map(move |drawn| {
            drawn
                .into_iter()
                .map(|(a, b)| {
                    let (mut a, b) = (a.map(f64::from), b.map(f64::from));
                    if long {
                        a[0] = -1.0;
                    }
                    AABB::from_corners(a, b)
                })
                .collect()
        })
    }

    proptest! {
        /// Every pair of meeting boxes is asked exactly once and no other pair, by the sweep
        /// and, for boxes all spanning the x-range, by the tree; on one thread and on many.
        #[test]
        fn the_pairs_asked_are_the_pairs_that_meet(
            boxes in prop_oneof![lattice_boxes(false), lattice_boxes(true)],
            parallel in any::<bool>(),
        ) {
            let want = brute(&boxes);
            let got = asked(&boxes, parallel);
            prop_assert_eq!(got.iter().collect::<BTreeSet<_>>().len(), got.len(), "a pair asked twice");
            prop_assert_eq!(got, want);
        }
    }

    /// A false answer stops the search and is returned, by the sweep and by the tree.
    #[test]
    fn a_false_pair_is_the_answer() {
        let unit = |x: f64| AABB::from_corners([x, 0.0, 0.0], [x + 1.0, 1.0, 1.0]);
        let short: Vec<_> = (0..10).map(|k| unit(k as f64)).collect();
        let long: Vec<_> = (0..200)
            .map(|k| AABB::from_corners([0.0, k as f64, 0.0], [1000.0, k as f64 + 1.0, 1.0]))
            .collect();
        for boxes in [short, long] {
            for parallel in [false, true] {
                let no = |i: usize, j: usize| (i.min(j), i.max(j)) != (3, 4);
                let meeting = MeetingBoxes::new(boxes.clone());
                assert!(!meeting.all_pairs(parallel, no));
                assert!(meeting.all_pairs(parallel, |_, _| true));
            }
        }
    }
}
