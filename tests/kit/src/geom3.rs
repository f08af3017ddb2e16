//! Exact integer geometry of 3D boundaries, and the ray oracle built on it: a set's vertices
//! and query points are reduced to integers by a common denominator and everything is decided
//! with exact big-integer determinants (point on a closed triangle, proper crossing of a
//! segment with a triangle, coplanar overlap of triangles). The ray oracle counts crossings
//! along a random ray (re-drawn when it meets an edge or a vertex), giving parity and signed
//! winding, independently of the kernel's point location.

use crate::{P3, Y3};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// An integer vector (a scaled point).
pub type V = [BigInt; 3];

fn sub(a: &V, b: &V) -> V {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn cross(a: &V, b: &V) -> V {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot(a: &V, b: &V) -> BigInt {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn sign(x: &BigInt) -> Ordering {
    x.cmp(&BigInt::zero())
}

/// The sign of ((b − a) × (c − a)) · (d − a): positive if d is on the side the normal of the
/// counterclockwise triangle abc points to.
pub fn orient(a: &V, b: &V, c: &V, d: &V) -> Ordering {
    sign(&dot(&cross(&sub(b, a), &sub(c, a)), &sub(d, a)))
}

/// A set's boundary (and query points) in integer coordinates: every rational coordinate
/// multiplied by the least common denominator.
#[derive(Clone, Debug)]
pub struct IntGeom {
    /// The common denominator the coordinates were multiplied by.
    pub den: BigInt,
    /// The boundary's triangles, outward.
    pub tris: Vec<[V; 3]>,
    /// The vertices, with their original index.
    pub verts: Vec<V>,
}

/// The least common denominator of the coordinates of the points.
pub fn common_den<'a>(pts: impl IntoIterator<Item = &'a P3>) -> BigInt {
    let mut d = BigInt::one();
    for p in pts {
        for c in p.coords() {
            d = d.lcm(&c.denom());
        }
    }
    d
}

/// `p · den` as integers (`den` must be a multiple of every coordinate's denominator).
pub fn scale(p: &P3, den: &BigInt) -> V {
    p.coords().map(|c| c.numer() * (den / &c.denom()))
}

impl IntGeom {
    /// The boundary of `y` scaled by `den` (a common denominator of its vertices and of any
    /// points to be compared with it).
    pub fn new(y: &Y3, den: &BigInt) -> IntGeom {
        let verts: Vec<V> = y.vertices().iter().map(|p| scale(p, den)).collect();
        let tris = y
            .triangles()
            .iter()
            .map(|t| t.map(|k| verts[k].clone()))
            .collect();
        IntGeom {
            den: den.clone(),
            tris,
            verts,
        }
    }

    /// Twice the signed volume times 3 (6 × volume × den³): positive for a bounded set, negative
    /// for an unbounded one (outward normals point into the bounded complement).
    pub fn volume6(&self) -> BigInt {
        self.tris.iter().map(|[a, b, c]| dot(&cross(a, b), c)).sum()
    }
}

/// Is the point p, coplanar with the triangle abc, in its closed (`strict` false) or open
/// (`strict` true) interior?
pub fn in_coplanar_triangle(t: &[V; 3], p: &V, strict: bool) -> bool {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    (0..3).all(|k| {
        let (a, b) = (&t[k], &t[(k + 1) % 3]);
        let s = sign(&dot(&n, &cross(&sub(b, a), &sub(p, a))));
        if strict {
            s == Ordering::Greater
        } else {
            s != Ordering::Less
        }
    })
}

/// Is p on the closed triangle?
pub fn on_triangle(t: &[V; 3], p: &V) -> bool {
    orient(&t[0], &t[1], &t[2], p) == Ordering::Equal && in_coplanar_triangle(t, p, false)
}

/// The normal of a triangle.
pub fn normal(t: &[V; 3]) -> V {
    cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]))
}

/// For two triangles: `None` unless they are coplanar with overlapping open interiors; then
/// whether their normals point the same way.
pub fn coplanar_overlap(s: &[V; 3], t: &[V; 3]) -> Option<bool> {
    if t.iter()
        .any(|p| orient(&s[0], &s[1], &s[2], p) != Ordering::Equal)
    {
        return None;
    }
    let n = normal(s);
    // Separating axis along an edge: the other triangle lies in the closed half-plane opposite
    // to the third vertex.
    let side = |a: &V, b: &V, p: &V| sign(&dot(&n, &cross(&sub(b, a), &sub(p, a))));
    for (x, y) in [(s, t), (t, s)] {
        for k in 0..3 {
            let (a, b, c) = (&x[k], &x[(k + 1) % 3], &x[(k + 2) % 3]);
            let own = side(a, b, c);
            if y.iter().all(|p| side(a, b, p) != own) {
                return None;
            }
        }
    }
    Some(dot(&n, &normal(t)).is_positive())
}

/// How a segment pq meets a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    /// No common point.
    Miss,
    /// The open segment crosses the open triangle at one point; `true` if q is on the side the
    /// normal points to.
    Cross(bool),
    /// Any other contact (through an edge or a vertex of the triangle, or at p on it), or q on
    /// the triangle's plane: the caller re-draws its ray (or does not count a crossing).
    Degenerate,
}

/// The segment pq against the triangle t.
pub fn segment_triangle(p: &V, q: &V, t: &[V; 3]) -> Hit {
    let (op, oq) = (
        orient(&t[0], &t[1], &t[2], p),
        orient(&t[0], &t[1], &t[2], q),
    );
    if op == oq && op != Ordering::Equal {
        return Hit::Miss;
    }
    if oq == Ordering::Equal {
        // The far end on the triangle's plane (rare): re-draw.
        return Hit::Degenerate;
    }
    if op == Ordering::Equal {
        // p on the plane (callers keep p off every closed triangle): the segment meets the
        // plane only at p.
        return if in_coplanar_triangle(t, p, false) {
            Hit::Degenerate
        } else {
            Hit::Miss
        };
    }
    let s = [0, 1, 2].map(|k| orient(p, q, &t[k], &t[(k + 1) % 3]));
    if s.iter().all(|&x| x == Ordering::Greater) || s.iter().all(|&x| x == Ordering::Less) {
        Hit::Cross(oq == Ordering::Greater)
    } else if s.contains(&Ordering::Greater) && s.contains(&Ordering::Less) {
        Hit::Miss
    } else {
        Hit::Degenerate
    }
}

/// A small deterministic generator for ray directions.
#[derive(Clone, Debug)]
pub struct Rng(pub u64);

impl Rng {
    /// The next value (xorshift64*).
    pub fn next_u64(&mut self) -> u64 {
        // xorshift64*
        let mut x = self.0.max(1);
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// Uniform in lo..=hi.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }
}

/// The ray oracle's answer for one point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RayAnswer {
    /// On a closed triangle of the boundary.
    pub on_boundary: bool,
    /// The parity of the crossings along the ray.
    pub odd: bool,
    /// The signed count (+1 where the ray leaves through the outward side of a triangle).
    pub winding: i64,
    /// Rays drawn (re-drawn when one met an edge or a vertex).
    pub rays: u32,
}

/// Locate `p` against the boundary `g` by counting crossings along a random ray from p.
pub fn ray_count(g: &IntGeom, p: &V, rng: &mut Rng) -> RayAnswer {
    if g.tris.iter().any(|t| on_triangle(t, p)) {
        return RayAnswer {
            on_boundary: true,
            odd: false,
            winding: 0,
            rays: 0,
        };
    }
    let m = g
        .verts
        .iter()
        .chain(std::iter::once(p))
        .flat_map(|v| v.iter())
        .map(|c| c.abs())
        .max()
        .unwrap_or_default();
    let len = BigInt::from(2) * m + 1;
    for rays in 1..=1000u32 {
        let d = [0; 3].map(|_| BigInt::from(rng.range(-997, 997)));
        if d.iter().all(|c| c.is_zero()) {
            continue;
        }
        // Far enough that q is beyond every vertex in some coordinate: off every triangle.
        let far: V = [0, 1, 2].map(|k| &p[k] + &d[k] * &len);
        let mut winding = 0;
        let mut crossings = 0;
        let mut degenerate = false;
        for t in &g.tris {
            match segment_triangle(p, &far, t) {
                Hit::Miss => {}
                Hit::Cross(out) => {
                    crossings += 1;
                    winding += if out { 1 } else { -1 };
                }
                Hit::Degenerate => {
                    degenerate = true;
                    break;
                }
            }
        }
        if !degenerate {
            return RayAnswer {
                on_boundary: false,
                odd: crossings % 2 == 1,
                winding,
                rays,
            };
        }
    }
    panic!("ray oracle: 1000 rays from one point all met an edge")
}
