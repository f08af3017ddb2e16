//! The exact meet by the construction-light meet of [`super::transversal`] (yin3 docs:
//! *Meet*). Where every coordinate of both operands, times one positive integer L (the lcm of
//! their denominators: decimal input of a few places, lattices), is an integer below 2⁵³ in
//! magnitude, the scaled operands are float sets with the same predicates, met on `f64`
//! filters and stack integers; the meet's vertices divided by L are the exact meet's. Other
//! operands are met on their rationals. Operands that meet otherwise (a coplanar overlap, an
//! edge in the other's plane, a vertex on an edge) take the general arrangement.

use super::error::Yin3Error;
use super::set::{compact, Brep, YinSet3};
use super::transversal::{transversal_meet, Transversal};
use crate::kernel::Point3;
use crate::num::{common_denominator, Float, Num, Rational};

/// Magnitudes below this are integers that an `f64` holds exactly.
const EXACT_INTEGERS: i64 = 1 << 53;

/// The least positive L such that every coordinate of `points` times L is an integer, if each
/// of those integers lies below 2⁵³ in magnitude.
fn common_grid<'a, N: Num + 'a>(
    points: impl Iterator<Item = &'a Point3<N>> + Clone,
) -> Option<i64> {
    common_denominator(points.flat_map(|p| [&p.x, &p.y, &p.z]), EXACT_INTEGERS)
}

/// The point `p` times `l`, a float point (every coordinate of `p` times `l` an integer below
/// 2⁵³).
fn scale<N: Num>(p: &Point3<N>, l: i64) -> Point3<Float> {
    let times_l = |v: &N| {
        let (n, d) = v.small_fraction().expect("a coordinate on the common grid");
        Float::new((n * (l / d)) as f64)
    };
    Point3::new(times_l(&p.x), times_l(&p.y), times_l(&p.z))
}

/// The points scaled to their common integer grid (module docs), as float points with the
/// same orientations; `None` if they are on no such grid.
pub(crate) fn on_grid<N: Num>(points: &[Point3<N>]) -> Option<Vec<Point3<Float>>> {
    let l = common_grid(points.iter())?;
    Some(points.iter().map(|p| scale(p, l)).collect())
}

/// The exact meet of the sets `x` and `y` with the boundaries `a` and `b` by the transversal
/// meet, under the context `ctx`: of the operands scaled to a common integer grid where they
/// are on one (module docs), else of the operands themselves; `None` where they meet
/// degenerately.
pub(crate) fn exact_transversal_meet<N: Num>(
    [x, y]: [&YinSet3<N>; 2],
    [a, b]: [&Brep<N>; 2],
    ctx: N::Ctx,
) -> Option<Result<YinSet3<N>, Yin3Error>> {
    debug_assert!(N::EXACT, "float sets take the transversal meet directly");
    let Some(l) = common_grid(a.points.iter().chain(&b.points)) else {
        let meet = transversal_meet(a, b)?;
        return Some(assembled(meet, [x, y], [a, b], ctx, N::nearest));
    };
    let scaled = |b: &Brep<N>| b.clone().map_points(|p| scale(p, l));
    let (fa, fb) = (scaled(a), scaled(b));
    let meet = transversal_meet(&fa, &fb)?;
    let l = Rational::from_i64(l);
    let unscale = |v: &Rational| N::nearest(&(v.clone() / l.clone()));
    Some(assembled(meet, [x, y], [&fa, &fb], ctx, unscale))
}

/// The set of the transversal meet `meet` of the sets `x` and `y`, found on the boundaries
/// `a` and `b` (theirs, or their images on a grid), each coordinate of its vertices mapped back
/// by `back`, under the context `ctx`.
fn assembled<N: Num, M: Num>(
    meet: Transversal,
    [x, y]: [&YinSet3<N>; 2],
    [a, b]: [&Brep<M>; 2],
    ctx: N::Ctx,
    back: impl Fn(&Rational) -> N,
) -> Result<YinSet3<N>, Yin3Error> {
    if let Transversal::Operand(o) = meet {
        return Ok([x, y][o].clone().with_ctx(ctx));
    }
    let (points, kept) = meet.complex(a, b);
    if kept.is_empty() {
        return Ok(YinSet3::empty().with_ctx(ctx));
    }
    let (points, kept) = compact(points, kept);
    let points = (points.iter())
        .map(|p| Point3::new(back(&p.x), back(&p.y), back(&p.z)))
        .collect();
    Brep::assemble(points, kept)
        .map(|brep| YinSet3::from_brep(brep, ctx))
        .map_err(|e| Yin3Error::Internal(format!("the transversal meet is not a Yin set: {e}")))
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::kernel::orient3d;
    use crate::yin3::meet::constructed_meet;
    use num_bigint::BigInt;
    use rand::{RngExt, SeedableRng};
    use std::cmp::Ordering;

    /// The point (x, y, z) / d.
    pub(in crate::yin3) fn point(x: i64, y: i64, z: i64, d: i64) -> Point3<Rational> {
        let q = |n: i64| Rational::new(BigInt::from(n), BigInt::from(d));
        Point3::new(q(x), q(y), q(z))
    }

    #[test]
    fn common_grid_by_hand() {
        let grid = |p: &[Point3<Rational>]| common_grid(p.iter());
        // Tenths, halves and fifths share the grid of tenths.
        let decimals = [point(1, 2, 3, 10), point(5, 5, 5, 10), point(2, 4, 6, 10)];
        assert_eq!(grid(&decimals), Some(10));
        assert_eq!(grid(&[point(1, 1, 1, 3), point(1, 0, 0, 4)]), Some(12));
        // 2⁵³ − 1 is the largest integer in range, 2⁵³ is not.
        let top = (1i64 << 53) - 1;
        assert_eq!(grid(&[point(top, 0, -top, 1)]), Some(1));
        assert_eq!(grid(&[point(top + 1, 0, 0, 1)]), None);
        // In range alone, out of range on the common grid: 2⁵² on the grid of halves.
        assert_eq!(grid(&[point(1 << 52, 0, 0, 1), point(1, 0, 0, 2)]), None);
        // Denominators whose lcm passes 2⁵³.
        let primes = [1_000_003, 1_000_033, 1_000_037];
        assert_eq!(grid(&primes.map(|p| point(1, 1, 1, p))), None);
    }

    /// A tetrahedron with corners on the grid of tenths in [0, 2]³, faces outward; `None` if
    /// flat.
    pub(in crate::yin3) fn tetrahedron(rng: &mut rand::rngs::StdRng) -> Option<YinSet3<Rational>> {
        tetrahedron_over(rng, &[10])
    }

    /// A tetrahedron in [0, 2]³ with each corner on the grid of 1/d for a d of `ds`, faces
    /// outward; `None` if flat.
    pub(in crate::yin3) fn tetrahedron_over(
        rng: &mut rand::rngs::StdRng,
        ds: &[i64],
    ) -> Option<YinSet3<Rational>> {
        let mut corner = || {
            let d = ds[rng.random_range(0..ds.len())];
            let mut c = || rng.random_range(0..=2 * d);
            point(c(), c(), c(), d)
        };
        let v: Vec<Point3<Rational>> = (0..4).map(|_| corner()).collect();
        let faces = match orient3d(&v[0], &v[1], &v[2], &v[3], &()) {
            Ordering::Greater => [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
            Ordering::Less => [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]],
            Ordering::Equal => return None,
        };
        YinSet3::from_triangles(v, faces.map(|f| f.to_vec()).to_vec()).ok()
    }

    /// Tetrahedra on the grid of tenths, or over denominators of about 40 bits (no common grid
    /// below 2⁵³: met on their rationals), against each other, against the cube [1/2, 3/2]³
    /// and against their complements: wherever the transversal meet is taken it equals the
    /// general arrangement's meet, and it is taken in most cases, the complements' too.
    #[test]
    fn exact_transversal_meets_are_the_general_meets() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let cube = YinSet3::cuboid(&point(5, 5, 5, 10), &point(15, 15, 15, 10)).expect("a cube");
        // Cases and meets taken, on the grid and off it.
        let (mut taken, mut cases) = ([0; 2], [0; 2]);
        let wide: &[i64] = &[1_099_511_627_791, 1_099_511_627_689];
        for round in 0..600 {
            let ds = [&[10], wide][round % 2];
            let (Some(t), Some(s)) = (tetrahedron_over(&mut rng, ds), tetrahedron(&mut rng)) else {
                continue;
            };
            for (x, y) in [(&t, s.clone()), (&t, s.complement()), (&cube, s.clone())] {
                let (a, b) = (x.brep().expect("bounded"), y.brep().expect("a boundary"));
                let off = usize::from(common_grid(a.points.iter().chain(&b.points)).is_none());
                cases[off] += 1;
                if let Some(meet) = exact_transversal_meet([x, &y], [a, b], ()) {
                    assert_eq!(meet.expect("an exact meet"), constructed_meet(x, &y));
                    taken[off] += 1;
                }
            }
        }
        for off in 0..2 {
            assert!(
                taken[off] * 10 >= cases[off] * 6 && cases[off] >= 300,
                "taken in {taken:?} of {cases:?}"
            );
        }
    }

    /// Operands sharing a face take the general arrangement, on a grid or off every grid of
    /// integers below 2⁵³; operands off every grid that meet generically are met on their
    /// rationals.
    #[test]
    fn degenerate_operands_are_declined() {
        let unit =
            |x: i64| YinSet3::cuboid(&point(x, 0, 0, 1), &point(x + 1, 1, 1, 1)).expect("a cube");
        let (a, b) = (unit(0), unit(1));
        let breps = [a.brep().expect("a cube"), b.brep().expect("a cube")];
        assert!(exact_transversal_meet([&a, &b], breps, ()).is_none());
        let tiny = Rational::new(BigInt::from(1), BigInt::from(1u64 << 60));
        let far = YinSet3::cuboid(
            &Point3::new(tiny.clone(), tiny.clone(), tiny),
            &point(1, 1, 1, 2),
        )
        .expect("a box");
        let breps = [a.brep().expect("a cube"), far.brep().expect("a box")];
        assert_eq!(common_grid(breps.iter().flat_map(|b| &b.points)), None);
        let meet = exact_transversal_meet([&a, &far], breps, ()).expect("no degenerate contact");
        assert_eq!(meet.expect("an exact meet"), constructed_meet(&a, &far));
        // Off every grid too: boxes with sides 1/p, 1/q, 1/7 (p, q about 2⁴⁰) sharing a face.
        let (p, q) = (1_099_511_627_791, 1_099_511_627_689);
        let at = |x: i64| {
            Point3::new(
                point(x, 0, 0, p).x,
                point(0, 1, 0, q).y,
                point(0, 0, 1, 7).z,
            )
        };
        let origin = Point3::int(0, 0, 0);
        let left = YinSet3::cuboid(&origin, &at(1)).expect("a box");
        let right = YinSet3::cuboid(
            &Point3::new(point(1, 0, 0, p).x, origin.y.clone(), origin.z.clone()),
            &at(2),
        )
        .expect("a box");
        let breps = [left.brep().expect("a box"), right.brep().expect("a box")];
        assert_eq!(common_grid(breps.iter().flat_map(|b| &b.points)), None);
        assert!(exact_transversal_meet([&left, &right], breps, ()).is_none());
        assert!(left.meet(&right).is_empty());
    }
}
