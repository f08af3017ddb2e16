//! A Yin set → a file of any format (yin2 exactly; OGC polygons — WKT, GeoJSON, WKB — only for
//! bounded sets; OBJ, one
//! object per glued surface, STL, OFF and PLY for 3D sets).

use super::decode::WHOLE_SPACE;
use super::error::CliError;
use super::format::{Dimension, Format};
use crate::io::obj::{surface_groups, write_obj};
use crate::io::off::write_off;
use crate::io::ply::write_ply;
use crate::io::stl::{write_stl_ascii, write_stl_binary};
use crate::io::{geojson, polygons_of, wkb, wkt, yin2_text, NumberStyle, Polygon, WriteError};
use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::YinSet2;
use crate::yin3::YinSet3;

/// A writer of OGC polygons (WKT, GeoJSON or WKB) to bytes.
type Writer<N> = fn(&[Polygon<N>], NumberStyle) -> Result<Vec<u8>, WriteError>;

/// The file of `set` in `format`, WKT, GeoJSON and WKB coordinates in `style`.
pub fn encode<N: Num>(
    set: &YinSet2<N>,
    format: Format,
    style: NumberStyle,
) -> Result<Vec<u8>, CliError> {
    let (name, write): (_, Writer<N>) = match format {
        Format::Yin2 => return Ok(yin2(set).into_bytes()),
        Format::Obj | Format::Stl | Format::StlBinary | Format::Off | Format::Ply => {
            return Err(wrong_dimension(format, Dimension::Two))
        }
        Format::Wkt => ("WKT", |p, s| line(wkt::write_multipolygon(p, s)?)),
        Format::Geojson => ("GeoJSON", |p, s| line(geojson::write_multipolygon(p, s)?)),
        Format::Wkb => ("WKB", wkb::write_multipolygon),
        Format::WkbHex => ("WKB", |p, s| {
            line(wkb::to_hex(&wkb::write_multipolygon(p, s)?))
        }),
    };
    write(&polygons(set, name)?, style).map_err(|source| CliError::Unwritable {
        format: name,
        source,
    })
}

/// `text` as the bytes of a line.
fn line(text: String) -> Result<Vec<u8>, WriteError> {
    Ok((text + "\n").into_bytes())
}

/// The file of the 3D `set` in `format`. Only OBJ can hold 1̂, by its whole-space comment
/// line (in the others it is an error of the input, exit status 1, as the whole plane in a
/// polygon format is); the triangles of STL, OFF and PLY bound unbounded sets as they bound
/// bounded ones (normals out of the set).
pub fn encode3<N: Num>(set: &YinSet3<N>, format: Format) -> Result<Vec<u8>, CliError> {
    let (v, t) = (set.vertices(), set.triangles());
    let no_whole_space = || CliError::Unwritable {
        format: format.name(),
        source: WriteError(
            "the set is the whole space, which has no boundary triangles to write: \
             write obj instead (--to obj)"
                .to_string(),
        ),
    };
    match format {
        Format::Obj => Ok(obj(set).into_bytes()),
        _ if set.is_full() => Err(no_whole_space()),
        Format::Stl => Ok(write_stl_ascii(v, t).into_bytes()),
        Format::StlBinary => Ok(write_stl_binary(v, t)?),
        Format::Off => Ok(write_off(v, t).into_bytes()),
        Format::Ply => Ok(write_ply(v, t).into_bytes()),
        Format::Yin2 | Format::Wkt | Format::Geojson | Format::Wkb | Format::WkbHex => {
            Err(wrong_dimension(format, Dimension::Three))
        }
    }
}

/// The error of writing a set of `dimension` in `format`, which holds the other dimension.
fn wrong_dimension(format: Format, dimension: Dimension) -> CliError {
    CliError::Usage(format!(
        "{} cannot hold a {} set",
        format.name(),
        dimension.name()
    ))
}

/// The OBJ text of `set`: one object `surface_K_positive` or `surface_K_negative` per glued
/// surface, normals out of the set; a comment line for an unbounded set, the comment line
/// [`WHOLE_SPACE`] alone for 1̂, a comment line alone for 0̂ (read back as the file without
/// vertices or faces).
fn obj<N: Num>(set: &YinSet3<N>) -> String {
    if set.is_full() {
        return format!("{WHOLE_SPACE}\n");
    }
    if set.is_empty() {
        return "# yinset: the empty set (no boundary)\n".to_string();
    }
    let text = write_obj(set.vertices(), &surface_groups(set));
    if set.is_bounded() {
        text
    } else {
        "# yinset: the set is unbounded (it contains everything far enough out); \
         the normals point out of the set\n"
            .to_string()
            + &text
    }
}

/// The yin2 text of `set`: its curves, the whole-plane statement for 1̂, a comment line for 0̂.
fn yin2<N: Num>(set: &YinSet2<N>) -> String {
    if set.is_full() {
        return yin2_text::write_plane();
    }
    if set.is_empty() {
        return "# yinset: the empty set (no curves)\n".to_string();
    }
    let curves: Vec<Vec<Point<N>>> = set.curves().iter().map(|c| c.vertices().to_vec()).collect();
    yin2_text::write_curves(&curves)
}

/// One polygon per atom (outer curve and its holes); an error naming `format` if unbounded.
fn polygons<N: Num>(set: &YinSet2<N>, format: &'static str) -> Result<Vec<Polygon<N>>, CliError> {
    polygons_of(set).ok_or(CliError::Unbounded { format })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::decode::{decode, decode_mesh, Decoded};
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
        let wkt = encode(&square_with_hole(), Format::Wkt, NumberStyle::Decimal).unwrap();
        assert_eq!(
            wkt,
            b"MULTIPOLYGON (((0 0, 2 0, 4 0, 4 4, 0 4, 0 0), (1 2, 3 2, 2 0, 1 2)))\n"
        );
        let empty = encode(
            &YinSet2::<Rational>::empty(),
            Format::Geojson,
            NumberStyle::Decimal,
        )
        .unwrap();
        assert_eq!(empty, b"{\"type\":\"MultiPolygon\",\"coordinates\":[]}\n");
        let hex = encode(&square_with_hole(), Format::WkbHex, NumberStyle::Exact).unwrap();
        let bytes = encode(&square_with_hole(), Format::Wkb, NumberStyle::Exact).unwrap();
        // One polygon of two rings, 6 and 4 points: 9 + 9 + (4 + 6·16) + (4 + 4·16) bytes.
        assert_eq!(bytes.len(), 186);
        assert_eq!(hex.len(), 2 * 186 + 1);
        assert!(hex.starts_with(b"0106000000010000000103000000"));
    }

    #[test]
    fn unbounded_sets_are_only_written_as_yin2() {
        let outside = square_with_hole().complement();
        let e = encode(&outside, Format::Geojson, NumberStyle::Exact)
            .unwrap_err()
            .to_string();
        assert!(e.contains("unbounded") && e.contains("--to yin2"), "{e}");
        let yin2 = encode(&outside, Format::Yin2, NumberStyle::Exact).unwrap();
        assert!(String::from_utf8(yin2).unwrap().contains("\n\n"));
        assert!(encode(&outside, Format::Wkb, NumberStyle::Exact).is_err());
    }

    #[test]
    fn empty_and_full_round_trip_through_yin2() {
        let full = encode(
            &YinSet2::<Rational>::full(),
            Format::Yin2,
            NumberStyle::Decimal,
        )
        .unwrap();
        assert!(matches!(
            decode::<Rational>(std::str::from_utf8(&full).unwrap(), Format::Yin2, false),
            Ok(Decoded::Full)
        ));
        let empty = encode(
            &YinSet2::<Rational>::empty(),
            Format::Yin2,
            NumberStyle::Decimal,
        )
        .unwrap();
        match decode::<Rational>(std::str::from_utf8(&empty).unwrap(), Format::Yin2, false) {
            Ok(Decoded::Boundary(r)) => assert!(r.rings.is_empty()),
            _ => panic!("not empty"),
        }
    }

    /// The cube [lo, hi]³.
    fn cube(lo: i64, hi: i64) -> YinSet3<Rational> {
        let p = |c: i64| crate::kernel::Point3::int(c, c, c);
        YinSet3::cuboid(&p(lo), &p(hi)).unwrap()
    }

    #[test]
    fn obj_has_one_object_per_glued_surface() {
        let hollow = &cube(0, 3) - &cube(1, 2);
        let text = String::from_utf8(encode3(&hollow, Format::Obj).unwrap()).unwrap();
        assert!(text.contains("o surface_0_positive\n"), "{text}");
        assert!(text.contains("o surface_1_negative\n"), "{text}");
        assert_eq!(text.matches("\no ").count(), 2);
        let outside =
            String::from_utf8(encode3(&hollow.complement(), Format::Obj).unwrap()).unwrap();
        assert!(
            outside.starts_with("# yinset: the set is unbounded"),
            "{outside}"
        );
        assert_eq!(
            encode3(&YinSet3::<Rational>::full(), Format::Obj).unwrap(),
            format!("{WHOLE_SPACE}\n").into_bytes()
        );
        let empty = encode3(&YinSet3::<Rational>::empty(), Format::Obj).unwrap();
        assert_eq!(empty, b"# yinset: the empty set (no boundary)\n");
        assert!(matches!(
            decode_mesh::<Rational>(&empty, Format::Obj),
            Ok(Decoded::Boundary(m)) if m.vertices.is_empty() && m.faces.is_empty()
        ));
        assert!(encode3(&hollow, Format::Wkt).is_err());
        assert!(encode(&square_with_hole(), Format::Obj, NumberStyle::Decimal).is_err());
    }
}
