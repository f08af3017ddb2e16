//! Issue 20 items 1 and 2: the command's WKT, GeoJSON and WKB output read by independent
//! readers (the `wkt`, `geojson` and `wkb` crates, as shapely or GEOS would): numbers parse,
//! rings are closed, exteriors run counterclockwise and holes clockwise (OGC SFA, RFC 7946
//! §3.1.6), and geo finds the polygons valid; and WKB written by the `wkb` crate read back.

use assert_cmd::Command;
use geo::{Area, Validation};
use geo_traits::to_geo::ToGeoGeometry;
use std::str::FromStr;
use tempfile::TempDir;

/// The binary under test.
fn yinset() -> Command {
    Command::new(env!("CARGO_BIN_EXE_yinset"))
}

/// The square [0,6]² with the hole [1,2]×[3,4], and the triangle (0,0), (7,1), (0,7), as yin2
/// files in `dir`.
fn operands(dir: &TempDir) -> [String; 2] {
    let a = dir.path().join("a.txt");
    let b = dir.path().join("b.txt");
    std::fs::write(&a, "0 0\n6 0\n6 6\n0 6\n\n1 3\n1 4\n2 4\n2 3\n").unwrap();
    std::fs::write(&b, "0 0\n7 1\n0 7\n").unwrap();
    [a, b].map(|p| p.to_str().unwrap().to_string())
}

/// The stdout of `yinset args…`, which must succeed.
fn run(args: &[&str]) -> String {
    let out = yinset().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// The rings of a multipolygon as (x, y) lists, as an independent reader gives them.
type Rings = Vec<Vec<Vec<(f64, f64)>>>;

/// Twice the signed area of a closed ring (positive iff counterclockwise), by the shoelace
/// formula.
fn twice_area(ring: &[(f64, f64)]) -> f64 {
    ring.windows(2)
        .map(|w| w[0].0 * w[1].1 - w[1].0 * w[0].1)
        .sum()
}

/// Closed rings, exteriors counterclockwise, holes clockwise; and the hand-computed vertices of
/// the meet (its edge y = x/7 meets x = 6 at 6/7, its edge from (7,1) to (0,7) meets x = 6 at
/// 13/7 and y = 6 at 7/6), each the nearest f64 of the exact value.
fn check_meet(rings: &Rings) {
    assert_eq!(rings.len(), 1, "one polygon");
    assert_eq!(rings[0].len(), 2, "an exterior and one hole");
    for (k, ring) in rings[0].iter().enumerate() {
        assert!(ring.len() >= 4, "ring {k}: {ring:?}");
        assert_eq!(ring.first(), ring.last(), "ring {k} is not closed");
        let want_ccw = k == 0;
        assert_eq!(twice_area(ring) > 0.0, want_ccw, "ring {k}: {ring:?}");
    }
    let mut exterior = rings[0][0].clone();
    exterior.pop();
    exterior.sort_by(|p, q| p.partial_cmp(q).unwrap());
    let want = [
        (0.0, 0.0),
        (0.0, 6.0),
        (7.0 / 6.0, 6.0),
        (6.0, 6.0 / 7.0),
        (6.0, 13.0 / 7.0),
    ];
    assert_eq!(exterior, want);
}

/// The rings of a WKT MULTIPOLYGON read by the `wkt` crate.
fn wkt_rings(text: &str) -> Rings {
    let wkt::Wkt::MultiPolygon(mp) = wkt::Wkt::<f64>::from_str(text.trim()).unwrap() else {
        panic!("not a MULTIPOLYGON: {text}")
    };
    mp.polygons()
        .iter()
        .map(|p| {
            p.rings()
                .iter()
                .map(|r| r.coords().iter().map(|c| (c.x, c.y)).collect())
                .collect()
        })
        .collect()
}

/// The rings of a GeoJSON MultiPolygon read by the `geojson` crate.
fn geojson_rings(text: &str) -> Rings {
    let geojson::GeoJson::Geometry(g) = text.parse::<geojson::GeoJson>().unwrap() else {
        panic!("not a geometry: {text}")
    };
    let geojson::GeometryValue::MultiPolygon { coordinates } = g.value else {
        panic!("not a MultiPolygon: {text}")
    };
    coordinates
        .iter()
        .map(|p| {
            p.iter()
                .map(|r| {
                    r.iter()
                        .map(|pos| match pos.as_slice() {
                            [x, y] => (*x, *y),
                            other => panic!("not 2D: {other:?}"),
                        })
                        .collect()
                })
                .collect()
        })
        .collect()
}

/// Area of the meet by the shoelace formula on its hand-computed vertices, less the hole's 1.
fn meet_area() -> f64 {
    let exterior = [
        (0.0, 0.0),
        (6.0, 6.0 / 7.0),
        (6.0, 13.0 / 7.0),
        (7.0 / 6.0, 6.0),
        (0.0, 6.0),
        (0.0, 0.0),
    ];
    twice_area(&exterior) / 2.0 - 1.0
}

/// geo finds the meet as read valid, with the hand-computed area.
fn check_geometry(geometry: geo::Geometry<f64>) {
    assert!(geometry.is_valid(), "{:?}", geometry.check_validation());
    assert!((geometry.unsigned_area() - meet_area()).abs() < 1e-12);
}

#[test]
fn wkt_output_reads_in_the_wkt_crate_as_valid_ogc_polygons() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = operands(&dir);
    let text = run(&["meet", &a, &b, "--to", "wkt"]);
    assert!(!text.contains('/'), "fractions in default output: {text}");
    check_meet(&wkt_rings(&text));
    check_geometry(
        wkt::Wkt::<f64>::from_str(text.trim())
            .unwrap()
            .try_into()
            .unwrap(),
    );
}

#[test]
fn geojson_output_reads_in_the_geojson_crate_as_valid_rfc7946_polygons() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = operands(&dir);
    let text = run(&["meet", &a, &b, "--to", "geojson"]);
    check_meet(&geojson_rings(&text));
    check_geometry(
        text.parse::<geojson::Geometry>()
            .unwrap()
            .try_into()
            .unwrap(),
    );
}

#[test]
fn both_writers_follow_one_rule() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = operands(&dir);
    // The same numbers in both formats, token for token.
    let numbers = |text: &str| -> Vec<String> {
        text.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
            .filter(|t| !t.is_empty())
            .map(str::to_string)
            .collect()
    };
    let wkt = run(&["meet", &a, &b, "--to", "wkt"]);
    let json = run(&["meet", &a, &b, "--to", "geojson"]);
    assert_eq!(numbers(&wkt), numbers(&json));
    assert!(numbers(&wkt).contains(&"0.8571428571428571".to_string()));
}

#[test]
fn exact_output_on_request() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = operands(&dir);
    let wkt = run(&["meet", &a, &b, "--to", "wkt", "--exact"]);
    assert!(wkt.contains("6 6/7, 6 13/7, 7/6 6"), "{wkt}");
    let out = yinset()
        .args(["meet", &a, &b, "--to", "geojson", "--exact"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("cannot write the result as GeoJSON")
            && stderr.contains("6/7 has no finite decimal expansion"),
        "{stderr}"
    );
    // Integer coordinates are exact decimals in both.
    let square = run(&["meet", &a, &a, "--to", "geojson", "--exact"]);
    assert!(
        square.contains("[[0,0],[6,0],[6,6],[0,6],[0,0]]"),
        "{square}"
    );
}

/// The rings of a geo multipolygon as (x, y) lists.
fn geo_rings(geometry: &geo::Geometry<f64>) -> Rings {
    let geo::Geometry::MultiPolygon(mp) = geometry else {
        panic!("not a MultiPolygon: {geometry:?}")
    };
    let ring = |r: &geo::LineString<f64>| r.coords().map(|c| (c.x, c.y)).collect();
    mp.iter()
        .map(|p| {
            std::iter::once(p.exterior())
                .chain(p.interiors())
                .map(ring)
                .collect()
        })
        .collect()
}

#[test]
fn wkb_output_reads_in_the_wkb_crate_as_valid_ogc_polygons() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = operands(&dir);
    let file = dir.path().join("meet.wkb");
    run(&["meet", &a, &b, "-o", file.to_str().unwrap()]);
    let bytes = std::fs::read(&file).unwrap();
    let geometry = wkb::reader::read_wkb(&bytes).unwrap().to_geometry();
    check_meet(&geo_rings(&geometry));
    check_geometry(geometry);
    // The hex form spells the same bytes.
    let hex = run(&["meet", &a, &b, "--to", "wkb-hex"]);
    assert_eq!(hex::decode(hex.trim()).unwrap(), bytes);
}

#[test]
fn wkb_of_the_wkb_crate_reads_in_either_byte_order() {
    let dir = tempfile::tempdir().unwrap();
    let [a, _] = operands(&dir);
    // The square [0,6]² with the hole [1,2]×[3,4], as geo_types, the hole counterclockwise.
    let ring = |points: Vec<(f64, f64)>| geo::LineString::from(points);
    let square = geo::Polygon::new(
        ring(vec![(0.0, 0.0), (6.0, 0.0), (6.0, 6.0), (0.0, 6.0)]),
        vec![ring(vec![(1.0, 3.0), (2.0, 3.0), (2.0, 4.0), (1.0, 4.0)])],
    );
    let want = run(&["convert", &a, "--to", "wkt"]);
    for endianness in [wkb::Endianness::BigEndian, wkb::Endianness::LittleEndian] {
        let mut bytes = Vec::new();
        let options = wkb::writer::WriteOptions { endianness };
        wkb::writer::write_geometry(&mut bytes, &square, &options).unwrap();
        let file = dir.path().join("square.wkb");
        std::fs::write(&file, &bytes).unwrap();
        let got = run(&["convert", file.to_str().unwrap(), "--to", "wkt"]);
        assert_eq!(got, want, "{endianness:?}");
    }
}
