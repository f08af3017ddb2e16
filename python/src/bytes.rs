//! The byte layouts arrays cross the boundary in: coordinates as little-endian `f64`, indices as
//! little-endian `i64`, location codes as `i8`; and the exact numbers the Python half turns
//! into `fractions.Fraction`.

use crate::error;
use pyo3::PyResult;
use yinset::kernel::{Point, Point3};
use yinset::num::Num;
use yinset::yin2::Location;

/// `locate`'s code of a point in the set.
pub const INSIDE: i8 = 1;
/// `locate`'s code of a point on the boundary.
pub const ON_BOUNDARY: i8 = 0;
/// `locate`'s code of a point outside the closure.
pub const OUTSIDE: i8 = -1;

/// The `f64`s of `data`, whose length must be a multiple of 8 and of `8 * width`.
pub fn floats(data: &[u8], width: usize) -> PyResult<Vec<f64>> {
    if data.len() % (8 * width) != 0 {
        return Err(error(format!(
            "{} bytes are not a whole number of {width}-coordinate points",
            data.len()
        )));
    }
    Ok(data
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().expect("chunks of 8")))
        .collect())
}

/// The `i64`s of `data`, as indices (a negative one is refused, naming `what` and its place).
pub fn indices(data: &[u8], what: &str) -> PyResult<Vec<usize>> {
    if data.len() % 8 != 0 {
        return Err(error(format!(
            "{} bytes are not whole 64-bit integers",
            data.len()
        )));
    }
    data.chunks_exact(8)
        .enumerate()
        .map(|(k, c)| {
            let v = i64::from_le_bytes(c.try_into().expect("chunks of 8"));
            usize::try_from(v).map_err(|_| error(format!("{what} {k}: index {v} is negative")))
        })
        .collect()
}

/// The number `v`, exactly in exact mode; `place` names it in the error if it is not finite.
fn number<N: Num>(v: f64, place: impl FnOnce() -> String) -> PyResult<N> {
    N::from_f64(v).map_err(|_| error(format!("{}: coordinate {v} is not finite", place())))
}

/// The 2D points of the coordinate pairs `xy`; `place(k)` names point k in errors.
pub fn points2<N: Num>(xy: &[f64], place: impl Fn(usize) -> String) -> PyResult<Vec<Point<N>>> {
    xy.chunks_exact(2)
        .enumerate()
        .map(|(k, c)| {
            Ok(Point::new(
                number(c[0], || place(k))?,
                number(c[1], || place(k))?,
            ))
        })
        .collect()
}

/// The 3D points of the coordinate triples `xyz`.
pub fn points3<N: Num>(xyz: &[f64]) -> PyResult<Vec<Point3<N>>> {
    xyz.chunks_exact(3)
        .enumerate()
        .map(|(k, c)| {
            let at = || format!("vertex {k}");
            Ok(Point3::new(
                number(c[0], at)?,
                number(c[1], at)?,
                number(c[2], at)?,
            ))
        })
        .collect()
}

/// The little-endian bytes of the nearest `f64`s of `coords`.
pub fn float_bytes<'a, N: Num + 'a>(coords: impl Iterator<Item = &'a N>) -> Vec<u8> {
    coords.flat_map(|c| c.to_f64().to_le_bytes()).collect()
}

/// The code bytes of `locations`.
pub fn location_codes(locations: &[Location]) -> Vec<u8> {
    locations
        .iter()
        .map(|l| match l {
            Location::Inside => INSIDE,
            Location::OnBoundary => ON_BOUNDARY,
            Location::Outside => OUTSIDE,
        } as u8)
        .collect()
}

/// A measure for Python: `(numerator, denominator)` as decimal texts in exact mode (a
/// `Fraction` there), else the `f64`; `None` for an unbounded set.
#[derive(pyo3::IntoPyObject)]
pub enum Measure {
    /// The exact value's numerator and denominator.
    Exact(String, String),
    /// The float value.
    Float(f64),
}

/// The measure `m` (exact in exact mode), or `None` if the set is unbounded.
pub fn measure<N: Num>(m: Option<N>) -> Option<Measure> {
    m.map(|v| {
        if N::EXACT {
            let (p, q) = v.fraction();
            Measure::Exact(p.to_string(), q.to_string())
        } else {
            Measure::Float(v.to_f64())
        }
    })
}
