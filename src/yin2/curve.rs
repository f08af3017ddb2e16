//! Oriented Jordan polygons (seed 000 Def. 3.5–3.6; seed 002 J^pl) and their canonical form.

use crate::kernel::{on_closed_segment, orient, BBox, Point};
use crate::num::{balanced_sum, Num};
use foldhash::HashSet;
use std::cmp::Ordering;

/// An oriented Jordan polygon: its vertices in order, the edge from the last back to the first
/// implied. Positively oriented (counterclockwise) curves have their bounded region on the left.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Curve<N> {
    vertices: Vec<Point<N>>,
}

impl<N: Num> Curve<N> {
    /// The vertices in order (the closing edge back to the first is implied).
    pub fn vertices(&self) -> &[Point<N>] {
        &self.vertices
    }

    /// Number of vertices (= number of edges).
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Never true for a curve of a Yin set (kept for API completeness).
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// The directed edges `(v_k, v_{k+1})`, closing edge last.
    pub fn edges(&self) -> impl Iterator<Item = (&Point<N>, &Point<N>)> {
        let n = self.vertices.len();
        (0..n).map(move |k| (&self.vertices[k], &self.vertices[(k + 1) % n]))
    }

    /// Twice the signed area (shoelace formula): positive iff counterclockwise.
    pub fn twice_signed_area(&self) -> N {
        twice_signed_area(&self.vertices)
    }

    /// True if counterclockwise, i.e. positively oriented (seed 000 Def. 3.6): decided by the
    /// turn at the lexicographically smallest vertex (the first one), which is convex on a
    /// simple curve; O(1), where the signed area would sum numbers of ever-growing size.
    pub fn is_positive(&self) -> bool {
        let v = &self.vertices;
        let n = v.len();
        if n < 3 {
            return self.twice_signed_area().sign() == Ordering::Greater;
        }
        match orient(&v[n - 1], &v[0], &v[1], &N::exact_ctx()) {
            Ordering::Equal => self.twice_signed_area().sign() == Ordering::Greater,
            turn => turn == Ordering::Greater,
        }
    }

    /// The bounding box.
    pub fn bbox(&self) -> BBox<N> {
        BBox::of(&self.vertices).unwrap_or(BBox {
            min: Point::int(0, 0),
            max: Point::int(0, 0),
        })
    }

    /// The same curve with the opposite orientation.
    pub fn reversed(&self) -> Curve<N> {
        let mut v = self.vertices.clone();
        v.reverse();
        canonical_rotation(&mut v);
        Curve { vertices: v }
    }

    /// A point on the curve that lies on no other curve of its spadjor: the midpoint of the
    /// first edge (every touching point is a vertex of each curve through it).
    pub(crate) fn sample(&self) -> Point<N> {
        self.vertices[0].midpoint(&self.vertices[1 % self.vertices.len()])
    }
}

/// Twice the signed area of a vertex cycle (shoelace formula), on coordinates relative to its
/// first vertex as local origin: the same value exactly, and in float mode free of the
/// cancellation of products of large coordinates (its terms are as large as the cycle, not as
/// its distance from 0).
pub(crate) fn twice_signed_area<N: Num>(v: &[Point<N>]) -> N {
    let n = v.len();
    let Some(o) = v.first() else {
        return N::zero();
    };
    let rel = |p: &Point<N>| (p.x.clone() - o.x.clone(), p.y.clone() - o.y.clone());
    balanced_sum(
        (1..n.saturating_sub(1))
            .map(|k| {
                let ((px, py), (qx, qy)) = (rel(&v[k]), rel(&v[k + 1]));
                px * qy - qx * py
            })
            .collect(),
    )
}

/// Canonical form of one curve (seed 000 Thm 3.21 up to start vertex and straight runs):
/// drop vertices in the middle of a straight run unless they are in `keep` (touching points),
/// then start at the lexicographically smallest vertex.
pub(crate) fn canonical_curve<N: Num>(
    mut v: Vec<Point<N>>,
    keep: &HashSet<Point<N>>,
    ctx: &N::Ctx,
) -> Curve<N> {
    loop {
        let n = v.len();
        let straight = |k: usize| {
            let (p, q, r) = (&v[(k + n - 1) % n], &v[k], &v[(k + 1) % n]);
            !keep.contains(q)
                && orient(p, q, r, ctx) == Ordering::Equal
                && on_closed_segment(p, r, q)
        };
        if n <= 3 || !(0..n).any(straight) {
            break;
        }
        let drop: Vec<bool> = (0..n).map(straight).collect();
        // Never drop two neighbours in one pass where that would leave fewer than 3 vertices.
        let kept = drop.iter().filter(|&&d| !d).count();
        if kept < 3 {
            break;
        }
        v = v
            .into_iter()
            .zip(drop)
            .filter(|(_, d)| !d)
            .map(|(p, _)| p)
            .collect();
    }
    canonical_rotation(&mut v);
    Curve { vertices: v }
}

/// Rotate a vertex cycle to start at its lexicographically smallest vertex.
fn canonical_rotation<N: Num>(v: &mut [Point<N>]) {
    if let Some((k, _)) = v.iter().enumerate().min_by(|a, b| a.1.cmp(b.1)) {
        v.rotate_left(k);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use foldhash::HashSetExt;

    fn pts(c: &[(i64, i64)]) -> Vec<Point<Rational>> {
        c.iter().map(|&(x, y)| Point::int(x, y)).collect()
    }

    #[test]
    fn canonical_form_drops_straight_runs_and_rotates() {
        let a = canonical_curve(
            pts(&[(2, 0), (2, 2), (1, 2), (0, 2), (0, 0), (1, 0)]),
            &HashSet::new(),
            &(),
        );
        assert_eq!(
            a.vertices(),
            pts(&[(0, 0), (2, 0), (2, 2), (0, 2)]).as_slice()
        );
    }

    #[test]
    fn canonical_form_keeps_touching_points() {
        let keep: HashSet<_> = pts(&[(1, 0)]).into_iter().collect();
        let a = canonical_curve(pts(&[(2, 0), (2, 2), (0, 2), (0, 0), (1, 0)]), &keep, &());
        assert_eq!(
            a.vertices(),
            pts(&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]).as_slice()
        );
    }

    #[test]
    fn orientation_from_signed_area() {
        let ccw = canonical_curve(pts(&[(0, 0), (1, 0), (0, 1)]), &HashSet::new(), &());
        assert!(ccw.is_positive());
        assert!(!ccw.reversed().is_positive());
        assert_eq!(ccw.twice_signed_area(), Rational::from_integer(1.into()));
    }
}
