//! Float mode's boundary band of 3D `locate`: whether a point's Euclidean distance to a closed
//! triangle is at most ε, decided exactly on the rationals the coordinates and ε are, after an
//! interval filter that settles all but near ties.

use crate::kernel::Point3;
use crate::num::{Interval, Num, Rational};
use std::cmp::Ordering;
use std::ops::{Add, Mul, Sub};

/// The numbers the distance test is written over: intervals (a filter, which may leave a sign
/// undecided) and rationals (exact, always decided).
trait Field: Clone + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> {
    /// A coordinate's value (an interval enclosing it, or exactly).
    fn of<N: Num>(v: &N) -> Self;
    /// The value of the finite `f64` ε.
    fn of_f64(v: f64) -> Self;
    /// The sign, where it is certain.
    fn sign(&self) -> Option<Ordering>;
}

impl Field for Interval {
    fn of<N: Num>(v: &N) -> Interval {
        Interval::around(v.approx())
    }
    fn of_f64(v: f64) -> Interval {
        Interval::around(v)
    }
    fn sign(&self) -> Option<Ordering> {
        Interval::sign(*self)
    }
}

impl Field for Rational {
    fn of<N: Num>(v: &N) -> Rational {
        let (n, d) = v.fraction();
        Rational::new(n, d)
    }
    fn of_f64(v: f64) -> Rational {
        Rational::from_float(v).expect("ε is finite")
    }
    fn sign(&self) -> Option<Ordering> {
        Some(Num::sign(self))
    }
}

/// True if the Euclidean distance from `q` to the closed triangle `t` is at most `eps`
/// (finite, ≥ 0), decided exactly: in intervals where they settle it, else in rationals.
pub(crate) fn within<N: Num>(t: [&Point3<N>; 3], q: &Point3<N>, eps: f64) -> bool {
    within_in::<Interval, N>(t, q, eps)
        .or_else(|| within_in::<Rational, N>(t, q, eps))
        .expect("rationals decide every sign")
}

/// [`within`] in the numbers `F`, `None` where a sign it needs is uncertain in them. The
/// distance is at most ε iff q is within ε of one of the three closed edges, or q projects into
/// the triangle and is within ε of its plane; squared distances are compared with ε².
fn within_in<F: Field, N: Num>(t: [&Point3<N>; 3], q: &Point3<N>, eps: f64) -> Option<bool> {
    let p = |p: &Point3<N>| p.coords().map(|v| F::of(v));
    let (t, q) = (t.map(p), p(q));
    let e2 = F::of_f64(eps) * F::of_f64(eps);
    let edges = [(0, 1), (1, 2), (2, 0)];
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    let near_edge = edges
        .iter()
        .map(|&(u, v)| near_segment(&t[u], &t[v], &q, &e2));
    let near_face = || {
        let inside = edges.iter().map(|&(u, v)| {
            let outward = cross(&sub(&t[v], &t[u]), &n);
            at_most(&dot(&outward, &sub(&q, &t[u])), &F::of_f64(0.0))
        });
        let h = dot(&n, &sub(&q, &t[0]));
        let nn = dot(&n, &n);
        all([
            Some(nn.sign()? == Ordering::Greater),
            all(inside),
            at_most(&(h.clone() * h), &(e2.clone() * nn)),
        ])
    };
    any(near_edge.chain(std::iter::once_with(near_face)))
}

/// True if `q` is within distance √`e2` of the closed segment `uv`: of one of its ends, or of
/// its line where q projects strictly between the ends (|(q − u) × d|² ≤ ε²|d|², d = v − u).
fn near_segment<F: Field>(u: &[F; 3], v: &[F; 3], q: &[F; 3], e2: &F) -> Option<bool> {
    let (d, e) = (sub(v, u), sub(q, u));
    let between = || {
        let (along, dd) = (dot(&e, &d), dot(&d, &d));
        all([
            Some(along.sign()? == Ordering::Greater),
            Some((dd.clone() - along).sign()? == Ordering::Greater),
            at_most(&norm2(&cross(&e, &d)), &(e2.clone() * dd)),
        ])
    };
    any([
        at_most(&norm2(&e), e2),
        at_most(&norm2(&sub(q, v)), e2),
        between(),
    ])
}

/// Kleene's or: true if a term is true, false if all are false, `None` otherwise (terms after a
/// true one are not evaluated).
fn any(terms: impl IntoIterator<Item = Option<bool>>) -> Option<bool> {
    let mut known = true;
    for t in terms {
        match t {
            Some(true) => return Some(true),
            Some(false) => {}
            None => known = false,
        }
    }
    known.then_some(false)
}

/// Kleene's and: false if a term is false, true if all are true, `None` otherwise.
fn all(terms: impl IntoIterator<Item = Option<bool>>) -> Option<bool> {
    any(terms.into_iter().map(|t| t.map(|b| !b))).map(|b| !b)
}

/// a ≤ b, where certain.
fn at_most<F: Field>(a: &F, b: &F) -> Option<bool> {
    Some((b.clone() - a.clone()).sign()? != Ordering::Less)
}

/// a − b.
fn sub<F: Field>(a: &[F; 3], b: &[F; 3]) -> [F; 3] {
    [0, 1, 2].map(|k| a[k].clone() - b[k].clone())
}

/// a × b.
fn cross<F: Field>(a: &[F; 3], b: &[F; 3]) -> [F; 3] {
    [0, 1, 2].map(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        a[i].clone() * b[j].clone() - a[j].clone() * b[i].clone()
    })
}

/// a · b.
fn dot<F: Field>(a: &[F; 3], b: &[F; 3]) -> F {
    let [x, y, z] = [0, 1, 2].map(|k| a[k].clone() * b[k].clone());
    x + y + z
}

/// |a|².
fn norm2<F: Field>(a: &[F; 3]) -> F {
    dot(a, a)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Float;
    use proptest::prelude::*;

    /// The part of a triangle nearest to a point.
    #[derive(Clone, Copy, Debug, PartialEq)]
    enum Feature {
        Corner,
        Edge,
        Face,
    }

    /// The oracle: the squared distance from `p` to the triangle `abc` and the feature where it
    /// is attained, by the Voronoi regions of the triangle's corners, edges and face (Ericson,
    /// *Real-Time Collision Detection* §5.1.5), in rationals — another method than [`within`]'s.
    fn nearest(t: [[f64; 3]; 3], p: [f64; 3]) -> (Rational, Feature) {
        let r = |v: [f64; 3]| v.map(|x| Rational::from_float(x).unwrap());
        let ([a, b, c], p) = (t.map(r), r(p));
        let dist = |x: [Rational; 3]| norm2(&sub(&p, &x));
        let at = |o: &[Rational; 3], d: &[Rational; 3], s: Rational| {
            [0, 1, 2].map(|k| o[k].clone() + d[k].clone() * s.clone())
        };
        let zero = Rational::from_i64(0);
        let (ab, ac, ap) = (sub(&b, &a), sub(&c, &a), sub(&p, &a));
        let (d1, d2) = (dot(&ab, &ap), dot(&ac, &ap));
        if d1 <= zero && d2 <= zero {
            return (dist(a), Feature::Corner);
        }
        let bp = sub(&p, &b);
        let (d3, d4) = (dot(&ab, &bp), dot(&ac, &bp));
        if d3 >= zero && d4 <= d3 {
            return (dist(b), Feature::Corner);
        }
        let vc = d1.clone() * d4.clone() - d3.clone() * d2.clone();
        if vc <= zero && d1 >= zero && d3 <= zero {
            let v = d1.clone() / (d1.clone() - d3.clone());
            return (dist(at(&a, &ab, v)), Feature::Edge);
        }
        let cp = sub(&p, &c);
        let (d5, d6) = (dot(&ab, &cp), dot(&ac, &cp));
        if d6 >= zero && d5 <= d6 {
            return (dist(c), Feature::Corner);
        }
        let vb = d5.clone() * d2.clone() - d1.clone() * d6.clone();
        if vb <= zero && d2 >= zero && d6 <= zero {
            let w = d2.clone() / (d2.clone() - d6.clone());
            return (dist(at(&a, &ac, w)), Feature::Edge);
        }
        let va = d3.clone() * d6.clone() - d5.clone() * d4.clone();
        let (e, f) = (d4 - d3, d5 - d6);
        if va <= zero && e >= zero && f >= zero {
            let w = e.clone() / (e + f);
            return (dist(at(&b, &sub(&c, &b), w)), Feature::Edge);
        }
        let s = va + vb.clone() + vc.clone();
        let (v, w) = (vb / s.clone(), vc / s);
        (dist(at(&at(&a, &ab, v), &ac, w)), Feature::Face)
    }

    /// A point of `f64`s as the kernel's.
    fn point(v: [f64; 3]) -> Point3<Float> {
        let [x, y, z] = v.map(Float::new);
        Point3::new(x, y, z)
    }

    /// [`within`] on `f64` corners, checking that the interval filter, where it decides, agrees
    /// with the rationals.
    fn within_f64(t: [[f64; 3]; 3], q: [f64; 3], eps: f64) -> bool {
        let (t, q) = (t.map(point), point(q));
        let t = [&t[0], &t[1], &t[2]];
        let exact = within_in::<Rational, Float>(t, &q, eps).unwrap();
        if let Some(filtered) = within_in::<Interval, Float>(t, &q, eps) {
            assert_eq!(filtered, exact, "the interval filter at ε = {eps}");
        }
        assert_eq!(within(t, &q, eps), exact);
        exact
    }

    /// The f64 operations of the generators.
    fn add(a: [f64; 3], b: [f64; 3], s: f64) -> [f64; 3] {
        [0, 1, 2].map(|k| a[k] + s * b[k])
    }
    fn cross_f64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }
    fn unit(a: [f64; 3]) -> [f64; 3] {
        let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|x| x / n)
    }
    fn diff(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [0, 1, 2].map(|k| a[k] - b[k])
    }

    /// A triangle of integer corners moved by up to 2²⁰ and scaled by 2^scale (so that it may
    /// lie far from the origin relative to its size), with an angle of at least about 10° at
    /// each corner (so that the generated points' regions are clear).
    fn triangle() -> impl Strategy<Value = [[f64; 3]; 3]> {
        let corner = proptest::array::uniform3(-20i32..=20);
        let shift = -(1i32 << 20)..(1 << 20);
        (proptest::array::uniform3(corner), -30i32..30, shift)
            .prop_map(|(c, scale, shift)| {
                c.map(|p| p.map(|x| f64::from(x + shift) * 2f64.powi(scale)))
            })
            .prop_filter("an angle of at least 10°", |t| {
                (0..3).all(|k| {
                    let (u, v) = (diff(t[(k + 1) % 3], t[k]), diff(t[(k + 2) % 3], t[k]));
                    let n = cross_f64(u, v);
                    let sin = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
                        / ((u.iter().map(|x| x * x).sum::<f64>()
                            * v.iter().map(|x| x * x).sum::<f64>())
                        .sqrt());
                    sin > 0.17
                })
            })
    }

    /// A point off the triangle `t` in the region of the `feature` asked for: `s`, `along` and
    /// `lift` place it (parameters along the feature, and a distance out of it relative to the
    /// triangle's size).
    fn off(t: [[f64; 3]; 3], feature: Feature, k: usize, s: [f64; 2], lift: [f64; 2]) -> [f64; 3] {
        let (a, b, c) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
        let (ab, ac) = (diff(b, a), diff(c, a));
        let n = unit(cross_f64(ab, ac));
        let size = ab.iter().chain(&ac).fold(0.0f64, |m, x| m.max(x.abs()));
        match feature {
            Feature::Face => {
                let (u, v) = (0.1 + 0.35 * s[0], 0.1 + 0.35 * s[1]);
                add(add(add(a, ab, u), ac, v), n, size * (lift[0] - 0.5))
            }
            Feature::Edge => {
                let foot = add(a, ab, 0.1 + 0.8 * s[0]);
                let out = unit(cross_f64(ab, n));
                add(
                    add(foot, out, size * (0.05 + lift[0])),
                    n,
                    size * (lift[1] - 0.5),
                )
            }
            Feature::Corner => {
                let away = unit(add(unit(ab), unit(ac), 1.0));
                let side = unit(diff(unit(ab), unit(ac)));
                let dir = add(add(away, side, 0.3 * (s[0] - 0.5)), n, s[1] - 0.5);
                add(a, dir, -size * (0.05 + lift[0]))
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(600)))]

        /// Points near a face, an edge or a corner of a random triangle (the oracle confirms
        /// which), at every scale and far from the origin: [`within`] agrees with the exact
        /// squared distance of the oracle at ε just below, at and just above the distance —
        /// the points just outside and just inside the ε-ball.
        #[test]
        fn the_band_is_the_euclidean_distance(
            t in triangle(),
            feature in prop_oneof![Just(Feature::Face), Just(Feature::Edge), Just(Feature::Corner)],
            k in 0usize..3,
            s in proptest::array::uniform2(0.0f64..1.0),
            lift in proptest::array::uniform2(0.0f64..1.0),
        ) {
            let q = off(t, feature, k, s, lift);
            let (d2, found) = nearest(t, q);
            prop_assert_eq!(found, feature, "the generator's point {:?}", q);
            prop_assume!(d2 > Rational::from_i64(0));
            let d = d2.to_f64().sqrt();
            let two_ulps = |e: f64, up: bool| match up {
                true => e.next_up().next_up(),
                false => e.next_down().next_down(),
            };
            let (below, above) = (two_ulps(d, false), two_ulps(d, true));
            prop_assert!(!within_f64(t, q, below), "ε = {below} below the distance {d}");
            prop_assert!(within_f64(t, q, above), "ε = {above} above the distance {d}");
            let e = Rational::from_float(d).unwrap();
            prop_assert_eq!(within_f64(t, q, d), e.clone() * e >= d2);
        }
    }

    /// The corner of the issue: (2.45, 2.45, 2.45) is 0.45·√3 ≈ 0.779 from the corner (2, 2, 2)
    /// of the face x = 2 of [0, 2]³, though within 0.5 of it in each coordinate.
    #[test]
    fn a_point_off_a_corner_is_as_far_as_its_euclidean_distance() {
        let t = [[2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [2.0, 2.0, 2.0]];
        let q = [2.45; 3];
        assert!(!within_f64(t, q, 0.5));
        assert!(!within_f64(t, q, 0.779));
        assert!(within_f64(t, q, 0.78));
        // 0.45² · 3 = 0.6075 exactly in rationals; q's f64 value is a little off 2.45.
        let (d2, found) = nearest(t, q);
        assert_eq!(found, Feature::Corner);
        assert!((d2.to_f64() - 0.6075).abs() < 1e-12);
    }

    /// Exactly at distance ε (a 3-4-5 triangle of distances): on the band's edge, inside it.
    #[test]
    fn a_point_exactly_eps_away_is_within() {
        let t = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]];
        // From the face: straight above an interior point.
        assert!(within_f64(t, [1.0, 1.0, 5.0], 5.0));
        assert!(!within_f64(t, [1.0, 1.0, 5.0], 5f64.next_down()));
        // From the edge y = 0: 3 below it in y and 4 above in z.
        assert!(within_f64(t, [2.0, -3.0, 4.0], 5.0));
        assert!(!within_f64(t, [2.0, -3.0, 4.0], 5f64.next_down()));
        // From the corner (4, 0, 0).
        assert!(within_f64(t, [7.0, -4.0, 0.0], 5.0));
        assert!(!within_f64(t, [7.0, -4.0, 0.0], 5f64.next_down()));
    }
}
