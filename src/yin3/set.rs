//! The 3D Yin space {0̂, 1̂, boundary representations} (seed 003 Def. 7.1–7.8, Cor. 7.11;
//! yin3 docs: *Data model*) as the type `YinSet3`.

use super::betti::{betti, Betti3};
use super::canonical::{canonical, Canon};
use super::error::{Spot, Yin3Error};
use super::fins::{first_non_alternating, FinTable, Pairing};
use super::geom::det3;
use super::glue::{corner_cycles, glued_surfaces};
use super::hasse::{hasse, Atom3};
use super::locate::{on_triangles, winding, TriBoxes};
use super::values::{exact_point, exact_points};
use crate::kernel::{BBox3, Point3};
use crate::num::{balanced_sum, det_sum, lattice_det_sum, Num, Rational};
use crate::yin2::Location;
use num_bigint::BigInt;
use std::hash::{Hash, Hasher};
use std::sync::OnceLock;

/// A 3D Yin set, stored as its boundary representation (seed 003 Thm 7.10, Cor. 7.11): 0̂ (∅),
/// 1̂ (ℝ³), or oriented triangles forming a conforming complex, partitioned into glued
/// surfaces. Normals point out of the set. `==` and `Hash` are set equality, although
/// triangulations are not unique.
#[derive(Clone, Debug)]
pub struct YinSet3<N: Num> {
    pub(crate) repr: Repr3<N>,
    pub(crate) ctx: N::Ctx,
}

#[derive(Clone, Debug)]
pub(crate) enum Repr3<N: Num> {
    Empty,
    Full,
    Brep(Box<Brep<N>>),
}

/// One glued surface (seed 003 Def. 7.1) of a set's boundary.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct GluedSurface {
    /// Its triangles (indices into [`YinSet3::triangles`]).
    pub triangles: Vec<usize>,
    /// True if positively oriented: normals point from its bounded to its unbounded complement
    /// (seed 003 Def. 7.3).
    pub positive: bool,
    /// The genus of the surface it is a quotient of.
    pub genus: usize,
}

/// A boundary representation with its glued surfaces, Hasse diagram and atoms.
#[derive(Clone, Debug)]
pub(crate) struct Brep<N: Num> {
    pub(crate) points: Vec<Point3<N>>,
    pub(crate) tris: Vec<[usize; 3]>,
    pub(crate) table: FinTable,
    pub(crate) surfaces: Vec<GluedSurface>,
    pub(crate) parent: Vec<Option<usize>>,
    pub(crate) atoms: Vec<Atom3>,
    pub(crate) bounded: bool,
    pub(super) betti: OnceLock<Betti3>,
    pub(super) canon: OnceLock<Canon<N>>,
}

impl<N: Num> Brep<N> {
    /// Build from a conforming closed complex (points may be unused): fins, glued surfaces,
    /// orientations, Hasse diagram, atoms, decided by exact predicates (float mode too: a float
    /// set is a valid set of its `f64` values read as rationals). Errors name triangles by
    /// their index in `tris`.
    pub(crate) fn assemble(
        points: Vec<Point3<N>>,
        tris: Vec<[usize; 3]>,
    ) -> Result<Brep<N>, Yin3Error> {
        if !N::EXACT {
            // The structure of a float set is its exact values' (the f64 arithmetic of signed
            // volumes and fin orders is not exact); compaction renumbers both alike.
            let (points, tris) = compact(points, tris);
            return Ok(Brep::assemble(exact_points(&points), tris)?.with_points(points));
        }
        let ctx = &N::exact_ctx();
        let (points, tris) = compact(points, tris);
        let table = FinTable::new(&points, &tris, ctx);
        if let Some((e, f, g)) = first_non_alternating(&table) {
            let (a, b) = table.edges[e];
            let (from, to) = (Spot::new(&points[a]), Spot::new(&points[b]));
            let count = table.fins(e).len();
            return Err(if count % 2 == 1 {
                Yin3Error::OpenEdge {
                    from,
                    to,
                    count,
                    face: f.tri,
                }
            } else {
                Yin3Error::Inconsistent {
                    from,
                    to,
                    a: f.tri,
                    b: g.tri,
                }
            });
        }
        let (label, count) = glued_surfaces(&table, tris.len(), Pairing::Inside);
        let h = hasse(&points, &tris, &label, count, ctx);
        let genus = genera(&tris, &table, &label, count);
        Ok(Brep {
            surfaces: surfaces(&label, count, &h.positive, &genus),
            points,
            tris,
            table,
            parent: h.parent,
            atoms: h.atoms,
            bounded: h.bounded,
            betti: OnceLock::new(),
            canon: OnceLock::new(),
        })
    }

    /// The same structure over the points `f(p)` (which must keep every predicate's value).
    pub(crate) fn map_points<M: Num>(self, f: impl FnMut(&Point3<N>) -> Point3<M>) -> Brep<M> {
        Brep {
            points: self.points.iter().map(f).collect(),
            tris: self.tris,
            table: self.table,
            surfaces: self.surfaces,
            parent: self.parent,
            atoms: self.atoms,
            bounded: self.bounded,
            betti: OnceLock::new(),
            canon: OnceLock::new(),
        }
    }

    /// The same boundary over `points`, given for its points in order.
    pub(crate) fn with_points<M: Num>(self, points: Vec<Point3<M>>) -> Brep<M> {
        let mut points = points.into_iter();
        self.map_points(|_| points.next().expect("one point for each point"))
    }

    /// The boundary of a float set over its exact values: the same triangles, which form a valid
    /// boundary because float sets are valid exactly.
    pub(crate) fn exact_values(&self) -> Brep<Rational> {
        self.clone().map_points(exact_point)
    }

    /// The Betti numbers of the set it bounds (yin3 docs: *Betti numbers*), computed once.
    pub(crate) fn betti(&self) -> Betti3 {
        *self.betti.get_or_init(|| {
            let (atoms, bounded) = (self.atoms.len(), self.bounded);
            if N::EXACT {
                betti(
                    &self.points,
                    &self.tris,
                    &self.table,
                    atoms,
                    bounded,
                    &N::exact_ctx(),
                )
            } else {
                let exact = exact_points(&self.points);
                betti(&exact, &self.tris, &self.table, atoms, bounded, &())
            }
        })
    }

    /// The corners of triangle `t`.
    pub(crate) fn corners(&self, t: usize) -> [&Point3<N>; 3] {
        self.tris[t].map(|v| &self.points[v])
    }

    /// The exact volume of a float boundary's `f64` vertices: a sixth of Σ det[p − o, q − o,
    /// r − o] over its triangles, on the integers of their power-of-two grid ([`det_sum`]).
    fn float_volume(&self) -> Rational {
        let points: Vec<[f64; 3]> = self.points.iter().map(|p| p.to_f64()).collect();
        det_sum(&points, self.tris.iter().copied()) / Rational::from_i64(6)
    }

    /// The volume of an exact boundary: a sixth of Σ det[p − o, q − o, r − o] over its
    /// triangles, on the integers of its coordinates' common lattice where it has a modest one
    /// ([`lattice_det_sum`]), else summed in `N` pairwise ([`balanced_sum`]).
    fn exact_volume(&self) -> N {
        let fractions: Vec<[(BigInt, BigInt); 3]> = (self.points.iter())
            .map(|p| p.coords().map(|c| c.fraction()))
            .collect();
        match lattice_det_sum(&fractions, self.tris.iter().copied()) {
            Some(sum) => N::nearest(&(sum / Rational::from_i64(6))),
            None => {
                let dets = self.all_corners().map(|[p, q, r]| det3(p, q, r)).collect();
                balanced_sum(dets) / N::from_i64(6)
            }
        }
    }

    /// All triangles' corners.
    pub(crate) fn all_corners(&self) -> impl Iterator<Item = [&Point3<N>; 3]> + '_ {
        (0..self.tris.len()).map(|t| self.corners(t))
    }

    /// Locate each point (yin3 docs: *Locate*): on the boundary if on a triangle (float mode: at
    /// Euclidean distance at most ε from one), otherwise by the exact winding number. The
    /// triangles' boxes are put in an R-tree first, so that each point meets only the triangles
    /// near it and its ray.
    pub(crate) fn locate(&self, points: &[Point3<N>], ctx: &N::Ctx) -> Vec<Location> {
        let (exact, eps) = (N::exact_ctx(), N::tolerance(ctx));
        let boxes = TriBoxes::new((0..self.tris.len()).map(|t| (t, self.corners(t))));
        points
            .iter()
            .map(|q| {
                if on_triangles(boxes.at(q, eps).map(|t| self.corners(t)), q, eps) {
                    Location::OnBoundary
                } else if winding(boxes.along_x(q).map(|t| self.corners(t)), q, &exact)
                    + i64::from(!self.bounded)
                    == 1
                {
                    Location::Inside
                } else {
                    Location::Outside
                }
            })
            .collect()
    }

    /// The canonical form deciding equality (exact predicates).
    fn canon(&self) -> &Canon<N> {
        self.canon
            .get_or_init(|| canonical(&self.points, &self.tris, &N::exact_ctx()))
    }
}

/// Keep only the points that triangles use, renumbered in order of first use.
pub(crate) fn compact<N: Num>(
    points: Vec<Point3<N>>,
    tris: Vec<[usize; 3]>,
) -> (Vec<Point3<N>>, Vec<[usize; 3]>) {
    let mut new = vec![usize::MAX; points.len()];
    let mut kept = Vec::with_capacity(points.len());
    let mut slots: Vec<Option<Point3<N>>> = points.into_iter().map(Some).collect();
    let tris = tris
        .into_iter()
        .map(|t| {
            t.map(|v| {
                if new[v] == usize::MAX {
                    new[v] = kept.len();
                    kept.push(slots[v].take().expect("each point is taken once"));
                }
                new[v]
            })
        })
        .collect();
    (kept, tris)
}

/// The glued surfaces of the triangles' labels `label` (`count` of them), each with its
/// orientation and genus.
pub(super) fn surfaces(
    label: &[usize],
    count: usize,
    positive: &[bool],
    genus: &[usize],
) -> Vec<GluedSurface> {
    let mut surfaces: Vec<GluedSurface> = (0..count)
        .map(|s| GluedSurface {
            triangles: Vec::new(),
            positive: positive[s],
            genus: genus[s],
        })
        .collect();
    for (t, &l) in label.iter().enumerate() {
        surfaces[l].triangles.push(t);
    }
    surfaces
}

/// The genus of each glued surface: its triangles joined across its own pairing (the
/// ⊥-pairing restricted to its fins, GS.2), χ = V − E + F with V its corner cycles.
pub(super) fn genera(
    tris: &[[usize; 3]],
    table: &FinTable,
    label: &[usize],
    count: usize,
) -> Vec<usize> {
    let mut cycles = corner_cycles(table, tris, Some(label), Pairing::Outside);
    // A cycle joins corners of one surface: counted once, at its root corner.
    let mut vertices = vec![0i64; count];
    let mut faces = vec![0i64; count];
    for (t, &l) in label.iter().enumerate() {
        faces[l] += 1;
        for c in 3 * t..3 * t + 3 {
            vertices[l] += i64::from(cycles.find(c) == c);
        }
    }
    (0..count)
        .map(|s| {
            let chi = vertices[s] - faces[s] / 2;
            ((2 - chi) / 2).max(0) as usize
        })
        .collect()
}

impl<N: Num> YinSet3<N> {
    /// 0̂, the empty set.
    ///
    /// ```
    /// use yinset::{num::{Num, Rational}, yin3::YinSet3};
    /// let e = YinSet3::<Rational>::empty();
    /// assert!(e.is_empty() && e.is_bounded());
    /// assert_eq!(e.volume(), Some(Rational::from_i64(0)));
    /// ```
    pub fn empty() -> YinSet3<N> {
        YinSet3 {
            repr: Repr3::Empty,
            ctx: N::Ctx::default(),
        }
    }

    /// 1̂, the whole space.
    ///
    /// ```
    /// use yinset::{num::Rational, yin3::YinSet3};
    /// let all = YinSet3::<Rational>::full();
    /// assert!(all.is_full() && !all.is_bounded());
    /// assert_eq!(all.volume(), None);
    /// assert_eq!(!&all, YinSet3::empty());
    /// ```
    pub fn full() -> YinSet3<N> {
        YinSet3 {
            repr: Repr3::Full,
            ctx: N::Ctx::default(),
        }
    }

    pub(crate) fn from_brep(b: Brep<N>, ctx: N::Ctx) -> YinSet3<N> {
        YinSet3 {
            repr: Repr3::Brep(Box::new(b)),
            ctx,
        }
    }

    pub(crate) fn brep(&self) -> Option<&Brep<N>> {
        match &self.repr {
            Repr3::Brep(b) => Some(b),
            _ => None,
        }
    }

    /// The exact set of a float set's values ([`Brep::exact_values`]).
    pub(crate) fn exact_values(&self) -> YinSet3<Rational> {
        match self.brep() {
            None if self.is_empty() => YinSet3::empty(),
            None => YinSet3::full(),
            Some(b) => YinSet3::from_brep(b.exact_values(), ()),
        }
    }

    /// The number context in force.
    pub fn ctx(&self) -> N::Ctx {
        self.ctx
    }

    /// True for 0̂.
    pub fn is_empty(&self) -> bool {
        matches!(self.repr, Repr3::Empty)
    }

    /// True for 1̂.
    pub fn is_full(&self) -> bool {
        matches!(self.repr, Repr3::Full)
    }

    /// True if the set is bounded (0̂ is, 1̂ is not).
    pub fn is_bounded(&self) -> bool {
        match &self.repr {
            Repr3::Empty => true,
            Repr3::Full => false,
            Repr3::Brep(b) => b.bounded,
        }
    }

    /// The boundary's vertices (empty for 0̂ and 1̂).
    pub fn vertices(&self) -> &[Point3<N>] {
        self.brep().map_or(&[], |b| &b.points)
    }

    /// The boundary's oriented triangles, as indices into [`YinSet3::vertices`]; normals
    /// (b − a) × (c − a) point out of the set.
    pub fn triangles(&self) -> &[[usize; 3]] {
        self.brep().map_or(&[], |b| &b.tris)
    }

    /// The glued surfaces of the boundary (seed 003 Def. 7.8).
    pub fn surfaces(&self) -> &[GluedSurface] {
        self.brep().map_or(&[], |b| &b.surfaces)
    }

    /// The Hasse diagram: each surface's parent, the smallest surface whose bounded complement
    /// contains it (seed 003 Def. 7.5–7.6).
    pub fn parents(&self) -> &[Option<usize>] {
        self.brep().map_or(&[], |b| &b.parent)
    }

    /// The atoms: one per connected component (seed 003 Thm 7.10, Cor. 7.11).
    pub fn atoms(&self) -> &[Atom3] {
        self.brep().map_or(&[], |b| &b.atoms)
    }

    /// Betti numbers b0, b1, b2 of the set as an open subset of ℝ³ (yin3 docs: *Betti numbers*).
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// // A cube with a cavity: one component, no tunnel, one cavity.
    /// let hollow = &cube(0, 0, 0, 3) - &cube(1, 1, 1, 1);
    /// let b = hollow.betti();
    /// assert_eq!((b.b0, b.b1, b.b2), (1, 0, 1));
    /// // Two cubes sharing only an edge are two components.
    /// let pair = &cube(0, 0, 0, 1) | &cube(1, 1, 0, 1);
    /// assert_eq!(pair.betti().b0, 2);
    /// ```
    pub fn betti(&self) -> Betti3 {
        match &self.repr {
            Repr3::Empty => Betti3::default(),
            Repr3::Full => Betti3 {
                b0: 1,
                b1: 0,
                b2: 0,
            },
            Repr3::Brep(b) => b.betti(),
        }
    }

    /// The volume; `None` if the set is unbounded. Exact in exact mode; in float mode the
    /// nearest `f64` of [`YinSet3::volume_exact`], so a set far from the origin keeps its
    /// volume, and the value is 0 or infinite only where the exact one is below or beyond the
    /// range of `f64`.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Float, Num, Rational, Tolerance}, yin3::{shapes, YinSet3}};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let (a, b) = (cube(0, 0, 0, 2), cube(1, 1, 1, 2));
    /// assert_eq!(a.volume(), Some(Rational::from_i64(8)));
    /// // Exact: |A ∧ B| + |A ∨ B| = |A| + |B|.
    /// assert_eq!((&a & &b).volume().unwrap() + (&a | &b).volume().unwrap(), Rational::from_i64(16));
    /// assert_eq!((!&a).volume(), None); // unbounded
    ///
    /// // Float mode: a cube of side 2 at 10⁹, where f64 products of the corners would cancel.
    /// let p = |v: f64| Point3::new(Float::new(v), Float::new(v), Float::new(v));
    /// let (corners, faces) = shapes::cuboid(&p(1e9), &p(1e9 + 2.0));
    /// let far = YinSet3::from_triangles_with(corners, faces, Tolerance::new(1.0)).unwrap();
    /// assert_eq!(far.volume(), Some(Float::new(8.0)));
    /// assert_eq!(far.volume_exact(), Some(Rational::from_i64(8)));
    /// ```
    pub fn volume(&self) -> Option<N> {
        match &self.repr {
            Repr3::Empty => Some(N::zero()),
            Repr3::Full => None,
            Repr3::Brep(b) if b.bounded && N::EXACT => Some(b.exact_volume()),
            Repr3::Brep(b) if b.bounded => Some(N::nearest(&b.float_volume())),
            Repr3::Brep(_) => None,
        }
    }

    /// The exact volume of the set its vertices bound (in float mode: of their `f64` values,
    /// read as the rationals they are); `None` if the set is unbounded.
    pub fn volume_exact(&self) -> Option<Rational> {
        match &self.repr {
            Repr3::Brep(b) if b.bounded && !N::EXACT => Some(b.float_volume()),
            _ => self.volume().map(|v| {
                let (n, d) = v.fraction();
                Rational::new(n, d)
            }),
        }
    }

    /// The area of the boundary (the interface area between the set and its complement), in
    /// `f64` in either mode: each triangle's area |(q − p) × (r − p)| / 2 takes a square root.
    /// 0 for 0̂ and 1̂.
    ///
    /// ```
    /// use yinset::kernel::Point3;
    /// use yinset::num::{Num, Rational};
    /// use yinset::yin3::YinSet3;
    /// let p = |x, y, z| Point3::new(Rational::from_i64(x), Rational::from_i64(y), Rational::from_i64(z));
    /// let boxed = YinSet3::cuboid(&p(0, 0, 0), &p(1, 2, 3)).unwrap();
    /// assert_eq!(boxed.boundary_area(), 22.0);
    /// assert_eq!(boxed.complement().boundary_area(), 22.0);
    /// ```
    pub fn boundary_area(&self) -> f64 {
        let area = |[p, q, r]: [&Point3<N>; 3]| {
            let [p, q, r] = [p, q, r].map(|x| x.to_f64());
            let u = [0, 1, 2].map(|k| q[k] - p[k]);
            let w = [0, 1, 2].map(|k| r[k] - p[k]);
            let n = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() / 2.0
        };
        self.brep().map_or(0.0, |b| b.all_corners().map(area).sum())
    }

    /// The bounding box of the boundary (`None` for 0̂ and 1̂).
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let b = (&cube(0, 0, 0, 1) | &cube(2, 0, 0, 1)).bbox().unwrap();
    /// assert_eq!((b.min, b.max), (Point3::int(0, 0, 0), Point3::int(3, 1, 1)));
    /// ```
    pub fn bbox(&self) -> Option<BBox3<N>> {
        BBox3::of(self.vertices())
    }

    /// Locate each point: inside, outside or on the boundary (yin3 docs: *Locate*); in float mode
    /// on the boundary where its Euclidean distance to the boundary is at most ε.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// use yinset::yin2::Location;
    /// let a = cube(0, 0, 0, 2);
    /// let at = [Point3::int(1, 1, 1), Point3::int(2, 1, 1), Point3::int(3, 3, 3)];
    /// assert_eq!(a.locate(&at), vec![Location::Inside, Location::OnBoundary, Location::Outside]);
    /// ```
    pub fn locate(&self, points: &[Point3<N>]) -> Vec<Location> {
        match &self.repr {
            Repr3::Empty => vec![Location::Outside; points.len()],
            Repr3::Full => vec![Location::Inside; points.len()],
            Repr3::Brep(b) => b.locate(points, &self.ctx),
        }
    }
}

impl<N: Num> PartialEq for YinSet3<N> {
    fn eq(&self, other: &Self) -> bool {
        match (&self.repr, &other.repr) {
            (Repr3::Empty, Repr3::Empty) | (Repr3::Full, Repr3::Full) => true,
            (Repr3::Brep(a), Repr3::Brep(b)) if N::EXACT => a.canon() == b.canon(),
            // Float sets are equal if their exact values are (plane keys need exact arithmetic).
            (Repr3::Brep(a), Repr3::Brep(b)) => {
                a.exact_values().canon() == b.exact_values().canon()
            }
            _ => false,
        }
    }
}
impl<N: Num> Eq for YinSet3<N> {}

impl<N: Num> Hash for YinSet3<N> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        match &self.repr {
            Repr3::Empty => 0u8.hash(state),
            Repr3::Full => 1u8.hash(state),
            Repr3::Brep(b) => {
                2u8.hash(state);
                if N::EXACT {
                    b.canon().hash(state);
                } else {
                    b.exact_values().canon().hash(state);
                }
            }
        }
    }
}
