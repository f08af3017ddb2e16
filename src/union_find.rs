//! Disjoint sets (union–find with path halving), shared by the 2D and 3D kernels.

/// Disjoint sets over `0..n`.
#[derive(Clone, Debug)]
pub(crate) struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    /// `n` singletons.
    pub(crate) fn new(n: usize) -> UnionFind {
        UnionFind {
            parent: (0..n).collect(),
        }
    }

    /// A new singleton; its index.
    pub(crate) fn add(&mut self) -> usize {
        self.parent.push(self.parent.len());
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

    /// Join the sets of `a` and `b`; false if they were already one (a cycle).
    pub(crate) fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        self.parent[ra] = rb;
        ra != rb
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
