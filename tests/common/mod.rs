//! Shapes and generators shared by the integration tests; the laws, the oracles and the
//! integer meshes are the test kit's (tests/kit), re-exported here.
#![allow(dead_code)]

use std::path::PathBuf;
use yinset::kernel::Point;
use yinset::num::Rational;
use yinset::yin2::YinSet2;

// Each test binary uses some of them (as with `dead_code` above).
#[allow(unused_imports)]
pub use yinset_testkit::{cells, cells3, geom3, laws, membership, ops, q, rotation, shapes, Y};

#[path = "../../src/io/testdata.rs"]
mod testdata;

/// True if the shared data is there; if not, a notice and false (outside CI: skip the test),
/// or a panic (with `CI` set).
pub fn data_available() -> bool {
    testdata::available()
}

/// A directory of the shared data under `2d` (see [`data_available`]); panics naming the path
/// if it is missing.
pub fn data_dir(name: &str) -> PathBuf {
    testdata::dir(&format!("2d/{name}"))
}

/// A file of the shared data under `3d`; panics naming the path if it is missing.
pub fn data_file_3d(name: &str) -> PathBuf {
    let path = testdata::root().join("3d").join(name);
    assert!(path.is_file(), "test data missing: {}", path.display());
    path
}

/// A vertex cycle from integer pairs.
pub fn ring(c: &[(i64, i64)]) -> Vec<Point<Rational>> {
    c.iter().map(|&(x, y)| Point::int(x, y)).collect()
}

/// Axis-aligned rectangle [x0,x1]×[y0,y1], counterclockwise.
pub fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Vec<Point<Rational>> {
    ring(&[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
}

/// The same cycle, clockwise.
pub fn rev(mut v: Vec<Point<Rational>>) -> Vec<Point<Rational>> {
    v.reverse();
    v
}

/// The Yin set bounded by the given cycles (panics with the validator's message if invalid).
pub fn yin(curves: Vec<Vec<Point<Rational>>>) -> Y {
    YinSet2::from_curves(curves).unwrap_or_else(|e| panic!("invalid test shape: {e}"))
}

/// Exact area (panics if unbounded).
pub fn area(y: &Y) -> Rational {
    y.area().expect("bounded")
}

/// Assert that a set passes the exact validator.
pub fn valid(y: &Y) -> &Y {
    y.validate()
        .unwrap_or_else(|e| panic!("output fails the validator: {e}\n{y:?}"));
    y
}

/// Assert that a cell oracle's checks can fail: for the mask `s` and each `(other, law)`, the
/// set of `other` (built by `yin`) fails `==` against the set of `s`, and its invariants fail
/// `law` against the mask `s`.
pub fn assert_cell_checks_fail<O: laws::CellOracle>(
    o: &O,
    yin: impl Fn(cells::Cells) -> O::Set,
    s: cells::Cells,
    cases: &[(cells::Cells, &str)],
) {
    for &(other, law) in cases {
        let y = yin(other);
        let mut t = laws::Tally::default();
        let e = laws::cells_check(&mut t, o, s, &y, &yin(s), "y").unwrap_err();
        assert!(e.contains(O::SAME), "{e}");
        let e = o.invariants(&mut t, s, &y, "y").unwrap_err();
        assert!(e.contains(law), "{other:?} should fail '{law}': {e}");
    }
}

pub mod gen;
pub mod gen3;
pub mod runner;
