//! The pasting map S_V⁻¹ (seed 000 Lemma 4.2, S2R-a..d; seed 002 Alg. 2).

use super::buckets::Buckets;
use super::error::YinError;
use super::hasse::swept_parents;
use super::set::{Spadjor, YinSet2};
use crate::kernel::{cmp_clockwise_from, Point};
use crate::num::Num;
use foldhash::{HashMap, HashMapExt, HashSet, HashSetExt};

/// Jordan curves as vertex cycles, the touching points among their vertices, and the loop
/// of each piece.
type Loops<N> = (Vec<Vec<Point<N>>>, HashSet<Point<N>>, Vec<usize>);

/// The result of an infallible operation whose internal invariant failed: a kernel bug,
/// reported loudly instead of returning a wrong set.
pub(crate) fn or_kernel_bug<N: Num>(r: Result<YinSet2<N>, YinError>) -> YinSet2<N> {
    r.unwrap_or_else(|e| panic!("kernel bug: {e}"))
}

/// A segmented realizable spadjor: points and the directed straight pieces between them.
pub(crate) struct Segmented<N: Num> {
    points: Vec<Point<N>>,
    index: HashMap<Point<N>, usize>,
    edges: Vec<(usize, usize)>,
    /// For pieces made by a plane sweep: the piece directly below each one's lower end.
    below: Option<Vec<Option<usize>>>,
}

impl<N: Num> Segmented<N> {
    pub(crate) fn new() -> Segmented<N> {
        Segmented {
            points: Vec::new(),
            index: HashMap::new(),
            edges: Vec::new(),
            below: None,
        }
    }

    /// The pieces `edges` between `points` as a plane sweep made them (no interning:
    /// [`Segmented::id`] must not be used on it): the points in sweep order, the pieces in the
    /// order the sweep opened them, `below[e]` the piece directly below the lower end of piece
    /// `e` as it leaves (`None` for the far face). The sweep gives the Hasse diagram
    /// ([`swept_parents`]).
    pub(crate) fn swept(
        points: Vec<Point<N>>,
        edges: Vec<(usize, usize)>,
        below: Vec<Option<usize>>,
    ) -> Segmented<N> {
        Segmented {
            points,
            index: HashMap::new(),
            edges,
            below: Some(below),
        }
    }

    /// The id of a point (interned).
    pub(crate) fn id(&mut self, p: &Point<N>) -> usize {
        if let Some(&i) = self.index.get(p) {
            return i;
        }
        self.points.push(p.clone());
        self.index.insert(p.clone(), self.points.len() - 1);
        self.points.len() - 1
    }

    /// Add the directed piece `a → b`.
    pub(crate) fn push(&mut self, a: usize, b: usize) {
        self.edges.push((a, b));
    }

    /// S_V⁻¹: paste the pieces into Jordan curves and build the Yin set (0̂ if no piece is
    /// left, which the callers rule out for 1̂), with the predicates of `ctx` taken as exact.
    /// The pieces must bound a Yin set; a piece set that is not a union of closed cycles is an
    /// error ([`YinError::Unbalanced`]), never a silently dropped path.
    pub(crate) fn paste_exact(self, ctx: N::Ctx) -> Result<YinSet2<N>, YinError> {
        if self.edges.is_empty() {
            return Ok(YinSet2::empty().with_ctx(ctx));
        }
        let (loops, touching, loop_of) = self.loops(&ctx)?;
        let spadjor = match &self.below {
            Some(below) => {
                let ascending = |e: usize| self.edges[e].0 < self.edges[e].1;
                let parent = swept_parents(&loop_of, below, ascending, loops.len());
                Spadjor::assemble_nested(loops, &parent, &touching, &ctx)
            }
            None => Spadjor::assemble(loops, &touching, &ctx).0,
        };
        Ok(YinSet2::from_spadjor(spadjor, ctx))
    }

    /// S2R-b..d: grow paths by the clockwise rule and cut loops off at repeated vertices
    /// (S2R-c), so that every loop is a Jordan curve. Also returns the touching points: vertices
    /// entered by more than one piece.
    ///
    /// The seed grows the path until it closes at its start into a loop γ₁ and then divides γ₁
    /// into Jordan curves; cutting a loop off as soon as the path returns to any vertex (seed
    /// 002, Alg. 2) gives the same curves because of the *nesting property*: on γ₁, no two
    /// vertices alternate as u … w … u … w, that is, between two visits of a vertex the path
    /// meets only vertices it does not meet outside them. The clockwise rule makes it hold for
    /// pieces bounding a Yin set: γ₁ traces the boundary of one region and touches itself
    /// without crossing. The property test in `paste/s2r_c_oracle.rs` checks the property and
    /// the equality against the seed's version on random piece sets.
    ///
    /// A path can only stop where more pieces enter than leave, so any piece set that is not
    /// a union of cycles is an [`YinError::Unbalanced`] error (in every build profile).
    fn loops(&self, ctx: &N::Ctx) -> Result<Loops<N>, YinError> {
        let n = self.points.len();
        // The pieces leaving each vertex, in order.
        let out = Buckets::new(n, self.edges.iter().enumerate().map(|(e, &(a, _))| (a, e)));
        let mut indegree = vec![0usize; n];
        for &(_, b) in &self.edges {
            indegree[b] += 1;
        }
        let mut touching = HashSet::with_capacity(indegree.iter().filter(|&&d| d > 1).count());
        touching.extend(
            (0..n)
                .filter(|&v| indegree[v] > 1)
                .map(|v| self.points[v].clone()),
        );
        let mut used = vec![false; self.edges.len()];
        let mut pos = vec![usize::MAX; n];
        let mut loops = Vec::new();
        let mut loop_of = vec![usize::MAX; self.edges.len()];
        let mut path = Vec::new();
        for first in 0..self.edges.len() {
            if used[first] {
                continue;
            }
            used[first] = true;
            pos[self.edges[first].0] = 0;
            path.push(first);
            while let Some(&last) = path.last() {
                let v = self.edges[last].1;
                if pos[v] != usize::MAX {
                    // S2R-c: the path came back to v; cut the loop off.
                    let start = pos[v];
                    let cycle = &path[start..];
                    for &e in cycle {
                        pos[self.edges[e].0] = usize::MAX;
                        loop_of[e] = loops.len();
                    }
                    loops.push(
                        cycle
                            .iter()
                            .map(|&e| self.points[self.edges[e].0].clone())
                            .collect(),
                    );
                    path.truncate(start);
                    continue;
                }
                match self.next_piece(last, out.get(v), &used, ctx) {
                    Some(e) => {
                        used[e] = true;
                        pos[v] = path.len();
                        path.push(e);
                    }
                    None => {
                        return Err(YinError::Unbalanced {
                            point: self.points[v].to_string(),
                        })
                    }
                }
            }
        }
        Ok((loops, touching, loop_of))
    }

    /// S2R-b: of the unused pieces leaving the end of `incoming`, the one with the smallest
    /// counterclockwise angle ∠β_out v β_in, i.e. the clockwise neighbour.
    fn next_piece(
        &self,
        incoming: usize,
        candidates: &[usize],
        used: &[bool],
        ctx: &N::Ctx,
    ) -> Option<usize> {
        let (from, v) = self.edges[incoming];
        let (vp, rp) = (&self.points[v], &self.points[from]);
        candidates
            .iter()
            .copied()
            .filter(|&e| !used[e])
            .min_by(|&e, &f| {
                cmp_clockwise_from(
                    vp,
                    rp,
                    &self.points[self.edges[e].1],
                    &self.points[self.edges[f].1],
                    ctx,
                )
            })
    }
}

#[cfg(test)]
mod s2r_c_oracle;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    #[test]
    fn unbalanced_pieces_are_an_error_not_a_dropped_path() {
        // Two sides of a triangle: the path from (0,0) ends at (0,2), which nothing leaves.
        let mut g = Segmented::<Rational>::new();
        let v: Vec<usize> = [(0, 0), (2, 0), (0, 2)]
            .iter()
            .map(|&(x, y)| g.id(&Point::int(x, y)))
            .collect();
        g.push(v[0], v[1]);
        g.push(v[1], v[2]);
        assert_eq!(
            g.paste_exact(()).err(),
            Some(YinError::Unbalanced {
                point: Point::<Rational>::int(0, 2).to_string()
            })
        );
    }
}
