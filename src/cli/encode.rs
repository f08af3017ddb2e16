//! A Yin set → text of any format (yin2 exactly; OGC polygons only for bounded sets).

use super::decode::FULL_PLANE;
use super::error::CliError;
use super::format::Format;
use crate::io::{geojson, wkt, yin2_text, Polygon};
use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::YinSet2;

/// The text of `set` in `format`.
pub fn encode<N: Num>(set: &YinSet2<N>, format: Format) -> Result<String, CliError> {
    match format {
        Format::Yin2 => Ok(yin2(set)),
        Format::Wkt => Ok(wkt::write_multipolygon(&polygons(set, "WKT")?) + "\n"),
        Format::Geojson => Ok(geojson::write_multipolygon(&polygons(set, "GeoJSON")?) + "\n"),
    }
}

/// The yin2 text of `set`: its curves, or a comment line for 0̂ and 1̂.
fn yin2<N: Num>(set: &YinSet2<N>) -> String {
    if set.is_full() {
        return format!("{FULL_PLANE}\n");
    }
    if set.is_empty() {
        return "# yinset: the empty set (no curves)\n".to_string();
    }
    let curves: Vec<Vec<Point<N>>> = set.curves().iter().map(|c| c.vertices().to_vec()).collect();
    yin2_text::write_curves(&curves)
}

/// One polygon per atom (outer curve and its holes); an error naming `format` if unbounded.
fn polygons<N: Num>(set: &YinSet2<N>, format: &'static str) -> Result<Vec<Polygon<N>>, CliError> {
    if !set.is_bounded() {
        return Err(CliError::Unbounded { format });
    }
    let curve = |k: usize| set.curves()[k].vertices().to_vec();
    Ok(set
        .atoms()
        .iter()
        .filter_map(|atom| {
            Some(Polygon {
                exterior: curve(atom.outer?),
                interiors: atom.holes.iter().map(|&h| curve(h)).collect(),
            })
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::decode::{decode, Decoded};
    use crate::num::Rational;

    fn square_with_hole() -> YinSet2<Rational> {
        let p = |x, y| Point::int(x, y);
        YinSet2::from_curves(vec![
            vec![p(0, 0), p(4, 0), p(4, 4), p(0, 4)],
            vec![p(2, 0), p(1, 2), p(3, 2)],
        ])
        .unwrap()
    }

    #[test]
    fn atoms_become_polygons_with_their_holes() {
        let wkt = encode(&square_with_hole(), Format::Wkt).unwrap();
        assert_eq!(
            wkt,
            "MULTIPOLYGON (((0 0, 2 0, 4 0, 4 4, 0 4, 0 0), (1 2, 3 2, 2 0, 1 2)))\n"
        );
        let empty = encode(&YinSet2::<Rational>::empty(), Format::Geojson).unwrap();
        assert_eq!(empty, "{\"type\":\"MultiPolygon\",\"coordinates\":[]}\n");
    }

    #[test]
    fn unbounded_sets_are_only_written_as_yin2() {
        let outside = square_with_hole().complement();
        let e = encode(&outside, Format::Geojson).unwrap_err().to_string();
        assert!(e.contains("unbounded") && e.contains("--to yin2"), "{e}");
        assert!(encode(&outside, Format::Yin2).unwrap().contains("\n\n"));
    }

    #[test]
    fn empty_and_full_round_trip_through_yin2() {
        let full = encode(&YinSet2::<Rational>::full(), Format::Yin2).unwrap();
        assert!(matches!(
            decode::<Rational>(&full, Format::Yin2),
            Ok(Decoded::Full)
        ));
        let empty = encode(&YinSet2::<Rational>::empty(), Format::Yin2).unwrap();
        match decode::<Rational>(&empty, Format::Yin2) {
            Ok(Decoded::Rings(r)) => assert!(r.rings.is_empty()),
            _ => panic!("not empty"),
        }
    }
}
