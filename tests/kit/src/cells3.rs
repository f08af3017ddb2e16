//! The 3D cell oracle: unions of the unit cells of a w×h×d grid, optionally with the grid's
//! exterior, optionally turned by a rational rotation ([`Rot`]) about the window's centre.
//! Their Boolean algebra is bitwise on the masks ([`Cells`], shared with the 2D oracle: its
//! operations are dimension-free); cell (i, j, k) is bit i + w (j + h k).
//!
//! Everything here is built **without the kernel's operations**. The set a mask stands for is
//! the regular open set Y = int(closure(∪ cells)), plus the exterior when `outside` is set.
//! From the mask alone:
//!
//! * **the expected set**: its boundary is the unit faces between a cell (or the exterior) in
//!   the set and one not in it, oriented out of the set; [`YinSet3::from_triangles`] only
//!   validates the faces and builds the canonical form that `==` compares;
//! * **membership**: a point of an open cell σ of the grid's cubical complex (a cube, face, edge
//!   or vertex) lies in Y iff every 3-cell incident to σ (the exterior counting as one) is in
//!   the set, outside closure(Y) iff none is, and on the boundary otherwise; so the location of
//!   the centre of every open cell of the window and of one layer of cells around it is read
//!   off the mask;
//! * **b0**: components of Y, the set's cells (and the exterior) under face adjacency (two cells
//!   sharing only an edge or a vertex are different components of the regular open set);
//! * **b2**: by Alexander duality, the bounded components of the closed complement ℝ³ ∖ Y, the
//!   union of the closed cells not in the set (and of the closed exterior): cells under
//!   26-adjacency (sharing any point), the exterior touching every cell on the grid's border;
//! * **b1** = b0 + b2 − χ, where χ(Y) = −χ_c(Y) by Poincaré duality for the open 3-manifold Y,
//!   and χ_c(Y) is the sum of (−1)^dim σ over the open cells σ of the closed window in Y, plus
//!   χ_c(ℝ³ ∖ window) = −1 − 1 = −2 if the exterior is in the set (b3 = 0 for an open subset of
//!   ℝ³);
//! * **volume**: the number of cells (a rotation has determinant 1).
//!
//! None of this shares code with the kernel's Betti numbers (a vertex-link formula on the
//! boundary and the Hasse diagram of the glued surfaces), its volume (signed tetrahedra) or its
//! point location (winding numbers).

use crate::cells::{full_mask, Cells};
use crate::laws::{law, BinaryOut, CellOracle, Res, Tally};
use crate::rotation::Rot;
use crate::shapes::Mesh;
use crate::{P3, Y3};
use std::collections::HashMap;
use std::sync::Mutex;
use yinset::num::{Num, Rational};
use yinset::yin2::Location;
use yinset::yin3::YinSet3;

/// Doubled integer coordinates of a lattice point: cell corners are even, cell centres odd.
type D = [i64; 3];

/// A grid of unit cells, turned by a rational rotation about its centre (or not), with its
/// probe points.
#[derive(Clone, Debug)]
pub struct Grid3 {
    /// Its name in tables and failure messages.
    pub name: String,
    /// Cells along x, y, z.
    pub dims: [i64; 3],
    /// The rotation of every point.
    pub rot: Rot,
    /// The probe points (doubled coordinates, and the points they stand for): the centre of
    /// every open cell of the window's complex and of one layer of cells around it.
    probes: Vec<(D, P3)>,
}

/// The Betti numbers (b0, b1, b2) of an open set, from the cell complex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CellBetti {
    /// Components.
    pub b0: usize,
    /// Tunnels.
    pub b1: usize,
    /// Cavities.
    pub b2: usize,
}

/// The names of the 3D cell oracle's checks, in the order [`Grid3`]'s [`CellOracle`] counts
/// them: the result against the set built from the mask, then its invariants.
pub const CELL_ORACLE3: [&str; 4] = [
    "cells: kernel result = set built from the mask's faces",
    "cells: Betti numbers b0, b1, b2 = cell-complex counts",
    "cells: volume = number of cells",
    "cells: locate(centre of every open cell) = read off the mask",
];

impl Grid3 {
    /// The w×h×d grid of unit cells, axis-aligned.
    pub fn grid(w: i64, h: i64, d: i64) -> Grid3 {
        assert!(w * h * d <= 64, "masks are u64");
        let mut g = Grid3 {
            name: format!("{w}×{h}×{d} cells"),
            dims: [w, h, d],
            rot: Rot::None,
            probes: Vec::new(),
        };
        g.probes = g.make_probes();
        g
    }

    /// The n×n×n grid.
    pub fn cube(n: i64) -> Grid3 {
        Grid3::grid(n, n, n)
    }

    /// The same grid turned by `rot` about its centre.
    pub fn rotated(self, rot: Rot) -> Grid3 {
        let mut g = Grid3 {
            name: format!("{}, {}", self.name, rot.describe()),
            rot,
            ..self
        };
        g.probes = g.make_probes();
        g
    }

    /// The number of cells.
    pub fn len(&self) -> usize {
        (self.dims[0] * self.dims[1] * self.dims[2]) as usize
    }

    /// Every set: all masks, bounded only or also with the exterior.
    pub fn all(&self, with_unbounded: bool) -> Vec<Cells> {
        let n = self.len();
        let mut v: Vec<Cells> = (0..=full_mask(n)).map(|m| Cells::new(m, false)).collect();
        if with_unbounded {
            v.extend((0..=full_mask(n)).map(|m| Cells::new(m, true)));
        }
        v
    }

    fn inside_window(&self, c: [i64; 3]) -> bool {
        (0..3).all(|k| (0..self.dims[k]).contains(&c[k]))
    }

    fn bit(&self, c: [i64; 3]) -> usize {
        let [w, h, _] = self.dims;
        (c[0] + w * (c[1] + h * c[2])) as usize
    }

    fn cell(&self, b: usize) -> [i64; 3] {
        let [w, h, _] = self.dims;
        let b = b as i64;
        [b % w, b / w % h, b / (w * h)]
    }

    /// Is the cell `c` (anywhere in space; cells off the window are the exterior) in `s`?
    pub fn contains(&self, s: Cells, c: [i64; 3]) -> bool {
        if self.inside_window(c) {
            s.mask >> self.bit(c) & 1 == 1
        } else {
            s.outside
        }
    }

    /// A doubled-coordinate point as an exact point, turned about the window's centre.
    pub fn point(&self, d: D) -> P3 {
        self.rot.apply(d, self.dims, 2)
    }

    /// The doubled coordinates of the centres of the open cells of the closed window's complex
    /// grown by `margin` cells on every side, with the dimension of each open cell.
    fn open_cells(&self, margin: i64) -> Vec<(D, usize)> {
        let r = |k: usize| -margin..=2 * self.dims[k] + margin;
        let mut v = Vec::new();
        for x in r(0) {
            for y in r(1) {
                for z in r(2) {
                    let d = [x, y, z];
                    v.push((d, d.iter().filter(|&&c| c.rem_euclid(2) == 1).count()));
                }
            }
        }
        v
    }

    fn make_probes(&self) -> Vec<(D, P3)> {
        self.open_cells(1)
            .into_iter()
            .map(|(d, _)| (d, self.point(d)))
            .collect()
    }

    /// The probe points: the centre of every open cell (cube, face, edge, vertex) of the
    /// window's complex and of one layer of cells around it.
    pub fn probes(&self) -> Vec<P3> {
        self.probes.iter().map(|(_, p)| p.clone()).collect()
    }

    /// The cube centres of the window and a point outside it, for the membership oracle (which
    /// skips points on an operand's boundary anyway).
    pub fn cube_probes(&self) -> Vec<P3> {
        self.open_cells(0)
            .into_iter()
            .filter(|&(_, dim)| dim == 3)
            .map(|(d, _)| self.point(d))
            .chain([self.point([-3, -1, -5])])
            .collect()
    }

    /// The cells incident to the open cell centred at a doubled-coordinate point (one choice
    /// per odd coordinate, two per even one).
    fn around(d: D) -> Vec<[i64; 3]> {
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
    pub fn expected_location(&self, s: Cells, d: D) -> Location {
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

    /// The expected location of each probe point.
    pub fn expected_locations(&self, s: Cells) -> Vec<Location> {
        self.probes
            .iter()
            .map(|&(d, _)| self.expected_location(s, d))
            .collect()
    }

    /// Classes of the nodes (cells of the window, and the exterior as node `len`) with
    /// `member`, under `adjacent` (the exterior touches every cell on the window's border).
    fn classes(
        &self,
        member: impl Fn(Option<[i64; 3]>) -> bool,
        adjacent: impl Fn([i64; 3], [i64; 3]) -> bool,
    ) -> usize {
        let n = self.len();
        let node = |i: usize| (i < n).then(|| self.cell(i));
        let on_border = |c: [i64; 3]| (0..3).any(|k| c[k] == 0 || c[k] == self.dims[k] - 1);
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
        // Cells sharing a face; the exterior and every border cell share one.
        let b0 = self.classes(is_in, |a, b| dist(a, b).iter().sum::<i64>() == 1);
        // Closed cells sharing any point; every border cell touches the exterior's closure.
        let closed = self.classes(|c| !is_in(c), |a, b| dist(a, b).iter().all(|&d| d <= 1));
        let b2 = closed - usize::from(!s.outside);
        // χ(Y) = −χ_c(Y): the open cells of the closed window in Y, and the exterior's −2.
        let mut chi: i64 = if s.outside { 2 } else { 0 };
        for (d, dim) in self.open_cells(0) {
            if self.expected_location(s, d) == Location::Inside {
                chi += if dim % 2 == 1 { 1 } else { -1 };
            }
        }
        let b1 = b0 as i64 + b2 as i64 - chi;
        assert!(b1 >= 0, "oracle: b1 = {b0} + {b2} − {chi} < 0 for {s:?}");
        CellBetti {
            b0,
            b1: b1 as usize,
            b2,
        }
    }

    /// The volume (number of cells), `None` if the exterior is in the set.
    pub fn volume(&self, s: Cells) -> Option<Rational> {
        (!s.outside).then(|| Rational::from_i64(i64::from(s.mask.count_ones())))
    }

    /// The boundary of `s` in cell units, unrotated: one unit square per face between a cell in
    /// the set and one not in it, counterclockwise seen from outside the set.
    pub fn mesh(&self, s: Cells) -> Mesh {
        let mut index = HashMap::new();
        let mut pts = Vec::new();
        let mut faces = Vec::new();
        for a in 0..3 {
            let (u, v) = ((a + 1) % 3, (a + 2) % 3);
            for x in -1..self.dims[a] {
                for y in 0..self.dims[u] {
                    for z in 0..self.dims[v] {
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

    /// The expected set of a mask, built by `from_triangles` from [`Grid3::mesh`] only.
    pub fn yin(&self, s: Cells) -> Y3 {
        if s.mask == 0 && !s.outside {
            return YinSet3::empty();
        }
        if s.mask == full_mask(self.len()) && s.outside {
            return YinSet3::full();
        }
        let (pts, faces) = self.mesh(s);
        let pts = pts
            .into_iter()
            .map(|p| self.point(p.map(|c| 2 * c)))
            .collect();
        YinSet3::from_triangles(pts, faces)
            .unwrap_or_else(|e| panic!("oracle faces of {s:?} on {} rejected: {e}", self.name))
    }

    /// The degenerate features of an ordered pair (a, b), read off the masks, with `betti` the
    /// oracle's Betti numbers (cached by the caller): see [`FEATURES3`].
    pub fn features(&self, a: Cells, b: Cells, betti: &dyn Fn(Cells) -> CellBetti) -> [bool; 8] {
        let mut f = [false; 8];
        for (d, dim) in self.open_cells(0) {
            let inc = Grid3::around(d);
            let side =
                |s: Cells| -> Vec<bool> { inc.iter().map(|&c| self.contains(s, c)).collect() };
            let (sa, sb) = (side(a), side(b));
            match dim {
                2 => {
                    let (on_a, on_b) = (sa[0] != sa[1], sb[0] != sb[1]);
                    if on_a && on_b {
                        f[if sa[0] == sb[0] { 0 } else { 1 }] = true;
                    }
                }
                1 => {
                    // Incident cells in lexicographic order of the two varying coordinates:
                    // 0 and 3, 1 and 2 are diagonal.
                    let diagonal = |s: &[bool]| s[0] == s[3] && s[1] == s[2] && s[0] != s[1];
                    if diagonal(&sa) || diagonal(&sb) {
                        f[2] = true;
                    }
                }
                0 => {
                    // Bit 4dx + 2dy + dz: cells sharing a face differ in one bit.
                    let pinched = |s: &[bool]| {
                        [true, false].iter().any(|&want| {
                            (0..8).any(|p| {
                                let q = 7 - p;
                                s[p] == want
                                    && s[q] == want
                                    && (0..3).all(|k| s[p ^ (1 << k)] != want)
                                    && (0..3).all(|k| s[q ^ (1 << k)] != want)
                            })
                        })
                    };
                    if pinched(&sa) || pinched(&sb) {
                        f[3] = true;
                    }
                }
                _ => {}
            }
        }
        let (ba, bb) = (betti(a), betti(b));
        f[4] = ba.b0 >= 2 || bb.b0 >= 2;
        f[5] = ba.b1 >= 1 || bb.b1 >= 1;
        let (m, j) = (betti(a.and(b)), betti(a.or(b)));
        f[6] = m.b0 >= 2 || j.b0 >= 2;
        f[7] = m.b1 >= 1 || j.b1 >= 1;
        f
    }
}

/// What [`Grid3::features`] reports, in order.
pub const FEATURES3: [&str; 8] = [
    "coplanar overlapping boundary faces, same orientation",
    "coplanar overlapping boundary faces, opposite orientation",
    "a non-manifold edge in a or b (two cells, or two complement cells, on a diagonal)",
    "a or b pinched at a vertex (two cells, or complement cells, meeting only there)",
    "a or b with several components",
    "a or b with a tunnel (b1 > 0)",
    "a∧b or a∨b with several components",
    "a∧b or a∨b with a tunnel",
];

impl CellOracle for Grid3 {
    type Set = Y3;
    const SAME: &'static str = CELL_ORACLE3[0];

    fn name(&self) -> &str {
        &self.name
    }

    fn cells(&self) -> usize {
        self.len()
    }

    /// Its Betti numbers equal the cell complex's, its volume the number of cells, and every
    /// probe point is located as the mask says.
    fn invariants(&self, t: &mut Tally, s: Cells, y: &Y3, what: &str) -> Res {
        let name = &self.name;
        let (got, want) = (y.betti(), self.betti(s));
        law(
            t,
            CELL_ORACLE3[1],
            (got.b0, got.b1, got.b2) == (want.b0, want.b1, want.b2),
            || format!("{what} on {name} ({s:?}): kernel {got:?}, cells {want:?}"),
        )?;
        let (gv, wv) = (y.volume(), self.volume(s));
        law(t, CELL_ORACLE3[2], gv == wv, || {
            format!("{what} on {name} ({s:?}): volume {gv:?}, expected {wv:?}")
        })?;
        let pts: Vec<P3> = self.probes();
        let (gl, wl) = (y.locate(&pts), self.expected_locations(s));
        law(t, CELL_ORACLE3[3], gl == wl, || {
            let bad: Vec<String> = (0..gl.len())
                .filter(|&k| gl[k] != wl[k])
                .map(|k| format!("{}: {:?}, expected {:?}", pts[k], gl[k], wl[k]))
                .collect();
            format!("{what} on {name} ({s:?}): {}", bad.join("; "))
        })
    }
}

/// A grid with a cache of the expected sets (for universes small enough to keep).
pub struct Oracle3 {
    /// The grid whose unions are checked.
    pub grid: Grid3,
    cache: Option<Mutex<HashMap<Cells, Y3>>>,
}

impl Oracle3 {
    /// The oracle of `grid`, caching the expected sets if `cache`.
    pub fn new(grid: Grid3, cache: bool) -> Oracle3 {
        Oracle3 {
            grid,
            cache: cache.then(|| Mutex::new(HashMap::new())),
        }
    }

    /// The expected set of a mask (built once per mask if caching).
    pub fn expected(&self, s: Cells) -> Y3 {
        let Some(c) = &self.cache else {
            return self.grid.yin(s);
        };
        if let Some(y) = c.lock().unwrap().get(&s) {
            return y.clone();
        }
        let y = self.grid.yin(s);
        c.lock().unwrap().insert(s, y.clone());
        y
    }

    /// One kernel result `y` that should be the union of cells `s` (see
    /// [`crate::laws::cells_check`]).
    pub fn check(&self, t: &mut Tally, s: Cells, y: &Y3, what: &str) -> Res {
        crate::laws::cells_check(t, &self.grid, s, y, &self.expected(s), what)
    }

    /// All results of one binary case (see [`crate::laws::cells_binary`]).
    pub fn check_binary(&self, t: &mut Tally, ab: (Cells, Cells), out: &BinaryOut<Y3>) -> Res {
        crate::laws::cells_binary(t, &self.grid, ab, out, &|s| self.expected(s))
    }
}
