//! The 3D cell oracle of the proofs: unions of the unit cells of a w×h×d grid, optionally with
//! the grid's exterior, optionally under a rational rotation. Their Boolean algebra is bitwise
//! on the masks ([`Cells`], shared with the 2D oracle).
//!
//! Everything here is built **without the kernel's operations**:
//!
//! * The expected set of a mask is bounded by the unit faces between a cell (or the exterior)
//!   in the set and one not in it, two triangles each, normals pointing out of the set; the
//!   only kernel entry point used is [`YinSet3::from_triangles`], which validates the faces,
//!   makes them conforming and builds the boundary representation that `==` compares.
//! * The set is the regular open set Y = int(closure(∪ cells)) (plus the exterior when
//!   `outside` is set). A point of an open cell σ of the grid's cubical complex (a cube, face,
//!   edge or vertex) lies in Y iff every 3-cell incident to σ (the exterior counting as one) is
//!   in the set, outside closure(Y) iff none is, and on the boundary otherwise. So the expected
//!   location of the lattice point at the centre of each open cell is read off the mask.
//! * b0: components of Y, the set's cells (and the exterior) under face adjacency (two cells
//!   sharing only an edge or a vertex are different components of the regular open set).
//! * b2: by Alexander duality, the bounded components of the closed complement ℝ³ ∖ Y, the
//!   union of the closed cells not in the set (and of the closed exterior): cells under
//!   26-adjacency (sharing any point), the exterior touching every cell on the grid's border.
//! * χ(Y) by Poincaré duality for the open 3-manifold Y: χ(Y) = −χ_c(Y), and χ_c(Y) is the sum
//!   of (−1)^dim σ over the open cells σ of the grid in Y, plus χ_c(ℝ³ ∖ [0,w]×[0,h]×[0,d]) =
//!   −1 − 1 = −2 if the exterior is in the set. Then b1 = b0 + b2 − χ (b3 = 0 for an open
//!   subset of ℝ³).
//! * Volume: the number of cells (a rotation has determinant 1).
//!
//! None of this shares code with the kernel's Betti numbers (a vertex-link formula on the
//! boundary and the Hasse diagram of the glued surfaces), its volume (signed tetrahedra) or its
//! point location (winding numbers).

use crate::common::cells::{full_mask, Cells};
use yinset::kernel::Point3;
use yinset::num::{Num, Rational};
use yinset::yin2::Location;
use yinset::yin3::YinSet3;

pub type Y3 = YinSet3<Rational>;

/// Doubled integer coordinates of a lattice point: cell corners are even, cell centres odd.
type D = [i64; 3];

/// A grid of unit cells, mapped into space by a rational rotation (or the identity).
#[derive(Clone, Debug)]
pub struct Grid3 {
    pub name: String,
    /// Cells along x, y, z.
    pub dims: [i64; 3],
    /// Row-major rotation matrix (`None`: the identity).
    rotation: Option<[[Rational; 3]; 3]>,
}

/// The expected Betti numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExpectedBetti3 {
    pub b0: usize,
    pub b1: usize,
    pub b2: usize,
}

impl Grid3 {
    /// The w×h×d grid of unit cells, axis-aligned.
    pub fn grid(w: i64, h: i64, d: i64) -> Grid3 {
        assert!(w * h * d <= 64, "masks are u64");
        Grid3 {
            name: format!("{w}×{h}×{d} cells"),
            dims: [w, h, d],
            rotation: None,
        }
    }

    /// The same grid rotated by the unit quaternion (a + bi + cj + dk)/√n, n = a²+b²+c²+d²,
    /// whose rotation matrix is rational (entries over n).
    pub fn rotated(self, [a, b, c, d]: [i64; 4]) -> Grid3 {
        let n = a * a + b * b + c * c + d * d;
        let m = [
            [
                a * a + b * b - c * c - d * d,
                2 * (b * c - a * d),
                2 * (b * d + a * c),
            ],
            [
                2 * (b * c + a * d),
                a * a - b * b + c * c - d * d,
                2 * (c * d - a * b),
            ],
            [
                2 * (b * d - a * c),
                2 * (c * d + a * b),
                a * a - b * b - c * c + d * d,
            ],
        ];
        let r = m.map(|row| row.map(|v| Rational::new(v.into(), n.into())));
        Grid3 {
            name: format!("{}, rotated by ({a} + {b}i + {c}j + {d}k)/√{n}", self.name),
            rotation: Some(r),
            ..self
        }
    }

    pub fn len(&self) -> usize {
        (self.dims[0] * self.dims[1] * self.dims[2]) as usize
    }

    /// The rotation's matrix entries, if any (for the sanity tests).
    pub fn rotation(&self) -> Option<&[[Rational; 3]; 3]> {
        self.rotation.as_ref()
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

    /// The index of cell (i, j, k), or `None` (the exterior) if it is off the grid.
    fn cell(&self, c: [i64; 3]) -> Option<usize> {
        let [w, h, d] = self.dims;
        let inside = (0..3).all(|k| c[k] >= 0 && c[k] < self.dims[k]);
        let _ = d;
        inside.then(|| (c[0] + w * (c[1] + h * c[2])) as usize)
    }

    fn coords_of(&self, p: usize) -> [i64; 3] {
        let [w, h, _] = self.dims;
        let p = p as i64;
        [p % w, (p / w) % h, p / (w * h)]
    }

    fn contains(&self, s: Cells, cell: Option<usize>) -> bool {
        match cell {
            Some(p) => s.mask >> p & 1 == 1,
            None => s.outside,
        }
    }

    /// The exact point of a doubled lattice point, rotated.
    pub fn point(&self, d: D) -> Point3<Rational> {
        let v = d.map(|c| Rational::new(c.into(), 2.into()));
        match &self.rotation {
            None => {
                let [x, y, z] = v;
                Point3::new(x, y, z)
            }
            Some(r) => {
                let row = |k: usize| {
                    r[k][0].clone() * v[0].clone()
                        + r[k][1].clone() * v[1].clone()
                        + r[k][2].clone() * v[2].clone()
                };
                Point3::new(row(0), row(1), row(2))
            }
        }
    }

    /// The 3-cells incident to the open cell of the complex whose centre is the doubled point
    /// `d` (`None`: the exterior), with repetitions for the exterior.
    fn incident(&self, d: D) -> Vec<Option<usize>> {
        let choices: Vec<Vec<i64>> = d
            .iter()
            .map(|&c| {
                if c % 2 == 0 {
                    vec![c / 2 - 1, c / 2]
                } else {
                    vec![(c - 1) / 2]
                }
            })
            .collect();
        let mut out = Vec::new();
        for &i in &choices[0] {
            for &j in &choices[1] {
                for &k in &choices[2] {
                    out.push(self.cell([i, j, k]));
                }
            }
        }
        out
    }

    /// The centres of every open cell of the closed window's complex (doubled coordinates
    /// 0..=2w etc.), with the dimension of the cell.
    fn open_cells(&self) -> Vec<(D, i64)> {
        let mut v = Vec::new();
        for x in 0..=2 * self.dims[0] {
            for y in 0..=2 * self.dims[1] {
                for z in 0..=2 * self.dims[2] {
                    let dim = [x, y, z].iter().filter(|&&c| c % 2 == 1).count() as i64;
                    v.push(([x, y, z], dim));
                }
            }
        }
        v
    }

    /// The location of the point at `d`: inside iff every incident 3-cell is in the set,
    /// outside iff none is.
    fn location_at(&self, s: Cells, d: D) -> Location {
        let inc = self.incident(d);
        let n_in = inc.iter().filter(|&&c| self.contains(s, c)).count();
        if n_in == inc.len() {
            Location::Inside
        } else if n_in == 0 {
            Location::Outside
        } else {
            Location::OnBoundary
        }
    }

    /// The probe points: the centre of every open cell of the window's complex (cubes, faces,
    /// edges, vertices) and a point outside the window.
    pub fn probes(&self) -> Vec<Point3<Rational>> {
        let mut v: Vec<Point3<Rational>> = self
            .open_cells()
            .into_iter()
            .map(|(d, _)| self.point(d))
            .collect();
        v.push(self.point([-3, -1, -5]));
        v
    }

    /// The expected location of each probe point, read off the mask.
    pub fn expected_locations(&self, s: Cells) -> Vec<Location> {
        let mut v: Vec<Location> = self
            .open_cells()
            .into_iter()
            .map(|(d, _)| self.location_at(s, d))
            .collect();
        v.push(if s.outside {
            Location::Inside
        } else {
            Location::Outside
        });
        v
    }

    /// The probe points interior to cells (cube centres) and outside the window, for the
    /// membership oracle (which skips points on an operand's boundary anyway).
    pub fn cube_probes(&self) -> Vec<Point3<Rational>> {
        self.open_cells()
            .into_iter()
            .filter(|&(_, dim)| dim == 3)
            .map(|(d, _)| self.point(d))
            .chain([self.point([-3, -1, -5])])
            .collect()
    }

    /// The cells (index `n` = the exterior) in the set, labelled by components under
    /// `adjacent`.
    fn components(
        &self,
        member: impl Fn(Option<usize>) -> bool,
        adjacent: impl Fn(Option<usize>, Option<usize>) -> bool,
    ) -> (Vec<usize>, usize) {
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
                for (j, l) in label.iter_mut().enumerate() {
                    if *l == usize::MAX && member(node(j)) && adjacent(node(i), node(j)) {
                        *l = count;
                        stack.push(j);
                    }
                }
            }
            count += 1;
        }
        (label, count)
    }

    /// Adjacency of two 3-cells (`None`: the exterior): the largest number of coordinates in
    /// which they differ by one (others equal) for which they still touch. `max_diff` = 1 is
    /// face adjacency, 3 is 26-adjacency (sharing any point).
    fn touches(&self, a: Option<usize>, b: Option<usize>, max_diff: usize) -> bool {
        match (a, b) {
            (None, None) => true,
            (Some(p), None) | (None, Some(p)) => {
                // The exterior meets every border cell in a face, and (26-adjacency) every
                // cell with a point on the window's boundary: in a grid, the same cells.
                let c = self.coords_of(p);
                (0..3).any(|k| c[k] == 0 || c[k] == self.dims[k] - 1)
            }
            (Some(p), Some(q)) => {
                let (c, e) = (self.coords_of(p), self.coords_of(q));
                let diffs: Vec<i64> = (0..3).map(|k| (c[k] - e[k]).abs()).collect();
                let moved = diffs.iter().filter(|&&v| v == 1).count();
                diffs.iter().all(|&v| v <= 1) && moved >= 1 && moved <= max_diff
            }
        }
    }

    /// The expected Betti numbers of the set (see the module documentation).
    pub fn betti(&self, s: Cells) -> ExpectedBetti3 {
        let (_, b0) = self.components(|c| self.contains(s, c), |a, b| self.touches(a, b, 1));
        let (label, parts) =
            self.components(|c| !self.contains(s, c), |a, b| self.touches(a, b, 3));
        let n = self.len();
        let b2 = parts - usize::from(label[n] != usize::MAX);
        // χ_c(Y) over the open cells of the closed window in Y, and the exterior's −2.
        let mut chi_c: i64 = if s.outside { -2 } else { 0 };
        for (d, dim) in self.open_cells() {
            if self.location_at(s, d) == Location::Inside {
                chi_c += if dim % 2 == 0 { 1 } else { -1 };
            }
        }
        let chi = -chi_c;
        let b1 = b0 as i64 + b2 as i64 - chi;
        assert!(b1 >= 0, "oracle: negative b1 for {s:?} on {}", self.name);
        ExpectedBetti3 {
            b0,
            b1: b1 as usize,
            b2,
        }
    }

    /// Exact volume of a bounded set (`None` if `outside`).
    pub fn volume(&self, s: Cells) -> Option<Rational> {
        (!s.outside).then(|| Rational::from_i64(i64::from(s.mask.count_ones())))
    }

    /// The boundary faces of the set: every unit face of the closed window between a 3-cell in
    /// the set and one not in it, as two triangles of doubled points with normals out of the
    /// set.
    pub fn faces(&self, s: Cells) -> Vec<[D; 3]> {
        let mut out = Vec::new();
        for (d, dim) in self.open_cells() {
            if dim != 2 {
                continue;
            }
            // The face's normal axis is its even coordinate; below and above it, two 3-cells.
            let a = (0..3)
                .find(|&k| d[k] % 2 == 0)
                .expect("a face has an even coordinate");
            let (u, v) = ((a + 1) % 3, (a + 2) % 3);
            let mut below = [0; 3];
            let mut above = [0; 3];
            for k in 0..3 {
                below[k] = (d[k] - 1).div_euclid(2);
                above[k] = below[k];
            }
            below[a] = d[a] / 2 - 1;
            above[a] = d[a] / 2;
            let (lo, hi) = (
                self.contains(s, self.cell(below)),
                self.contains(s, self.cell(above)),
            );
            if lo == hi {
                continue;
            }
            // Corners: centre ∓ e_u ∓ e_v; base → +u → +u+v → +v turns about e_u × e_v = e_a,
            // i.e. its normal points to `above`: outward iff the set is below.
            let corner = |du: i64, dv: i64| {
                let mut c = d;
                c[u] += du;
                c[v] += dv;
                c
            };
            let mut quad = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
            if hi {
                quad.reverse();
            }
            out.push([quad[0], quad[1], quad[2]]);
            out.push([quad[0], quad[2], quad[3]]);
        }
        out
    }

    /// The expected Yin set of a mask, built by `from_triangles` from [`Grid3::faces`] only.
    pub fn yin(&self, s: Cells) -> Y3 {
        let faces = self.faces(s);
        if faces.is_empty() {
            return if s.outside {
                YinSet3::full()
            } else {
                YinSet3::empty()
            };
        }
        let mut index = std::collections::HashMap::new();
        let mut pts = Vec::new();
        let tris: Vec<Vec<usize>> = faces
            .iter()
            .map(|t| {
                t.iter()
                    .map(|&d| {
                        *index.entry(d).or_insert_with(|| {
                            pts.push(self.point(d));
                            pts.len() - 1
                        })
                    })
                    .collect()
            })
            .collect();
        YinSet3::from_triangles(pts, tris)
            .unwrap_or_else(|e| panic!("oracle faces of {s:?} on {} rejected: {e}", self.name))
    }

    /// The degenerate features of an ordered pair (a, b), read off the masks (for the shares
    /// in proofs/README.md), with `betti` the oracle's Betti numbers (cached by the caller):
    /// see [`FEATURES3`].
    pub fn features(
        &self,
        a: Cells,
        b: Cells,
        betti: &dyn Fn(Cells) -> ExpectedBetti3,
    ) -> [bool; 8] {
        let mut f = [false; 8];
        for (d, dim) in self.open_cells() {
            let inc = self.incident(d);
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
