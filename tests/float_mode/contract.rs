//! Float mode's contract (`yinset::num::Tolerance`), one regression test per case of issue 14:
//! extreme magnitudes, extreme tolerances, the refused too-fine ε, the refused collapse, the
//! grid's independence from position, area on a local origin, and one location rule.
//!
//! Oracles are independent of the code under test: exact mode on the same `f64` values, grid
//! bounds worked out by hand in the comments, and points placed at known distances.

use super::data;
use super::gen::{translate, Curves};
use super::harness::*;
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::{Location, YinError, YinSet2};

/// The axis-parallel rectangle [x0, x1] × [y0, y1], counterclockwise.
fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Curves {
    vec![vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]]
}

/// The float set of `c` at tolerance ε, or the error.
fn try_float(c: &Curves, eps: f64) -> Result<Flt, YinError> {
    YinSet2::from_curves_with(float_curves(c), Tolerance::new(eps))
}

/// Every binary operation on (a, b) in both modes: the float result is exactly valid and
/// within area(F △ E) ≤ C · ε · L of the exact one.
fn assert_within_bound(a: &Curves, b: &Curves, eps: f64) {
    let (fa, fb) = (float_set(a, eps), float_set(b, eps));
    let (ea, eb) = (exact_set(a), exact_set(b));
    for op in OPS {
        let o = compare(op, (&ea, &eb), (&fa, &fb), eps).unwrap_or_else(|e| panic!("{e}"));
        assert!(o.ratio <= AREA_C, "{op:?}: area(F△E) = {} ε·L", o.ratio);
    }
}

/// `r` is the error that ε = `requested` is too fine, `representable` the finest grid.
fn assert_too_fine(r: Result<Flt, YinError>, requested: f64, representable: f64) {
    match r {
        Err(YinError::ToleranceTooFine {
            requested: got,
            representable: finest,
        }) => assert_eq!((got.get(), finest.get()), (requested, representable)),
        other => panic!("expected ToleranceTooFine, got {other:?}"),
    }
}

#[test]
fn coordinates_near_1e160_do_not_overflow_the_predicates() {
    // A square of side 2·10¹⁶⁰ against a shifted copy, ε = 10¹⁵⁰: products of coordinates
    // (10³²⁰) overflow f64; the kernel must neither panic nor lose the result.
    let a = rect(-1e160, -1e160, 1e160, 1e160);
    let b = rect(0.0, -3e160, 2e160, 5e159);
    assert_within_bound(&a, &b, 1e150);
    let m = float_set(&a, 1e150).meet(&float_set(&b, 1e150));
    assert_eq!(m.curves().len(), 1);
}

#[test]
fn a_square_of_side_2e_minus_200_is_accepted() {
    // Products of coordinates (10⁻⁴⁰⁰) underflow f64: exact mode accepts the square, so must
    // float mode, at its default ε and at an explicit one.
    let a = rect(-1e-200, -1e-200, 1e-200, 1e-200);
    let b = rect(0.0, 0.0, 3e-200, 3e-200);
    let fa = YinSet2::from_curves(float_curves(&a)).expect("valid tiny square accepted");
    fa.validate().unwrap();
    assert_eq!(fa.curves()[0].len(), 4);
    assert_within_bound(&a, &b, 1e-205);
}

#[test]
fn subnormal_tolerances_end_with_an_error_or_a_result() {
    // ε = 10⁻³¹⁰ < 2⁻¹⁰²²: the unit square needs a grid of at least 2⁻⁵¹ (coordinates up to
    // 1 = 2⁵¹ · 2⁻⁵¹), so the request is refused, naming that grid.
    let unit = rect(0.0, 0.0, 1.0, 1.0);
    assert_too_fine(try_float(&unit, 1e-310), 1e-310, 2f64.powi(-51));
    // Squares with coordinates up to 2·10⁻³⁰⁰ < 2⁻⁹⁹⁵ carry a subnormal grid (any grid of at
    // least 2⁻⁹⁹⁵⁻⁵¹ will do; ε = 10⁻³¹⁰ gives 2⁻¹⁰³⁰): it works, within the bound.
    let tiny = rect(0.0, 0.0, 1e-300, 1e-300);
    let other = rect(5e-301, 5e-301, 2e-300, 2e-300);
    assert_within_bound(&tiny, &other, 1e-310);
}

#[test]
fn a_tolerance_too_fine_for_the_coordinates_is_refused_not_coarsened() {
    // A 10⁶ × 1 strip at x = 10¹²: 10¹² < 2⁴⁰, so the finest grid is 2⁴⁰⁻⁵¹ = 2⁻¹¹.
    let strip = rect(1e12, 0.0, 1e12 + 1e6, 1.0);
    assert_too_fine(try_float(&strip, 1e-9), 1e-9, 2f64.powi(-11));
    // ε = 10⁻³ is representable (grid 2⁻¹⁰): the strip comes back whole, area exactly 10⁶.
    let y = try_float(&strip, 1e-3).unwrap();
    assert_eq!(y.grid(), Some(2f64.powi(-10)));
    assert_eq!(y.area().map(Float::get), Some(1e6));
    // No ε given: the default, 10⁻¹⁰ × 10⁶, is raised to the finest grid and reported.
    let y = YinSet2::from_curves(float_curves(&strip)).unwrap();
    assert_eq!(y.ctx().eps(), 2f64.powi(-11));
    assert_eq!(y.grid(), Some(2f64.powi(-11)));
    assert_eq!(y.area().map(Float::get), Some(1e6));
}

#[test]
fn a_tolerance_that_swallows_the_input_is_an_error_not_the_empty_set() {
    if !crate::common::data_available() {
        return;
    }
    // ε = 10³⁰⁰ on the panda: every vertex snaps to the origin.
    match try_float(&data::panda(), 1e300) {
        Err(YinError::CollapsedOnGrid { grid }) => assert_eq!(grid.get(), 2f64.powi(996)),
        other => panic!("expected CollapsedOnGrid, got {other:?}"),
    }
    assert!(matches!(
        try_float(&data::mickey(), 1e300),
        Err(YinError::CollapsedOnGrid { .. })
    ));
}

#[test]
fn results_move_with_translations_by_the_grid() {
    if !crate::common::data_available() {
        return;
    }
    // With one ε the grid is fixed; translating both operands by a multiple of it translates
    // every result, vertex by vertex.
    let (p, m) = (data::panda(), data::mickey());
    let t = [1024.0, -3072.0];
    let eps = 1e-6;
    let (a, b) = (float_set(&p, eps), float_set(&m, eps));
    let (ta, tb) = (
        float_set(&translate(&p, t), eps),
        float_set(&translate(&m, t), eps),
    );
    for op in OPS {
        let (r, tr) = (op.apply(&a, &b), op.apply(&ta, &tb));
        let moved: Vec<Vec<[f64; 2]>> = r
            .curves()
            .iter()
            .map(|c| {
                c.vertices()
                    .iter()
                    .map(|v| [v.x.get() + t[0], v.y.get() + t[1]])
                    .collect()
            })
            .collect();
        let got: Vec<Vec<[f64; 2]>> = tr
            .curves()
            .iter()
            .map(|c| {
                c.vertices()
                    .iter()
                    .map(|v| [v.x.get(), v.y.get()])
                    .collect()
            })
            .collect();
        assert_eq!(moved, got, "{op:?}");
    }
    // The default ε depends on the size of the input, not on its position.
    let d = |c: &Curves| YinSet2::from_curves(float_curves(c)).unwrap().ctx().eps();
    assert_eq!(d(&p), d(&translate(&p, t)));
}

#[test]
fn area_of_a_thin_triangle_far_from_the_origin() {
    // Twice the area is (b − a) × (c − a) = 0.5 · (0.5 + δ) − 1 · 0.25 = δ/2 with δ ≈ 3·10⁻⁴:
    // the shoelace sum on raw coordinates (terms ≈ 1.7·10¹²) cancels to noise of 10⁻⁴.
    let tri: Curves = vec![vec![
        [700000.0, 2400000.0],
        [700000.5, 2400001.0],
        [700000.25, 2400000.5003],
    ]];
    let exact = exact_set(&tri).area().unwrap().to_f64();
    assert!((exact - 7.5e-5).abs() < 1e-9, "exact area {exact}");
    let f = YinSet2::from_curves(float_curves(&tri)).unwrap();
    let g = f.grid().unwrap();
    let got = f.area().unwrap().get();
    // Snapping moves each vertex by at most g·√2/2: the area moves by at most g · L.
    let l = boundary_length(&exact_set(&tri));
    assert!(
        (got - exact).abs() <= g * l,
        "float area {got}, exact {exact}, g {g}"
    );
}

#[test]
fn locate_applies_one_distance_rule_in_every_direction() {
    use Location::*;
    let eps = 1e-3;
    let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
    let square = try_float(&rect(0.0, 0.0, 1.0, 1.0), eps).unwrap();
    let q = [
        p(1e-4, 0.5),
        p(0.5, 1e-4),
        p(1.0 - 1e-4, 0.5),
        p(0.5, 1.0 + 1e-4),
        p(2e-3, 0.5),
        p(0.5, 2e-3),
        p(-2e-3, 0.5),
        p(0.5, -2e-3),
    ];
    let want = [
        OnBoundary, OnBoundary, OnBoundary, OnBoundary, Inside, Inside, Outside, Outside,
    ];
    assert_eq!(square.locate(&q), want);
    // A slanted edge and a vertex: the distance to the segment decides, not the line.
    let tri = try_float(&vec![vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]], eps).unwrap();
    let q = [
        p(0.5003, 0.5003),   // 4.2·10⁻⁴ from the hypotenuse
        p(0.501, 0.501),     // 1.4·10⁻³ from it
        p(0.499, 0.499),     // 1.4·10⁻³ inside
        p(1.0005, -0.0005),  // 7.1·10⁻⁴ from the vertex (1, 0)
        p(1.002, 0.0),       // on the bottom edge's line, 2·10⁻³ beyond its end
        p(-0.0008, -0.0008), // 1.1·10⁻³ from the vertex (0, 0)
    ];
    let want = [OnBoundary, Outside, Inside, OnBoundary, Outside, Outside];
    assert_eq!(tri.locate(&q), want);
    // Exact mode is untouched: only points on the boundary are on it.
    let exact = exact_set(&rect(0.0, 0.0, 1.0, 1.0));
    let r = |x: f64, y: f64| {
        Point::new(
            <Rational as Num>::from_f64(x).unwrap(),
            <Rational as Num>::from_f64(y).unwrap(),
        )
    };
    assert_eq!(
        exact.locate(&[r(1e-4, 0.5), r(0.5, 1e-4)]),
        [Inside, Inside]
    );
}
