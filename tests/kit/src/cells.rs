//! The grid-cell oracle: unions of the pieces of a fixed planar subdivision (unit squares, or
//! squares cut into triangles by their diagonals), whose Boolean algebra is bitwise on masks.
//!
//! Everything here is built **without the kernel's operations**: the expected boundary curves
//! are traced from the mask by a small independent algorithm, the expected Betti numbers are
//! counted by flood fill, areas by summing pieces, and membership by reading the mask. The only
//! kernel entry point used is [`YinSet2::from_curves`], which validates the traced curves and
//! puts them in canonical form, so that the kernel's results can be compared with `==`.
//!
//! # Which connectivity
//!
//! A set is the regular open set `int(closure(∪ pieces))`, plus everything outside the window
//! when `outside` is set. Two pieces that share only a corner are *not* connected in it: a small
//! disc around the corner meets the set in two sectors that the corner itself (a boundary point)
//! does not join. So components are the classes of pieces under **edge adjacency** (for unit
//! squares: 4-connectivity), and the window's exterior counts as one more piece adjacent to every
//! piece with an edge on the window's boundary.
//!
//! The complement is again a regular open set of the same kind (the pieces not in the mask, and
//! the exterior iff `outside` is unset), so its components are also edge-adjacency classes: at a
//! corner where two complement pieces touch diagonally, the complement separates exactly as the
//! set does. This is what the kernel's Betti numbers count (seed 000 Cor. 3.14): the holes of a
//! component K are its negatively oriented curves, one per *bounded* edge-adjacency component of
//! the pieces not in K. Note that this is not singular homology of K: a square with a triangular
//! hole touching the outer boundary at one point counts one hole (the hole curve), although the
//! open set is simply connected. Two holes touching at a point count as two.
//!
//! # Tracing the boundary curves
//!
//! For each component K, and for each edge-adjacency component D of the pieces not in K (the
//! exterior included), the edges of K that face D, directed with K on the left, form exactly one
//! Jordan polygon: each vertex has at most one such outgoing edge (if K had two sectors at a
//! vertex both facing D, the loop through K joining them would separate D's sectors there), and
//! the boundary between a connected set and a complementary domain is connected. The curve is
//! positively oriented iff D is the unbounded component. No turning rule at pinch vertices is
//! needed, and the decomposition is the unique realizable spadjor (seed 000 Thm 3.21): within
//! one atom, curves touch only where a component of the complement pinches, never in a cycle.

use crate::arrangement;
use crate::laws::{law, CellOracle, Res, Tally};
use crate::Y;
use std::collections::HashMap;
use yinset::kernel::Point;
use yinset::num::Rational;
use yinset::yin2::{Location, YinSet2};

/// A vertex in integer coordinates scaled by the complex's denominator (2 for the grids).
type V = (i64, i64);

/// How a unit cell of the window is cut into pieces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Split {
    /// One square piece.
    None,
    /// Two triangles, cut by the diagonal from lower left to upper right.
    Slash,
    /// Two triangles, cut by the diagonal from lower right to upper left.
    Backslash,
    /// Four triangles, cut by both diagonals.
    Cross,
}

/// A planar subdivision of a window into pieces: a w×h window of unit cells, or the faces of
/// an arrangement of polygons. Coordinates are stored as integers over a common denominator
/// `den` (2 for the grids, so that the centre of a cell is an integer point), and mapped to the
/// plane by [`Complex::point`], through a rational affine map if the complex has one.
#[derive(Clone, Debug)]
pub struct Complex {
    /// Its name in tables and failure messages.
    pub name: String,
    /// Each piece as a counterclockwise cycle of scaled integer coordinates.
    pub pieces: Vec<Vec<(i64, i64)>>,
    /// For each piece and each of its edges, the neighbour across it (`None`: the exterior).
    adj: Vec<Vec<Option<usize>>>,
    /// The edges on the window's boundary, directed with the window on the left.
    border: Vec<((i64, i64), (i64, i64))>,
    /// Each piece's twice-area in scaled coordinates (so 2 den² × the true area).
    area2: Vec<i64>,
    /// The common denominator of the coordinates.
    den: i64,
    /// The map applied to every point, if any.
    affine: Option<Affine>,
}

/// An orientation-preserving rational affine map p ↦ M p + t of the plane (det M > 0).
#[derive(Clone, Debug)]
pub struct Affine {
    m: [[Rational; 2]; 2],
    t: [Rational; 2],
}

impl Affine {
    /// The map with matrix `m` and translation `t`, entries given as fractions (p, q).
    pub fn new(m: [[(i64, i64); 2]; 2], t: [(i64, i64); 2]) -> Affine {
        let q = |(p, d): (i64, i64)| Rational::new(p.into(), d.into());
        let a = Affine {
            m: m.map(|row| row.map(q)),
            t: t.map(q),
        };
        assert!(
            a.det() > Rational::new(0.into(), 1.into()),
            "not orientation-preserving"
        );
        a
    }

    /// The image of a point.
    pub fn apply(&self, p: Point<Rational>) -> Point<Rational> {
        let [[a, b], [c, d]] = &self.m;
        Point::new(
            a.clone() * p.x.clone() + b.clone() * p.y.clone() + self.t[0].clone(),
            c.clone() * p.x + d.clone() * p.y + self.t[1].clone(),
        )
    }

    /// The determinant of M: the factor of areas.
    pub fn det(&self) -> Rational {
        let [[a, b], [c, d]] = &self.m;
        a.clone() * d.clone() - b.clone() * c.clone()
    }
}

/// A union of pieces of a [`Complex`], plus the exterior of the window if `outside`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Cells {
    /// Bit p: piece (or cell) p is in the set.
    pub mask: u64,
    /// The exterior of the window is in the set.
    pub outside: bool,
}

impl Cells {
    /// The set of these pieces, with the exterior if `outside`.
    pub fn new(mask: u64, outside: bool) -> Cells {
        Cells { mask, outside }
    }
    /// The meet (intersection of the masks).
    pub fn and(self, o: Cells) -> Cells {
        Cells::new(self.mask & o.mask, self.outside && o.outside)
    }
    /// The join (union of the masks).
    pub fn or(self, o: Cells) -> Cells {
        Cells::new(self.mask | o.mask, self.outside || o.outside)
    }
    /// The complement in a universe of `n` pieces.
    pub fn not(self, n: usize) -> Cells {
        Cells::new(!self.mask & full_mask(n), !self.outside)
    }
    /// The difference, in a universe of `n` pieces.
    pub fn minus(self, o: Cells, n: usize) -> Cells {
        self.and(o.not(n))
    }
    /// The symmetric difference.
    pub fn xor(self, o: Cells) -> Cells {
        Cells::new(self.mask ^ o.mask, self.outside != o.outside)
    }
    /// Set inclusion.
    pub fn le(self, o: Cells) -> bool {
        self.mask & !o.mask == 0 && (!self.outside || o.outside)
    }
}

/// The mask with the low `n` bits set.
pub fn full_mask(n: usize) -> u64 {
    if n >= 64 {
        u64::MAX
    } else {
        (1u64 << n) - 1
    }
}

/// The expected Betti numbers: components, and the sorted multiset of holes per component.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExpectedBetti {
    /// The number of components.
    pub components: usize,
    /// The number of holes of each component, in increasing order.
    pub holes_sorted: Vec<usize>,
    /// The number of holes in all.
    pub total_holes: usize,
}

impl Complex {
    /// A w×h window whose cell (i, j) is cut by `split(i, j)`.
    pub fn new(name: &str, w: i64, h: i64, split: impl Fn(i64, i64) -> Split) -> Complex {
        let mut pieces = Vec::new();
        for j in 0..h {
            for i in 0..w {
                let (x0, y0, x1, y1) = (2 * i, 2 * j, 2 * i + 2, 2 * j + 2);
                let (c, a, b, d, e) = ((x0 + 1, y0 + 1), (x0, y0), (x1, y0), (x1, y1), (x0, y1));
                match split(i, j) {
                    Split::None => pieces.push(vec![a, b, d, e]),
                    Split::Slash => {
                        pieces.push(vec![a, b, d]);
                        pieces.push(vec![a, d, e]);
                    }
                    Split::Backslash => {
                        pieces.push(vec![a, b, e]);
                        pieces.push(vec![b, d, e]);
                    }
                    Split::Cross => {
                        pieces.push(vec![a, b, c]);
                        pieces.push(vec![b, d, c]);
                        pieces.push(vec![d, e, c]);
                        pieces.push(vec![e, a, c]);
                    }
                }
            }
        }
        Complex::from_pieces(name, pieces, 2)
    }

    /// The subdivision into `pieces` (counterclockwise cycles of integer coordinates over `den`).
    pub fn from_pieces(name: &str, pieces: Vec<Vec<V>>, den: i64) -> Complex {
        assert!(pieces.len() <= 64, "masks are u64");
        let mut owner: HashMap<(V, V), usize> = HashMap::new();
        for (p, v) in pieces.iter().enumerate() {
            for k in 0..v.len() {
                let e = (v[k], v[(k + 1) % v.len()]);
                assert!(owner.insert(e, p).is_none(), "pieces overlap");
            }
        }
        let mut adj = Vec::new();
        let mut border = Vec::new();
        for v in &pieces {
            let mut row = Vec::new();
            for k in 0..v.len() {
                let (a, b) = (v[k], v[(k + 1) % v.len()]);
                let n = owner.get(&(b, a)).copied();
                if n.is_none() {
                    border.push((a, b));
                }
                row.push(n);
            }
            adj.push(row);
        }
        let area2 = pieces
            .iter()
            .map(|v| {
                (0..v.len())
                    .map(|k| {
                        let (p, q) = (v[k], v[(k + 1) % v.len()]);
                        p.0 * q.1 - q.0 * p.1
                    })
                    .sum::<i64>()
            })
            .collect();
        Complex {
            name: name.to_string(),
            pieces,
            adj,
            border,
            area2,
            den,
            affine: None,
        }
    }

    /// The bounded faces of the arrangement of the sides of `polygons` (integer vertices, no two
    /// sides collinear): pieces whose vertices include the sides' crossings, with their
    /// non-trivial denominators (tests/kit/src/arrangement.rs).
    pub fn arrangement(name: &str, polygons: &[Vec<(i64, i64)>]) -> Complex {
        let (faces, den) = arrangement::faces(polygons);
        Complex::from_pieces(name, faces, den)
    }

    /// The same subdivision moved by the affine map `a`, named `<name>, <what>`.
    pub fn mapped(mut self, what: &str, a: Affine) -> Complex {
        assert!(self.affine.is_none(), "{} is mapped already", self.name);
        self.name = format!("{}, {what}", self.name);
        self.affine = Some(a);
        self
    }

    /// A point of the plane from exact coordinates over `den`, through the affine map.
    fn place(&self, x: Rational, y: Rational) -> Point<Rational> {
        let p = Point::new(x, y);
        match &self.affine {
            Some(a) => a.apply(p),
            None => p,
        }
    }

    /// The w×h window of unit squares.
    pub fn grid(w: i64, h: i64) -> Complex {
        Complex::new(&format!("{w}x{h} grid"), w, h, |_, _| Split::None)
    }

    /// 2×2 cells, each cut by the diagonal through the window's centre: eight triangles around
    /// one vertex, where up to four sectors of a set meet (slanted edges, corner contacts).
    pub fn pinwheel() -> Complex {
        Complex::new(
            "pinwheel (2x2 cells, diagonals through the centre)",
            2,
            2,
            |i, j| {
                if i == j {
                    Split::Slash
                } else {
                    Split::Backslash
                }
            },
        )
    }

    /// One cell cut by both diagonals: four triangles meeting at the centre.
    pub fn cross() -> Complex {
        Complex::new("1 cell cut by both diagonals", 1, 1, |_, _| Split::Cross)
    }

    /// 3×3 cells with a mix of cuts (random-sampling universe: 2^16 sets).
    pub fn mixed() -> Complex {
        Complex::new("3x3 cells, mixed diagonal cuts", 3, 3, |i, j| {
            match (i, j) {
                (1, 1) => Split::Cross,
                (0, 0) | (2, 2) => Split::Slash,
                (2, 0) | (0, 2) => Split::Backslash,
                _ => Split::None,
            }
        })
    }

    /// The number of pieces.
    pub fn len(&self) -> usize {
        self.pieces.len()
    }

    /// Every set of the universe: all masks, bounded only or also with the exterior.
    pub fn all(&self, with_unbounded: bool) -> Vec<Cells> {
        let n = self.len();
        let mut v: Vec<Cells> = (0..=full_mask(n)).map(|m| Cells::new(m, false)).collect();
        if with_unbounded {
            v.extend((0..=full_mask(n)).map(|m| Cells::new(m, true)));
        }
        v
    }

    /// A scaled integer coordinate pair as an exact point.
    pub fn point(&self, p: (i64, i64)) -> Point<Rational> {
        self.place(
            Rational::new(p.0.into(), self.den.into()),
            Rational::new(p.1.into(), self.den.into()),
        )
    }

    fn contains(&self, s: Cells, piece: Option<usize>) -> bool {
        match piece {
            Some(p) => s.mask >> p & 1 == 1,
            None => s.outside,
        }
    }

    /// Edge-adjacency components of the pieces for which `member` holds; index `n` stands for
    /// the exterior. Returns the component label of every node (`usize::MAX` if not a member).
    fn components(&self, member: impl Fn(Option<usize>) -> bool) -> (Vec<usize>, usize) {
        let n = self.len();
        let node = |i: usize| if i == n { None } else { Some(i) };
        let mut label = vec![usize::MAX; n + 1];
        let mut count = 0;
        for start in 0..=n {
            if label[start] != usize::MAX || !member(node(start)) {
                continue;
            }
            label[start] = count;
            let mut stack = vec![start];
            while let Some(i) = stack.pop() {
                let neighbours: Vec<usize> = if i == n {
                    (0..n)
                        .filter(|&p| self.adj[p].iter().any(|a| a.is_none()))
                        .collect()
                } else {
                    self.adj[i].iter().map(|a| a.unwrap_or(n)).collect()
                };
                for j in neighbours {
                    if label[j] == usize::MAX && member(node(j)) {
                        label[j] = count;
                        stack.push(j);
                    }
                }
            }
            count += 1;
        }
        (label, count)
    }

    /// The expected Betti numbers, by flood fill (see the module documentation).
    pub fn betti(&self, s: Cells) -> ExpectedBetti {
        let n = self.len();
        let (label, count) = self.components(|p| self.contains(s, p));
        let mut holes = Vec::new();
        for k in 0..count {
            let (dl, dcount) = self.components(|p| {
                let i = p.unwrap_or(n);
                label[i] != k
            });
            let _ = dl;
            // All components of the rest are bounded if K holds the exterior; else one is not.
            holes.push(if label[n] == k { dcount } else { dcount - 1 });
        }
        holes.sort_unstable();
        ExpectedBetti {
            components: count,
            total_holes: holes.iter().sum(),
            holes_sorted: holes,
        }
    }

    /// The boundary curves of `s`, traced from the mask (doubled coordinates), with their
    /// orientation (true: positive).
    pub fn curves(&self, s: Cells) -> Vec<(Vec<(i64, i64)>, bool)> {
        let n = self.len();
        let (label, count) = self.components(|p| self.contains(s, p));
        let mut out = Vec::new();
        for k in 0..count {
            let (dl, dcount) = self.components(|p| label[p.unwrap_or(n)] != k);
            // Directed edges of K facing each D, K on the left.
            let mut next: Vec<HashMap<(i64, i64), (i64, i64)>> = vec![HashMap::new(); dcount];
            let mut push = |d: usize, a: (i64, i64), b: (i64, i64)| {
                let prev = next[d].insert(a, b);
                assert!(prev.is_none(), "oracle: two edges of one curve leave {a:?}");
            };
            for p in 0..n {
                if label[p] != k {
                    continue;
                }
                let v = &self.pieces[p];
                for (e, nb) in self.adj[p].iter().enumerate() {
                    let other = nb.unwrap_or(n);
                    if label[other] != k {
                        push(dl[other], v[e], v[(e + 1) % v.len()]);
                    }
                }
            }
            if label[n] == k {
                // The exterior is in K: the window's border edges facing pieces not in K,
                // reversed (the exterior on their left).
                for &(a, b) in &self.border {
                    let p = self.piece_of_border(a, b);
                    if label[p] != k {
                        push(dl[p], b, a);
                    }
                }
            }
            for (d, map) in next.into_iter().enumerate() {
                if map.is_empty() {
                    continue;
                }
                let start = *map.keys().min().unwrap();
                let mut cycle = vec![start];
                let mut v = map[&start];
                while v != start {
                    cycle.push(v);
                    v = map[&v];
                }
                assert_eq!(
                    cycle.len(),
                    map.len(),
                    "oracle: K–D boundary is not one cycle"
                );
                let positive = dl[n] == d;
                out.push((cycle, positive));
            }
        }
        out
    }

    fn piece_of_border(&self, a: (i64, i64), b: (i64, i64)) -> usize {
        for (p, v) in self.pieces.iter().enumerate() {
            for k in 0..v.len() {
                if v[k] == a && v[(k + 1) % v.len()] == b {
                    return p;
                }
            }
        }
        unreachable!("border edge without a piece")
    }

    /// The expected Yin set, built from the traced curves by `from_curves` (validation and
    /// canonical form only), transformed by `map` (e.g. scaling and translation).
    pub fn yin_mapped(&self, s: Cells, map: &dyn Fn(Point<Rational>) -> Point<Rational>) -> Y {
        let n = self.len();
        if s.mask == 0 && !s.outside {
            return YinSet2::empty();
        }
        if s.mask == full_mask(n) && s.outside {
            return YinSet2::full();
        }
        let curves: Vec<Vec<Point<Rational>>> = self
            .curves(s)
            .into_iter()
            .map(|(c, _)| c.into_iter().map(|p| map(self.point(p))).collect())
            .collect();
        YinSet2::from_curves(curves)
            .unwrap_or_else(|e| panic!("oracle curves of {s:?} on {} rejected: {e}", self.name))
    }

    /// The expected Yin set in the window's own coordinates.
    pub fn yin(&self, s: Cells) -> Y {
        self.yin_mapped(s, &|p| p)
    }

    /// Exact area of a bounded set (`None` if `outside`).
    pub fn area(&self, s: Cells) -> Option<Rational> {
        if s.outside {
            return None;
        }
        let a2: i64 = (0..self.len())
            .filter(|&p| s.mask >> p & 1 == 1)
            .map(|p| self.area2[p])
            .sum();
        let area = Rational::new(a2.into(), (2 * self.den * self.den).into());
        Some(match &self.affine {
            Some(a) => area * a.det(),
            None => area,
        })
    }

    /// An interior point of each piece (see [`interior`]), and a point outside the window (the
    /// image of (−1, −1): every window has x, y ≥ 0).
    pub fn probes(&self) -> Vec<(Option<usize>, Point<Rational>)> {
        let mut v: Vec<(Option<usize>, Point<Rational>)> = self
            .pieces
            .iter()
            .enumerate()
            .map(|(p, c)| {
                let (sx, sy, k) = interior(c);
                (
                    Some(p),
                    self.place(
                        Rational::new(sx.into(), (self.den * k).into()),
                        Rational::new(sy.into(), (self.den * k).into()),
                    ),
                )
            })
            .collect();
        let minus_one = Rational::new((-1).into(), 1.into());
        v.push((None, self.place(minus_one.clone(), minus_one)));
        v
    }

    /// The location of each probe point, read off the mask.
    pub fn expected_locations(&self, s: Cells) -> Vec<Location> {
        self.probes()
            .iter()
            .map(|(p, _)| {
                if self.contains(s, *p) {
                    Location::Inside
                } else {
                    Location::Outside
                }
            })
            .collect()
    }
}

/// An interior point of a counterclockwise polygon, as coordinate sums and their count: the
/// vertex centroid if the polygon is convex, else the centroid of an ear (a convex corner whose
/// triangle holds no other vertex).
fn interior(c: &[V]) -> (i64, i64, i64) {
    let n = c.len();
    let orient = |a: V, b: V, d: V| (b.0 - a.0) * (d.1 - a.1) - (b.1 - a.1) * (d.0 - a.0);
    let corner = |k: usize| (c[(k + n - 1) % n], c[k], c[(k + 1) % n]);
    if (0..n).all(|k| {
        let (a, b, d) = corner(k);
        orient(a, b, d) >= 0
    }) {
        let sx = c.iter().map(|q| q.0).sum();
        let sy = c.iter().map(|q| q.1).sum();
        return (sx, sy, n as i64);
    }
    (0..n)
        .map(corner)
        .find(|&(a, b, d)| {
            orient(a, b, d) > 0
                && c.iter().all(|&p| {
                    [a, b, d].contains(&p)
                        || orient(a, b, p) < 0
                        || orient(b, d, p) < 0
                        || orient(d, a, p) < 0
                })
        })
        .map(|(a, b, d)| (a.0 + b.0 + d.0, a.1 + b.1 + d.1, 3))
        .expect("a simple polygon has an ear")
}

/// The names of the 2D cell oracle's checks, in the order [`Complex`]'s [`CellOracle`] counts
/// them: the result against the set traced from the mask, then its invariants.
pub const CELL_ORACLE: [&str; 4] = [
    "cells: kernel result = set traced from the mask",
    "cells: Betti numbers = flood-fill counts",
    "cells: area = sum of the pieces",
    "cells: locate(piece centroid) = mask bit",
];

impl CellOracle for Complex {
    type Set = Y;
    const SAME: &'static str = CELL_ORACLE[0];

    fn name(&self) -> &str {
        &self.name
    }

    fn cells(&self) -> usize {
        self.len()
    }

    /// Its Betti numbers equal the flood-fill counts, its area the sum of the pieces, and each
    /// piece centroid (and a point outside the window) is located as the mask says.
    fn invariants(&self, t: &mut Tally, s: Cells, y: &Y, what: &str) -> Res {
        let want = self.betti(s);
        let got = y.betti();
        let mut holes = got.holes.clone();
        holes.sort_unstable();
        law(
            t,
            CELL_ORACLE[1],
            got.components == want.components
                && holes == want.holes_sorted
                && got.total_holes == want.total_holes,
            || {
                format!(
                    "{what} on {} ({s:?}): kernel {got:?}, expected {want:?}",
                    self.name
                )
            },
        )?;
        let (ga, wa) = (y.area(), self.area(s));
        law(t, CELL_ORACLE[2], ga == wa, || {
            format!(
                "{what} on {} ({s:?}): area {ga:?}, expected {wa:?}",
                self.name
            )
        })?;
        let pts: Vec<_> = self.probes().into_iter().map(|(_, p)| p).collect();
        let (gl, wl) = (y.locate(&pts), self.expected_locations(s));
        law(t, CELL_ORACLE[3], gl == wl, || {
            format!(
                "{what} on {} ({s:?}): located {gl:?}, expected {wl:?}",
                self.name
            )
        })
    }
}
