//! The status of a plane sweep (seed 002 §1.3): the edges cut by the sweep line, bottom to top,
//! as a treap searched with monotone predicates at the current event.

/// No node (the empty treap).
pub(crate) const NIL: usize = usize::MAX;

/// The sweep status of seed 002 §1.3: a treap over the edges cut by the sweep line, bottom to top.
// The order is implicit (held by the tree's shape): it is searched with monotone predicates at
// the current event, and an edge is removed through its node (parent links), so two stored edges
// are never compared.
pub(crate) struct Status {
    left: Vec<usize>,
    right: Vec<usize>,
    up: Vec<usize>,
    prio: Vec<u64>,
    /// Whether each edge is in the status.
    pub live: Vec<bool>,
    /// The root of the main tree.
    pub root: usize,
}

impl Status {
    /// An empty status for the edges `0..n` (priorities from a fixed hash: deterministic output).
    pub fn new(n: usize) -> Status {
        let prio = (0..n as u64)
            .map(|i| {
                let mut z = i.wrapping_add(0x9e37_79b9_7f4a_7c15);
                z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
                z ^ (z >> 31)
            })
            .collect();
        Status {
            left: vec![NIL; n],
            right: vec![NIL; n],
            up: vec![NIL; n],
            prio,
            live: vec![false; n],
            root: NIL,
        }
    }

    /// Detach node `x` from every link (before it is re-inserted or dropped).
    pub fn reset(&mut self, x: usize) {
        self.left[x] = NIL;
        self.right[x] = NIL;
        self.up[x] = NIL;
    }

    /// Split treap `t` into the nodes where the monotone predicate `goes_right` is false, then
    /// true.
    pub fn split(
        &mut self,
        mut t: usize,
        mut goes_right: impl FnMut(usize) -> bool,
    ) -> (usize, usize) {
        let (mut lroot, mut rroot, mut lhook, mut rhook) = (NIL, NIL, NIL, NIL);
        while t != NIL {
            if goes_right(t) {
                if rhook == NIL {
                    rroot = t;
                    self.up[t] = NIL;
                } else {
                    self.left[rhook] = t;
                    self.up[t] = rhook;
                }
                rhook = t;
                t = self.left[t];
            } else {
                if lhook == NIL {
                    lroot = t;
                    self.up[t] = NIL;
                } else {
                    self.right[lhook] = t;
                    self.up[t] = lhook;
                }
                lhook = t;
                t = self.right[t];
            }
        }
        if lhook != NIL {
            self.right[lhook] = NIL;
        }
        if rhook != NIL {
            self.left[rhook] = NIL;
        }
        (lroot, rroot)
    }

    /// The treap holding all of `a` followed by all of `b`.
    pub fn merge(&mut self, mut a: usize, mut b: usize) -> usize {
        let (mut root, mut hook, mut hook_right) = (NIL, NIL, false);
        loop {
            let (x, done) = if a == NIL {
                (b, true)
            } else if b == NIL {
                (a, true)
            } else if self.prio[a] >= self.prio[b] {
                (a, false)
            } else {
                (b, false)
            };
            if hook == NIL {
                root = x;
            } else if hook_right {
                self.right[hook] = x;
            } else {
                self.left[hook] = x;
            }
            if x != NIL {
                self.up[x] = hook;
            }
            if done {
                return root;
            }
            hook = x;
            if x == a {
                hook_right = true;
                a = self.right[a];
            } else {
                hook_right = false;
                b = self.left[b];
            }
        }
    }

    /// Make the main tree the treap `below`, then the nodes `next` in order, then the treap
    /// `above` (split off it at one event), with `next` live; returns the last node of `below`
    /// and the first of `above`, the new neighbours of `next` (`NIL` where there is none).
    pub fn rejoin(&mut self, below: usize, next: &[usize], above: usize) -> (usize, usize) {
        let (lower, upper) = (self.last(below), self.first(above));
        let mut middle = NIL;
        for &s in next {
            self.live[s] = true;
            middle = self.merge(middle, s);
        }
        let joined = self.merge(below, middle);
        self.root = self.merge(joined, above);
        (lower, upper)
    }

    /// Remove node `x` from the main tree through its parent link.
    pub fn remove(&mut self, x: usize) {
        let m = self.merge(self.left[x], self.right[x]);
        let par = self.up[x];
        if m != NIL {
            self.up[m] = par;
        }
        if par == NIL {
            self.root = m;
        } else if self.left[par] == x {
            self.left[par] = m;
        } else {
            self.right[par] = m;
        }
        self.reset(x);
        self.live[x] = false;
    }

    /// Put node `new` (not in the tree) in the place of node `x` of the main tree, which
    /// leaves it: the order of the others is kept, and `new` takes `x`'s priority, so the
    /// heap order holds.
    pub fn replace(&mut self, x: usize, new: usize) {
        let (l, r, par) = (self.left[x], self.right[x], self.up[x]);
        (self.left[new], self.right[new], self.up[new]) = (l, r, par);
        self.prio.swap(x, new);
        for child in [l, r] {
            if child != NIL {
                self.up[child] = new;
            }
        }
        if par == NIL {
            self.root = new;
        } else if self.left[par] == x {
            self.left[par] = new;
        } else {
            self.right[par] = new;
        }
        self.reset(x);
        self.live[x] = false;
        self.live[new] = true;
    }

    /// The node before `x` in the main tree (`NIL` if it is the first).
    pub fn before(&self, mut x: usize) -> usize {
        if self.left[x] != NIL {
            return self.last(self.left[x]);
        }
        while self.up[x] != NIL && self.left[self.up[x]] == x {
            x = self.up[x];
        }
        self.up[x]
    }

    /// The node after `x` in the main tree (`NIL` if it is the last).
    pub fn after(&self, mut x: usize) -> usize {
        if self.right[x] != NIL {
            return self.first(self.right[x]);
        }
        while self.up[x] != NIL && self.right[self.up[x]] == x {
            x = self.up[x];
        }
        self.up[x]
    }

    /// The first node of treap `t` (`NIL` if empty).
    pub fn first(&self, mut t: usize) -> usize {
        while t != NIL && self.left[t] != NIL {
            t = self.left[t];
        }
        t
    }

    /// The last node of treap `t` (`NIL` if empty).
    pub fn last(&self, mut t: usize) -> usize {
        while t != NIL && self.right[t] != NIL {
            t = self.right[t];
        }
        t
    }

    /// Append the nodes of treap `t` to `out`, in order.
    pub fn collect(&self, t: usize, out: &mut Vec<usize>) {
        let mut stack = Vec::new();
        let mut x = t;
        while x != NIL || !stack.is_empty() {
            while x != NIL {
                stack.push(x);
                x = self.left[x];
            }
            if let Some(y) = stack.pop() {
                out.push(y);
                x = self.right[y];
            }
        }
    }
}
