//! Independent 3D oracles: unions of the unit cells of an n×n×n grid, and exact geometry for a
//! ray-parity point location.
//!
//! Everything here is computed **without the kernel's operations**. A union of cells is a mask
//! (bit `i + n j + n² k` for the cell [i,i+1]×[j,j+1]×[k,k+1]) plus an exterior bit for the
//! region outside the window [0,n]³ (the 2D [`Cells`] type, reused: its bitwise operations are
//! dimension-free). The set it stands for is the regular open set int(closure(∪ cells)), plus
//! the exterior when the bit is set. From the mask alone:
//!
//! * **the expected set**: its boundary is the unit faces between a cell (or the exterior) in
//!   the set and one not in it, oriented out of the set; `from_triangles` only validates and
//!   canonicalizes it, so kernel results can be compared with `==`;
//! * **volume** = number of cells;
//! * **membership** at every cell centre, face and edge midpoint and vertex of the grid (and one
//!   layer beyond the window): Inside iff every cell around the point is in the set, Outside
//!   iff none is, on the boundary otherwise;
//! * **Betti numbers** of the open set: b0 = face-adjacency classes of the cells in the set
//!   (cells sharing only an edge or a vertex are separated by boundary points); b2 = bounded
//!   components of the closed complement, i.e. classes of the cells not in the set under
//!   26-adjacency (closed cells sharing any point); b1 = b0 + b2 − χ, where χ of the open set is
//!   n3 − n2 + n1 − n0 over the open cubes, squares, segments and points of the grid lying in it
//!   (χ = −χ_c for an open 3-manifold, and χ_c is additive over the cells), plus 2 if the set
//!   contains the exterior (χ_c(ℝ³ ∖ closed window) = −1 − 1 = −2).
//!
//! The geometry ([`IntGeom`]) reduces a set's vertices and query points to integers by a common
//! denominator and decides everything with exact big-integer determinants: point on a closed
//! triangle, proper crossing of a segment with a triangle, coplanar overlap of triangles. The
//! ray oracle counts crossings along a random ray (re-drawn when it meets an edge or a vertex)
//! and checks parity and signed winding against each other.

use super::cells::{full_mask, Cells};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::collections::HashMap;
use yinset::kernel::Point3;
use yinset::num::{Num, Rational};
use yinset::yin2::Location;
use yinset::yin3::YinSet3;

pub type Y3 = YinSet3<Rational>;
pub type P3 = Point3<Rational>;
/// A mesh with integer vertices: points and faces (vertex indices, counterclockwise seen from
/// outside).
pub type Mesh = (Vec<[i64; 3]>, Vec<Vec<usize>>);

/// Exact rational n/d.
pub fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// The window [0,n]³ of n³ unit cells.
#[derive(Clone, Copy, Debug)]
pub struct Grid3 {
    pub n: i64,
}

/// The Betti numbers (b0, b1, b2) and the Euler characteristic of an open set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CellBetti {
    pub b0: usize,
    pub b1: usize,
    pub b2: usize,
    pub chi: i64,
}

impl Grid3 {
    pub fn new(n: i64) -> Grid3 {
        assert!((1..=3).contains(&n), "masks of at most 27 cells");
        Grid3 { n }
    }

    pub fn len(&self) -> usize {
        (self.n * self.n * self.n) as usize
    }

    pub fn name(&self) -> String {
        let n = self.n;
        format!("{n}x{n}x{n} grid")
    }

    fn inside_window(&self, c: [i64; 3]) -> bool {
        c.iter().all(|&x| (0..self.n).contains(&x))
    }

    fn bit(&self, c: [i64; 3]) -> usize {
        (c[0] + self.n * c[1] + self.n * self.n * c[2]) as usize
    }

    fn cell(&self, b: usize) -> [i64; 3] {
        let (b, n) = (b as i64, self.n);
        [b % n, b / n % n, b / (n * n)]
    }

    /// Is the cell `c` (anywhere in space; cells off the window are the exterior) in `s`?
    pub fn contains(&self, s: Cells, c: [i64; 3]) -> bool {
        if self.inside_window(c) {
            s.mask >> self.bit(c) & 1 == 1
        } else {
            s.outside
        }
    }

    /// Every set of the universe (2^(n³) masks, each bounded and with the exterior).
    pub fn all(&self) -> Vec<Cells> {
        let m = full_mask(self.len());
        (0..=m)
            .flat_map(|k| [Cells::new(k, false), Cells::new(k, true)])
            .collect()
    }

    /// The boundary of `s` (not 0̂ or 1̂): one outward unit square per face between a cell in
    /// the set and one not in it.
    pub fn mesh(&self, s: Cells) -> Mesh {
        let n = self.n;
        let mut index: HashMap<[i64; 3], usize> = HashMap::new();
        let mut pts: Vec<[i64; 3]> = Vec::new();
        let mut faces = Vec::new();
        for a in 0..3 {
            let (u, v) = ((a + 1) % 3, (a + 2) % 3);
            for x in -1..n {
                for y in 0..n {
                    for z in 0..n {
                        let mut c = [0; 3];
                        (c[a], c[u], c[v]) = (x, y, z);
                        let mut d = c;
                        d[a] += 1;
                        let (lo, hi) = (self.contains(s, c), self.contains(s, d));
                        if lo == hi {
                            continue;
                        }
                        // base → +e_u → +e_u+e_v → +e_v turns about e_u × e_v = e_a.
                        let (mut bu, mut buv, mut bv) = (d, d, d);
                        bu[u] += 1;
                        buv[u] += 1;
                        buv[v] += 1;
                        bv[v] += 1;
                        let mut quad: Vec<usize> = [d, bu, buv, bv]
                            .into_iter()
                            .map(|w| {
                                *index.entry(w).or_insert_with(|| {
                                    pts.push(w);
                                    pts.len() - 1
                                })
                            })
                            .collect();
                        if hi {
                            quad.reverse(); // the set is on the high side: normal −e_a
                        }
                        faces.push(quad);
                    }
                }
            }
        }
        (pts, faces)
    }

    /// The expected set, turned by `rot` about the window's centre, built by `from_triangles`
    /// (validation and canonical form only).
    pub fn yin(&self, s: Cells, rot: Rot) -> Y3 {
        if s.mask == 0 && !s.outside {
            return YinSet3::empty();
        }
        if s.mask == full_mask(self.len()) && s.outside {
            return YinSet3::full();
        }
        let (pts, faces) = self.mesh(s);
        let pts = pts
            .into_iter()
            .map(|p| self.point(p.map(|c| 2 * c), rot))
            .collect();
        YinSet3::from_triangles(pts, faces)
            .unwrap_or_else(|e| panic!("oracle boundary of {s:?} on {} rejected: {e}", self.name()))
    }

    /// The volume (number of cells), `None` if the exterior is in the set.
    pub fn volume(&self, s: Cells) -> Option<Rational> {
        (!s.outside).then(|| Rational::from_i64(s.mask.count_ones() as i64))
    }

    /// The probe points in doubled coordinates: every cell centre, face and edge midpoint and
    /// vertex of the window, and of one layer of cells around it.
    pub fn probes(&self) -> Vec<[i64; 3]> {
        let r = -1..=2 * self.n + 1;
        let mut v = Vec::new();
        for x in r.clone() {
            for y in r.clone() {
                for z in r.clone() {
                    v.push([x, y, z]);
                }
            }
        }
        v
    }

    /// A doubled-coordinate point as an exact point, turned by `rot` about the window's centre.
    pub fn point(&self, d: [i64; 3], rot: Rot) -> P3 {
        rot.apply(d, [self.n; 3], 2)
    }

    /// The cells around a doubled-coordinate point (one per odd coordinate choice, two per even
    /// one).
    fn around(d: [i64; 3]) -> Vec<[i64; 3]> {
        let choices = |x: i64| -> Vec<i64> {
            if x.rem_euclid(2) == 1 {
                vec![(x - 1) / 2]
            } else {
                vec![x / 2 - 1, x / 2]
            }
        };
        let mut v = Vec::new();
        for i in choices(d[0]) {
            for j in choices(d[1]) {
                for k in choices(d[2]) {
                    v.push([i, j, k]);
                }
            }
        }
        v
    }

    /// The location of a doubled-coordinate point in `s`, read off the mask.
    pub fn expected_location(&self, s: Cells, d: [i64; 3]) -> Location {
        let around = Grid3::around(d);
        let inside = around.iter().filter(|&&c| self.contains(s, c)).count();
        if inside == around.len() {
            Location::Inside
        } else if inside == 0 {
            Location::Outside
        } else {
            Location::OnBoundary
        }
    }

    /// Classes of the nodes (cells of the window, and the exterior as node `len`) with
    /// `member`, under `adjacent`.
    fn classes(
        &self,
        member: impl Fn(Option<[i64; 3]>) -> bool,
        adjacent: impl Fn([i64; 3], [i64; 3]) -> bool,
    ) -> usize {
        let n = self.len();
        let node = |i: usize| (i < n).then(|| self.cell(i));
        let on_border = |c: [i64; 3]| c.iter().any(|&x| x == 0 || x == self.n - 1);
        let linked = |i: usize, j: usize| match (node(i), node(j)) {
            (Some(a), Some(b)) => adjacent(a, b),
            (Some(c), None) | (None, Some(c)) => on_border(c),
            (None, None) => false,
        };
        let mut seen = vec![false; n + 1];
        let mut count = 0;
        for start in 0..=n {
            if seen[start] || !member(node(start)) {
                continue;
            }
            count += 1;
            seen[start] = true;
            let mut stack = vec![start];
            while let Some(i) = stack.pop() {
                for (j, s) in seen.iter_mut().enumerate() {
                    if !*s && member(node(j)) && linked(i, j) {
                        *s = true;
                        stack.push(j);
                    }
                }
            }
        }
        count
    }

    /// The Betti numbers of `s` from the cell complex (see the module documentation).
    pub fn betti(&self, s: Cells) -> CellBetti {
        let dist = |a: [i64; 3], b: [i64; 3]| -> Vec<i64> {
            (0..3).map(|k| (a[k] - b[k]).abs()).collect()
        };
        let is_in = |c: Option<[i64; 3]>| match c {
            Some(c) => self.contains(s, c),
            None => s.outside,
        };
        // Cells sharing a face, and (for the exterior) every border cell: each has a face on
        // the window's boundary.
        let b0 = self.classes(is_in, |a, b| dist(a, b).iter().sum::<i64>() == 1);
        // Closed cells sharing any point; every border cell touches the exterior's closure.
        let closed = self.classes(|c| !is_in(c), |a, b| dist(a, b).iter().all(|&d| d <= 1));
        let b2 = closed - usize::from(!s.outside);
        let mut chi: i64 = if s.outside { 2 } else { 0 };
        let r = 0..=2 * self.n;
        for x in r.clone() {
            for y in r.clone() {
                for z in r.clone() {
                    let d = [x, y, z];
                    if self.expected_location(s, d) == Location::Inside {
                        let dim = d.iter().filter(|&&c| c % 2 == 1).count();
                        chi += if dim % 2 == 1 { 1 } else { -1 };
                    }
                }
            }
        }
        let b1 = b0 as i64 + b2 as i64 - chi;
        assert!(b1 >= 0, "oracle: b1 = {b0} + {b2} − {chi} < 0 for {s:?}");
        CellBetti {
            b0,
            b1: b1 as usize,
            b2,
            chi,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Rational rotations (Pythagorean-triple angles)

/// A rotation by a rational orthogonal matrix, or none.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Rot {
    /// The identity.
    None,
    /// About the z axis by the angle with cos = 3/5, sin = 4/5.
    Z,
    /// About an oblique axis: the rotation about z above, then about the x axis by the angle
    /// with cos = 12/13, sin = 5/13.
    Oblique,
}

impl Rot {
    /// The matrix, as integer entries over a common denominator.
    fn matrix(self) -> ([[i64; 3]; 3], i64) {
        match self {
            Rot::None => ([[1, 0, 0], [0, 1, 0], [0, 0, 1]], 1),
            Rot::Z => ([[3, -4, 0], [4, 3, 0], [0, 0, 5]], 5),
            // Rx · Rz with Rx = [[13,0,0],[0,12,-5],[0,5,12]]/13, Rz = [[3,-4,0],[4,3,0],[0,0,5]]/5.
            Rot::Oblique => ([[39, -52, 0], [48, 36, -25], [20, 15, 60]], 65),
        }
    }

    /// The image of the point `p / den` under the rotation about the centre `c / den`.
    pub fn apply(self, p: [i64; 3], c: [i64; 3], den: i64) -> P3 {
        let (m, d) = self.matrix();
        let v = [0, 1, 2].map(|k| p[k] - c[k]);
        let r = [0, 1, 2].map(|i| {
            let s: i64 = (0..3).map(|j| m[i][j] * v[j]).sum();
            q(s + d * c[i], d * den)
        });
        let [x, y, z] = r;
        Point3::new(x, y, z)
    }
}

// ---------------------------------------------------------------------------------------------
// Exact integer geometry

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
    pub den: BigInt,
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
    pub fn next(&mut self) -> u64 {
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
        lo + (self.next() % (hi - lo + 1) as u64) as i64
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

// ---------------------------------------------------------------------------------------------
// The cell oracle's checks

use super::laws::{law, BinaryOut, Res, Tally};
use std::sync::Mutex;

pub const CELL3_ORACLE: [&str; 5] = [
    "cells 3D: kernel result = set built from the mask",
    "cells 3D: Betti numbers (b0, b1, b2) = cell-complex counts",
    "cells 3D: volume = number of cells",
    "cells 3D: locate(centres, midpoints, vertices) = read off the mask",
    "cells 3D: a∧b = a ⇔ mask(a) ⊆ mask(b)",
];

/// The cell oracle on one grid, possibly turned by a rotation, with its probe points and (for
/// small universes) a cache of the expected sets.
pub struct Oracle3 {
    pub grid: Grid3,
    pub rot: Rot,
    probes_d: Vec<[i64; 3]>,
    probes: Vec<P3>,
    cache: Option<Mutex<HashMap<Cells, Y3>>>,
}

impl Oracle3 {
    pub fn new(n: i64, rot: Rot, cache: bool) -> Oracle3 {
        let grid = Grid3::new(n);
        let probes_d = grid.probes();
        let probes = probes_d.iter().map(|&d| grid.point(d, rot)).collect();
        Oracle3 {
            grid,
            rot,
            probes_d,
            probes,
            cache: cache.then(|| Mutex::new(HashMap::new())),
        }
    }

    pub fn name(&self) -> String {
        match self.rot {
            Rot::None => self.grid.name(),
            r => format!("{} turned by {r:?}", self.grid.name()),
        }
    }

    /// The expected set of a mask (built once per mask if caching).
    pub fn expected(&self, s: Cells) -> Y3 {
        match &self.cache {
            None => self.grid.yin(s, self.rot),
            Some(c) => {
                if let Some(y) = c.lock().unwrap().get(&s) {
                    return y.clone();
                }
                let y = self.grid.yin(s, self.rot);
                c.lock().unwrap().insert(s, y.clone());
                y
            }
        }
    }

    /// One kernel result `y` that should be the union of cells `s`: `y == expected(s)`, its
    /// Betti numbers from the cell complex, its volume the number of cells, and its location at
    /// every probe point read off the mask.
    pub fn check(&self, t: &mut Tally, s: Cells, y: &Y3, what: &str) -> Res {
        let name = self.name();
        let want = self.expected(s);
        law(t, CELL3_ORACLE[0], *y == want, || {
            format!(
                "{what} on {name} ({s:?}): volumes {:?} and {:?}",
                y.volume(),
                want.volume()
            )
        })?;
        let (got, cb) = (y.betti(), self.grid.betti(s));
        law(
            t,
            CELL3_ORACLE[1],
            (got.b0, got.b1, got.b2) == (cb.b0, cb.b1, cb.b2),
            || format!("{what} on {name} ({s:?}): kernel {got:?}, cells {cb:?}"),
        )?;
        let (gv, wv) = (y.volume(), self.grid.volume(s));
        law(t, CELL3_ORACLE[2], gv == wv, || {
            format!("{what} on {name} ({s:?}): volume {gv:?}, expected {wv:?}")
        })?;
        let got = y.locate(&self.probes);
        for (k, &d) in self.probes_d.iter().enumerate() {
            let want = self.grid.expected_location(s, d);
            law(t, CELL3_ORACLE[3], got[k] == want, || {
                format!(
                    "{what} on {name} ({s:?}) at {}: {:?}, expected {want:?}",
                    self.probes[k], got[k]
                )
            })?;
        }
        Ok(())
    }

    /// All results of one binary case — a∧b, a∨b, a∖b, a⊕b and a' — against the bitwise
    /// operations on the masks, and the order against mask inclusion.
    pub fn check_binary(&self, t: &mut Tally, (a, b): (Cells, Cells), out: &BinaryOut<Y3>) -> Res {
        let n = self.grid.len();
        let cases: [(&str, Cells, &Y3); 5] = [
            ("a∧b", a.and(b), &out.meet),
            ("a∨b", a.or(b), &out.join),
            ("a∖b", a.minus(b, n), &out.difference),
            ("a⊕b", a.xor(b), &out.symmetric_difference),
            ("a'", a.not(n), &out.complement_a),
        ];
        for (what, s, y) in cases {
            self.check(t, s, y, what)?;
        }
        let order = out.meet == self.expected(a);
        law(t, CELL3_ORACLE[4], order == a.le(b), || {
            format!("on {}: a = {a:?}, b = {b:?}", self.name())
        })
    }
}
