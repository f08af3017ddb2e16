//! S_V on a set of edges (seed 000 Def. 4.8, MRS-a/b): every edge cut where it meets others.

use super::intersect::{intersections, Edge};
use crate::kernel::{Contact, Point};
use crate::num::Num;
use rayon::prelude::*;

/// For each edge `i`, its pieces between consecutive points where it meets an edge `j` with
/// `wanted(i, j)` (MRS-a by the sweep, then MRS-b), in the edge's direction.
pub(crate) fn cut_at_contacts<N: Num>(
    edges: &[Edge<N>],
    ctx: &N::Ctx,
    wanted: impl Fn(usize, usize) -> bool,
) -> Vec<Vec<Edge<N>>> {
    let mut cuts: Vec<Vec<Point<N>>> = vec![Vec::new(); edges.len()];
    for (i, j, contact) in intersections(edges, ctx, wanted) {
        let points = match contact {
            Contact::Crossing(p) | Contact::Touching(p) => vec![p],
            Contact::Overlap(p, q) => vec![p, q],
            Contact::Disjoint => vec![],
        };
        cuts[i].extend(points.iter().cloned());
        cuts[j].extend(points);
    }
    // Each edge is cut on its own: in parallel, in the edges' order.
    edges
        .par_iter()
        .zip(cuts)
        .map(|(e, cut)| cut_edge(e, cut))
        .collect()
}

/// S_V on one edge: the pieces between consecutive cut points, in the edge's direction.
fn cut_edge<N: Num>(e: &Edge<N>, mut cut: Vec<Point<N>>) -> Vec<Edge<N>> {
    let (a, b) = (&e.0, &e.1);
    cut.retain(|p| p != a && p != b);
    cut.sort();
    cut.dedup();
    if a > b {
        cut.reverse();
    }
    let mut stops = Vec::with_capacity(cut.len() + 2);
    stops.push(a.clone());
    stops.extend(cut);
    stops.push(b.clone());
    stops
        .windows(2)
        .map(|w| (w[0].clone(), w[1].clone()))
        .collect()
}
