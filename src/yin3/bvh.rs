//! A bounding volume hierarchy of triangle boxes for finding the pairs of boxes, one from each
//! of two sets, that meet: the boxes sorted along a Morton (Z-order) curve of their centres and
//! grouped bottom-up in runs of [`WIDTH`] (a linear BVH, Lauterbach et al., "Fast BVH
//! construction on GPUs", 2009). Two hierarchies are walked together into the pairs of nodes
//! whose boxes meet only, so the parts of two meshes far from where they meet cost nothing
//! below the nodes that hold them.

use rstar::{Envelope, AABB};

/// Children per node.
const WIDTH: usize = 8;

/// Bits per axis of a Morton code.
const BITS: u32 = 21;

/// A node: its level (0 for a box of the set) and its place in that level.
type Node = (usize, usize);

/// The hierarchy of a set of boxes (module docs).
pub(crate) struct Bvh {
    /// The boxes' indices (in the caller's numbering), in Morton order.
    items: Vec<usize>,
    /// Level 0: the boxes in Morton order; each next level: one box per run of [`WIDTH`]
    /// boxes of the level below, merged. The last level has one box, the root.
    levels: Vec<Vec<AABB<[f64; 3]>>>,
}

impl Bvh {
    /// The hierarchy of the boxes `boxes[i]` for `i` in `items`.
    pub(crate) fn new(items: &[usize], boxes: &[AABB<[f64; 3]>]) -> Bvh {
        let hull = (items.iter()).fold(AABB::new_empty(), |h, &i| h.merged(&boxes[i]));
        let mut keyed: Vec<(u64, usize)> = (items.iter())
            .map(|&i| (morton(&hull, &boxes[i]), i))
            .collect();
        keyed.sort_unstable();
        let items: Vec<usize> = keyed.into_iter().map(|(_, i)| i).collect();
        let mut levels = vec![items.iter().map(|&i| boxes[i]).collect::<Vec<_>>()];
        while levels.last().is_some_and(|l| l.len() > 1) {
            let below = levels.last().expect("a level");
            let merged = (below.chunks(WIDTH))
                .map(|run| run.iter().fold(AABB::new_empty(), |h, b| h.merged(b)))
                .collect();
            levels.push(merged);
        }
        Bvh { items, levels }
    }

    /// The root, if the set is not empty.
    fn root(&self) -> Option<Node> {
        let top = self.levels.len().checked_sub(1)?;
        (!self.levels[top].is_empty()).then_some((top, 0))
    }

    /// The box of a node.
    fn node_box(&self, (level, i): Node) -> &AABB<[f64; 3]> {
        &self.levels[level][i]
    }

    /// What stands for `n` when it is paired with a node at level `beside`, as a level and a
    /// range of places in it: its children if it is above level 0 and no lower than that node
    /// (the higher node of a pair is split, both at equal levels, so nodes of like size are
    /// paired), else `n` itself.
    fn split(&self, (level, i): Node, beside: usize) -> (usize, std::ops::Range<usize>) {
        if level > 0 && level >= beside {
            let end = ((i + 1) * WIDTH).min(self.levels[level - 1].len());
            (level - 1, i * WIDTH..end)
        } else {
            (level, i..i + 1)
        }
    }

    /// The boxes of the set (their indices in the caller's numbering) that meet `query`.
    pub(crate) fn meeting(&self, query: &AABB<[f64; 3]>) -> Vec<usize> {
        let mut found = Vec::new();
        let mut stack: Vec<Node> = self.root().into_iter().collect();
        while let Some(node) = stack.pop() {
            if !self.node_box(node).intersects(query) {
                continue;
            }
            if node.0 == 0 {
                found.push(self.items[node.1]);
                continue;
            }
            let (level, places) = self.split(node, 0);
            stack.extend(places.map(|i| (level, i)));
        }
        found
    }

    /// Pairs of nodes of `self` and `other` whose boxes meet, covering every pair of boxes
    /// that meet exactly once: the roots' pairs, split down until there are at least `enough`
    /// or every pair is of boxes of the sets. The pieces of work of [`Bvh::meeting_pairs`].
    pub(crate) fn meeting_nodes(&self, other: &Bvh, enough: usize) -> Vec<[Node; 2]> {
        let (Some(x), Some(y)) = (self.root(), other.root()) else {
            return Vec::new();
        };
        let mut pairs = match self.node_box(x).intersects(other.node_box(y)) {
            true => vec![[x, y]],
            false => Vec::new(),
        };
        while pairs.len() < enough && pairs.iter().any(|[x, y]| x.0 > 0 || y.0 > 0) {
            let mut split = Vec::new();
            for &[x, y] in &pairs {
                let ((lx, xs), (ly, ys)) = (self.split(x, y.0), other.split(y, x.0));
                for cx in xs {
                    let bx = &self.levels[lx][cx];
                    let meeting = ys
                        .clone()
                        .filter(|&cy| bx.intersects(&other.levels[ly][cy]));
                    split.extend(meeting.map(|cy| [(lx, cx), (ly, cy)]));
                }
            }
            pairs = split;
        }
        pairs
    }

    /// Calls `f(t, s)` on every pair of a box `t` of `self` and a box `s` of `other` that
    /// meet.
    pub(crate) fn each_meeting_pair(&self, other: &Bvh, mut f: impl FnMut(usize, usize)) {
        for piece in self.meeting_nodes(other, 1) {
            self.meeting_pairs(other, piece, &mut |t, s| {
                f(t, s);
                true
            });
        }
    }

    /// Calls `f(t, s)` on each pair of boxes, `t` under the node `x` of `self` and `s` under
    /// the node `y` of `other`, that meet, until `f` returns false; false if it did. The boxes
    /// of `x` and `y` must meet.
    pub(crate) fn meeting_pairs(
        &self,
        other: &Bvh,
        [x, y]: [Node; 2],
        f: &mut impl FnMut(usize, usize) -> bool,
    ) -> bool {
        if x.0 == 0 && y.0 == 0 {
            return f(self.items[x.1], other.items[y.1]);
        }
        let ((lx, xs), (ly, ys)) = (self.split(x, y.0), other.split(y, x.0));
        let (x_boxes, y_boxes) = (&self.levels[lx], &other.levels[ly]);
        // Only children that meet the other node's box can meet any of its children: each side
        // is filtered by the other's box first (the pairs left, and their order, are the same).
        let (bx, by) = (self.node_box(x), other.node_box(y));
        let mut near_x = [0; WIDTH];
        let mut count = 0;
        for cy in ys {
            if y_boxes[cy].intersects(bx) {
                near_x[count] = cy;
                count += 1;
            }
        }
        // Loops, not `all` with closures: the closures, with `f` inlined, were calls with
        // large frames on every node visited.
        for cx in xs {
            let b = &x_boxes[cx];
            if !b.intersects(by) {
                continue;
            }
            for &cy in &near_x[..count] {
                if b.intersects(&y_boxes[cy]) && !self.meeting_pairs(other, [(lx, cx), (ly, cy)], f)
                {
                    return false;
                }
            }
        }
        true
    }
}

/// The Morton code of the centre of `b`, its coordinates scaled to [`BITS`] bits in `hull`.
fn morton(hull: &AABB<[f64; 3]>, b: &AABB<[f64; 3]>) -> u64 {
    let (lo, hi, c) = (hull.lower(), hull.upper(), b.center());
    let max = ((1u64 << BITS) - 1) as f64;
    let cell = |k: usize| {
        let span = hi[k] - lo[k];
        let t = if span > 0.0 {
            (c[k] - lo[k]) / span
        } else {
            0.0
        };
        // Values outside [0, 1] (none for finite boxes) clamp to the ends; NaN (a box with a
        // NaN corner, which meets nothing) becomes 0 in the cast.
        (t.clamp(0.0, 1.0) * max) as u64
    };
    spread(cell(0)) | spread(cell(1)) << 1 | spread(cell(2)) << 2
}

/// The low [`BITS`] bits of `v` spread to every third bit.
fn spread(v: u64) -> u64 {
    let mut x = v & 0x1f_ffff;
    x = (x | x << 32) & 0x1f00000000ffff;
    x = (x | x << 16) & 0x1f0000ff0000ff;
    x = (x | x << 8) & 0x100f00f00f00f00f;
    x = (x | x << 4) & 0x10c30c30c30c30c3;
    (x | x << 2) & 0x1249249249249249
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A box from a corner and non-negative sides.
    pub(in crate::yin3) fn a_box(corner: [f64; 3], sides: [f64; 3]) -> AABB<[f64; 3]> {
        AABB::from_corners(corner, [0, 1, 2].map(|k| corner[k] + sides[k]))
    }

    #[test]
    fn spread_puts_each_bit_three_apart() {
        for k in 0..BITS {
            assert_eq!(spread(1 << k), 1 << (3 * k));
        }
        assert_eq!(spread(u64::MAX), 0x1249249249249249);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]

        /// Walking two hierarchies together from the pieces of [`Bvh::meeting_nodes`] (for
        /// any number of pieces asked) yields each pair of boxes that meet exactly once:
        /// boxes that touch in a face or corner included (sides may be 0), sets of up to 300
        /// boxes (three levels and more), and sets that are empty or lie apart.
        #[test]
        fn the_walk_finds_every_meeting_pair_once(
            a in prop::collection::vec(
                ([0.0..16.0, 0.0..16.0, 0.0..16.0f64], [0.0..3.0, 0.0..3.0, 0.0..3.0f64]), 0..300),
            b in prop::collection::vec(
                ([0.0..16.0, 0.0..16.0, 0.0..16.0f64], [0.0..3.0, 0.0..3.0, 0.0..3.0f64]), 0..300),
            shift in 0.0..24.0f64,
            enough in 1usize..200,
        ) {
            let boxes: Vec<AABB<[f64; 3]>> = (a.iter().map(|(c, s)| (c, s, 0.0)))
                .chain(b.iter().map(|(c, s)| (c, s, shift)))
                .map(|(c, s, d)| a_box(c.map(|v| (v + d).floor()), s.map(f64::floor)))
                .collect();
            let (ia, ib): (Vec<usize>, Vec<usize>) =
                ((0..a.len()).collect(), (a.len()..boxes.len()).collect());
            let (x, y) = (Bvh::new(&ia, &boxes), Bvh::new(&ib, &boxes));
            let mut found = Vec::new();
            for pair in x.meeting_nodes(&y, enough) {
                let whole = x.meeting_pairs(&y, pair, &mut |t, s| {
                    found.push((t, s));
                    true
                });
                prop_assert!(whole);
            }
            found.sort_unstable();
            let mut expected = Vec::new();
            for &t in &ia {
                expected.extend(ib.iter().filter(|&&s| boxes[t].intersects(&boxes[s])).map(|&s| (t, s)));
            }
            prop_assert_eq!(found, expected);
        }

        /// A query box finds the boxes that meet it, touching ones included, each once.
        #[test]
        fn a_query_finds_the_boxes_that_meet_it(
            a in prop::collection::vec(
                ([0.0..16.0, 0.0..16.0, 0.0..16.0f64], [0.0..3.0, 0.0..3.0, 0.0..3.0f64]), 0..300),
            corner in [0.0..16.0, 0.0..16.0, 0.0..16.0f64],
            sides in [0.0..8.0, 0.0..8.0, 0.0..8.0f64],
        ) {
            let boxes: Vec<AABB<[f64; 3]>> = (a.iter())
                .map(|(c, s)| a_box(c.map(f64::floor), s.map(f64::floor)))
                .collect();
            let items: Vec<usize> = (0..boxes.len()).rev().collect();
            let query = a_box(corner.map(f64::floor), sides.map(f64::floor));
            let mut found = Bvh::new(&items, &boxes).meeting(&query);
            found.sort_unstable();
            let expected: Vec<usize> =
                (0..boxes.len()).filter(|&i| boxes[i].intersects(&query)).collect();
            prop_assert_eq!(found, expected);
        }
    }
}
