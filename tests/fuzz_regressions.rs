//! Inputs found by the fuzz targets (fuzz/, issue 5), minimized, each asserting the correct
//! behaviour. A test marked `#[ignore = "kernel bug: …"]` pins a bug not fixed yet: run those
//! with `cargo test --test fuzz_regressions -- --ignored`, and remove the `ignore` with the fix.
//! Each test names the target and the input (as the target's decoded `Debug` form) it came from.

use yinset::kernel::Point;
use yinset::num::{Float, Tolerance};
use yinset::yin2::{FillRule, Location, YinSet2};

/// A float point.
fn f(x: f64, y: f64) -> Point<Float> {
    Point::new(Float::new(x), Float::new(y))
}

/// Assert that a float-mode set passes the exact validator.
fn valid_float(y: &YinSet2<Float>) {
    y.validate()
        .unwrap_or_else(|e| panic!("output fails the validator: {e}\n{y:?}"));
}

/// ops_float, `OpsInput { tol: 23, a: Shape { flags: 2 (fill only, even-odd), curves:
/// [[(1,1), (2,2), (2,3)], [(4,3), (6,2), (0,1)+δy], [(2,1), (1,2)]] }, b: empty }`: ε = 0.25,
/// δ = ε/2. Iterated snap rounding (`snap::snap_round`) used to loop forever, at constant
/// memory, on the even-odd fill of three small rings (rerouting fragments instead of the
/// original segments could zigzag); with that bug present this test hangs rather than fails.
#[test]
fn float_fill_snap_rounding_terminates() {
    let rings = vec![
        vec![f(1.0, 1.0), f(2.0, 2.0), f(2.0, 3.0)],
        vec![f(4.0, 3.0), f(6.0, 2.0), f(0.0, 1.125)],
        vec![f(2.0, 1.0), f(1.0, 2.0)],
    ];
    let set = YinSet2::from_rings_filled_with(rings, FillRule::EvenOdd, Tolerance::new(0.25))
        .expect("finite rings are always filled");
    valid_float(&set);
    assert!(set.area().is_some(), "the fill of bounded rings is bounded");
    // The same on integer rings (ops_float and construct find many such, all at ε = 0.25).
    let rings = vec![
        vec![
            f(4.0, 4.0),
            f(1.0, 0.0),
            f(4.0, 0.0),
            f(0.0, 2.0),
            f(1.0, 2.0),
            f(4.0, 0.0),
        ],
        vec![f(3.0, 0.0), f(1.0, 2.0)],
    ];
    let set = YinSet2::from_rings_filled_with(rings, FillRule::EvenOdd, Tolerance::new(0.25))
        .expect("finite rings are always filled");
    valid_float(&set);
}

/// ops_float, `OpsInput { tol: 16, a: Shape { flags: 0, curves: [[(3,7)−δ, (7,7)−δ, (0,0),
/// (3,1)−δ]] } }`: ε from the extent (7·10⁻¹⁰), δ = 5·10⁻¹⁰ off both coordinates. The ring
/// crosses itself at (3, 3); its even-odd fill in float mode has a curve that meets itself.
#[test]
fn float_fill_of_self_crossing_ring_is_valid() {
    let d = 5e-10;
    let rings = vec![vec![
        f(3.0 - d, 7.0 - d),
        f(7.0 - d, 7.0 - d),
        f(0.0, 0.0),
        f(3.0 - d, 1.0 - d),
    ]];
    let set = YinSet2::from_rings_filled_with(rings, FillRule::EvenOdd, Tolerance::default())
        .expect("finite rings are always filled");
    valid_float(&set);
}

/// construct, `ConstructInput { tol: 17, shape: [[(7,7), (4,4), (0,4)], [(3,3), (0,2)+δx,
/// (2,2), (6,0), (1,2), (1,6), (6,2), (0,1), (0,0)]] }`: ε = 10⁻⁹, δ = 5·10⁻¹⁰. The float
/// even-odd fill has outermost curves of both orientations.
#[test]
fn float_fill_outermost_curves_agree() {
    let d = 5e-10;
    let rings = vec![
        vec![f(7.0, 7.0), f(4.0, 4.0), f(0.0, 4.0)],
        vec![
            f(3.0, 3.0),
            f(d, 2.0),
            f(2.0, 2.0),
            f(6.0, 0.0),
            f(1.0, 2.0),
            f(1.0, 6.0),
            f(6.0, 2.0),
            f(0.0, 1.0),
            f(0.0, 0.0),
        ],
    ];
    let set = YinSet2::from_rings_filled_with(rings, FillRule::EvenOdd, Tolerance::new(1e-9))
        .expect("finite rings are always filled");
    valid_float(&set);
}

/// ops_float, `OpsInput { tol: 49, a: empty, b: Shape { flags: 0, curves: [[(7,7)−δ, (7,7),
/// (3,7)]] }, probes: [(4.5, 4.5)] }`: ε = 10⁻⁹, δ = 5·10⁻¹⁰. B is a sliver triangle on the
/// ε-grid; its complement B' (unbounded, one sliver hole) locates (4.5, 4.5), 2.5 away from
/// every boundary point, as Outside in float mode, while the same curves read exactly say
/// Inside. The fuzzer finds the same on many unbounded float results (A', A∨B).
#[test]
fn float_locate_far_from_a_sliver_hole() {
    let d = 5e-10;
    let tol = Tolerance::new(1e-9);
    let ring = vec![f(7.0 - d, 7.0 - d), f(7.0, 7.0), f(3.0, 7.0)];
    let b = YinSet2::from_curves_with(vec![ring.clone()], tol)
        .or_else(|_| YinSet2::from_rings_filled_with(vec![ring], FillRule::EvenOdd, tol))
        .expect("finite rings are always filled");
    let complement = b.complement();
    valid_float(&complement);
    let p = f(4.5, 4.5);
    let exact = complement.to_exact().expect("valid sets read exactly");
    let exact_p = Point::new(
        yinset::num::Rational::from_float(4.5).unwrap(),
        yinset::num::Rational::from_float(4.5).unwrap(),
    );
    assert_eq!(exact.locate(&[exact_p]), vec![Location::Inside]);
    assert_eq!(
        complement.locate(&[p]),
        vec![Location::Inside],
        "float locate disagrees with exact locate\n{complement:?}"
    );
}

/// ops_float, fuzz/seeds/ops/found_tiny_hole_grows_to_a_grid_cell: on a grid of
/// g = 2.2·10¹², an unbounded operand's hole of area 1505/46 centred near a point halfway
/// between grid points rounds to a hole of one whole grid cell (area g²), beyond g·L with L
/// the input's and E's boundary length alone. Here the same in small numbers: the complement
/// of a square of side 2⁻⁶ centred on the cell (0, 1)² of the grid g = 1. The hole is kept
/// (never silently emptied) and area(F △ E) = 1 − 2⁻¹² is within g·L only with F's boundary
/// length (4) in L — the contract on `Tolerance`.
#[test]
fn float_tiny_hole_grows_to_a_grid_cell_within_the_contract() {
    let (lo, hi) = (0.5 - 2f64.powi(-7), 0.5 + 2f64.powi(-7));
    let tiny = vec![f(lo, lo), f(hi, lo), f(hi, hi), f(lo, hi)];
    let hole = YinSet2::from_curves_with(vec![tiny], Tolerance::new(1.0))
        .expect("a valid square")
        .complement();
    valid_float(&hole);
    assert_eq!(hole.grid(), Some(1.0));
    let half = yinset::num::Rational::from_float(0.5).unwrap();
    let centre = Point::new(half.clone(), half);
    let exact_hole = hole.to_exact().expect("valid sets read exactly");
    assert_eq!(
        exact_hole.locate(&[centre]),
        vec![Location::Outside],
        "{hole:?}"
    );
    // F's hole is the cell, which holds E's: area(F △ E) = 1 − (2⁻⁶)².
    let grown = hole.complement().area().expect("bounded").get();
    assert_eq!(grown, 1.0, "{hole:?}");
    let sym_diff = grown - 2f64.powi(-12);
    let (input, exact, float) = (4.0 * 2f64.powi(-6), 4.0 * 2f64.powi(-6), 4.0);
    assert!(
        sym_diff > input + exact,
        "the case no longer needs F's length"
    );
    assert!(sym_diff <= input + exact + float);
}

/// The float fill of `rings` at ε passes the validator.
fn float_fill_is_valid(rings: &[&[(f64, f64)]], rule: FillRule, eps: f64) {
    let rings = rings
        .iter()
        .map(|r| r.iter().map(|&(x, y)| f(x, y)).collect())
        .collect();
    let set = YinSet2::from_rings_filled_with(rings, rule, Tolerance::new(eps))
        .expect("finite rings are always filled");
    valid_float(&set);
}

/// ops_float (campaign of 2026-11-21, `crash-184202cb…`), B = `Shape { flags: 7 (complement,
/// fill only, non-zero), … }` at ε = 0.25, δ = 2⁻³⁰, minimized to three triangles (one vertex
/// δ off the grid): the non-zero fill's snap rounding left two curves crossing at (31/8, 7/8)
/// (two segments through the same pixel corner zigzagged across each other through closed
/// pixels; fixed by half-open pixels in `snap::meets_pixel`).
#[test]
fn float_nonzero_fill_of_three_triangles_is_valid() {
    let d = 2f64.powi(-30);
    float_fill_is_valid(
        &[
            &[(3.0, 0.0), (7.0, 4.0), (4.0, 2.0)],
            &[(3.0, 4.0), (4.0 + d, 0.0), (3.0, 7.0)],
            &[(7.0, 0.0), (6.0, 0.0), (1.0, 2.0)],
        ],
        FillRule::NonZero,
        0.25,
    );
}

/// ops_float (campaign of 2026-11-21, `crash-3570f85e…`), A = `Shape { flags: 0, … }` at
/// ε = 0.25, δ = ε/2, minimized to three rings on the grid: the even-odd fill's snap rounding
/// left two curves crossing at (11/8, 17/8) (the same bug).
#[test]
fn float_even_odd_fill_with_a_doubled_edge_is_valid() {
    float_fill_is_valid(
        &[
            &[(1.0, 3.0), (7.0, 4.0)],
            &[(2.0, 0.0), (0.0, 7.0), (1.0, 4.0)],
            &[(7.0, 4.0), (1.0, 2.0), (2.0, 2.0), (1.0, 2.0), (3.0, 4.0)],
        ],
        FillRule::EvenOdd,
        0.25,
    );
}

/// parse_wkt (campaign of 2026-11-21, `timeout-d2ca8fe4…`): one self-crossing ring whose
/// coordinates run from 60 to 2·10⁶⁶. Its exact even-odd fill cuts it into pieces 10⁻⁵⁸ long
/// beside (140, 160), whose orientation tests multiply numbers with denominators beyond `f64`'s
/// range: the floating-point filter read such a fraction as 0 and decided an orientation
/// wrongly, the winding sweep's "first piece above" then formed a cycle, and the walk up the
/// faces allocated without bound (a 45 s timeout in the fuzzer). Fixed in the filter
/// (`Rational`'s approximation is NaN when a part overflows).
#[test]
fn exact_fill_of_a_ring_spanning_sixty_orders_of_magnitude() {
    let text = "POLYGON((94 160, 140 160, 090149 6950670, \
        222222222222222222222222222222222222222222222222222222222224 160, 140 160, \
        140 6099950670, \
        2222222222222222222222222222222222222222222222222222222222222222222.2222222222222222222222222222222222220 4502660, \
        60 160, 94 160))";
    let polygons =
        yinset::io::wkt::read_polygons::<yinset::num::Rational>(text).expect("valid WKT");
    let rings: Vec<_> = polygons
        .into_iter()
        .flat_map(|p| std::iter::once(p.exterior).chain(p.interiors))
        .collect();
    let set = YinSet2::from_rings_filled(rings, FillRule::EvenOdd)
        .expect("finite rings are always filled");
    set.validate().expect("valid");
}

/// parse_wkt, `POLYGON((0 0666…60, 0 0))` (a 67-digit y): an unclosed ring is refused by the
/// exact and the float reader with the same message, although its first point reads as
/// different numbers in the two modes (the message once showed them).
#[test]
fn unclosed_ring_is_refused_alike_in_both_modes() {
    let text = format!("POLYGON((0 0{}0, 0 0))", "6".repeat(66));
    let exact = yinset::io::wkt::read_polygons::<yinset::num::Rational>(&text).unwrap_err();
    let float = yinset::io::wkt::read_polygons::<Float>(&text).unwrap_err();
    assert_eq!(exact, float);
    assert!(exact.message.contains("is not closed"), "{exact:?}");
}
