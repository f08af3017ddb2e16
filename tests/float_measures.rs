//! Float-mode areas and volumes against exact mode on the same `f64` values, at every offset
//! and scale: a float set is the exact set of its `f64` vertices, so its `area_exact` /
//! `volume_exact` must equal the area / volume that exact mode computes from the same values
//! read as rationals (an independent code path: rational arithmetic, no power-of-two grid),
//! and its `area` / `volume` must be the nearest `f64` of that value — never a cancelled, NaN
//! or spurious value, whatever the offset (10⁰…10¹⁵ times the shape's size) and the scale
//! (10⁻³⁰⁰…10³⁰⁰).

use proptest::prelude::*;
use yinset::kernel::{Point, Point3};
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::YinSet2;
use yinset::yin3::shapes::cuboid;
use yinset::yin3::YinSet3;

/// The `f64` of (`v` + `offset`) · `scale`: the offset is exact (integers below 2⁵³), the
/// product is rounded once; both modes read the same result.
fn place(v: i64, offset: f64, scale: f64) -> f64 {
    (v as f64 + offset) * scale
}

/// A counterclockwise triangle (0, 0), (4a, 2t), (0, 4b) with t < b, alone or with the
/// clockwise triangular hole (a, b + t), (a, 2b), (2a, b + t), which lies strictly inside it.
fn rings() -> impl Strategy<Value = Vec<Vec<(i64, i64)>>> {
    (1i64..1000, 1i64..1000, 0i64..1000, any::<bool>()).prop_map(|(a, b, t, hole)| {
        let t = t % b;
        let outer = vec![(0, 0), (4 * a, 2 * t), (0, 4 * b)];
        let inner = vec![(a, b + t), (a, 2 * b), (2 * a, b + t)];
        match hole {
            true => vec![outer, inner],
            false => vec![outer],
        }
    })
}

/// Offsets 10⁰…10¹⁵ (in units of the shape's lattice) and scales 10⁻³⁰⁰…10³⁰⁰, each sign (a
/// negative scale turns the plane by a half turn, which keeps orientations).
fn placement() -> impl Strategy<Value = (f64, f64)> {
    (0i32..=15, -300i32..=300, any::<bool>(), any::<bool>()).prop_map(|(o, s, neg_o, neg_s)| {
        let offset = 10f64.powi(o) * if neg_o { -1.0 } else { 1.0 };
        let scale = format!("1e{s}").parse::<f64>().unwrap() * if neg_s { -1.0 } else { 1.0 };
        (offset, scale)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(400)))]

    /// 2D: the float set's exact area is exact mode's area of its own `f64` vertices, and its
    /// area is the nearest `f64` of that.
    #[test]
    fn float_area_is_the_exact_area_of_its_vertices(curves in rings(), (offset, scale) in placement()) {
        let p = |&(x, y): &(i64, i64)| {
            Point::new(Float::new(place(x, offset, scale)), Float::new(place(y, offset, scale)))
        };
        let float = YinSet2::from_curves_with(curves.iter().map(|c| c.iter().map(p).collect()).collect(), Tolerance::default());
        // Rounding to the grid may collapse a ring far from the origin: nothing to measure.
        prop_assume!(float.is_ok());
        let float = float.unwrap();
        let exact = float.to_exact().expect("a float set's values bound an exact set");
        let area = exact.area().expect("bounded");
        prop_assert!(area.sign() == std::cmp::Ordering::Greater);
        prop_assert_eq!(float.area_exact(), Some(area.clone()));
        prop_assert_eq!(float.area().map(Float::get), Some(area.to_f64()));
    }

    /// 3D: a box at any offset and scale; the float set's exact volume is exact mode's volume
    /// of the same `f64` corners, and its volume the nearest `f64` of that.
    #[test]
    fn float_volume_is_the_exact_volume_of_its_vertices(
        size in [1i64..1000, 1i64..1000, 1i64..1000], (offset, scale) in placement(),
    ) {
        let lo = [0i64; 3].map(|v| place(v, offset, scale));
        let hi = size.map(|v| place(v, offset, scale));
        let (lo, hi) = ([0, 1, 2].map(|k| lo[k].min(hi[k])), [0, 1, 2].map(|k| lo[k].max(hi[k])));
        prop_assume!((0..3).all(|k| lo[k] < hi[k]));
        let f = |v: [f64; 3]| Point3::new(Float::new(v[0]), Float::new(v[1]), Float::new(v[2]));
        let (corners, faces) = cuboid(&f(lo), &f(hi));
        let float = YinSet3::from_triangles_with(corners, faces.clone(), Tolerance::default())
            .expect("a box is a valid set at any magnitude");
        let r = |v: f64| Rational::from_float(v).unwrap();
        let e = |v: [f64; 3]| Point3::new(r(v[0]), r(v[1]), r(v[2]));
        let (corners, faces) = cuboid(&e(lo), &e(hi));
        let exact = YinSet3::from_triangles(corners, faces).unwrap().volume().unwrap();
        let side = |k: usize| r(hi[k]) - r(lo[k]);
        prop_assert_eq!(&exact, &(side(0) * side(1) * side(2)));
        prop_assert_eq!(float.volume_exact(), Some(exact.clone()));
        prop_assert_eq!(float.volume().map(Float::get), Some(exact.to_f64()));
    }
}

/// The cases that were wrong: a cube of side 2 at 10⁹ and of side 64 at 10¹⁵ (volumes 0 and
/// −9·10¹⁵ before), one at 3·10¹⁰; [10³⁰⁰, 3·10³⁰⁰]³ (NaN before: its volume is beyond `f64`);
/// and the square [0, 10³⁰⁰]² (area beyond `f64`: infinite as an `f64`, exact as a rational)
/// and one of side 10⁻³⁰⁰ (area below `f64`: 0 as an `f64`, positive as a rational).
#[test]
fn float_measures_far_out_huge_and_tiny() {
    let cube = |lo: f64, side: f64| {
        let f = |v: f64| Point3::new(Float::new(v), Float::new(v), Float::new(v));
        let (corners, faces) = cuboid(&f(lo), &f(lo + side));
        YinSet3::from_triangles_with(corners, faces, Tolerance::new(1.0)).unwrap()
    };
    for (lo, side) in [(1e9, 2.0), (3e10, 2.0), (1e15, 64.0)] {
        let v = cube(lo, side);
        assert_eq!(v.volume(), Some(Float::new(side * side * side)), "at {lo}");
        assert_eq!(
            v.volume_exact(),
            Some(Rational::from_float(side.powi(3)).unwrap())
        );
    }
    let huge = {
        let f = |v: f64| Point3::new(Float::new(v), Float::new(v), Float::new(v));
        let (corners, faces) = cuboid(&f(1e300), &f(3e300));
        YinSet3::from_triangles_with(corners, faces, Tolerance::default()).unwrap()
    };
    let side = Rational::from_float(3e300).unwrap() - Rational::from_float(1e300).unwrap();
    assert_eq!(
        huge.volume_exact(),
        Some(side.clone() * side.clone() * side)
    );
    assert_eq!(huge.volume(), Some(Float::new(f64::INFINITY)));
    let square = |s: f64| {
        let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
        let ring = vec![p(0.0, 0.0), p(s, 0.0), p(s, s), p(0.0, s)];
        YinSet2::from_curves_with(vec![ring], Tolerance::default()).unwrap()
    };
    // Float mode snaps the corners to its grid: the area is that of the snapped square.
    for s in [1e300, 1e-300] {
        let set = square(s);
        let exact = set.to_exact().unwrap().area().unwrap();
        assert!(exact.sign() == std::cmp::Ordering::Greater, "side {s}");
        assert_eq!(set.area_exact(), Some(exact), "side {s}");
    }
    assert_eq!(square(1e300).area(), Some(Float::new(f64::INFINITY)));
    assert_eq!(square(1e-300).area(), Some(Float::new(0.0)));
}

/// `volume_exact` is `None` for an unbounded set in either mode, and in exact mode the exact
/// volume whatever the coordinates: the box [0, 1/3]³ holds 1/27 (by hand), a value that no
/// sum over `f64`s gives.
#[test]
fn volume_exact_of_unbounded_and_of_thirds() {
    let third = Rational::new(1.into(), 3.into());
    let p = |v: &Rational| Point3::new(v.clone(), v.clone(), v.clone());
    let exact = YinSet3::<Rational>::cuboid(&p(&Rational::from_i64(0)), &p(&third)).unwrap();
    assert_eq!(
        exact.volume_exact(),
        Some(Rational::new(1.into(), 27.into()))
    );
    assert_eq!(exact.complement().volume_exact(), None);
    let f = |v: f64| Point3::new(Float::new(v), Float::new(v), Float::new(v));
    let (corners, faces) = cuboid(&f(0.0), &f(2.0));
    let float = YinSet3::from_triangles_with(corners, faces, Tolerance::new(1e-9)).unwrap();
    assert_eq!(float.volume_exact(), Some(Rational::from_i64(8)));
    assert_eq!(float.complement().volume_exact(), None);
}
