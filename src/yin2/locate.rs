//! Batch point location by plane sweep (seed 002 Alg. 1), O((n + q) log n).

use crate::kernel::{orient, Point};
use crate::num::{segment_distance, Num};
use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};
use std::cmp::Ordering;
use std::collections::BTreeSet;

/// Where a point lies relative to a Yin set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// In the (open) Yin set.
    Inside,
    /// In the exterior (the complement of the closure).
    Outside,
    /// On the boundary.
    OnBoundary,
}

/// A directed edge in the sweep status, or a query point (`lo == hi`, `id == usize::MAX`).
struct Key<'a, N: Num> {
    lo: &'a Point<N>,
    hi: &'a Point<N>,
    from: &'a Point<N>,
    to: &'a Point<N>,
    id: usize,
    ctx: &'a N::Ctx,
}

impl<N: Num> Key<'_, N> {
    fn is_query(&self) -> bool {
        self.id == usize::MAX
    }
}

/// Order of two non-crossing, non-vertical edges that are both cut by a vertical line just right
/// of the sweep position: decided from endpoints alone, so it holds for the edges' whole stay
/// in the status. Decided exactly even in float mode: two edges closer than ε (a sliver) must
/// still be stacked in their true order, or a point far above the sliver sees the wrong edge.
fn cmp_edges<N: Num>(s: &Key<'_, N>, t: &Key<'_, N>) -> Ordering {
    if s.lo > t.lo {
        return cmp_edges(t, s).reverse();
    }
    // t starts at or right of s's start: compare t's start (or end) with s's line.
    let exact = N::exact_ctx();
    let mut o = if s.lo == t.lo {
        Ordering::Equal
    } else {
        orient(s.lo, s.hi, t.lo, &exact)
    };
    if o == Ordering::Equal {
        o = orient(s.lo, s.hi, t.hi, &exact);
    }
    o.reverse().then(s.id.cmp(&t.id))
}

impl<N: Num> Ord for Key<'_, N> {
    fn cmp(&self, other: &Self) -> Ordering {
        match (self.is_query(), other.is_query()) {
            (true, true) => Ordering::Equal,
            (true, false) => orient(other.lo, other.hi, self.lo, self.ctx),
            (false, true) => orient(self.lo, self.hi, other.lo, self.ctx).reverse(),
            (false, false) if self.id == other.id => Ordering::Equal,
            (false, false) => cmp_edges(self, other),
        }
    }
}
impl<N: Num> PartialOrd for Key<'_, N> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl<N: Num> PartialEq for Key<'_, N> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl<N: Num> Eq for Key<'_, N> {}

/// Locate each query point relative to the region bounded by the directed edges `edges`
/// (pairwise non-crossing, interior on the left). `unbounded` says whether the region contains
/// the points far away (seed 002 Alg. 1, line 17).
pub fn locate_in_edges<N: Num>(
    edges: &[(&Point<N>, &Point<N>)],
    unbounded: bool,
    queries: &[Point<N>],
    ctx: &N::Ctx,
) -> Vec<Location> {
    let mut vertices: Vec<&Point<N>> = edges.iter().map(|e| e.0).collect();
    vertices.sort();
    let mut verticals: Vec<(&N, &N, &N)> = edges
        .iter()
        .filter(|(a, b)| a.x == b.x)
        .map(|&(a, b)| {
            if a.y <= b.y {
                (&a.x, &a.y, &b.y)
            } else {
                (&a.x, &b.y, &a.y)
            }
        })
        .collect();
    verticals.sort();
    let far = if unbounded {
        Location::Inside
    } else {
        Location::Outside
    };
    let mut out = vec![far; queries.len()];
    sweep(edges, queries, ctx, |i, status, probe| {
        let p = &queries[i];
        out[i] = if vertices.binary_search(&p).is_ok() || on_vertical(&verticals, p) {
            Location::OnBoundary
        } else {
            classify_between(status, probe, p, far, ctx)
        };
    });
    out
}

/// The location of `q` relative to the region bounded by the directed closed curves `edges`
/// (pairwise non-crossing, interior on the left, nothing far away inside) by the parity of
/// their crossings with the ray from `q` to the right (Jordan's curve theorem), in one pass
/// over the edges: cheaper than [`locate_in_edges`]' sweep for a few queries. An edge counts
/// where it spans `q`'s height half-open (one end above, the other at or below), so a ray
/// through a vertex counts it once or not at all as the curve passes or turns there.
pub(crate) fn locate_by_crossings<N: Num>(
    edges: &[(&Point<N>, &Point<N>)],
    q: &Point<N>,
    ctx: &N::Ctx,
) -> Location {
    let mut inside = false;
    for &(a, b) in edges {
        if a == q {
            return Location::OnBoundary;
        }
        let (a_above, b_above) = (a.y > q.y, b.y > q.y);
        if a_above == b_above {
            // Only a horizontal edge at q's height can hold q here (its ends are not q).
            let between = (a.x < q.x) != (b.x < q.x);
            if a.y == q.y && b.y == q.y && between {
                return Location::OnBoundary;
            }
            continue;
        }
        // The edge crosses q's height: q is left of it (upward) or right of it (downward)
        // where the crossing lies right of q.
        match orient(a, b, q, ctx) {
            Ordering::Equal => return Location::OnBoundary,
            side => inside ^= (side == Ordering::Greater) == b_above,
        }
    }
    if inside {
        Location::Inside
    } else {
        Location::Outside
    }
}

/// Float mode's location rule ([`crate::num::Tolerance`]): the exact location of each query
/// relative to the region bounded by `edges`, except that a point whose distance to an edge is
/// at most `eps` is on the boundary, whatever the edge's direction.
pub(crate) fn locate_within<N: Num>(
    edges: &[(&Point<N>, &Point<N>)],
    unbounded: bool,
    queries: &[Point<N>],
    eps: f64,
) -> Vec<Location> {
    // Chunks of queries swept in parallel, each over all edges: worth it once there are more
    // queries than edges. Results concatenated in the queries' order.
    let chunks = rayon::current_num_threads().min(queries.len() / edges.len().max(1));
    let size = queries.len().div_ceil(chunks.max(1)).max(1);
    let mut out: Vec<Location> = queries
        .par_chunks(size)
        .map(|part| locate_in_edges(edges, unbounded, part, &N::exact_ctx()))
        .collect::<Vec<_>>()
        .concat();
    if eps <= 0.0 {
        return out;
    }
    let ends: Vec<([f64; 2], [f64; 2])> = edges
        .iter()
        .map(|(a, b)| (a.to_f64(), b.to_f64()))
        .collect();
    let boxes = ends
        .iter()
        .enumerate()
        .map(|(i, (a, b))| {
            let lo = [a[0].min(b[0]), a[1].min(b[1])];
            let hi = [a[0].max(b[0]), a[1].max(b[1])];
            GeomWithData::new(Rectangle::from_corners(lo, hi), i)
        })
        .collect();
    let tree = RTree::bulk_load(boxes);
    out.par_iter_mut().zip(queries).for_each(|(loc, q)| {
        if *loc == Location::OnBoundary {
            return;
        }
        let p = q.to_f64();
        let near = AABB::from_corners(
            [p[0] - eps, p[1] - eps].map(f64::next_down),
            [p[0] + eps, p[1] + eps].map(f64::next_up),
        );
        if tree
            .locate_in_envelope_intersecting(&near)
            .any(|r| segment_distance(ends[r.data].0, ends[r.data].1, p) <= eps)
        {
            *loc = Location::OnBoundary;
        }
    });
    out
}

/// The plane sweep of seed 002 Alg. 1: the status holds the non-vertical edges cut by the
/// vertical line just right of the sweep position, bottom to top; `query(i, status, probe)` is
/// called for each query point `i` when the sweep reaches it.
fn sweep<'a, N: Num>(
    edges: &'a [(&'a Point<N>, &'a Point<N>)],
    queries: &'a [Point<N>],
    ctx: &'a N::Ctx,
    mut query: impl FnMut(usize, &BTreeSet<&Key<'a, N>>, &Key<'a, N>),
) {
    // Sweep events: (x, kind, index) with kind 0 = remove, 1 = insert, 2 = query.
    let mut events: Vec<(&N, u8, usize)> = Vec::with_capacity(2 * edges.len() + queries.len());
    let mut keys: Vec<Key<'_, N>> = Vec::with_capacity(edges.len());
    for (id, &(from, to)) in edges.iter().enumerate() {
        let (lo, hi) = if from <= to { (from, to) } else { (to, from) };
        if lo.x == hi.x {
            continue;
        }
        events.push((&lo.x, 1, keys.len()));
        events.push((&hi.x, 0, keys.len()));
        keys.push(Key {
            lo,
            hi,
            from,
            to,
            id,
            ctx,
        });
    }
    for (i, q) in queries.iter().enumerate() {
        events.push((&q.x, 2, i));
    }
    events.sort_by(|a, b| a.0.cmp(b.0).then(a.1.cmp(&b.1)));
    let mut status: BTreeSet<&Key<'_, N>> = BTreeSet::new();
    for (_, kind, i) in events {
        match kind {
            0 => {
                status.remove(&keys[i]);
            }
            1 => {
                status.insert(&keys[i]);
            }
            _ => {
                let p = &queries[i];
                let probe = Key {
                    lo: p,
                    hi: p,
                    from: p,
                    to: p,
                    id: usize::MAX,
                    ctx,
                };
                query(i, &status, &probe);
            }
        }
    }
}

/// True if `p` lies on one of the sorted vertical edges.
fn on_vertical<N: Num>(verticals: &[(&N, &N, &N)], p: &Point<N>) -> bool {
    let k = verticals.partition_point(|&(x, ylo, _)| (x, ylo) <= (&p.x, &p.y));
    k > 0 && {
        let (x, _, yhi) = verticals[k - 1];
        x == &p.x && yhi >= &p.y
    }
}

/// Alg. 1 lines 15–21: classify `p` from its neighbours in the status.
fn classify_between<N: Num>(
    status: &BTreeSet<&Key<'_, N>>,
    probe: &Key<'_, N>,
    p: &Point<N>,
    far: Location,
    ctx: &N::Ctx,
) -> Location {
    let above = status.range::<Key<'_, N>, _>(probe..).next();
    if let Some(s) = above {
        if probe.cmp(s) == Ordering::Equal {
            return Location::OnBoundary;
        }
    }
    let below = status.range::<Key<'_, N>, _>(..probe).next_back();
    match below.or(above) {
        None => far,
        Some(s) => match orient(s.from, s.to, p, ctx) {
            Ordering::Greater => Location::Inside,
            Ordering::Less => Location::Outside,
            Ordering::Equal => Location::OnBoundary,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use crate::yin2::YinSet2;

    fn p(x: i64, y: i64) -> Point<Rational> {
        Point::int(x, y)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The crossing parity locates every point of a half-unit grid as the sweep does,
        /// inside each curve of joins of up to four random triangles and boxes on a 5×5
        /// lattice: curves with horizontal and vertical edges, vertices where curves touch,
        /// and queries on vertices, on edges and level with vertices.
        #[test]
        fn crossing_parity_is_the_sweep(
            shapes in proptest::collection::vec(
                (proptest::bool::ANY, proptest::array::uniform6(0i64..5)), 1..5),
        ) {
            let y = shapes.iter().fold(YinSet2::<Rational>::empty(), |y, (boxed, c)| {
                let ring = match boxed {
                    true if c[0] != c[2] && c[1] != c[3] => {
                        let (x0, x1) = (c[0].min(c[2]), c[0].max(c[2]));
                        let (y0, y1) = (c[1].min(c[3]), c[1].max(c[3]));
                        vec![p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)]
                    }
                    _ => vec![p(c[0], c[1]), p(c[2], c[3]), p(c[4], c[5])],
                };
                let ring = match YinSet2::from_curves(vec![ring.clone()]) {
                    Ok(r) if r.is_bounded() => r,
                    Ok(_) => YinSet2::from_curves(vec![ring.into_iter().rev().collect()])
                        .expect("the reversed ring"),
                    Err(_) => return y,
                };
                y.join(&ring)
            });
            let queries: Vec<Point<Rational>> = (-2..=10)
                .flat_map(|x| (-2..=10).map(move |y| (x, y)))
                .map(|(x, y)| Point::new(Rational::new(x.into(), 2.into()), Rational::new(y.into(), 2.into())))
                .collect();
            for c in y.curves() {
                let ccw = c.is_positive();
                let edges: Vec<_> = c.edges().map(|(a, b)| if ccw { (a, b) } else { (b, a) }).collect();
                let swept = locate_in_edges(&edges, false, &queries, &());
                for (q, want) in queries.iter().zip(swept) {
                    proptest::prop_assert_eq!(locate_by_crossings(&edges, q, &()), want, "{}", q);
                }
            }
        }
    }

    #[test]
    fn many_queries_are_located_in_chunks_in_their_order() {
        // The diamond |x| + |y| < 4; queries on a 21×21 grid, far more than its 4 edges, so
        // they are swept in parallel chunks. Oracle: the inequality itself.
        let v = [p(4, 0), p(0, 4), p(-4, 0), p(0, -4)];
        let edges: Vec<_> = (0..4).map(|k| (&v[k], &v[(k + 1) % 4])).collect();
        let grid: Vec<(i64, i64)> = (-10..=10)
            .flat_map(|x| (-10..=10).map(move |y| (x, y)))
            .collect();
        let queries: Vec<_> = grid.iter().map(|&(x, y)| p(x, y)).collect();
        let got = locate_within(&edges, false, &queries, 0.0);
        let want: Vec<Location> = grid
            .iter()
            .map(|&(x, y)| match (x.abs() + y.abs()).cmp(&4) {
                Ordering::Less => Location::Inside,
                Ordering::Equal => Location::OnBoundary,
                Ordering::Greater => Location::Outside,
            })
            .collect();
        assert_eq!(got, want);
    }

    #[test]
    fn square_with_vertical_and_horizontal_edges() {
        let v = [p(0, 0), p(2, 0), p(2, 2), p(0, 2)];
        let edges: Vec<_> = (0..4).map(|k| (&v[k], &v[(k + 1) % 4])).collect();
        let q = [
            p(1, 1),
            p(3, 1),
            p(0, 1),
            p(1, 0),
            p(2, 2),
            p(-1, 1),
            p(1, 2),
            p(2, 1),
            p(1, 3),
        ];
        use Location::*;
        let got = locate_in_edges(&edges, false, &q, &());
        assert_eq!(
            got,
            vec![
                Inside, Outside, OnBoundary, OnBoundary, OnBoundary, Outside, OnBoundary,
                OnBoundary, Outside
            ]
        );
        // The reversed square is its complement.
        let rev: Vec<_> = edges.iter().map(|&(a, b)| (b, a)).collect();
        let got = locate_in_edges(&rev, true, &q[..2], &());
        assert_eq!(got, vec![Outside, Inside]);
    }

    #[test]
    fn query_directly_above_a_vertex_and_between_touching_triangles() {
        // Two triangles touching at (2,1); queries at x = 2 above and below the touch.
        let v = [p(0, 0), p(2, 1), p(0, 2), p(4, 0), p(4, 2), p(2, 1)];
        let edges = vec![
            (&v[0], &v[1]),
            (&v[1], &v[2]),
            (&v[2], &v[0]),
            (&v[3], &v[4]),
            (&v[4], &v[5]),
            (&v[5], &v[3]),
        ];
        use Location::*;
        let got = locate_in_edges(
            &edges,
            false,
            &[p(2, 0), p(2, 3), p(1, 1), p(3, 1), p(2, 1)],
            &(),
        );
        assert_eq!(got, vec![Outside, Outside, Inside, Inside, OnBoundary]);
    }
}
