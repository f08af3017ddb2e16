//! The Jordan space {0̂, 1̂, realizable spadjors} (seed 000 Def. 3.19) as the type `YinSet2`.

use super::curve::{canonical_curve, Curve};
use super::hasse::{atoms, parents, Atom, Betti};
use super::locate::{locate_within, Location};
use crate::kernel::{BBox, Point};
use crate::num::{balanced_sum, det_sum, Num, Rational};
use foldhash::HashSet;
use std::hash::{Hash, Hasher};

/// A 2D Yin set, stored as its unique boundary representation (seed 000 Thm 3.21): 0̂ (∅),
/// 1̂ (ℝ²), or a realizable spadjor in canonical form. `==` and `Hash` are set equality.
#[derive(Clone, Debug)]
pub struct YinSet2<N: Num> {
    pub(crate) repr: Repr<N>,
    pub(crate) ctx: N::Ctx,
}

#[derive(Clone, Debug)]
pub(crate) enum Repr<N: Num> {
    Empty,
    Full,
    Spadjor(Spadjor<N>),
}

/// A realizable spadjor (seed 000 Def. 3.17) with its Hasse diagram, atoms and Betti numbers.
#[derive(Clone, Debug)]
pub(crate) struct Spadjor<N: Num> {
    pub(crate) curves: Vec<Curve<N>>,
    pub(crate) positive: Vec<bool>,
    pub(crate) parent: Vec<Option<usize>>,
    pub(crate) atoms: Vec<Atom>,
    pub(crate) betti: Betti,
    pub(crate) bounded: bool,
}

impl<N: Num> Spadjor<N> {
    /// The exact area of a float spadjor's `f64` vertices: half of Σ det[p − o, q − o] over
    /// the curves' directed edges pq, on the integers of their power-of-two grid ([`det_sum`]).
    fn float_area(&self) -> Rational {
        let points: Vec<[f64; 2]> = (self.curves.iter())
            .flat_map(|c| c.vertices().iter().map(|p| p.to_f64()))
            .collect();
        let mut start = 0;
        let edges = self.curves.iter().flat_map(|c| {
            let (first, n) = (start, c.vertices().len());
            start += n;
            (0..n).map(move |k| [first + k, first + (k + 1) % n])
        });
        det_sum(&points, edges) / Rational::from_i64(2)
    }

    /// Build from curves already simple and pairwise almost disjoint, with every touching point
    /// among `touching`: canonical form, Hasse diagram, atoms, Betti numbers. Also returns, for
    /// each canonical curve, the index of the loop it came from.
    pub(crate) fn assemble(
        loops: Vec<Vec<Point<N>>>,
        touching: &HashSet<Point<N>>,
        ctx: &N::Ctx,
    ) -> (Spadjor<N>, Vec<usize>) {
        Self::assemble_as(loops, touching, ctx, |curves, _| parents(curves, ctx))
    }

    /// [`Spadjor::assemble`] with the Hasse diagram known already: `parent[l]` the parent of
    /// loop `l` among `loops`.
    pub(crate) fn assemble_nested(
        loops: Vec<Vec<Point<N>>>,
        parent: &[Option<usize>],
        touching: &HashSet<Point<N>>,
        ctx: &N::Ctx,
    ) -> Spadjor<N> {
        let renumber = |_: &[Curve<N>], origin: &[usize]| {
            let mut rank = vec![0; origin.len()];
            for (i, &l) in origin.iter().enumerate() {
                rank[l] = i;
            }
            origin.iter().map(|&l| parent[l].map(|p| rank[p])).collect()
        };
        Self::assemble_as(loops, touching, ctx, renumber).0
    }

    /// [`Spadjor::assemble`] with the parents of the canonical curves given by `hasse` (from the
    /// curves and the loop each came from).
    fn assemble_as(
        loops: Vec<Vec<Point<N>>>,
        touching: &HashSet<Point<N>>,
        ctx: &N::Ctx,
        hasse: impl FnOnce(&[Curve<N>], &[usize]) -> Vec<Option<usize>>,
    ) -> (Spadjor<N>, Vec<usize>) {
        let mut curves: Vec<(Curve<N>, usize)> = loops
            .into_iter()
            .enumerate()
            .map(|(i, v)| (canonical_curve(v, touching, ctx), i))
            .collect();
        curves.sort();
        let (curves, origin): (Vec<Curve<N>>, Vec<usize>) = curves.into_iter().unzip();
        let positive: Vec<bool> = curves.iter().map(|c| c.is_positive()).collect();
        let parent = hasse(&curves, &origin);
        let atoms = atoms(&positive, &parent);
        let betti = Betti::of_atoms(&atoms);
        // Bounded iff the outermost curves are positive (seed 000 Lemma 3.18: else the
        // unbounded atom 𝒥⁻ is there).
        let bounded = (0..curves.len()).any(|i| parent[i].is_none() && positive[i]);
        (
            Spadjor {
                curves,
                positive,
                parent,
                atoms,
                betti,
                bounded,
            },
            origin,
        )
    }

    /// All directed edges of all curves.
    pub(crate) fn edges(&self) -> Vec<(&Point<N>, &Point<N>)> {
        self.curves.iter().flat_map(|c| c.edges()).collect()
    }

    /// Batch locate (seed 002 Alg. 1).
    pub(crate) fn locate(&self, queries: &[Point<N>], ctx: &N::Ctx) -> Vec<Location> {
        locate_within(&self.edges(), !self.bounded, queries, N::tolerance(ctx))
    }
}

impl<N: Num> YinSet2<N> {
    /// 0̂, the empty set.
    ///
    /// ```
    /// use yinset::{num::{Num, Rational}, yin2::YinSet2};
    /// let e = YinSet2::<Rational>::empty();
    /// assert!(e.is_empty() && e.is_bounded());
    /// assert_eq!(e.area(), Some(Rational::from_i64(0)));
    /// ```
    pub fn empty() -> YinSet2<N> {
        YinSet2 {
            repr: Repr::Empty,
            ctx: N::Ctx::default(),
        }
    }

    /// 1̂, the whole plane.
    ///
    /// ```
    /// use yinset::{num::Rational, yin2::YinSet2};
    /// let all = YinSet2::<Rational>::full();
    /// assert!(all.is_full() && !all.is_bounded());
    /// assert_eq!(all.area(), None);
    /// assert_eq!(!&all, YinSet2::empty());
    /// ```
    pub fn full() -> YinSet2<N> {
        YinSet2 {
            repr: Repr::Full,
            ctx: N::Ctx::default(),
        }
    }

    pub(crate) fn from_spadjor(s: Spadjor<N>, ctx: N::Ctx) -> YinSet2<N> {
        YinSet2 {
            repr: Repr::Spadjor(s),
            ctx,
        }
    }

    /// The same set carrying another context (float mode: another ε).
    pub fn with_ctx(mut self, ctx: N::Ctx) -> YinSet2<N> {
        self.ctx = ctx;
        self
    }

    /// The number context in force (float mode: the tolerance ε).
    pub fn ctx(&self) -> N::Ctx {
        self.ctx
    }

    /// The effective grid spacing of float mode (every vertex is a multiple of it, see
    /// [`crate::num::Tolerance`]); `None` in exact mode.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Float, Rational, Tolerance}, yin2::YinSet2};
    /// let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
    /// let unit = vec![vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]];
    /// let a = YinSet2::from_curves_with(unit, Tolerance::new(1e-9))?;
    /// assert_eq!(a.grid(), Some(2f64.powi(-30))); // the largest power of two not above ε
    /// assert_eq!(YinSet2::<Rational>::empty().grid(), None); // exact mode
    /// # Ok::<(), yinset::yin2::YinError>(())
    /// ```
    pub fn grid(&self) -> Option<f64> {
        N::grid(&self.ctx)
    }

    /// True for 0̂.
    pub fn is_empty(&self) -> bool {
        matches!(self.repr, Repr::Empty)
    }

    /// True for 1̂.
    pub fn is_full(&self) -> bool {
        matches!(self.repr, Repr::Full)
    }

    /// True if the set is bounded (0̂ is; 1̂ is not; a spadjor is iff it has no atom 𝒥⁻).
    pub fn is_bounded(&self) -> bool {
        match &self.repr {
            Repr::Empty => true,
            Repr::Full => false,
            Repr::Spadjor(s) => s.bounded,
        }
    }

    /// The Jordan curves of the realizable spadjor, in canonical order (empty for 0̂ and 1̂).
    pub fn curves(&self) -> &[Curve<N>] {
        match &self.repr {
            Repr::Spadjor(s) => &s.curves,
            _ => &[],
        }
    }

    /// The Hasse diagram of inclusion (seed 002 Alg. 3): each curve's parent.
    pub fn parents(&self) -> &[Option<usize>] {
        match &self.repr {
            Repr::Spadjor(s) => &s.parent,
            _ => &[],
        }
    }

    /// The atom spadjors (seed 000 Lemma 3.18), one per connected component.
    pub fn atoms(&self) -> &[Atom] {
        match &self.repr {
            Repr::Spadjor(s) => &s.atoms,
            _ => &[],
        }
    }

    /// Betti numbers (seed 000 Cor. 3.14), read off the stored representation.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// // A square with two square holes: one component, two holes.
    /// let frame = &(&sq(0, 0, 5) - &sq(1, 1, 1)) - &sq(3, 3, 1);
    /// assert_eq!(frame.betti().components, 1);
    /// assert_eq!(frame.betti().holes, vec![2]);
    /// assert_eq!(frame.betti().total_holes, 2);
    /// ```
    pub fn betti(&self) -> Betti {
        match &self.repr {
            Repr::Empty => Betti::default(),
            Repr::Full => Betti {
                components: 1,
                holes: vec![0],
                total_holes: 0,
            },
            Repr::Spadjor(s) => s.betti.clone(),
        }
    }

    /// The area; `None` if the set is unbounded. Exact in exact mode; in float mode the
    /// nearest `f64` of [`YinSet2::area_exact`], so a set far from the origin keeps its area,
    /// and the value is 0 or infinite only where the exact one is below or beyond the range
    /// of `f64`.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Float, Num, Rational, Tolerance}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let (a, b) = (sq(0, 0, 2), sq(1, 1, 2));
    /// assert_eq!(a.area(), Some(Rational::from_i64(4)));
    /// // Exact: |A ∧ B| + |A ∨ B| = |A| + |B|.
    /// assert_eq!((&a & &b).area().unwrap() + (&a | &b).area().unwrap(), Rational::from_i64(8));
    /// assert_eq!((!&a).area(), None); // unbounded
    ///
    /// // Float mode: the square [0, 2⁹⁹⁶]², whose area overflows f64 but not its corners.
    /// let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
    /// let s = 2f64.powi(996);
    /// let square = vec![p(0.0, 0.0), p(s, 0.0), p(s, s), p(0.0, s)];
    /// let set = YinSet2::from_curves_with(vec![square], Tolerance::default()).unwrap();
    /// assert_eq!(set.area(), Some(Float::new(f64::INFINITY)));
    /// let side = Rational::from_float(s).unwrap();
    /// assert_eq!(set.area_exact(), Some(side.clone() * side));
    /// ```
    pub fn area(&self) -> Option<N> {
        match &self.repr {
            Repr::Empty => Some(N::zero()),
            Repr::Full => None,
            Repr::Spadjor(s) if s.bounded && N::EXACT => {
                Some(balanced_sum(s.curves.iter().map(|c| c.twice_signed_area()).collect()).half())
            }
            Repr::Spadjor(s) if s.bounded => Some(N::nearest(&s.float_area())),
            Repr::Spadjor(_) => None,
        }
    }

    /// The exact area of the set its vertices bound (in float mode: of their `f64` values,
    /// read as the rationals they are); `None` if the set is unbounded.
    pub fn area_exact(&self) -> Option<Rational> {
        match &self.repr {
            Repr::Spadjor(s) if s.bounded && !N::EXACT => Some(s.float_area()),
            _ => self.area().map(|a| {
                let (n, d) = a.fraction();
                Rational::new(n, d)
            }),
        }
    }

    /// The bounding box of the boundary (`None` for 0̂ and 1̂).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let b = (&sq(0, 0, 2) | &sq(3, 1, 2)).bbox().unwrap();
    /// assert_eq!((b.min, b.max), (Point::int(0, 0), Point::int(5, 3)));
    /// assert!(YinSet2::<Rational>::empty().bbox().is_none());
    /// ```
    pub fn bbox(&self) -> Option<BBox<N>> {
        self.curves()
            .iter()
            .map(|c| c.bbox())
            .reduce(|a, b| a.union(&b))
    }

    /// Locate each point: inside, outside or on the boundary (seed 002 Alg. 1). Exact in exact
    /// mode; in float mode a point within ε of the boundary (Euclidean distance to the nearest
    /// edge, any direction) is on it, every other point is located exactly.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// use yinset::yin2::Location;
    /// let a = sq(0, 0, 2);
    /// let at = [Point::int(1, 1), Point::int(2, 1), Point::int(3, 3)];
    /// assert_eq!(a.locate(&at), vec![Location::Inside, Location::OnBoundary, Location::Outside]);
    /// ```
    pub fn locate(&self, points: &[Point<N>]) -> Vec<Location> {
        match &self.repr {
            Repr::Empty => vec![Location::Outside; points.len()],
            Repr::Full => vec![Location::Inside; points.len()],
            Repr::Spadjor(s) => s.locate(points, &self.ctx),
        }
    }
}

impl<N: Num> PartialEq for YinSet2<N> {
    fn eq(&self, other: &Self) -> bool {
        match (&self.repr, &other.repr) {
            (Repr::Empty, Repr::Empty) | (Repr::Full, Repr::Full) => true,
            (Repr::Spadjor(a), Repr::Spadjor(b)) => a.curves == b.curves,
            _ => false,
        }
    }
}
impl<N: Num> Eq for YinSet2<N> {}

impl<N: Num> Hash for YinSet2<N> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        match &self.repr {
            Repr::Empty => 0u8.hash(state),
            Repr::Full => 1u8.hash(state),
            Repr::Spadjor(s) => {
                2u8.hash(state);
                s.curves.hash(state);
            }
        }
    }
}
