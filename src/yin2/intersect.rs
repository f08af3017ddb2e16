//! MRS-a of seed 000 Def. 4.8: all contacts between the edges of polygons, by a plane sweep.

use crate::kernel::{classify, Contact, Point};
use crate::num::Num;

/// A closed straight edge `a → b` of positive length.
pub type Edge<N> = (Point<N>, Point<N>);

/// All pairs `(i, j)`, `i < j`, of edges that meet and for which `wanted(i, j)` holds, with
/// their contact. The result is sorted by `(i, j)`.
///
/// A sweep in x over the edges' extents: each edge is tested against the edges still active
/// whose y-extent overlaps its own.
pub fn intersections<N: Num>(
    edges: &[Edge<N>],
    ctx: &N::Ctx,
    wanted: impl Fn(usize, usize) -> bool,
) -> Vec<(usize, usize, Contact<N>)> {
    let lo = |e: &Edge<N>| if e.0 <= e.1 { e.0.clone() } else { e.1.clone() };
    let hi = |e: &Edge<N>| if e.0 <= e.1 { e.1.clone() } else { e.0.clone() };
    let ylo = |e: &Edge<N>| e.0.y.clone().min(e.1.y.clone());
    let yhi = |e: &Edge<N>| e.0.y.clone().max(e.1.y.clone());
    let mut order: Vec<usize> = (0..edges.len()).collect();
    let starts: Vec<Point<N>> = edges.iter().map(lo).collect();
    order.sort_by(|&i, &j| starts[i].cmp(&starts[j]));
    let ends: Vec<N> = edges.iter().map(|e| hi(e).x).collect();
    let mut active: Vec<usize> = Vec::new();
    let mut out = Vec::new();
    for &i in &order {
        let x = &starts[i].x;
        active.retain(|&j| &ends[j] >= x);
        let (y0, y1) = (ylo(&edges[i]), yhi(&edges[i]));
        for &j in &active {
            if yhi(&edges[j]) < y0 || ylo(&edges[j]) > y1 {
                continue;
            }
            let (a, b) = (i.min(j), i.max(j));
            if !wanted(a, b) {
                continue;
            }
            let c = classify(&edges[a].0, &edges[a].1, &edges[b].0, &edges[b].1, ctx);
            if c != Contact::Disjoint {
                out.push((a, b, c));
            }
        }
        active.push(i);
    }
    out.sort_by(|p, q| (p.0, p.1).cmp(&(q.0, q.1)));
    out
}
