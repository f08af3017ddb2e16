//! The pairs of boxes that meet (the broad phase of triangle–triangle tests), by sweep and
//! prune: the boxes sorted by their lower x, each scanned against those that start within its
//! x-range; where that would scan too many (a surface's boxes, side by side along x, most
//! often known before any sorting from a histogram of the lower x's), by a uniform grid of
//! cells about twice the boxes' mean size, its boxes grouped by cell with a radix sort, each
//! pair tested in the one cell that holds the lower corner of their common box; an R-tree of
//! the boxes where the grid too would hold too many (long boxes, infinite coordinates).

use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};

/// Boxes scanned per box before the sweep gives way to the grid (and the grid's box pairs per
/// box before it gives way to the tree): a scan is four comparisons on boxes stored in sweep
/// order, a query of the tree walks a few dozen nodes.
const SCANS_PER_BOX: usize = 64;

/// The scans of the sweep (or box pairs in the grid's cells) allowed for `n` boxes:
/// [`SCANS_PER_BOX`] per box, and a few thousand more for a handful of boxes.
fn budget(n: usize) -> usize {
    SCANS_PER_BOX * n + 4096
}

/// The most cells of the grid along one axis.
const GRID_CELLS: usize = 1024;

/// The most cells a box is in, on average, before the grid gives way to the tree.
const CELLS_PER_BOX: usize = 16;

/// The most bits of a cell's number that one pass of the grid's radix sort orders by.
const RADIX_BITS: u32 = 11;

/// The boxes, ready to give the pairs that meet.
pub(crate) enum MeetingBoxes {
    /// Sweep order: each box's index, its y- and z-ranges (lower y, lower z, upper y, upper
    /// z, side by side for the scan), and the end of the boxes that start within its x-range.
    Sweep {
        order: Vec<usize>,
        yz: Vec<[f64; 4]>,
        ends: Vec<usize>,
    },
    /// The boxes in a uniform grid.
    Grid(Grid),
    /// The boxes and their R-tree.
    Tree(
        Vec<AABB<[f64; 3]>>,
        RTree<GeomWithData<Rectangle<[f64; 3]>, usize>>,
    ),
}

/// Boxes in the cells of a uniform grid that they meet.
pub(crate) struct Grid {
    /// The boxes.
    boxes: Vec<AABB<[f64; 3]>>,
    /// The boxes of every cell they meet, cell by cell, as (cell number) · 2³² + box · 2³ +
    /// the axes (bits x, y, z from the lowest) on which the cell is the box's lowest.
    entries: Vec<u64>,
    /// Where each occupied cell's run of entries starts, then the end of the last.
    runs: Vec<usize>,
}

impl Grid {
    /// The grid of `boxes`, or the boxes back if a coordinate is infinite, there are 2²⁹ boxes
    /// or more, or the boxes are in more than [`CELLS_PER_BOX`] cells or have more than
    /// [`SCANS_PER_BOX`] pairs in a cell, per box on average.
    fn new(boxes: Vec<AABB<[f64; 3]>>) -> Result<Grid, Vec<AABB<[f64; 3]>>> {
        let n = boxes.len();
        if n == 0 || n >= 1 << 29 {
            return Err(boxes);
        }
        let (mut lo, mut hi) = (boxes[0].lower(), boxes[0].upper());
        let mut sizes = [0.0f64; 3];
        for b in &boxes {
            for d in 0..3 {
                lo[d] = lo[d].min(b.lower()[d]);
                hi[d] = hi[d].max(b.upper()[d]);
                sizes[d] += b.upper()[d] - b.lower()[d];
            }
        }
        if !(lo.iter().chain(&hi).chain(&sizes)).all(|v| v.is_finite()) {
            return Err(boxes);
        }
        // Cells twice the mean size along each axis, but not more than GRID_CELLS of them.
        let mut cells = [1u32; 3];
        let mut scale = [0.0f64; 3];
        for d in 0..3 {
            let side = (2.0 * sizes[d] / n as f64).max((hi[d] - lo[d]) / GRID_CELLS as f64);
            if side > 0.0 {
                let count = ((hi[d] - lo[d]) / side)
                    .ceil()
                    .clamp(1.0, GRID_CELLS as f64);
                cells[d] = count as u32;
                scale[d] = 1.0 / side;
            }
        }
        // A coordinate's cell: monotone in the coordinate, so the cell of the larger of two
        // lower corners is the larger of their cells.
        let cell = |d: usize, v: f64| (((v - lo[d]) * scale[d]) as u32).min(cells[d] - 1);
        let range = |b: &AABB<[f64; 3]>| {
            let (l, u) = (b.lower(), b.upper());
            [0, 1, 2].map(|d| (cell(d, l[d]), cell(d, u[d])))
        };
        let count: usize = (boxes.iter())
            .map(|b| {
                range(b)
                    .iter()
                    .map(|&(l, u)| (u - l + 1) as usize)
                    .product::<usize>()
            })
            .sum();
        if count > CELLS_PER_BOX * n + 4096 {
            return Err(boxes);
        }
        // Each box in each of its cells, marked with the axes on which that cell is its lowest.
        let mut entries = Vec::with_capacity(count);
        for (i, b) in boxes.iter().enumerate() {
            let [(x0, x1), (y0, y1), (z0, z1)] = range(b);
            for x in x0..=x1 {
                for y in y0..=y1 {
                    for z in z0..=z1 {
                        let number = (x as u64 * cells[1] as u64 + y as u64) * cells[2] as u64;
                        let lowest =
                            (x == x0) as u64 | ((y == y0) as u64) << 1 | ((z == z0) as u64) << 2;
                        entries.push((number + z as u64) << 32 | (i as u64) << 3 | lowest);
                    }
                }
            }
        }
        let total = cells.iter().map(|&c| c as u64).product::<u64>();
        let entries = by_cell(entries, u64::BITS - (total - 1).leading_zeros());
        let mut runs: Vec<usize> = (0..entries.len())
            .filter(|&k| k == 0 || entries[k] >> 32 != entries[k - 1] >> 32)
            .collect();
        runs.push(entries.len());
        let pairs: usize = (runs.windows(2))
            .map(|w| (w[1] - w[0]) * (w[1] - w[0] - 1) / 2)
            .sum();
        if pairs > budget(n) {
            return Err(boxes);
        }
        Ok(Grid {
            boxes,
            entries,
            runs,
        })
    }

    /// True if `f(i, j)` holds for the pairs of distinct boxes that meet and whose common
    /// box's lower corner lies in the `k`-th occupied cell (for each axis, the cell is the
    /// lowest of one box or the other); stops at the first false.
    fn pairs_in(&self, k: usize, mut f: impl FnMut(usize, usize) -> bool) -> bool {
        let run = &self.entries[self.runs[k]..self.runs[k + 1]];
        let index = |e: u64| (e as u32 >> 3) as usize;
        (0..run.len()).all(|a| {
            let (i, lowest) = (index(run[a]), run[a] & 7);
            let bi = &self.boxes[i];
            run[a + 1..].iter().all(|&e| {
                let j = index(e);
                !((lowest | e) & 7 == 7 && meet(bi, &self.boxes[j])) || f(i, j)
            })
        })
    }
}

/// `entries` ordered by their upper 32 bits, numbers below 2^`bits`: a stable radix sort from
/// the lowest digit up, in as few passes of at most [`RADIX_BITS`] bits as there can be.
fn by_cell(entries: Vec<u64>, bits: u32) -> Vec<u64> {
    let passes = bits.div_ceil(RADIX_BITS).max(1);
    let width = bits.div_ceil(passes);
    let mut to = vec![0; entries.len()];
    let mut from = entries;
    for pass in 0..passes {
        let digit = |e: u64| (e >> (32 + pass * width)) as usize & ((1 << width) - 1);
        let mut starts = vec![0usize; 1 << width];
        for &e in &from {
            starts[digit(e)] += 1;
        }
        let mut sum = 0;
        for s in &mut starts {
            (*s, sum) = (sum, sum + *s);
        }
        for &e in &from {
            let s = &mut starts[digit(e)];
            to[*s] = e;
            *s += 1;
        }
        std::mem::swap(&mut from, &mut to);
    }
    from
}

/// A lower bound on the sweep's scans of `boxes`, or a number past `budget` once the bound
/// passes it; 0 where an x-coordinate is NaN, a lower one infinite or all lower ones equal.
/// In O(n): the lower x's counted in n slabs of equal width, each box credited with those in
/// the slabs strictly between its lower and its upper x's (they start after it and within
/// its x-range).
fn fewest_scans(boxes: &[AABB<[f64; 3]>], budget: usize) -> usize {
    let n = boxes.len();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for b in boxes {
        let (l, u) = (b.lower()[0], b.upper()[0]);
        if l.is_nan() || u.is_nan() {
            return 0;
        }
        (lo, hi) = (lo.min(l), hi.max(l));
    }
    if !(lo.is_finite() && hi.is_finite()) || lo == hi {
        return 0;
    }
    // Monotone in x, so a box in a higher slab starts above, and one in a lower slab below.
    let scale = n as f64 / (hi - lo);
    let slab = |x: f64| (((x - lo) * scale) as usize).min(n - 1);
    // How many lower x's lie below each slab, then the total.
    let mut below = vec![0usize; n + 1];
    for b in boxes {
        below[slab(b.lower()[0]) + 1] += 1;
    }
    for s in 1..=n {
        below[s] += below[s - 1];
    }
    let mut scans = 0;
    for b in boxes {
        let (s, t) = (slab(b.lower()[0]), slab(b.upper()[0]));
        scans += below[t].saturating_sub(below[s + 1]);
        if scans > budget {
            break;
        }
    }
    scans
}

/// True if the closed boxes meet.
fn meet(a: &AABB<[f64; 3]>, b: &AABB<[f64; 3]>) -> bool {
    let (al, au, bl, bu) = (a.lower(), a.upper(), b.lower(), b.upper());
    (al[0] <= bu[0])
        & (bl[0] <= au[0])
        & (al[1] <= bu[1])
        & (bl[1] <= au[1])
        & (al[2] <= bu[2])
        & (bl[2] <= au[2])
}

impl MeetingBoxes {
    /// The sweep of `boxes`; past [`SCANS_PER_BOX`] scans per box their grid, or failing
    /// that their tree.
    pub(crate) fn new(boxes: Vec<AABB<[f64; 3]>>) -> MeetingBoxes {
        if let Some(sweep) = MeetingBoxes::sweep(&boxes) {
            return sweep;
        }
        let boxes = match Grid::new(boxes) {
            Ok(grid) => return MeetingBoxes::Grid(grid),
            Err(boxes) => boxes,
        };
        let tree = RTree::bulk_load(
            (boxes.iter().enumerate())
                .map(|(i, b)| GeomWithData::new(Rectangle::from_aabb(*b), i))
                .collect(),
        );
        MeetingBoxes::Tree(boxes, tree)
    }

    /// The sweep of `boxes`, or `None` if it scans more than [`SCANS_PER_BOX`] boxes per box
    /// (known without sorting where [`fewest_scans`] passes that).
    fn sweep(boxes: &[AABB<[f64; 3]>]) -> Option<MeetingBoxes> {
        let n = boxes.len();
        let budget = budget(n);
        if fewest_scans(boxes, budget) > budget {
            return None;
        }
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_unstable_by(|&i, &j| boxes[i].lower()[0].total_cmp(&boxes[j].lower()[0]));
        let lower_x: Vec<f64> = order.iter().map(|&i| boxes[i].lower()[0]).collect();
        // The scans, counted until they pass the budget (each box's own place is in its range).
        let mut scans = 0;
        let ends: Vec<usize> = (order.iter().enumerate())
            .map_while(|(k, &i)| {
                let end = lower_x.partition_point(|&x| x <= boxes[i].upper()[0]);
                scans += end.saturating_sub(k + 1);
                (scans <= budget).then_some(end)
            })
            .collect();
        if ends.len() < n {
            return None;
        }
        let yz = (order.iter())
            .map(|&i| {
                let (lo, hi) = (boxes[i].lower(), boxes[i].upper());
                [lo[1], lo[2], hi[1], hi[2]]
            })
            .collect();
        Some(MeetingBoxes::Sweep { order, yz, ends })
    }

    /// The number of parts the pairs come in: boxes, or the grid's occupied cells.
    fn len(&self) -> usize {
        match self {
            MeetingBoxes::Sweep { order, .. } => order.len(),
            MeetingBoxes::Grid(grid) => grid.runs.len() - 1,
            MeetingBoxes::Tree(boxes, _) => boxes.len(),
        }
    }

    /// True if `f(i, j)` holds for the `k`-th part's pairs, `i` and `j` the boxes' indices:
    /// a box and its partners, or a cell's pairs; stops at the first false. Over k in
    /// 0..len(), each pair of distinct boxes that meet (closed boxes) is asked once, in one of
    /// its orders.
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
            MeetingBoxes::Grid(grid) => grid.pairs_in(k, f),
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

    /// How the boxes are paired.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    enum Kind {
        Sweep,
        Grid,
        Tree,
    }

    fn kind(meeting: &MeetingBoxes) -> Kind {
        match meeting {
            MeetingBoxes::Sweep { .. } => Kind::Sweep,
            MeetingBoxes::Grid(_) => Kind::Grid,
            MeetingBoxes::Tree(..) => Kind::Tree,
        }
    }

    /// The pairs `all_pairs` asks for, as (smaller, larger), and how it paired them.
    fn asked(boxes: &[AABB<[f64; 3]>], parallel: bool) -> (Vec<(usize, usize)>, Kind) {
        let got = Mutex::new(Vec::new());
        let meeting = MeetingBoxes::new(boxes.to_vec());
        let all = meeting.all_pairs(parallel, |i, j| {
            got.lock().unwrap().push((i.min(j), i.max(j)));
            true
        });
        assert!(all, "every pair held");
        let mut got = got.into_inner().unwrap();
        got.sort_unstable();
        (got, kind(&meeting))
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

    /// 300 to 400 boxes past the sweep's budget, all spanning x ∈ [0, 1000], or if
    /// `staggered` starting at an integer x from 0 to 15 and 0 to 47 long (past the budget by
    /// [`fewest_scans`], and two cells of the grid along x), with corners on the integers from
    /// −20 to 20 in y and z (zero as −0.0 or 0.0) and sides of 0 to 3 there: many touching in
    /// a face, an edge or a corner, on and off the grid's cell walls.
    fn wide_boxes(staggered: bool) -> impl Strategy<Value = Vec<AABB<[f64; 3]>>> {
        let side = || (-20..20i32, 0..4i32, any::<bool>());
        let x = (0..16i32, 0..48i32);
        proptest::collection::vec((x, side(), side()), 300..400).prop_map(move |drawn| {
            drawn
                .into_iter()
                .map(|((x, dx), (y, dy, ny), (z, dz, nz))| {
                    let v = |k: i32, negative_zero: bool| match (k, negative_zero) {
                        (0, true) => -0.0,
                        _ => k as f64,
                    };
                    let (x0, x1) = match staggered {
                        true => (x as f64, (x + dx) as f64),
                        false => (0.0, 1000.0),
                    };
                    AABB::from_corners([x0, v(y, ny), v(z, nz)], [x1, v(y + dy, nz), v(z + dz, ny)])
                })
                .collect()
        })
    }

    /// The sweep's scans of `boxes`, each pair of boxes on its own: a pair is scanned once if
    /// their lower x's are equal, and otherwise if the higher lower x is within the other
    /// box's x-range.
    fn brute_scans(boxes: &[AABB<[f64; 3]>]) -> usize {
        let mut scans = 0;
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                let (a, b) = match a.lower()[0] <= b.lower()[0] {
                    true => (a, b),
                    false => (b, a),
                };
                scans += (b.lower()[0] <= a.upper()[0]) as usize;
            }
        }
        scans
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Every pair of meeting boxes is asked exactly once and no other pair, by the sweep
        /// (exactly where it is within its budget), by the grid for finite boxes side by side
        /// along x, and by the tree for boxes all reaching x = −∞; on one thread and on many.
        #[test]
        fn the_pairs_asked_are_the_pairs_that_meet(
            (boxes, how) in prop_oneof![
                lattice_boxes(false).prop_map(|b| (b, Kind::Sweep)),
                wide_boxes(false).prop_map(|b| (b, Kind::Grid)),
                wide_boxes(true).prop_map(|b| (b, Kind::Grid)),
                lattice_boxes(true).prop_map(|b| (b, Kind::Tree)),
            ],
            parallel in any::<bool>(),
        ) {
            let want = brute(&boxes);
            let (got, kind) = asked(&boxes, parallel);
            prop_assert_eq!(kind, how);
            prop_assert_eq!(kind == Kind::Sweep, brute_scans(&boxes) <= budget(boxes.len()));
            prop_assert_eq!(got.iter().collect::<BTreeSet<_>>().len(), got.len(), "a pair asked twice");
            prop_assert_eq!(got, want);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The bound on the sweep's scans is at most their number, and passes the budget for
        /// staggered boxes, which then go to the grid without the sweep's sorting.
        #[test]
        fn fewest_scans_is_a_lower_bound(
            (boxes, staggered) in prop_oneof![
                lattice_boxes(false).prop_map(|b| (b, false)),
                lattice_boxes(true).prop_map(|b| (b, false)),
                wide_boxes(false).prop_map(|b| (b, false)),
                wide_boxes(true).prop_map(|b| (b, true)),
            ],
        ) {
            let bound = fewest_scans(&boxes, usize::MAX);
            prop_assert!(bound <= brute_scans(&boxes), "{} scans at least", bound);
            if staggered {
                prop_assert!(fewest_scans(&boxes, budget(boxes.len())) > budget(boxes.len()));
            }
        }
    }

    /// A false answer is returned, by the sweep, the grid and the tree, on one thread and on
    /// many; on one thread nothing more is asked after it.
    #[test]
    fn a_false_pair_is_the_answer() {
        let unit = |x: f64| AABB::from_corners([x, 0.0, 0.0], [x + 1.0, 1.0, 1.0]);
        let short: Vec<_> = (0..10).map(|k| unit(k as f64)).collect();
        let side_by_side =
            |k: usize, to: f64| AABB::from_corners([0.0, k as f64, 0.0], [to, k as f64 + 1.0, 1.0]);
        let wide: Vec<_> = (0..400).map(|k| side_by_side(k, 1000.0)).collect();
        let long: Vec<_> = (0..400).map(|k| side_by_side(k, f64::INFINITY)).collect();
        for (boxes, how) in [(short, Kind::Sweep), (wide, Kind::Grid), (long, Kind::Tree)] {
            let meeting = MeetingBoxes::new(boxes);
            assert_eq!(kind(&meeting), how);
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

    /// Boxes that the grid would put in too many cells (unit boxes far apart, with one box
    /// over all of them) or with too many pairs in a cell (all in one place) go to the tree.
    #[test]
    fn crowded_grids_give_way_to_the_tree() {
        let b = |lo: [f64; 3], hi: [f64; 3]| AABB::from_corners(lo, hi);
        let mut spanning: Vec<_> = (0..4096)
            .map(|k| [k % 16, k / 16 % 16, k / 256].map(|c| 250.0 * c as f64))
            .map(|lo| b(lo, lo.map(|c| c + 1.0)))
            .collect();
        spanning.push(b([0.0; 3], [4000.0; 3]));
        let piled: Vec<_> = (0..2000).map(|_| b([0.0; 3], [1.0; 3])).collect();
        for boxes in [spanning, piled] {
            let want = brute(&boxes);
            let (got, kind) = asked(&boxes, true);
            assert_eq!(kind, Kind::Tree);
            assert_eq!(got, want);
        }
    }
}
