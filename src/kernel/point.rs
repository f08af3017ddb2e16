//! Points, the Left test and bounding boxes.

use crate::num::Num;
use std::cmp::Ordering;
use std::fmt;

/// A point of the plane. `Ord` is lexicographic (x, then y): the order of the plane sweeps.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Point<N> {
    /// Abscissa.
    pub x: N,
    /// Ordinate.
    pub y: N,
}

impl<N: Num> Point<N> {
    /// The point (x, y).
    pub fn new(x: N, y: N) -> Point<N> {
        Point { x, y }
    }

    /// The point with integer coordinates (x, y).
    pub fn int(x: i64, y: i64) -> Point<N> {
        Point {
            x: N::from_i64(x),
            y: N::from_i64(y),
        }
    }

    /// The midpoint of `self` and `other` (exact in exact mode).
    pub fn midpoint(&self, other: &Point<N>) -> Point<N> {
        Point {
            x: (self.x.clone() + other.x.clone()).half(),
            y: (self.y.clone() + other.y.clone()).half(),
        }
    }

    /// The centroid of the triangle `abc` (exact in exact mode).
    pub fn centroid(a: &Point<N>, b: &Point<N>, c: &Point<N>) -> Point<N> {
        let three = N::from_i64(3);
        Point {
            x: (a.x.clone() + b.x.clone() + c.x.clone()) / three.clone(),
            y: (a.y.clone() + b.y.clone() + c.y.clone()) / three,
        }
    }

    /// The point `self + t (other − self)`.
    pub fn lerp(&self, other: &Point<N>, t: &N) -> Point<N> {
        Point {
            x: self.x.clone() + t.clone() * (other.x.clone() - self.x.clone()),
            y: self.y.clone() + t.clone() * (other.y.clone() - self.y.clone()),
        }
    }

    /// Coordinates as `f64` (for output only).
    pub fn to_f64(&self) -> [f64; 2] {
        [self.x.to_f64(), self.y.to_f64()]
    }

    fn coords(&self) -> [&N; 2] {
        [&self.x, &self.y]
    }
}

impl<N: Num> fmt::Display for Point<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {})", self.x, self.y)
    }
}

/// The Left test of seed 002 (Alg. 1): `Greater` if `c` is left of the directed line `a → b`,
/// `Less` if right, `Equal` if on it (float mode: within ε).
pub fn orient<N: Num>(a: &Point<N>, b: &Point<N>, c: &Point<N>, ctx: &N::Ctx) -> Ordering {
    N::orient2d(a.coords(), b.coords(), c.coords(), ctx)
}

/// An axis-aligned bounding box `[min, max]` (seed 002 Alg. 3, BB).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BBox<N> {
    /// Lower-left corner.
    pub min: Point<N>,
    /// Upper-right corner.
    pub max: Point<N>,
}

impl<N: Num> BBox<N> {
    /// The bounding box of a non-empty point sequence (`None` if empty).
    pub fn of<'a>(points: impl IntoIterator<Item = &'a Point<N>>) -> Option<BBox<N>> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let mut b = BBox {
            min: first.clone(),
            max: first.clone(),
        };
        for p in it {
            b.include(p);
        }
        Some(b)
    }

    /// Grow the box to contain `p`.
    pub fn include(&mut self, p: &Point<N>) {
        if p.x < self.min.x {
            self.min.x = p.x.clone();
        }
        if p.y < self.min.y {
            self.min.y = p.y.clone();
        }
        if p.x > self.max.x {
            self.max.x = p.x.clone();
        }
        if p.y > self.max.y {
            self.max.y = p.y.clone();
        }
    }

    /// The smallest box containing both.
    pub fn union(&self, other: &BBox<N>) -> BBox<N> {
        let mut b = self.clone();
        b.include(&other.min);
        b.include(&other.max);
        b
    }

    /// True if `other` lies inside `self` (closed boxes).
    pub fn contains_box(&self, other: &BBox<N>) -> bool {
        self.min.x <= other.min.x
            && self.min.y <= other.min.y
            && other.max.x <= self.max.x
            && other.max.y <= self.max.y
    }

    /// The larger side, as an `f64` computed on half-coordinates so that it cannot overflow
    /// (for float mode's default ε, which must not depend on where the box sits).
    pub fn span(&self) -> f64 {
        let half = |v: &N| v.to_f64() / 2.0;
        let w = half(&self.max.x) - half(&self.min.x);
        let h = half(&self.max.y) - half(&self.min.y);
        (2.0 * w.max(h)).min(f64::MAX)
    }

    /// The largest coordinate magnitude, as an `f64` (for float mode's representable grid).
    pub fn extent(&self) -> f64 {
        [&self.min.x, &self.min.y, &self.max.x, &self.max.y]
            .iter()
            .map(|v| v.to_f64().abs())
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    /// `midpoint` and `lerp` against the definitions worked by hand: a + t (b − a) at t = 1/3
    /// of (1, 2)–(4, −5) is (2, −1/3), with both ends at t = 0 and t = 1.
    #[test]
    fn midpoint_and_lerp_by_hand() {
        let (a, b) = (Point::<Rational>::int(1, 2), Point::int(4, -5));
        assert_eq!(a.midpoint(&b), Point::new(q(5, 2), q(-3, 2)));
        assert_eq!(a.lerp(&b, &q(1, 3)), Point::new(q(2, 1), q(-1, 3)));
        assert_eq!(a.lerp(&b, &q(0, 1)), a);
        assert_eq!(a.lerp(&b, &q(1, 1)), b);
    }
}
