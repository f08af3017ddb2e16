//! The arrangement of closed edges as a plane sweep records it (seed 002 §1.3): its vertices in
//! sweep order, its pieces with the piece directly below each, and the winding numbers of the
//! faces beside every piece. Recorded by the exact sweep ([`super::intersect::arrange`]) and by
//! float mode's sweep of grid fragments ([`super::grid_arrange::arrange_grid`]).

use super::status::NIL;

/// The pieces of an arrangement of closed edges: each group is one piece of the plane's
/// subdivision, carried by one or more collinear edges (a shared stretch), from event `from`
/// to event `to` (`from < to` in sweep order), with the group directly below it in the sweep.
pub(crate) struct Arrangement<P> {
    /// The events in sweep order: every vertex of the subdivision, once.
    pub points: Vec<P>,
    /// The pieces, in the order the sweep opened them.
    pub groups: Vec<Group>,
    /// The edges of every group, `Group::members` indexes into it.
    pub members: Vec<usize>,
    /// Float mode's grid sweep: pairs of edges found crossing (no crossing point is made); if
    /// there is any, the rest of the arrangement is not valid. Empty in exact mode, whose sweep
    /// cuts edges at their crossings.
    pub crossed: Vec<(usize, usize)>,
}

/// One piece of an [`Arrangement`].
pub(crate) struct Group {
    /// Its lower end (an index of [`Arrangement::points`]).
    pub from: usize,
    /// Its upper end.
    pub to: usize,
    /// The group directly below it in the sweep (opened earlier), `None` for the far face.
    pub below: Option<usize>,
    /// The range of [`Arrangement::members`] holding its edges.
    pub members: std::ops::Range<usize>,
}

impl<P> Arrangement<P> {
    /// The points (made by `point`) that the `pieces` (pairs of indices of
    /// [`Arrangement::points`]) end at, in sweep order, with the pieces renumbered into them:
    /// the exact sweep's crossings among them are made exact here, the others never.
    pub fn into_points<Q>(
        self,
        pieces: &mut [(usize, usize)],
        mut point: impl FnMut(P) -> Q,
    ) -> Vec<Q> {
        let mut index = vec![NIL; self.points.len()];
        for &(a, b) in pieces.iter() {
            index[a] = 0;
            index[b] = 0;
        }
        // At most one point per piece where the pieces close up (each point starts one).
        let mut out = Vec::with_capacity(pieces.len());
        for (k, v) in self.points.into_iter().enumerate() {
            if index[k] != NIL {
                index[k] = out.len();
                out.push(point(v));
            }
        }
        for p in pieces.iter_mut() {
            *p = (index[p.0], index[p.1]);
        }
        out
    }

    /// The winding numbers `(below, above)` of the faces beside each group, edge `e` adding
    /// `mult(e)` from below to above (a directed edge adds its multiplicity from its right to
    /// its left, and `lo → hi` has its left above); the far face below all has `W::default()`.
    /// Along a piece they are constant when the edges are closed (as many enter as leave every
    /// vertex), as in every fill and Boolean operation. Group by group, in order (each needs
    /// the ones before it: only the faces above are kept).
    pub fn windings<'a, W>(
        &'a self,
        mult: impl Fn(usize) -> W + 'a,
    ) -> impl Iterator<Item = (W, W)> + 'a
    where
        W: Copy + Default + std::ops::Add<Output = W> + 'a,
    {
        let mut above: Vec<W> = Vec::with_capacity(self.groups.len());
        self.groups.iter().map(move |g| {
            let below = g.below.map_or_else(W::default, |b| above[b]);
            let up = self.members[g.members.clone()]
                .iter()
                .fold(below, |w, &e| w + mult(e));
            above.push(up);
            (below, up)
        })
    }
}

/// What a sweep records at each event to make an [`Arrangement`] of `n` edges.
pub(crate) struct Recorder<P> {
    arr: Arrangement<P>,
    /// The open group of each edge in the status.
    open: Vec<usize>,
}

impl<P> Recorder<P> {
    /// Nothing recorded yet, for edges `0..n`.
    pub fn new(n: usize) -> Self {
        Recorder {
            arr: Arrangement {
                points: Vec::with_capacity(n),
                groups: Vec::with_capacity(n),
                members: Vec::with_capacity(n),
                crossed: Vec::new(),
            },
            open: vec![NIL; n],
        }
    }

    /// The edges `old` leave the status at the event numbered `stamp`: their pieces end there.
    pub fn close(&mut self, old: &[usize], stamp: usize) {
        for &e in old {
            let g = std::mem::replace(&mut self.open[e], NIL);
            if g != NIL {
                self.arr.groups[g].to = stamp;
            }
        }
    }

    /// Event `p`: the edges `next` (bottom to top) enter the status above `lower`; runs of
    /// edges leaving `p` in the same direction (`same(k)` for `next[k]` after `next[k − 1]`)
    /// form one group.
    pub fn open(&mut self, p: P, next: &[usize], lower: usize, same: impl Fn(usize) -> bool) {
        let arr = &mut self.arr;
        let stamp = arr.points.len();
        arr.points.push(p);
        let mut below = (lower != NIL).then(|| self.open[lower]);
        for (k, &e) in next.iter().enumerate() {
            if k == 0 || !same(k) {
                let start = arr.members.len();
                arr.groups.push(Group {
                    from: stamp,
                    to: NIL,
                    below,
                    members: start..start,
                });
                below = Some(arr.groups.len() - 1);
            }
            let g = arr.groups.len() - 1;
            arr.members.push(e);
            arr.groups[g].members.end = arr.members.len();
            self.open[e] = g;
        }
    }

    /// Edges `i < j` were found crossing (see [`Arrangement::crossed`]).
    pub fn cross(&mut self, i: usize, j: usize) {
        self.arr.crossed.push((i, j));
    }

    /// The arrangement recorded.
    pub fn finish(self) -> Arrangement<P> {
        self.arr
    }
}
