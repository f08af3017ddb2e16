//! Orientation of glued surfaces, boundedness, the Hasse diagram of inclusion and the atoms (seed
//! 003 Def. 7.3–7.6, Thm 7.10, Cor. 7.11; yin3 docs: *Orientation, boundedness, Hasse diagram*).

use super::geom::{det3, widened_box};
use super::locate::winding;
use crate::kernel::Point3;
use crate::num::{balanced_sum, Num};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{Envelope, RTree, AABB};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// One connected component of a 3D Yin set (seed 003 Thm 7.10): its positively oriented
/// glued surface (none for the unbounded component) and the negatively oriented ones it
/// covers.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Atom3 {
    /// The outer surface 𝒮⁺ (an index into the set's surfaces), `None` for the unbounded atom.
    pub outer: Option<usize>,
    /// The surfaces 𝒮⁻ of its cavities (or, for the unbounded atom, of its complement's
    /// components).
    pub inner: Vec<usize>,
}

/// The inclusion structure of a set of glued surfaces.
#[derive(Clone, Debug)]
pub(crate) struct Hasse {
    /// True for each positively oriented surface (positive signed volume, Def. 7.3).
    pub positive: Vec<bool>,
    /// Each surface's parent: the smallest surface whose bounded complement contains it.
    pub parent: Vec<Option<usize>>,
    /// The atoms.
    pub atoms: Vec<Atom3>,
    /// True if the set is bounded (the total signed volume is positive).
    pub bounded: bool,
}

/// The Hasse diagram of the surfaces `label` (per triangle, `count` of them) of the triangles.
pub(crate) fn hasse<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    label: &[usize],
    count: usize,
    ctx: &N::Ctx,
) -> Hasse {
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); count];
    for (t, &l) in label.iter().enumerate() {
        members[l].push(t);
    }
    let corners = |t: usize| tris[t].map(|v| &points[v]);
    // Each point rounded to f64 once (a point is a corner of about six triangles).
    let rounded: Vec<[f64; 3]> = points.iter().map(Point3::to_f64).collect();
    let volumes = Volumes::new(&members, &corners, |t| tris[t].map(|v| rounded[v]));
    // Each surface's widened box on the rounded points, once a larger surface is tried as its
    // parent or as another's (a single surface, as most meets have, never needs one). Rounding
    // and widening keep order, so such a box outside another's shows the exact one outside too.
    let boxes: Vec<OnceCell<AABB<[f64; 3]>>> = (0..count).map(|_| OnceCell::new()).collect();
    let bbox = |s: usize| {
        boxes[s].get_or_init(|| {
            widened_box(members[s].iter().flat_map(|&t| tris[t].map(|v| rounded[v])))
        })
    };
    let inside = |l: usize, k: usize| bbox(k).contains_envelope(bbox(l));
    // The surfaces whose boxes may contain surface l's, in increasing order (of two equal
    // volumes the first is the parent): every surface, or past [`MANY_SURFACES`] those whose
    // boxes an R-tree of the boxes finds meeting l's.
    let tree = (count > MANY_SURFACES).then(|| {
        RTree::bulk_load(
            (0..count)
                .map(|s| GeomWithData::new(Rectangle::from_aabb(*bbox(s)), s))
                .collect(),
        )
    });
    let candidates = |l: usize| -> Vec<usize> {
        match &tree {
            None => (0..count).collect(),
            Some(tree) => {
                let mut near: Vec<usize> = (tree.locate_in_envelope_intersecting(bbox(l)))
                    .map(|g| g.data)
                    .collect();
                near.sort_unstable();
                near
            }
        }
    };
    let mut parent = vec![None; count];
    for l in 0..count {
        // A point inside the surface's first triangle, made once a larger surface is tried.
        let q = OnceCell::new();
        let q = || {
            q.get_or_init(|| {
                let [a, b, c] = corners(members[l][0]);
                Point3::centroid(a, b, c)
            })
        };
        let mut best: Option<usize> = None;
        for k in candidates(l) {
            // The boxes first: comparing volumes may need their exact sums.
            if k == l || !inside(l, k) || volumes.cmp_abs(k, l) != Ordering::Greater {
                continue;
            }
            if best.is_some_and(|b| volumes.cmp_abs(b, k) != Ordering::Greater) {
                continue;
            }
            if winding(members[k].iter().map(|&t| corners(t)), q(), ctx) != 0 {
                best = Some(k);
            }
        }
        parent[l] = best;
    }
    let positive: Vec<bool> = (0..count)
        .map(|s| volumes.sign(s) == Ordering::Greater)
        .collect();
    Hasse {
        bounded: volumes.total_sign() == Ordering::Greater,
        atoms: atoms(&positive, &parent),
        positive,
        parent,
    }
}

/// [`hasse`] looks for each surface's parent among the surfaces whose boxes meet its box, in
/// an R-tree, past this many surfaces (a checkerboard's meet has hundreds), and among all
/// below.
const MANY_SURFACES: usize = 32;

/// The atoms of surfaces with orientations `positive` and Hasse diagram `parent` (seed 003
/// Thm 7.10): one per positive surface, in increasing order, with the negative surfaces whose
/// parent it is; then, if any negative surface has no parent, the unbounded atom of those.
/// Inner surfaces are in increasing order.
pub(crate) fn atoms(positive: &[bool], parent: &[Option<usize>]) -> Vec<Atom3> {
    // The atom of each positive surface, and the unbounded atom's place after them.
    let mut atom = vec![usize::MAX; positive.len()];
    let mut atoms: Vec<Atom3> = Vec::new();
    for (s, _) in positive.iter().enumerate().filter(|(_, &p)| p) {
        atom[s] = atoms.len();
        atoms.push(Atom3 {
            outer: Some(s),
            inner: Vec::new(),
        });
    }
    let unbounded = atoms.len();
    for (n, _) in positive.iter().enumerate().filter(|(_, &p)| !p) {
        let a = match parent[n] {
            Some(s) if positive[s] => atom[s],
            Some(_) => continue,
            None => unbounded,
        };
        if a == atoms.len() {
            atoms.push(Atom3 {
                outer: None,
                inner: Vec::new(),
            });
        }
        atoms[a].inner.push(n);
    }
    atoms
}

/// Six times the signed volume of each surface, Σ det[a, b, c] over its triangles (seed 003
/// Def. 7.3), decided through a floating-point filter: each sum is first taken in `f64` with a
/// bound on its error, and summed exactly only when a sign or comparison falls within that
/// bound. (The exact sums of the pieces of a meet, whose corners are constructed points with
/// large, mostly coprime denominators, grow by hundreds of bits per term: exact summation
/// dominated the exact meet.)
struct Volumes<'a, N: Num, F> {
    members: &'a [Vec<usize>],
    corners: &'a F,
    /// Per surface: the `f64` sum and a bound on its distance from the exact sum.
    approx: Vec<(f64, f64)>,
    /// Per surface: the exact sum, once needed.
    exact: Vec<OnceCell<N>>,
}

impl<'a, N: Num, F: Fn(usize) -> [&'a Point3<N>; 3]> Volumes<'a, N, F> {
    /// The filtered volumes of the surfaces `members` (triangle lists), with `rounded` the
    /// corners of a triangle rounded to the nearest `f64`s.
    fn new(
        members: &'a [Vec<usize>],
        corners: &'a F,
        rounded: impl Fn(usize) -> [[f64; 3]; 3],
    ) -> Self {
        let approx = members
            .iter()
            .map(|m| det3_sum_f64(m.iter().map(|&t| rounded(t))))
            .collect();
        Volumes {
            members,
            corners,
            approx,
            exact: members.iter().map(|_| OnceCell::new()).collect(),
        }
    }

    /// The exact six-fold volume of surface `s`.
    fn exact(&self, s: usize) -> &N {
        self.exact[s].get_or_init(|| {
            let dets = (self.members[s].iter())
                .map(|&t| {
                    let [a, b, c] = (self.corners)(t);
                    det3(a, b, c)
                })
                .collect();
            balanced_sum(dets)
        })
    }

    /// The sign of surface `s`'s volume.
    fn sign(&self, s: usize) -> Ordering {
        let (v, e) = self.approx[s];
        if v.abs() > e {
            v.partial_cmp(&0.0).expect("a finite sum")
        } else {
            self.exact(s).sign()
        }
    }

    /// |volume of k| against |volume of l|.
    fn cmp_abs(&self, k: usize, l: usize) -> Ordering {
        let ((a, ea), (b, eb)) = (self.approx[k], self.approx[l]);
        if a.abs() - ea > b.abs() + eb {
            Ordering::Greater
        } else if a.abs() + ea < b.abs() - eb {
            Ordering::Less
        } else {
            super::geom::abs(self.exact(k)).cmp(&super::geom::abs(self.exact(l)))
        }
    }

    /// The sign of the total volume.
    fn total_sign(&self) -> Ordering {
        let v: f64 = self.approx.iter().map(|a| a.0).sum();
        let k = self.approx.len() as f64;
        let e: f64 = self
            .approx
            .iter()
            .map(|a| a.1 + k * f64::EPSILON * a.0.abs())
            .sum();
        if v.is_finite() && v.abs() > 2.0 * e {
            v.partial_cmp(&0.0).expect("a finite sum")
        } else {
            (0..self.approx.len())
                .fold(N::zero(), |sum, s| sum + self.exact(s).clone())
                .sign()
        }
    }
}

/// Σ det[a, b, c] over triangles given by the nearest `f64`s of their corners, and a bound on
/// the error. Each coordinate is within a relative 2⁻⁵³ of the exact one plus an absolute
/// η = 2⁻¹⁰⁷⁴ (a tiny coordinate may round to 0), and each product within a relative 2⁻⁵³
/// plus η/2 (underflow). The relative part: per term 8 roundings of the sum of the absolute
/// products, plus one rounding per addition. The absolute part, with S = max(1, |coordinates|):
/// η·(|bc| + |ac| + |ab|) and higher orders per triple product, 4ηS² for the six, plus the
/// products' underflows (at most 3Sη + 2η), in all below 29ηS² per triangle. Each part ×2 for
/// safety. An infinite or NaN sum gets an infinite bound (nothing decided).
fn det3_sum_f64(tris: impl Iterator<Item = [[f64; 3]; 3]>) -> (f64, f64) {
    // η = 2⁻⁵³⁷ · 2⁻⁵³⁷, so that S·2⁻⁵³⁷ is exact and ηS² is one rounded product of them.
    let root_eta = 2f64.powi(-537);
    let (mut sum, mut mag, mut count, mut tiny) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for [a, b, c] in tris {
        sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
        mag += a[0].abs() * (b[1] * c[2]).abs().max((b[2] * c[1]).abs()) * 2.0
            + a[1].abs() * (b[0] * c[2]).abs().max((b[2] * c[0]).abs()) * 2.0
            + a[2].abs() * (b[0] * c[1]).abs().max((b[1] * c[0]).abs()) * 2.0;
        let s = [a, b, c]
            .iter()
            .flatten()
            .fold(1.0f64, |m, v| m.max(v.abs()))
            * root_eta;
        tiny += 64.0 * (s * s);
        count += 1.0;
    }
    let err = 2.0 * (count + 8.0) * f64::EPSILON * mag + tiny;
    if sum.is_finite() && err.is_finite() {
        (sum, err)
    } else {
        (f64::NAN, f64::INFINITY)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    /// A triangle with `f64` corners.
    type Tri = [[f64; 3]; 3];

    /// The exact value of an `f64`.
    fn exact(x: f64) -> Rational {
        Rational::from_float(x).expect("finite")
    }

    /// The exact point of `f64` coordinates.
    fn point(c: [f64; 3]) -> Point3<Rational> {
        Point3::new(exact(c[0]), exact(c[1]), exact(c[2]))
    }

    /// The triangle (x, 0, 0), (0, 1, 0), (0, 0, 1): det = x, its one nonzero product a₀b₁c₂.
    fn diagonal(x: f64) -> Tri {
        [[x, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    }

    /// What the filtered volumes of the surfaces `surfaces` decide: |volume of 0| against
    /// |volume of 1| (where there are two), and the sign of the total.
    fn decided(surfaces: &[Vec<Tri>]) -> (Option<Ordering>, Ordering) {
        let tris: Vec<Tri> = surfaces.concat();
        let points: Vec<[Point3<Rational>; 3]> = tris.iter().map(|t| t.map(point)).collect();
        let mut members = Vec::new();
        for s in surfaces {
            let first = members.iter().map(Vec::len).sum::<usize>();
            members.push((first..first + s.len()).collect::<Vec<usize>>());
        }
        let corners = |t: usize| {
            let [a, b, c] = &points[t];
            [a, b, c]
        };
        let volumes = Volumes::new(&members, &corners, |t| tris[t]);
        let cmp = (surfaces.len() > 1).then(|| volumes.cmp_abs(0, 1));
        (cmp, volumes.total_sign())
    }

    /// The bound of [`det3_sum_f64`] covers the distance of its sum from the exact Σ det when
    /// every term after the first is lost to rounding: after det = 2⁴⁰ (from the product
    /// a₁b₂c₀, or a₂b₁c₀), 400 terms 3·2⁻¹⁵ are each below half an ulp (2⁻¹³) of the sum, so
    /// the `f64` sum stays 2⁴⁰ while the exact one is 2⁴⁰ + 1200·2⁻¹⁵.
    #[test]
    fn the_det_sums_bound_covers_additions_lost_to_rounding() {
        let x = 2f64.powi(20);
        // det = −a₁(b₀c₂ − b₂c₀) = x², and det = a₂(b₀c₁ − b₁c₀) = x².
        let firsts = [
            [[0.0, 1.0, 0.0], [0.0, 0.0, x], [x, 0.0, 0.0]],
            [[0.0, 0.0, 1.0], [0.0, x, 0.0], [-x, 0.0, 0.0]],
        ];
        let small = 3.0 * 2f64.powi(-15);
        for first in firsts {
            let tris: Vec<Tri> = std::iter::once(first)
                .chain(std::iter::repeat_n(diagonal(small), 400))
                .collect();
            let (sum, err) = det3_sum_f64(tris.iter().copied());
            assert_eq!(sum, 2f64.powi(40), "{first:?}");
            let lost = exact(400.0 * small);
            assert!(lost <= exact(err), "{first:?}: bound {err:e}");
        }
    }

    /// Products that underflow do not escape the bound: the needle (2¹⁰⁰⁰, 0, 0), (0, 2⁻⁵⁷⁰, 0),
    /// (0, 0, 2⁻⁵⁷⁰) has det = 2¹⁰⁰⁰·2⁻¹¹⁴⁰ = 2⁻¹⁴⁰ by hand, while its product b₁c₂ = 2⁻¹¹⁴⁰
    /// rounds to 0 in `f64`; against a surface of 6V = −10⁻⁵⁴, the needle is the larger in
    /// |volume| and the total, 2⁻¹⁴⁰ − 10⁻⁵⁴, is positive.
    #[test]
    fn underflowing_products_stay_within_the_bound() {
        let needle = [
            [2f64.powi(1000), 0.0, 0.0],
            [0.0, 2f64.powi(-570), 0.0],
            [0.0, 0.0, 2f64.powi(-570)],
        ];
        let (sum, err) = det3_sum_f64(std::iter::once(needle));
        assert_eq!(sum, 0.0);
        assert!(exact(2f64.powi(-140)) <= exact(err), "bound {err:e}");
        let got = decided(&[vec![needle], vec![diagonal(-1e-54)]]);
        assert_eq!(got, (Some(Ordering::Greater), Ordering::Greater));
    }

    /// |volume| is compared exactly where the `f64` sums are within their bounds of each other:
    /// 6V = 1 + 2⁻²⁰ against 6V = 1, either one also holding two triangles of det ±2⁴⁰ that
    /// cancel exactly but widen its bound beyond 2⁻²⁰ (its `f64` sum is 1: 2⁻²⁰ is below half
    /// an ulp of 2⁴⁰); and 6V = 1 against 6V = 8, apart by far more than either bound.
    #[test]
    fn volumes_are_compared_exactly_within_the_bounds() {
        let big = 2f64.powi(40);
        let cancelling = |x: f64| vec![diagonal(x), diagonal(big), diagonal(-big)];
        let larger = 1.0 + 2f64.powi(-20);
        let cases = [
            (cancelling(larger), vec![diagonal(1.0)], Ordering::Greater),
            (vec![diagonal(larger)], cancelling(1.0), Ordering::Greater),
            (vec![diagonal(1.0)], cancelling(larger), Ordering::Less),
            (vec![diagonal(1.0)], vec![diagonal(8.0)], Ordering::Less),
            (vec![diagonal(-8.0)], vec![diagonal(1.0)], Ordering::Greater),
        ];
        for (k, l, expected) in cases {
            let got = decided(&[k.clone(), l.clone()]).0;
            assert_eq!(got, Some(expected), "{k:?} against {l:?}");
        }
    }

    /// The total volume's sign is the exact one where the `f64` sum errs past zero: 2⁶⁰, ten
    /// terms 100 (each below half an ulp, 128, of 2⁶⁰, so lost) and −(2⁶⁰ + 256) sum to −256 in
    /// `f64`, exactly to 1000 − 256 = 744 > 0.
    #[test]
    fn the_total_sign_is_exact_where_the_sum_errs_past_zero() {
        let p60 = 2f64.powi(60);
        let tris: Vec<Tri> = std::iter::once(diagonal(p60))
            .chain(std::iter::repeat_n(diagonal(100.0), 10))
            .chain(std::iter::once(diagonal(-(p60 + 256.0))))
            .collect();
        assert_eq!(det3_sum_f64(tris.iter().copied()).0, -256.0);
        assert_eq!(decided(&[tris]).1, Ordering::Greater);
    }

    /// Past [`MANY_SURFACES`] (parents looked up in an R-tree): a cube with 36 cubic cavities,
    /// half of them holding a cubic island, 55 surfaces. Each surface's parent is the
    /// smallest other surface whose box holds its box (axis-aligned cubes: the box is the
    /// bounded complement), found by a scan.
    #[test]
    fn parents_of_many_nested_cubes_are_the_smallest_holding_boxes() {
        use crate::yin3::shapes::{concat, cuboid};
        use crate::yin3::YinSet3;
        let p = |x: i64, y: i64, z: i64| Point3::<Rational>::int(x, y, z);
        let mut cubes = vec![cuboid(&p(0, 0, 0), &p(64, 64, 16))];
        for i in 0..6 {
            for j in 0..6 {
                let (x, y) = (8 * i + 2, 8 * j + 2);
                let mut cavity = cuboid(&p(x, y, 2), &p(x + 4, y + 4, 6));
                cavity.1.iter_mut().for_each(|f| f.reverse());
                cubes.push(cavity);
                if (i + j) % 2 == 0 {
                    cubes.push(cuboid(&p(x + 1, y + 1, 3), &p(x + 3, y + 3, 5)));
                }
            }
        }
        let (v, f) = concat(cubes);
        let set = YinSet3::from_triangles(v, f).expect("nested cubes");
        let b = set.brep().expect("bounded");
        assert_eq!(b.surfaces.len(), 55);
        assert!(b.surfaces.len() > MANY_SURFACES);
        let boxes: Vec<[[i64; 3]; 2]> = (b.surfaces.iter())
            .map(|s| {
                let corners = s.triangles.iter().flat_map(|&t| b.tris[t]);
                let c = |v: usize| [0, 1, 2].map(|k| b.points[v].coord(k).to_f64() as i64);
                corners.fold([[i64::MAX; 3], [i64::MIN; 3]], |[lo, hi], v| {
                    let q = c(v);
                    [
                        [0, 1, 2].map(|k| lo[k].min(q[k])),
                        [0, 1, 2].map(|k| hi[k].max(q[k])),
                    ]
                })
            })
            .collect();
        let holds = |k: usize, l: usize| {
            (0..3).all(|d| boxes[k][0][d] < boxes[l][0][d] && boxes[l][1][d] < boxes[k][1][d])
        };
        let size = |k: usize| {
            (0..3)
                .map(|d| boxes[k][1][d] - boxes[k][0][d])
                .product::<i64>()
        };
        for l in 0..boxes.len() {
            let expected = (0..boxes.len())
                .filter(|&k| holds(k, l))
                .min_by_key(|&k| size(k));
            assert_eq!(b.parent[l], expected, "surface {l}");
        }
    }
}
