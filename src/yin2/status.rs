//! The status of a plane sweep (seed 002 §1.3): the edges cut by the sweep line, bottom to top,
//! as a treap searched with monotone predicates at the current event.

/// No node (the empty treap).
pub(crate) const NIL: usize = usize::MAX;

/// The sweep status of seed 002 §1.3: a treap over the edges cut by the sweep line, bottom to top.
// The order is implicit (held by the tree's shape): it is searched with monotone predicates at
// the current event, and an edge is removed through its node (parent links), so two stored edges
// are never compared.
pub(crate) struct Status {
    /// The links and priority of each edge's node, side by side (one cache line holds two).
    nodes: Vec<Node>,
    /// Whether each edge is in the status.
    pub live: Vec<bool>,
    /// The root of the main tree.
    pub root: usize,
}

/// A node of the treap: its children, its parent and its priority.
#[derive(Clone, Copy)]
struct Node {
    left: usize,
    right: usize,
    up: usize,
    prio: u64,
}

impl Status {
    /// An empty status for the edges `0..n` (priorities from a fixed hash: deterministic output).
    pub fn new(n: usize) -> Status {
        let nodes = (0..n as u64)
            .map(|i| {
                let mut z = i.wrapping_add(0x9e37_79b9_7f4a_7c15);
                z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
                Node {
                    left: NIL,
                    right: NIL,
                    up: NIL,
                    prio: z ^ (z >> 31),
                }
            })
            .collect();
        Status {
            nodes,
            live: vec![false; n],
            root: NIL,
        }
    }

    /// Detach node `x` from every link (before it is re-inserted or dropped).
    pub fn reset(&mut self, x: usize) {
        self.nodes[x].left = NIL;
        self.nodes[x].right = NIL;
        self.nodes[x].up = NIL;
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
                    self.nodes[t].up = NIL;
                } else {
                    self.nodes[rhook].left = t;
                    self.nodes[t].up = rhook;
                }
                rhook = t;
                t = self.nodes[t].left;
            } else {
                if lhook == NIL {
                    lroot = t;
                    self.nodes[t].up = NIL;
                } else {
                    self.nodes[lhook].right = t;
                    self.nodes[t].up = lhook;
                }
                lhook = t;
                t = self.nodes[t].right;
            }
        }
        if lhook != NIL {
            self.nodes[lhook].right = NIL;
        }
        if rhook != NIL {
            self.nodes[rhook].left = NIL;
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
            } else if self.nodes[a].prio >= self.nodes[b].prio {
                (a, false)
            } else {
                (b, false)
            };
            if hook == NIL {
                root = x;
            } else if hook_right {
                self.nodes[hook].right = x;
            } else {
                self.nodes[hook].left = x;
            }
            if x != NIL {
                self.nodes[x].up = hook;
            }
            if done {
                return root;
            }
            hook = x;
            if x == a {
                hook_right = true;
                a = self.nodes[a].right;
            } else {
                hook_right = false;
                b = self.nodes[b].left;
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
        let m = self.merge(self.nodes[x].left, self.nodes[x].right);
        let par = self.nodes[x].up;
        if m != NIL {
            self.nodes[m].up = par;
        }
        if par == NIL {
            self.root = m;
        } else if self.nodes[par].left == x {
            self.nodes[par].left = m;
        } else {
            self.nodes[par].right = m;
        }
        self.reset(x);
        self.live[x] = false;
    }

    /// Put node `new` (not in the tree) in the place of node `x` of the main tree, which
    /// leaves it: the order of the others is kept, and `new` takes `x`'s priority, so the
    /// heap order holds.
    pub fn replace(&mut self, x: usize, new: usize) {
        let (l, r, par) = (self.nodes[x].left, self.nodes[x].right, self.nodes[x].up);
        (
            self.nodes[new].left,
            self.nodes[new].right,
            self.nodes[new].up,
        ) = (l, r, par);
        let (px, pn) = (self.nodes[x].prio, self.nodes[new].prio);
        (self.nodes[x].prio, self.nodes[new].prio) = (pn, px);
        for child in [l, r] {
            if child != NIL {
                self.nodes[child].up = new;
            }
        }
        if par == NIL {
            self.root = new;
        } else if self.nodes[par].left == x {
            self.nodes[par].left = new;
        } else {
            self.nodes[par].right = new;
        }
        self.reset(x);
        self.live[x] = false;
        self.live[new] = true;
    }

    /// The node before `x` in the main tree (`NIL` if it is the first).
    pub fn before(&self, mut x: usize) -> usize {
        if self.nodes[x].left != NIL {
            return self.last(self.nodes[x].left);
        }
        while self.nodes[x].up != NIL && self.nodes[self.nodes[x].up].left == x {
            x = self.nodes[x].up;
        }
        self.nodes[x].up
    }

    /// The node after `x` in the main tree (`NIL` if it is the last).
    pub fn after(&self, mut x: usize) -> usize {
        if self.nodes[x].right != NIL {
            return self.first(self.nodes[x].right);
        }
        while self.nodes[x].up != NIL && self.nodes[self.nodes[x].up].right == x {
            x = self.nodes[x].up;
        }
        self.nodes[x].up
    }

    /// The first node of treap `t` (`NIL` if empty).
    pub fn first(&self, mut t: usize) -> usize {
        while t != NIL && self.nodes[t].left != NIL {
            t = self.nodes[t].left;
        }
        t
    }

    /// The last node of treap `t` (`NIL` if empty).
    pub fn last(&self, mut t: usize) -> usize {
        while t != NIL && self.nodes[t].right != NIL {
            t = self.nodes[t].right;
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
                x = self.nodes[x].left;
            }
            if let Some(y) = stack.pop() {
                out.push(y);
                x = self.nodes[y].right;
            }
        }
    }
}
