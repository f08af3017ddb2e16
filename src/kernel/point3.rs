//! Points of space, the 3D orientation test and 3D bounding boxes (yin3 docs: *Primitives*).

use crate::num::{Num, Rational};
use std::cmp::Ordering;
use std::fmt;

/// A point of space. `Ord` is lexicographic (x, then y, then z).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Point3<N> {
    /// First coordinate.
    pub x: N,
    /// Second coordinate.
    pub y: N,
    /// Third coordinate.
    pub z: N,
}

impl Point3<Rational> {
    /// True if every coordinate is an `f64` ([`Rational::is_f64`]).
    pub(crate) fn is_f64(&self) -> bool {
        self.x.is_f64() && self.y.is_f64() && self.z.is_f64()
    }
}

impl<N: Num> Point3<N> {
    /// The point (x, y, z).
    pub fn new(x: N, y: N, z: N) -> Point3<N> {
        Point3 { x, y, z }
    }

    /// The point with integer coordinates (x, y, z).
    pub fn int(x: i64, y: i64, z: i64) -> Point3<N> {
        Point3::new(N::from_i64(x), N::from_i64(y), N::from_i64(z))
    }

    /// Coordinate `k` (0 = x, 1 = y, 2 = z).
    pub fn coord(&self, k: usize) -> &N {
        match k {
            0 => &self.x,
            1 => &self.y,
            _ => &self.z,
        }
    }

    /// The coordinates as references, for the number trait's predicates.
    pub fn coords(&self) -> [&N; 3] {
        [&self.x, &self.y, &self.z]
    }

    /// The vector `self − o` as a point.
    pub fn sub(&self, o: &Point3<N>) -> Point3<N> {
        Point3::new(
            self.x.clone() - o.x.clone(),
            self.y.clone() - o.y.clone(),
            self.z.clone() - o.z.clone(),
        )
    }

    /// The point `self + t (other − self)`.
    pub fn lerp(&self, other: &Point3<N>, t: &N) -> Point3<N> {
        let d = other.sub(self);
        Point3::new(
            self.x.clone() + t.clone() * d.x,
            self.y.clone() + t.clone() * d.y,
            self.z.clone() + t.clone() * d.z,
        )
    }

    /// The cross product of `self` and `o`, both read as vectors.
    pub fn cross(&self, o: &Point3<N>) -> Point3<N> {
        let m = |a: &N, b: &N, c: &N, d: &N| a.clone() * b.clone() - c.clone() * d.clone();
        Point3::new(
            m(&self.y, &o.z, &self.z, &o.y),
            m(&self.z, &o.x, &self.x, &o.z),
            m(&self.x, &o.y, &self.y, &o.x),
        )
    }

    /// The dot product of `self` and `o`, both read as vectors.
    pub fn dot(&self, o: &Point3<N>) -> N {
        self.x.clone() * o.x.clone() + self.y.clone() * o.y.clone() + self.z.clone() * o.z.clone()
    }

    /// The centroid of three points (exact in exact mode).
    pub fn centroid(a: &Point3<N>, b: &Point3<N>, c: &Point3<N>) -> Point3<N> {
        let three = N::from_i64(3);
        Point3::new(
            (a.x.clone() + b.x.clone() + c.x.clone()) / three.clone(),
            (a.y.clone() + b.y.clone() + c.y.clone()) / three.clone(),
            (a.z.clone() + b.z.clone() + c.z.clone()) / three,
        )
    }

    /// The midpoint of `self` and `o`.
    pub fn midpoint(&self, o: &Point3<N>) -> Point3<N> {
        Point3::new(
            (self.x.clone() + o.x.clone()).half(),
            (self.y.clone() + o.y.clone()).half(),
            (self.z.clone() + o.z.clone()).half(),
        )
    }

    /// Coordinates as `f64` (for output only).
    pub fn to_f64(&self) -> [f64; 3] {
        [self.x.to_f64(), self.y.to_f64(), self.z.to_f64()]
    }
}

impl<N: Num> fmt::Display for Point3<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {}, {})", self.x, self.y, self.z)
    }
}

/// The sign of det[b − a, c − a, d − a]: `Greater` if `d` lies on the side of the plane `abc`
/// that its normal (b − a) × (c − a) points to, `Less` on the other side, `Equal` on the plane
/// (`orient3d(0, e_x, e_y, e_z) = Greater`).
pub fn orient3d<N: Num>(
    a: &Point3<N>,
    b: &Point3<N>,
    c: &Point3<N>,
    d: &Point3<N>,
    ctx: &N::Ctx,
) -> Ordering {
    N::orient3d(a.coords(), b.coords(), c.coords(), d.coords(), ctx)
}

/// An axis-aligned box `[min, max]` in space.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BBox3<N> {
    /// The corner of smallest coordinates.
    pub min: Point3<N>,
    /// The corner of largest coordinates.
    pub max: Point3<N>,
}

impl<N: Num> BBox3<N> {
    /// The bounding box of a non-empty point sequence (`None` if empty).
    pub fn of<'a>(points: impl IntoIterator<Item = &'a Point3<N>>) -> Option<BBox3<N>> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let mut b = BBox3 {
            min: first.clone(),
            max: first.clone(),
        };
        for p in it {
            b.include(p);
        }
        Some(b)
    }

    /// Grow the box to contain `p`.
    pub fn include(&mut self, p: &Point3<N>) {
        for k in 0..3 {
            let v = p.coord(k);
            if v < self.min.coord(k) {
                *coord_mut(&mut self.min, k) = v.clone();
            }
            if v > self.max.coord(k) {
                *coord_mut(&mut self.max, k) = v.clone();
            }
        }
    }

    /// True if the closed boxes share a point.
    pub fn meets(&self, o: &BBox3<N>) -> bool {
        (0..3).all(|k| self.min.coord(k) <= o.max.coord(k) && o.min.coord(k) <= self.max.coord(k))
    }

    /// True if `p` lies in the closed box.
    pub fn contains(&self, p: &Point3<N>) -> bool {
        (0..3).all(|k| self.min.coord(k) <= p.coord(k) && p.coord(k) <= self.max.coord(k))
    }

    /// The larger side, as an `f64` (for float mode's default ε).
    pub fn span(&self) -> f64 {
        let side = |k: usize| self.max.coord(k).to_f64() / 2.0 - self.min.coord(k).to_f64() / 2.0;
        (2.0 * side(0).max(side(1)).max(side(2))).min(f64::MAX)
    }

    /// The largest coordinate magnitude, as an `f64` (for float mode's representable ε).
    pub fn extent(&self) -> f64 {
        [&self.min, &self.max]
            .iter()
            .flat_map(|p| p.coords())
            .map(|v| v.to_f64().abs())
            .fold(0.0, f64::max)
    }
}

fn coord_mut<N>(p: &mut Point3<N>, k: usize) -> &mut N {
    match k {
        0 => &mut p.x,
        1 => &mut p.y,
        _ => &mut p.z,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn p(x: i64, y: i64, z: i64) -> Point3<Rational> {
        Point3::int(x, y, z)
    }

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn vector_algebra_by_hand() {
        let (a, b) = (p(1, 2, 3), p(4, -5, 6));
        assert_eq!(b.sub(&a), p(3, -7, 3));
        // (1,2,3) × (4,−5,6) = (2·6 − 3·(−5), 3·4 − 1·6, 1·(−5) − 2·4)
        assert_eq!(a.cross(&b), p(27, 6, -13));
        assert_eq!(a.dot(&b), Rational::from_i64(12));
        assert_eq!(a.midpoint(&b), Point3::new(q(5, 2), q(-3, 2), q(9, 2)));
        assert_eq!(
            a.lerp(&b, &q(1, 3)),
            Point3::new(q(2, 1), q(-1, 3), q(4, 1))
        );
        assert_eq!(
            Point3::centroid(&a, &b, &p(1, 0, 1)),
            Point3::new(q(2, 1), q(-1, 1), q(10, 3))
        );
        assert_eq!([a.coord(0), a.coord(1), a.coord(2)], a.coords());
        assert_eq!(a.to_string(), "(1, 2, 3)");
    }

    #[test]
    fn orient3d_signs() {
        let (o, x, y) = (p(0, 0, 0), p(1, 0, 0), p(0, 1, 0));
        assert_eq!(orient3d(&o, &x, &y, &p(3, -2, 1), &()), Ordering::Greater);
        assert_eq!(orient3d(&o, &x, &y, &p(3, -2, -1), &()), Ordering::Less);
        assert_eq!(orient3d(&o, &x, &y, &p(3, -2, 0), &()), Ordering::Equal);
    }

    #[test]
    fn boxes_meet_exactly_when_they_share_a_point() {
        let a = BBox3::of(&[p(2, 2, 2), p(0, 1, 0), p(1, 0, 1)]).expect("three points");
        assert_eq!((a.min.clone(), a.max.clone()), (p(0, 0, 0), p(2, 2, 2)));
        assert!(BBox3::<Rational>::of(&[]).is_none());
        let corner = BBox3::of(&[p(2, 2, 2), p(3, 3, 3)]).unwrap();
        assert!(a.meets(&corner) && corner.meets(&a), "sharing a corner");
        for k in 0..3 {
            // Apart along one axis only, overlapping along the others.
            let mut lo = [0, 0, 0];
            lo[k] = 3;
            let far = BBox3::of(&[p(lo[0], lo[1], lo[2]), p(lo[0] + 1, lo[1] + 1, lo[2] + 1)]);
            let far = far.unwrap();
            assert!(!a.meets(&far) && !far.meets(&a), "apart along axis {k}");
            assert!(a.contains(&p(2 * (k == 0) as i64, 1, 0)));
            let mut out = [1, 1, 1];
            out[k] = 3;
            assert!(!a.contains(&p(out[0], out[1], out[2])));
            out[k] = -1;
            assert!(!a.contains(&p(out[0], out[1], out[2])));
        }
    }
}
