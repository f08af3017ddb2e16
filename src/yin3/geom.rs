//! Plane keys, 2D charts of planes, and point/triangle predicates (yin3 docs: *Primitives*).

use crate::kernel::{orient, orient3d, Point, Point3};
use crate::num::{exact_orient_f64, filtered_orient_sum, Num};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// |v|.
pub(crate) fn abs<N: Num>(v: &N) -> N {
    if v.sign() == Ordering::Less {
        -v.clone()
    } else {
        v.clone()
    }
}

/// The normal (b − a) × (c − a) of the triangle `abc`.
pub(crate) fn normal<N: Num>(a: &Point3<N>, b: &Point3<N>, c: &Point3<N>) -> Point3<N> {
    b.sub(a).cross(&c.sub(a))
}

/// The magnitudes of the coordinates of the normal of the triangle `t`, computed in `f64`.
fn normal_sizes(t: [[f64; 3]; 3]) -> [f64; 3] {
    let [a, b, c] = t;
    let (u, v) = (
        [0, 1, 2].map(|k| b[k] - a[k]),
        [0, 1, 2].map(|k| c[k] - a[k]),
    );
    [0, 1, 2].map(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        (u[i] * v[j] - u[j] * v[i]).abs()
    })
}

/// True if `a`, `b`, `c` lie on one line, decided exactly: the normal (b − a) × (c − a) is
/// zero iff its three coordinates, the orientations of the three coordinate projections, are.
pub(crate) fn collinear<N: Num>(a: &Point3<N>, b: &Point3<N>, c: &Point3<N>) -> bool {
    (0..3).all(|k| projected_orient(a, b, c, k) == Ordering::Equal)
}

/// The exact orientation of the triangle `abc` projected by dropping coordinate `k`: the sign
/// of its normal's coordinate `k`.
fn projected_orient<'a, N: Num>(
    a: &'a Point3<N>,
    b: &'a Point3<N>,
    c: &'a Point3<N>,
    k: usize,
) -> Ordering {
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let pr = |p: &'a Point3<N>| [p.coord(i), p.coord(j)];
    N::orient2d(pr(a), pr(b), pr(c), &N::exact_ctx())
}

/// det[a, b, c] = a · (b × c): six times the signed volume of the tetrahedron (0, a, b, c).
pub(crate) fn det3<N: Num>(a: &Point3<N>, b: &Point3<N>, c: &Point3<N>) -> N {
    a.dot(&b.cross(c))
}

/// The index of the largest |v_k| (the first on ties).
pub(crate) fn dominant_axis<N: Num>(v: &Point3<N>) -> usize {
    let m = [abs(&v.x), abs(&v.y), abs(&v.z)];
    let mut k = 0;
    for i in 1..3 {
        if m[i] > m[k] {
            k = i;
        }
    }
    k
}

/// The oriented plane of a triangle as a canonical key: the normal scaled so that its first
/// nonzero coordinate is 1, and the offset `n · p` of the plane's points; two triangles are
/// coplanar iff their keys are equal (exact mode).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) struct PlaneKey<N> {
    /// Normal with first nonzero coordinate 1.
    pub n: [N; 3],
    /// The offset: n · p for every point p of the plane.
    pub d: N,
}

/// The canonical key of the plane of the (non-degenerate) triangle `abc`, and `true` if the
/// triangle's normal is a positive multiple of the key's normal.
pub(crate) fn plane_key<N: Num>(
    a: &Point3<N>,
    b: &Point3<N>,
    c: &Point3<N>,
) -> (PlaneKey<N>, bool) {
    let m = normal(a, b, c);
    let lead = [&m.x, &m.y, &m.z]
        .into_iter()
        .find(|v| v.sign() != Ordering::Equal)
        .expect("plane_key of a degenerate triangle")
        .clone();
    let n = [m.x / lead.clone(), m.y / lead.clone(), m.z / lead.clone()];
    let d = n[0].clone() * a.x.clone() + n[1].clone() * a.y.clone() + n[2].clone() * a.z.clone();
    (PlaneKey { n, d }, lead.sign() == Ordering::Greater)
}

/// A 2D chart of a plane: drop the coordinate where the normal is largest and keep the other
/// two in the order that maps triangles whose normal is a positive multiple of `n` to
/// counterclockwise triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Chart {
    /// The two coordinates kept, in order.
    keep: [usize; 2],
}

impl Chart {
    /// The chart of planes with normal `n` (nonzero).
    pub(crate) fn of_normal<N: Num>(n: &Point3<N>) -> Chart {
        let k = dominant_axis(n);
        Chart::of_axis(k, n.coord(k).sign())
    }

    /// The chart dropping coordinate `k`, for planes whose normal's coordinate `k` has the
    /// sign `s` (nonzero; `Equal` is taken as positive).
    pub(crate) fn of_axis(k: usize, s: Ordering) -> Chart {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        if s == Ordering::Less {
            Chart { keep: [j, i] }
        } else {
            Chart { keep: [i, j] }
        }
    }

    /// The chart of the triangle `t` of `f64` points, in which it is counterclockwise
    /// ([`Chart::of_signed_axes`], the normal's sizes computed in `f64`); `None` if the
    /// triangle is degenerate.
    pub(crate) fn of_f64_triangle(t: [[f64; 3]; 3]) -> Option<Chart> {
        let [a, b, c] = t;
        Chart::of_signed_axes(normal_sizes(t), |k| {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            exact_orient_f64([a[i], a[j]], [b[i], b[j]], [c[i], c[j]])
        })
    }

    /// The chart of a triangle in which it is counterclockwise, given estimates `size` of its
    /// normal's coordinates' magnitudes and their exact signs `sign(k)` (the orientation of
    /// its projection dropping coordinate k): the axis of the largest estimate among those
    /// whose sign is nonzero; `None` if every sign is zero (a degenerate triangle).
    fn of_signed_axes(size: [f64; 3], sign: impl Fn(usize) -> Ordering) -> Option<Chart> {
        // The first of the largest among `axes` (a later one only where strictly larger). The
        // largest of all, where its sign is nonzero, is also the largest of those signed so.
        let largest = |axes: &mut dyn Iterator<Item = usize>| {
            axes.reduce(|m, k| if size[k] > size[m] { k } else { m })
        };
        let first = largest(&mut (0..3)).expect("three axes");
        match sign(first) {
            Ordering::Equal => {
                let signs = [0, 1, 2].map(sign);
                let k = largest(&mut (0..3).filter(|&k| signs[k] != Ordering::Equal))?;
                Some(Chart::of_axis(k, signs[k]))
            }
            s => Some(Chart::of_axis(first, s)),
        }
    }

    /// The chart of the plane of the (non-degenerate) triangle `abc`, in which it is
    /// counterclockwise ([`Chart::of_signed_axes`]): the normal's sizes estimated on the
    /// points rounded to `f64`, its signs the exact orientations of the projections, so that
    /// no coordinate is constructed.
    pub(crate) fn of_triangle<N: Num>(a: &Point3<N>, b: &Point3<N>, c: &Point3<N>) -> Chart {
        // A degenerate triangle, which callers exclude, gets the chart of a zero normal.
        Chart::checked_of_triangle(a, b, c).unwrap_or(Chart::of_axis(0, Ordering::Equal))
    }

    /// [`Chart::of_triangle`], or `None` if the triangle is degenerate.
    pub(crate) fn checked_of_triangle<N: Num>(
        a: &Point3<N>,
        b: &Point3<N>,
        c: &Point3<N>,
    ) -> Option<Chart> {
        let sign = |k: usize| projected_orient(a, b, c, k);
        Chart::of_signed_axes(normal_sizes([a, b, c].map(|p| p.to_f64())), sign)
    }

    /// The coordinate the chart drops.
    pub(crate) fn dropped(&self) -> usize {
        3 - self.keep[0] - self.keep[1]
    }

    /// The image of the `f64` point `p`.
    pub(crate) fn image_f64(&self, p: [f64; 3]) -> [f64; 2] {
        self.keep.map(|k| p[k])
    }

    /// The image of `p`, as references to its coordinates.
    pub(crate) fn image_of<'a, N: Num>(&self, p: &'a Point3<N>) -> [&'a N; 2] {
        self.keep.map(|k| p.coord(k))
    }

    /// The image of `p`.
    pub(crate) fn project<N: Num>(&self, p: &Point3<N>) -> Point<N> {
        Point::new(p.coord(self.keep[0]).clone(), p.coord(self.keep[1]).clone())
    }

    /// The point of the plane `n · x = d` whose image is `q`.
    pub(crate) fn lift<N: Num>(&self, q: &Point<N>, n: &Point3<N>, d: &N) -> Point3<N> {
        let [i, j] = self.keep;
        let k = 3 - i - j;
        let mut c = [N::zero(), N::zero(), N::zero()];
        c[i] = q.x.clone();
        c[j] = q.y.clone();
        c[k] = (d.clone() - n.coord(i).clone() * q.x.clone() - n.coord(j).clone() * q.y.clone())
            / n.coord(k).clone();
        let [x, y, z] = c;
        Point3::new(x, y, z)
    }
}

/// True if `p` lies in the closed 2D triangle `abc` (counterclockwise).
pub(crate) fn in_triangle2<N: Num>(
    a: &Point<N>,
    b: &Point<N>,
    c: &Point<N>,
    p: &Point<N>,
    ctx: &N::Ctx,
) -> bool {
    orient(a, b, p, ctx) != Ordering::Less
        && orient(b, c, p, ctx) != Ordering::Less
        && orient(c, a, p, ctx) != Ordering::Less
}

/// A 2D triangle with its corners' approximations ([`Num::approx`]), the filters' input.
pub(crate) struct Triangle2<N> {
    /// The corners.
    pub corners: [Point<N>; 3],
    /// Their approximations, one `[x, y]` per corner.
    approx: [[f64; 2]; 3],
}

impl<N: Num> Triangle2<N> {
    /// The triangle with the corners `corners`.
    pub(crate) fn new(corners: [Point<N>; 3]) -> Triangle2<N> {
        let approx = corners.each_ref().map(|p| [p.x.approx(), p.y.approx()]);
        Triangle2 { corners, approx }
    }
}

/// True if the non-degenerate triangle `piece` lies in the closed counterclockwise triangle
/// `tri`, given that no side of `tri` passes through its interior (as no cut passes through a
/// piece of an arrangement): then it does iff its centroid lies inside `tri`, never on a side,
/// so that exact backends decide each side by the floating-point filter of the three corners'
/// orientations (corners on a side, whose zero no filter certifies, then cost nothing) and
/// construct the centroid only where the filter cannot tell. Float backends test every corner
/// as [`in_triangle2`].
pub(crate) fn piece_in_triangle2<N: Num>(
    tri: &Triangle2<N>,
    piece: &Triangle2<N>,
    ctx: &N::Ctx,
) -> bool {
    let [a, b, c] = &tri.corners;
    if !N::EXACT {
        return piece.corners.iter().all(|p| in_triangle2(a, b, c, p, ctx));
    }
    let centroid = OnceCell::new();
    let left = |i: usize, j: usize| {
        let side = filtered_orient_sum(tri.approx[i], tri.approx[j], piece.approx);
        side.unwrap_or_else(|| {
            let [p, q, r] = &piece.corners;
            let centroid = centroid.get_or_init(|| Point::centroid(p, q, r));
            orient(&tri.corners[i], &tri.corners[j], centroid, ctx)
        }) == Ordering::Greater
    };
    left(0, 1) && left(1, 2) && left(2, 0)
}

/// True if `p` lies in the closed triangle `abc` of space (non-degenerate).
pub(crate) fn in_triangle3<N: Num>(t: [&Point3<N>; 3], p: &Point3<N>, ctx: &N::Ctx) -> bool {
    let [a, b, c] = t;
    if orient3d(a, b, c, p, ctx) != Ordering::Equal {
        return false;
    }
    let ch = Chart::of_triangle(a, b, c);
    in_triangle2(
        &ch.project(a),
        &ch.project(b),
        &ch.project(c),
        &ch.project(p),
        ctx,
    )
}

/// The `f64` box of a set of points, widened by an ulp on each side so that it contains the
/// exact points' box whatever the arithmetic (as the 2D contact search does).
pub(crate) fn f64_box<'a, N: Num>(
    points: impl IntoIterator<Item = &'a Point3<N>>,
) -> rstar::AABB<[f64; 3]> {
    widened_box(points.into_iter().map(Point3::to_f64))
}

/// The box of points rounded to `f64` (each coordinate to the nearest), widened by an ulp on
/// each side: it contains the exact points' box, at the ends of the range too (a coordinate
/// past `f64::MAX` rounds to infinity, whose box starts at `f64::MAX`).
pub(crate) fn widened_box(rounded: impl IntoIterator<Item = [f64; 3]>) -> rstar::AABB<[f64; 3]> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for v in rounded {
        for k in 0..3 {
            lo[k] = lo[k].min(v[k]);
            hi[k] = hi[k].max(v[k]);
        }
    }
    rstar::AABB::from_corners(lo.map(f64::next_down), hi.map(f64::next_up))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use proptest::prelude::*;

    /// A coordinate: a random mantissa times a power of two, sometimes a shared value (so that
    /// coordinate planes and exact collinearity occur).
    fn coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![
            (-1000i32..1000, -60i32..60).prop_map(|(m, e)| f64::from(m) * 2f64.powi(e)),
            Just(0.0),
            Just(1.0),
        ]
    }

    /// The point (x, y) of small integers.
    fn q(x: i64, y: i64) -> Point<Rational> {
        Point::int(x, y)
    }

    /// True if the closed counterclockwise triangles `t` and `s` have disjoint interiors: a
    /// side of either has the other in its closed outer half-plane (the separating axes of
    /// two triangles).
    fn interiors_apart(t: &[Point<Rational>; 3], s: &[Point<Rational>; 3]) -> bool {
        let outside = |x: &[Point<Rational>; 3], y: &[Point<Rational>; 3]| {
            (0..3).any(|i| {
                y.iter()
                    .all(|p| orient(&x[i], &x[(i + 1) % 3], p, &()) != Ordering::Greater)
            })
        };
        outside(t, s) || outside(s, t)
    }

    /// A piece beside the triangle's corner, each side line of which has one of the piece's
    /// corners on its left (so no single corner tells): not in the triangle. Nor is a piece
    /// whose centroid lies on a side's line beyond the triangle, where the filter defers to
    /// the exact centroid. A piece in the corner is.
    #[test]
    fn a_piece_beside_a_corner_is_not_in_the_triangle() {
        let tri = Triangle2::new([q(0, 0), q(2, 0), q(0, 2)]);
        let beside = Triangle2::new([q(-2, 1), q(1, -2), q(-2, -2)]);
        assert!(!piece_in_triangle2(&tri, &beside, &()));
        let on_line = Triangle2::new([q(-3, 1), q(-3, -1), q(-6, 0)]);
        assert!(!piece_in_triangle2(&tri, &on_line, &()));
        let inside = Triangle2::new([q(0, 0), q(1, 0), q(0, 1)]);
        assert!(piece_in_triangle2(&tri, &inside, &()));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(2000)))]

        /// The chart of an `f64` triangle keeps it counterclockwise, checked on its exact
        /// values, and exists iff the triangle is not degenerate (exactly collinear corners,
        /// [`collinear`]); the third corner is sometimes on the line of the first two, or
        /// nearly so.
        #[test]
        fn f64_chart_keeps_the_triangle_counterclockwise(
            a in [coordinate(), coordinate(), coordinate()],
            b in [coordinate(), coordinate(), coordinate()],
            c in [coordinate(), coordinate(), coordinate()],
            on_line in prop_oneof![Just(None), (-4i32..8).prop_map(Some)],
            nudge in prop_oneof![Just(0.0), Just(1e-12), Just(-3e-15)],
        ) {
            // c on the line of a and b: a + 2^k (b − a) when that is exact in f64.
            let c = match on_line {
                Some(k) => [0, 1, 2].map(|i| a[i] + 2f64.powi(k) * (b[i] - a[i]) + nudge),
                None => c,
            };
            let exact = |p: [f64; 3]| {
                let r = |x: f64| Rational::from_f64(x).expect("finite");
                Point3::new(r(p[0]), r(p[1]), r(p[2]))
            };
            let (ea, eb, ec) = (exact(a), exact(b), exact(c));
            // The documented axis: the first of the largest f64 normal components (a later one
            // only where strictly larger) among the axes whose projection has a nonzero exact
            // orientation.
            let normal = |k: usize| {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                ((b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i])).abs()
            };
            let signed = (0..3).filter(|&k| {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                let p = |q: &Point3<Rational>| Point::new(q.coord(i).clone(), q.coord(j).clone());
                orient(&p(&ea), &p(&eb), &p(&ec), &()) != Ordering::Equal
            });
            let axis = signed.fold(None, |m: Option<usize>, k| match m {
                Some(m) if normal(k).partial_cmp(&normal(m)) != Some(Ordering::Greater) => Some(m),
                _ => Some(k),
            });
            match Chart::of_f64_triangle([a, b, c]) {
                None => prop_assert!(collinear(&ea, &eb, &ec)),
                Some(chart) => {
                    let (pa, pb, pc) = (chart.project(&ea), chart.project(&eb), chart.project(&ec));
                    prop_assert_eq!(orient(&pa, &pb, &pc, &()), Ordering::Greater);
                    prop_assert_eq!(Some(3 - chart.keep[0] - chart.keep[1]), axis);
                }
            }
        }
    }

    proptest! {
        // Most pairs of random triangles cross, which the premise excludes.
        #![proptest_config(ProptestConfig {
            max_global_rejects: 100_000,
            ..ProptestConfig::with_cases(yinset_testkit::cases(2000))
        })]

        /// [`piece_in_triangle2`] is the test of every corner on pieces that lie in the
        /// triangle or have no interior point in common with it (the arrangement's promise),
        /// half of them made inside from barycentric weights that are often zero (corners on
        /// sides and at corners), the others anywhere near it (touching it, beside a corner).
        #[test]
        fn a_piece_is_in_the_triangle_iff_its_corners_are(
            t in proptest::array::uniform3((-6i64..7, -6i64..7)),
            weights in proptest::array::uniform3(proptest::array::uniform3(0i64..3)),
            near in proptest::array::uniform3((-8i64..9, -8i64..9)),
            inside in any::<bool>(),
        ) {
            let mut corners = t.map(|(x, y)| q(x, y));
            let turn = orient(&corners[0], &corners[1], &corners[2], &());
            prop_assume!(turn != Ordering::Equal);
            if turn == Ordering::Less {
                corners.swap(1, 2);
            }
            prop_assume!(!inside || weights.iter().all(|w| w.iter().sum::<i64>() > 0));
            let mut piece: [Point<Rational>; 3] = match inside {
                true => weights.map(|w| {
                    let total = Rational::from_i64(w.iter().sum::<i64>());
                    let mean = |k: fn(&Point<Rational>) -> &Rational| {
                        (0..3).fold(Rational::from_i64(0), |s, i| {
                            s + k(&corners[i]).clone() * Rational::from_i64(w[i])
                        }) / total.clone()
                    };
                    Point::new(mean(|p| &p.x), mean(|p| &p.y))
                }),
                false => near.map(|(x, y)| q(x, y)),
            };
            match orient(&piece[0], &piece[1], &piece[2], &()) {
                Ordering::Equal => prop_assume!(false),
                Ordering::Less => piece.swap(1, 2),
                Ordering::Greater => {}
            }
            let [a, b, c] = &corners;
            let by_corners = piece.iter().all(|p| in_triangle2(a, b, c, p, &()));
            prop_assume!(by_corners || interiors_apart(&corners, &piece));
            let (tri, image) = (Triangle2::new(corners.clone()), Triangle2::new(piece));
            prop_assert_eq!(piece_in_triangle2(&tri, &image, &()), by_corners);
        }
    }
}
