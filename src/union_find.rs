//! Disjoint sets (union–find by rank with path halving), shared by the 2D and 3D kernels.

/// Disjoint sets over `0..n`.
#[derive(Clone, Debug)]
pub(crate) struct UnionFind {
    parent: Vec<usize>,
    /// An upper bound on the height of each root's tree (at most log₂ n, so a byte).
    rank: Vec<u8>,
}

impl UnionFind {
    /// `n` singletons.
    pub(crate) fn new(n: usize) -> UnionFind {
        UnionFind {
            parent: (0..n).collect(),
            rank: vec![0; n],
        }
    }

    /// A new singleton; its index.
    pub(crate) fn add(&mut self) -> usize {
        self.parent.push(self.parent.len());
        self.rank.push(0);
        self.parent.len() - 1
    }

    /// The representative of `x`'s set.
    pub(crate) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    /// Join the sets of `a` and `b`, the lower-ranked root under the other; false if they were
    /// already one (a cycle).
    pub(crate) fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        let (lo, hi) = match self.rank[ra] < self.rank[rb] {
            true => (ra, rb),
            false => (rb, ra),
        };
        self.parent[lo] = hi;
        if self.rank[lo] == self.rank[hi] {
            self.rank[hi] += 1;
        }
        true
    }

    /// Each element's class as a number in `0..k`, numbered in order of first appearance, and k.
    pub(crate) fn classes(&mut self) -> (Vec<usize>, usize) {
        let mut label = vec![usize::MAX; self.parent.len()];
        let mut out = Vec::with_capacity(self.parent.len());
        let mut k = 0;
        for x in 0..self.parent.len() {
            let r = self.find(x);
            if label[r] == usize::MAX {
                label[r] = k;
                k += 1;
            }
            out.push(label[r]);
        }
        (out, k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::collections::BTreeSet;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// `union` is false exactly for elements already joined (some added after the start),
        /// and the classes are the components of the joined pairs, numbered from 0 in order of
        /// first appearance: an oracle that relabels a whole class on every join.
        #[test]
        fn classes_are_the_components(
            (n, added) in (1usize..40, 0usize..5),
            pairs in proptest::collection::vec((0usize..45, 0usize..45), 0..80),
        ) {
            let mut uf = UnionFind::new(n);
            for k in 0..added {
                prop_assert_eq!(uf.add(), n + k);
            }
            let n = n + added;
            let mut label: Vec<usize> = (0..n).collect();
            for (a, b) in pairs.into_iter().map(|(a, b)| (a % n, b % n)) {
                let joined = label[a] != label[b];
                prop_assert_eq!(uf.union(a, b), joined);
                let (from, to) = (label[a], label[b]);
                label.iter_mut().filter(|l| **l == from).for_each(|l| *l = to);
            }
            let (classes, k) = uf.classes();
            for i in 0..n {
                for j in 0..n {
                    prop_assert_eq!(classes[i] == classes[j], label[i] == label[j]);
                }
            }
            prop_assert_eq!(k, label.iter().collect::<BTreeSet<_>>().len());
            // The first element of each class, in order, carries the class's number.
            let firsts = (0..n).filter(|&i| !classes[..i].contains(&classes[i]));
            prop_assert!(firsts.enumerate().all(|(c, i)| classes[i] == c));
        }
    }
}
