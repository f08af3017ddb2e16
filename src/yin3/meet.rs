//! The general meet of two 3D Yin sets (yin3 docs: *Selection*, *Meet*; seed 004 steps 1–5; the 3D
//! MRS-b..d of seed 000 Lemma 4.6, Cor. 4.7, Def. 4.8), taken where the transversal meet declines
//! the operands: arrange both boundaries against each other, keep the pieces of each that lie in
//! the other (coincident pieces: one copy if equally oriented, none if opposite), and paste the
//! kept pieces into glued surfaces.

use super::arrange::{arrange, arrange_named, Arrangement, Pairs};
use super::contact::key;
use super::error::Yin3Error;
use super::geom::{piece_in_triangle2, Chart, Triangle2};
use super::locate::{ray_box, winding};
use super::set::{Brep, YinSet3};
use super::soup::Soup;
use super::tri::corners_after;
use crate::kernel::{orient, Point3};
use crate::num::{Num, Rational};
use crate::union_find::UnionFind;
use foldhash::{HashMap, HashMapExt};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// Where a piece of one operand lies relative to the other operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    /// On a face of the other with the same orientation (MRS-c, kept once).
    Same,
    /// On a face of the other with the opposite orientation (dropped from both).
    Opposite,
    /// In the other's interior.
    Inside,
    /// In the other's exterior.
    Outside,
}

/// The meet by the general arrangement alone, never by the transversal one, its pairs
/// classified by name for exact sets: the arrangement that [`constructed_meet`] checks.
#[cfg(test)]
pub(crate) fn general_meet<N: Num>(x: &YinSet3<N>, y: &YinSet3<N>) -> YinSet3<N> {
    arranged_meet(x, y, N::EXACT)
}

/// The meet by the general arrangement with every contact constructed: the oracle of the
/// tests of the transversal meet and of [`Named`](super::named::Named), float and exact.
#[cfg(test)]
pub(crate) fn constructed_meet<N: Num>(x: &YinSet3<N>, y: &YinSet3<N>) -> YinSet3<N> {
    arranged_meet(x, y, false)
}

/// The meet by the general arrangement, its pairs first classified by name if `named`.
#[cfg(test)]
fn arranged_meet<N: Num>(x: &YinSet3<N>, y: &YinSet3<N>, named: bool) -> YinSet3<N> {
    match (x.brep(), y.brep()) {
        (Some(a), Some(b)) => {
            meet_with(a, b, N::combine_ctx(x.ctx, y.ctx), named).expect("an exact meet")
        }
        _ => x.meet(y),
    }
}

/// The meet of two sets with the boundaries `a` and `b` whose boxes meet where both are
/// bounded, computed with the predicates of `ctx` (MRS-a..d in 3D); an error if the
/// arrangement or the kept pieces are inconsistent (never in exact mode). Exact sets' pairs
/// are classified by name first ([`arrange_named`]).
pub(super) fn meet_in<N: Num>(
    a: &Brep<N>,
    b: &Brep<N>,
    ctx: N::Ctx,
) -> Result<YinSet3<N>, Yin3Error> {
    meet_with(a, b, ctx, N::EXACT)
}

/// [`meet_in`], with the pairs classified by name first if `named` (exact sets only).
fn meet_with<N: Num>(
    a: &Brep<N>,
    b: &Brep<N>,
    ctx: N::Ctx,
    named: bool,
) -> Result<YinSet3<N>, Yin3Error> {
    let (points, kept) = kept_pieces(a, b, &ctx, named)?;
    if kept.is_empty() {
        return Ok(YinSet3::empty().with_ctx(ctx));
    }
    let brep = Brep::assemble(points, kept).map_err(|e| {
        Yin3Error::Internal(format!(
            "the kept pieces of a meet do not bound a Yin set: {e}"
        ))
    })?;
    Ok(YinSet3::from_brep(brep, ctx))
}

/// Triangles over a table of points (some may be unused).
type Pieces<N> = (Vec<Point3<N>>, Vec<[usize; 3]>);

/// The pieces of the exact boundaries `a` and `b` that bound their meet (MRS-a..d in 3D), by
/// the general arrangement with its pairs classified by name, over the arrangement's points
/// (some may be unused): float mode's where the transversal meet declined the operands'
/// values, to be rounded.
pub(crate) fn general_pieces(a: &Brep<Rational>, b: &Brep<Rational>) -> Pieces<Rational> {
    kept_pieces(a, b, &(), true).expect("an exact meet")
}

/// The pieces that bound the meet of the sets with the boundaries `a` and `b`, over the
/// arrangement's points, computed with the predicates of `ctx` ([`meet_with`]).
fn kept_pieces<N: Num>(
    a: &Brep<N>,
    b: &Brep<N>,
    ctx: &N::Ctx,
    named: bool,
) -> Result<Pieces<N>, Yin3Error> {
    let mut soup = Soup::of_operands(a, b);
    let arrangement = match named {
        true => arrange_named(&mut soup, ctx),
        false => arrange(&mut soup, Pairs::Across, ctx),
    };
    let arrangement = arrangement.map_err(|e| {
        Yin3Error::Internal(format!(
            "the arrangement of a meet's operands failed: {e:?}"
        ))
    })?;
    let bounded = [a.bounded, b.bounded];
    let sides = classify(&soup, &arrangement, bounded, ctx);
    let kept = (arrangement.pieces.iter().zip(&sides))
        .filter(|((_, parent), side)| {
            matches!(
                (soup.operand[*parent], side),
                (0, Side::Same) | (_, Side::Inside)
            )
        })
        .map(|((t, _), _)| *t)
        .collect();
    Ok((soup.points, kept))
}

/// The corners of a triangle in increasing order.
fn sorted(mut t: [usize; 3]) -> [usize; 3] {
    t.sort_unstable();
    t
}

/// The side of every piece relative to the other operand, decided without constructing a point
/// where a patch has a vertex off the other's boundary. Membership is constant on patches: pieces
/// of one operand joined across edges that are no edge of the other's pieces. (Every contact point
/// goes to every triangle containing it, so an edge of one operand's pieces on the other's boundary
/// is an edge of the other's pieces too, but for edges inside a coplanar overlap, which join only
/// pieces on the other's boundary.) A piece lies on the other's boundary iff it lies in a closed
/// triangle that overlaps its parent in their plane (the overlap's sides are cuts, so no piece
/// straddles them: [`piece_in_triangle2`]), on the same or the opposite side as that triangle's
/// orientation in the parent's chart tells; where the other operand has a piece with the same
/// corners, that piece's parent is such a triangle, and the two pieces' turns tell the side.
/// Every other patch is decided by one ray, from a vertex off the other's boundary where it has
/// one (an input vertex), else from a piece's centroid.
fn classify<N: Num>(
    soup: &Soup<N>,
    arrangement: &Arrangement,
    bounded: [bool; 2],
    ctx: &N::Ctx,
) -> Vec<Side> {
    let (pieces, contact) = (&arrangement.pieces, &arrangement.contact);
    let op = |i: usize| soup.operand[pieces[i].1] as usize;
    // Patches across edges that are no edge of the other operand's pieces: for each edge its
    // first piece and the operands of all its pieces (bit o for operand o), then every piece
    // joined to the first at each edge that only one operand's pieces have.
    let edges = |t: &[usize; 3]| [0, 1, 2].map(|k| key(t[k], t[(k + 1) % 3]));
    let mut at_edge: HashMap<(usize, usize), (usize, u8)> =
        HashMap::with_capacity(2 * pieces.len());
    for (i, (t, _)) in pieces.iter().enumerate() {
        for e in edges(t) {
            at_edge.entry(e).or_insert((i, 0)).1 |= 1 << op(i);
        }
    }
    let mut uf = UnionFind::new(pieces.len());
    for (i, (t, _)) in pieces.iter().enumerate() {
        for e in edges(t) {
            if let (first, 1 | 2) = at_edge[&e] {
                uf.union(first, i);
            }
        }
    }
    // A vertex off the other's boundary for each patch that has one.
    let mut off_vertex: HashMap<usize, usize> = HashMap::new();
    for (i, (t, _)) in pieces.iter().enumerate() {
        if let Some(&v) = t.iter().find(|&&v| !contact[v]) {
            off_vertex.entry(uf.find(i)).or_insert(v);
        }
    }
    // For each parent with overlaps, made once: its chart (counterclockwise for it), and the
    // triangles overlapping it there, counterclockwise, each with the side of the pieces in it.
    type Overlaps<N> = (Chart, Vec<(Triangle2<N>, Side)>);
    let overlap_cells: Vec<OnceCell<Overlaps<N>>> =
        (0..soup.tris.len()).map(|_| OnceCell::new()).collect();
    // The pieces that may lie on an overlap (their parents overlap others, their corners are
    // contacts), by operand and corners in increasing order.
    let may_overlap = |(t, parent): &([usize; 3], usize)| {
        !arrangement.coplanar[*parent].is_empty() && t.iter().all(|&v| contact[v])
    };
    let by_corners: HashMap<(usize, [usize; 3]), usize> = (0..pieces.len())
        .filter(|&i| may_overlap(&pieces[i]))
        .map(|i| ((op(i), sorted(pieces[i].0)), i))
        .collect();
    // The side of piece `i` if it lies in a triangle overlapping its parent: a piece of the
    // other operand with the same corners lies in its parent, which overlaps this one (on the
    // same side iff the two pieces turn the same way); else the triangles overlapping the
    // parent are searched.
    let on_overlap = |i: usize| -> Option<Side> {
        let (t, parent) = pieces[i];
        if !may_overlap(&pieces[i]) {
            return None;
        }
        if let Some(&j) = by_corners.get(&(1 - op(i), sorted(t))) {
            let same_turn = corners_after(pieces[j].0, t[0]) == [t[1], t[2]];
            return Some(if same_turn {
                Side::Same
            } else {
                Side::Opposite
            });
        }
        let (ch, tris_over) = overlap_cells[parent].get_or_init(|| {
            let [a, b, c] = soup.corners(parent);
            let ch = Chart::of_triangle(a, b, c);
            let tris_over = (arrangement.coplanar[parent].iter())
                .map(|&s| {
                    let mut other = soup.tris[s].map(|v| ch.project(&soup.points[v]));
                    let turn = orient(&other[0], &other[1], &other[2], ctx);
                    if turn == Ordering::Less {
                        other.swap(1, 2);
                    }
                    let side = match turn {
                        Ordering::Greater => Side::Same,
                        _ => Side::Opposite,
                    };
                    (Triangle2::new(other), side)
                })
                .collect();
            (ch, tris_over)
        });
        let image = Triangle2::new(t.map(|v| ch.project(&soup.points[v])));
        (tris_over.iter())
            .find_map(|(other, side)| piece_in_triangle2(other, &image, ctx).then_some(*side))
    };
    let mut memo: HashMap<usize, Side> = HashMap::new();
    (0..pieces.len())
        .map(|i| {
            let t = &pieces[i].0;
            if let Some(side) = on_overlap(i) {
                return side;
            }
            let o = op(i);
            let root = uf.find(i);
            *memo.entry(root).or_insert_with(|| {
                let centroid;
                let q = match off_vertex.get(&root) {
                    Some(&v) => &soup.points[v],
                    None => {
                        let [a, b, c] = t.map(|v| &soup.points[v]);
                        centroid = Point3::centroid(a, b, c);
                        &centroid
                    }
                };
                let along = arrangement.trees[1 - o].meeting(&ray_box(q));
                let others = along.into_iter().map(|s| soup.corners(s));
                if winding(others, q, ctx) + i64::from(!bounded[1 - o]) == 1 {
                    Side::Inside
                } else {
                    Side::Outside
                }
            })
        })
        .collect()
}
