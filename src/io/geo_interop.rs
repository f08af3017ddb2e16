//! Conversions between `geo_types` polygons and Yin sets (feature `geo-types`): a polygon or
//! multipolygon of `f64` coordinates becomes the Yin set it bounds — in float mode, or exactly,
//! every `f64` being a rational — and a bounded Yin set becomes a multipolygon, one polygon per
//! atom, coordinates rounded to the nearest `f64` (an error where the rounded rings would not
//! bound the set, e.g. a square of side 10⁻⁴⁰⁰).
//!
//! ```
//! use geo_types::{polygon, MultiPolygon};
//! use yinset::num::Rational;
//! use yinset::yin2::YinSet2;
//!
//! let square = polygon![(x: 0.0, y: 0.0), (x: 2.0, y: 0.0), (x: 2.0, y: 2.0), (x: 0.0, y: 2.0)];
//! let shifted = polygon![(x: 1.0, y: 1.0), (x: 3.0, y: 1.0), (x: 3.0, y: 3.0), (x: 1.0, y: 3.0)];
//! let a = YinSet2::<Rational>::try_from(&square).unwrap();
//! let b = YinSet2::<Rational>::try_from(&shifted).unwrap();
//! let meet = MultiPolygon::try_from(&(&a & &b)).unwrap();
//! assert_eq!(meet.0.len(), 1);
//! assert_eq!(meet.0[0].exterior().0.len(), 5); // the unit square [1,2]², closed
//! ```

use super::nearest::nearest_polygons;
use super::{closed, polygons_of, Polygon as Rings, WriteError};
use crate::kernel::Point;
use crate::num::{Num, NumError};
use crate::yin2::{YinError, YinSet2};
use geo_types::{Coord, LineString, MultiPolygon, Polygon};

/// Why `geo_types` polygons do not give a Yin set, or a Yin set no multipolygon.
#[derive(Debug, thiserror::Error)]
pub enum GeoError {
    /// A coordinate is not finite (NaN or infinite).
    #[error("polygon {polygon}: {source}")]
    Number {
        /// The polygon, counting from 0.
        polygon: usize,
        /// What is wrong with the coordinate.
        source: NumError,
    },
    /// The rings do not bound a Yin set (the validator's reason; curves count exteriors and
    /// holes in order, polygon by polygon).
    #[error(transparent)]
    NotYin(#[from] YinError),
    /// The set is unbounded: no polygon holds it.
    #[error("the set is unbounded (it contains everything far enough out): no polygon holds it")]
    Unbounded,
    /// The set's nearest `f64`s do not bound it (a coordinate beyond the range of `f64`, or
    /// rings that collapse, cross or turn round when rounded).
    #[error(transparent)]
    Rounding(#[from] WriteError),
}

/// The rings of `polygon`, number `index` of its multipolygon, as open point lists.
fn rings<N: Num>(polygon: &Polygon<f64>, index: usize) -> Result<Rings<N>, GeoError> {
    let ring = |line: &LineString<f64>| {
        let points: Result<Vec<Point<N>>, NumError> = line
            .0
            .iter()
            .map(|c| Ok(Point::new(N::from_f64(c.x)?, N::from_f64(c.y)?)))
            .collect();
        points.map(super::open_ring)
    };
    let number = |source| GeoError::Number {
        polygon: index,
        source,
    };
    Ok(Rings {
        exterior: ring(polygon.exterior()).map_err(number)?,
        interiors: polygon
            .interiors()
            .iter()
            .map(ring)
            .collect::<Result<_, _>>()
            .map_err(number)?,
    })
}

/// The Yin set bounded by `polygons`' rings, oriented as OGC's (exterior counterclockwise).
fn yin_set<N: Num>(polygons: &[Polygon<f64>]) -> Result<YinSet2<N>, GeoError> {
    let mut curves = Vec::new();
    for (k, p) in polygons.iter().enumerate() {
        curves.extend(rings::<N>(p, k)?.oriented_rings().map(|(_, r, _)| r));
    }
    if curves.is_empty() {
        return Ok(YinSet2::empty());
    }
    Ok(YinSet2::from_curves(curves)?)
}

/// The Yin set a polygon bounds (its rings must form a Yin set's boundary: simple, holes
/// inside the exterior and apart from each other but for touching vertices).
impl<N: Num> TryFrom<&Polygon<f64>> for YinSet2<N> {
    type Error = GeoError;
    fn try_from(polygon: &Polygon<f64>) -> Result<Self, GeoError> {
        yin_set(std::slice::from_ref(polygon))
    }
}

/// The Yin set a multipolygon bounds (its polygons' interiors disjoint).
impl<N: Num> TryFrom<&MultiPolygon<f64>> for YinSet2<N> {
    type Error = GeoError;
    fn try_from(multi: &MultiPolygon<f64>) -> Result<Self, GeoError> {
        yin_set(&multi.0)
    }
}

/// The multipolygon of a bounded Yin set: one polygon per atom, exterior counterclockwise and
/// holes clockwise, coordinates the nearest `f64`s (refused where those would not bound the
/// set's rings, as by the WKT, GeoJSON and WKB writers).
impl<N: Num> TryFrom<&YinSet2<N>> for MultiPolygon<f64> {
    type Error = GeoError;
    fn try_from(set: &YinSet2<N>) -> Result<Self, GeoError> {
        let line = |ring: &[Point<f64>]| {
            let coords = closed(ring).map(|p| Coord { x: p.x, y: p.y }).collect();
            LineString(coords)
        };
        let polygons = nearest_polygons(&polygons_of(set).ok_or(GeoError::Unbounded)?)?;
        Ok(MultiPolygon(
            polygons
                .iter()
                .map(|p| {
                    Polygon::new(
                        line(&p.exterior),
                        p.interiors.iter().map(|h| line(h)).collect(),
                    )
                })
                .collect(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational};
    use geo_types::polygon;

    /// The square [0,4]² with the hole [1,2]², both rings given clockwise.
    fn framed() -> Polygon<f64> {
        polygon!(
            exterior: [(x: 0.0, y: 0.0), (x: 0.0, y: 4.0), (x: 4.0, y: 4.0), (x: 4.0, y: 0.0)],
            interiors: [[(x: 1.0, y: 1.0), (x: 1.0, y: 2.0), (x: 2.0, y: 2.0), (x: 2.0, y: 1.0)]],
        )
    }

    #[test]
    fn polygons_become_yin_sets_exactly_and_in_float_mode() {
        let exact = YinSet2::<Rational>::try_from(&framed()).unwrap();
        assert_eq!(exact.area(), Some(Rational::from_i64(15)));
        assert_eq!(exact.curves().len(), 2);
        let float = YinSet2::<Float>::try_from(&framed()).unwrap();
        assert_eq!(float.area().map(|a| a.to_f64()), Some(15.0));
        let tenth = polygon![(x: 0.0, y: 0.0), (x: 0.1, y: 0.0), (x: 0.0, y: 0.1)];
        let exact = YinSet2::<Rational>::try_from(&tenth).unwrap();
        // The exact value of the f64 nearest 0.1, squared and halved: not 1/200.
        let area = exact.area().unwrap();
        assert_ne!(area, Rational::parse("1/200").unwrap());
        assert_eq!(
            area,
            Rational::from_f64(0.1).unwrap() * Rational::from_f64(0.05).unwrap()
        );
    }

    #[test]
    fn yin_sets_become_multipolygons_ogc_oriented() {
        let set = YinSet2::<Rational>::try_from(&framed()).unwrap();
        let multi = MultiPolygon::try_from(&set).unwrap();
        assert_eq!(multi.0.len(), 1);
        let p = &multi.0[0];
        assert_eq!(p.interiors().len(), 1);
        let twice = |l: &LineString<f64>| -> f64 {
            l.0.windows(2)
                .map(|w| w[0].x * w[1].y - w[1].x * w[0].y)
                .sum()
        };
        assert_eq!(twice(p.exterior()), 32.0, "counterclockwise");
        assert_eq!(twice(&p.interiors()[0]), -2.0, "clockwise");
        assert_eq!(p.exterior().0.first(), p.exterior().0.last());
        let back = YinSet2::<Rational>::try_from(&multi).unwrap();
        assert_eq!(back, set);
        assert!(matches!(
            MultiPolygon::try_from(&set.complement()),
            Err(GeoError::Unbounded)
        ));
        assert_eq!(
            MultiPolygon::try_from(&YinSet2::<Rational>::empty())
                .unwrap()
                .0
                .len(),
            0
        );
        assert!(YinSet2::<Rational>::try_from(&MultiPolygon::<f64>(vec![]))
            .unwrap()
            .is_empty());
    }

    #[test]
    fn sets_that_round_to_nothing_are_errors() {
        let tiny = Rational::parse("1e-400").unwrap();
        let p = |x: &Rational, y: &Rational| Point::new(x.clone(), y.clone());
        let z = Rational::zero();
        let square = YinSet2::from_curves(vec![vec![
            p(&z, &z),
            p(&tiny, &z),
            p(&tiny, &tiny),
            p(&z, &tiny),
        ]])
        .unwrap();
        let e = MultiPolygon::try_from(&square).unwrap_err();
        assert!(matches!(e, GeoError::Rounding(_)), "{e}");
        assert!(e.to_string().contains("repeats the previous vertex"), "{e}");
    }

    #[test]
    fn bad_polygons_are_errors() {
        let nan = polygon![(x: 0.0, y: 0.0), (x: f64::NAN, y: 0.0), (x: 0.0, y: 1.0)];
        let e = YinSet2::<Rational>::try_from(&nan).unwrap_err();
        assert!(matches!(e, GeoError::Number { polygon: 0, .. }), "{e}");
        let bow = polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 1.0), (x: 1.0, y: 0.0), (x: 0.0, y: 1.0)];
        let e = YinSet2::<Rational>::try_from(&bow).unwrap_err();
        assert!(matches!(e, GeoError::NotYin(_)), "{e}");
    }
}
