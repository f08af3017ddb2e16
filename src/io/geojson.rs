//! GeoJSON (RFC 7946): polygonal objects read with exact numbers, multipolygons written.
//!
//! Read: `Polygon`, `MultiPolygon`, `GeometryCollection` (of those), `Feature` (with a
//! polygonal or `null` geometry) and `FeatureCollection`; members may come in any order and
//! foreign members are ignored. Numbers keep their decimal text (`serde_json` with
//! `arbitrary_precision`) and are parsed by [`Num::parse`], so exact backends read them
//! without rounding. Rings must be closed, their first position repeated at the end (RFC 7946
//! §3.1.6), and are returned open. Positions must have exactly two numbers (altitudes are rejected), and the
//! point types `Point`, `LineString`, … are rejected as not polygonal. An empty `coordinates`
//! array is an empty geometry. Errors caused by the content rather than the JSON syntax are
//! located at the end of the innermost object that holds them, and name the offending member
//! (e.g. `coordinates[0][3]`).
//!
//! Written: a `MultiPolygon` geometry object, each ring closed by repeating its first point,
//! coordinates as [`NumberStyle`] says: by default the shortest decimal of the nearest `f64`;
//! exactly on request, which fails for a number without a finite decimal expansion (1/3),
//! since JSON has no fractions.

use super::{ogc_ring, polygon_texts, without_bom, NumberStyle, ParseError, Polygon, WriteError};
use crate::kernel::Point;
use crate::num::Num;
use serde::de::value::MapAccessDeserializer;
use serde::de::{self, Deserialize, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Value};
use std::fmt;
use std::marker::PhantomData;

/// What the reader accepts, for the message rejecting other geometries.
const POLYGONAL_ONLY: &str = "only Polygon, MultiPolygon and GeometryCollection are read";

/// One feature: its properties (empty for `null` or for a bare geometry) and its polygons.
#[derive(Debug, Clone, PartialEq)]
pub struct Feature<N> {
    /// The feature's `properties` member, numbers kept as their text.
    pub properties: Map<String, Value>,
    /// The polygons of the feature's geometry (none for a `null` geometry).
    pub polygons: Vec<Polygon<N>>,
}

/// Read the features of a GeoJSON text: a `FeatureCollection`'s in order, a `Feature`, or a
/// bare geometry as one feature without properties.
pub fn read_features<N: Num>(text: &str) -> Result<Vec<Feature<N>>, ParseError> {
    read_with::<N, false>(text)
}

/// Read the features of a GeoJSON text as [`read_features`] does, but with the geometries that
/// have no area (`Point`, `LineString`, …) read as empty instead of rejected.
pub fn read_polygonal_features<N: Num>(text: &str) -> Result<Vec<Feature<N>>, ParseError> {
    read_with::<N, true>(text)
}

/// Read the features of a GeoJSON text, skipping the geometries without area if `SKIP_LOWER`.
fn read_with<N: Num, const SKIP_LOWER: bool>(text: &str) -> Result<Vec<Feature<N>>, ParseError> {
    let text = without_bom(text);
    let object: Object<N, SKIP_LOWER> =
        serde_json::from_str(text).map_err(|e| json_error(text, &e))?;
    Ok(match object {
        Object::Geometry(polygons) => vec![Feature {
            properties: Map::new(),
            polygons,
        }],
        Object::Feature(feature) => vec![feature],
        Object::Collection(features) => features,
    })
}

/// Read all polygons of a GeoJSON text, features flattened in order.
pub fn read_polygons<N: Num>(text: &str) -> Result<Vec<Polygon<N>>, ParseError> {
    Ok(flatten(read_features(text)?))
}

/// Read all polygons of a GeoJSON text, features flattened in order, skipping the geometries
/// that have no area (such as the `Point`s of a `FeatureCollection`).
pub fn read_polygonal_parts<N: Num>(text: &str) -> Result<Vec<Polygon<N>>, ParseError> {
    Ok(flatten(read_polygonal_features(text)?))
}

/// The polygons of `features`, in order.
fn flatten<N>(features: Vec<Feature<N>>) -> Vec<Polygon<N>> {
    features.into_iter().flat_map(|f| f.polygons).collect()
}

/// The GeoJSON `MultiPolygon` geometry object of `polys`, coordinates in `style` (see the
/// module documentation).
pub fn write_multipolygon<N: Num>(
    polys: &[Polygon<N>],
    style: NumberStyle,
) -> Result<String, WriteError> {
    let point = |x, y| format!("[{x},{y}]");
    let parts = polygon_texts(polys, style, false, point, ["[", "]"], ",")?;
    Ok(format!(
        r#"{{"type":"MultiPolygon","coordinates":[{}]}}"#,
        parts.join(",")
    ))
}

/// The [`ParseError`] of a `serde_json` error (whose columns count bytes) in `text`.
fn json_error(text: &str, e: &serde_json::Error) -> ParseError {
    let line_start: usize = text
        .split_inclusive('\n')
        .take(e.line().saturating_sub(1))
        .map(str::len)
        .sum();
    let message = e.to_string();
    let message = message
        .strip_suffix(&format!(" at line {} column {}", e.line(), e.column()))
        .unwrap_or(&message);
    let message = match e.classify() {
        serde_json::error::Category::Eof => format!("truncated JSON: {message}"),
        serde_json::error::Category::Syntax => format!("invalid JSON: {message}"),
        _ => message.to_string(),
    };
    ParseError::at(text, line_start + e.column().saturating_sub(1), message)
}

/// A GeoJSON object, checked as soon as its members are read; geometries without area are
/// read as empty if `SKIP_LOWER`, else rejected.
enum Object<N, const SKIP_LOWER: bool> {
    /// A polygonal geometry.
    Geometry(Vec<Polygon<N>>),
    /// A `Feature`.
    Feature(Feature<N>),
    /// A `FeatureCollection`.
    Collection(Vec<Feature<N>>),
}

impl<'de, N: Num, const SKIP_LOWER: bool> Deserialize<'de> for Object<N, SKIP_LOWER> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_map(ObjectVisitor(PhantomData))
    }
}

/// The members of a GeoJSON object that this reader uses.
struct Members<N, const SKIP_LOWER: bool> {
    kind: Option<String>,
    coordinates: Option<Coords<N>>,
    geometry: Option<Option<Object<N, SKIP_LOWER>>>,
    geometries: Option<Vec<Object<N, SKIP_LOWER>>>,
    features: Option<Vec<Object<N, SKIP_LOWER>>>,
    properties: Option<Map<String, Value>>,
}

/// Reads a JSON object as an [`Object`].
struct ObjectVisitor<N, const SKIP_LOWER: bool>(PhantomData<N>);

impl<'de, N: Num, const SKIP_LOWER: bool> Visitor<'de> for ObjectVisitor<N, SKIP_LOWER> {
    type Value = Object<N, SKIP_LOWER>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a GeoJSON object")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Object<N, SKIP_LOWER>, A::Error> {
        let mut m = Members {
            kind: None,
            coordinates: None,
            geometry: None,
            geometries: None,
            features: None,
            properties: None,
        };
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                "type" => m.kind = Some(map.next_value()?),
                "coordinates" => m.coordinates = Some(map.next_value()?),
                "geometry" => m.geometry = Some(map.next_value()?),
                "geometries" => m.geometries = Some(map.next_value()?),
                "features" => m.features = Some(map.next_value()?),
                "properties" => m.properties = map.next_value()?,
                _ => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
        }
        m.build().map_err(de::Error::custom)
    }
}

impl<N: Num, const SKIP_LOWER: bool> Members<N, SKIP_LOWER> {
    /// The object these members make, or what is wrong with them.
    fn build(self) -> Result<Object<N, SKIP_LOWER>, String> {
        let kind = self.kind.ok_or("a GeoJSON object needs a `type` member")?;
        let missing = |member: &str| format!("a {kind} needs a `{member}` member");
        match kind.as_str() {
            "Polygon" => {
                let coordinates = self.coordinates.ok_or_else(|| missing("coordinates"))?;
                Ok(Object::Geometry(
                    polygon(coordinates, "coordinates")?.into_iter().collect(),
                ))
            }
            "MultiPolygon" => {
                let coordinates = self.coordinates.ok_or_else(|| missing("coordinates"))?;
                let parts = indexed(coordinates, "coordinates")?;
                let polygons: Result<Vec<_>, String> =
                    parts.map(|(c, path)| polygon(c, &path)).collect();
                Ok(Object::Geometry(polygons?.into_iter().flatten().collect()))
            }
            "GeometryCollection" => {
                let geometries = self.geometries.ok_or_else(|| missing("geometries"))?;
                let mut polygons = Vec::new();
                for (i, object) in geometries.into_iter().enumerate() {
                    polygons.extend(geometry(Some(object), &format!("geometries[{i}]"))?);
                }
                Ok(Object::Geometry(polygons))
            }
            "Feature" => Ok(Object::Feature(Feature {
                properties: self.properties.unwrap_or_default(),
                polygons: geometry(
                    self.geometry.ok_or_else(|| missing("geometry"))?,
                    "geometry",
                )?,
            })),
            "FeatureCollection" => {
                let features = self.features.ok_or_else(|| missing("features"))?;
                let features = features
                    .into_iter()
                    .enumerate()
                    .map(|(i, object)| match object {
                        Object::Feature(feature) => Ok(feature),
                        _ => Err(format!("`features[{i}]` is not a Feature")),
                    });
                Ok(Object::Collection(features.collect::<Result<_, _>>()?))
            }
            "Point" | "MultiPoint" | "LineString" | "MultiLineString" if SKIP_LOWER => {
                Ok(Object::Geometry(Vec::new()))
            }
            "Point" | "MultiPoint" | "LineString" | "MultiLineString" => {
                Err(format!("`{kind}` is not polygonal: {POLYGONAL_ONLY}"))
            }
            _ => Err(format!("unknown GeoJSON type `{kind}`")),
        }
    }
}

/// The polygons of the geometry member at `path` (none for `null`).
fn geometry<N, const SKIP_LOWER: bool>(
    object: Option<Object<N, SKIP_LOWER>>,
    path: &str,
) -> Result<Vec<Polygon<N>>, String> {
    match object {
        None => Ok(Vec::new()),
        Some(Object::Geometry(polygons)) => Ok(polygons),
        Some(_) => Err(format!("`{path}` is not a geometry")),
    }
}

/// A `coordinates` value: nested arrays of numbers, typed only once the object's `type` is
/// known (it may come after the coordinates).
enum Coords<N> {
    /// A number.
    Number(N),
    /// An array.
    Array(Vec<Coords<N>>),
}

impl<'de, N: Num> Deserialize<'de> for Coords<N> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(CoordsVisitor(PhantomData))
    }
}

/// Reads a JSON number or array as [`Coords`].
struct CoordsVisitor<N>(PhantomData<N>);

impl<'de, N: Num> Visitor<'de> for CoordsVisitor<N> {
    type Value = Coords<N>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number or an array of coordinates")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Coords<N>, A::Error> {
        let mut items = Vec::new();
        while let Some(item) = seq.next_element()? {
            items.push(item);
        }
        let numbers = items
            .iter()
            .filter(|c| matches!(c, Coords::Number(_)))
            .count();
        if numbers == items.len() && numbers != 2 && numbers != 0 {
            return Err(de::Error::custom(format!(
                "expected a position [x, y] of 2 numbers, found {numbers} (only 2D is supported)"
            )));
        }
        Ok(Coords::Array(items))
    }

    /// An integer that fits 64 bits (`serde_json` passes those as integers).
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Coords<N>, E> {
        number(&v.to_string())
    }

    /// A negative integer that fits 64 bits.
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Coords<N>, E> {
        number(&v.to_string())
    }

    /// With `arbitrary_precision`, any other JSON number arrives as a one-member map holding
    /// its text.
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Coords<N>, A::Error> {
        let text = serde_json::Number::deserialize(MapAccessDeserializer::new(map))
            .map_err(|_: A::Error| de::Error::invalid_type(de::Unexpected::Map, &self))?;
        number(text.as_str())
    }
}

/// The number of JSON number text `text`, read by [`Num::parse`].
fn number<N: Num, E: de::Error>(text: &str) -> Result<Coords<N>, E> {
    N::parse(text).map(Coords::Number).map_err(E::custom)
}

/// The items of the array at `path`, each with its own path.
fn indexed<N>(
    coords: Coords<N>,
    path: &str,
) -> Result<impl Iterator<Item = (Coords<N>, String)>, String> {
    match coords {
        Coords::Array(items) => {
            let path = path.to_string();
            Ok(items
                .into_iter()
                .enumerate()
                .map(move |(i, c)| (c, format!("{path}[{i}]"))))
        }
        Coords::Number(_) => Err(format!("`{path}` should be an array, found a number")),
    }
}

/// The polygon at `path` (none for an empty array).
fn polygon<N: Num>(coords: Coords<N>, path: &str) -> Result<Option<Polygon<N>>, String> {
    let mut rings = indexed(coords, path)?.map(|(c, path)| ring(c, &path));
    let Some(exterior) = rings.next().transpose()? else {
        return Ok(None);
    };
    Ok(Some(Polygon {
        exterior,
        interiors: rings.collect::<Result<_, _>>()?,
    }))
}

/// The closed ring at `path`, returned open.
fn ring<N: Num>(coords: Coords<N>, path: &str) -> Result<Vec<Point<N>>, String> {
    let points: Result<Vec<_>, String> = indexed(coords, path)?
        .map(|(c, path)| position(c, &path))
        .collect();
    ogc_ring(points?).map_err(|e| format!("`{path}`: {e}"))
}

/// The position `[x, y]` at `path`.
fn position<N>(coords: Coords<N>, path: &str) -> Result<Point<N>, String> {
    let items: Vec<Coords<N>> = indexed(coords, path)?.map(|(c, _)| c).collect();
    match <[Coords<N>; 2]>::try_from(items) {
        Ok([Coords::Number(x), Coords::Number(y)]) => Ok(Point { x, y }),
        _ => Err(format!(
            "`{path}` should be a position [x, y] of two numbers"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::testdata;
    use crate::num::Rational;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    fn read(text: &str) -> Result<Vec<Polygon<Rational>>, ParseError> {
        read_polygons(text)
    }

    #[test]
    fn reads_geometries_exactly_in_any_member_order() {
        let text = r#"{"coordinates": [[[0.1, 0], [1, 0], [1, 1e-30], [0.1, 0]], [[0.2, 0.1], [0.3, 0.1], [0.3, 0.2], [0.2, 0.1]]],
                       "bbox": [0, 0, 1, 1], "type": "Polygon"}"#;
        let polys = read(text).unwrap();
        assert_eq!(polys.len(), 1);
        assert_eq!(polys[0].exterior.len(), 3);
        assert_eq!(polys[0].exterior[0], Point::new(q("1/10"), q("0")));
        assert_eq!(
            polys[0].exterior[2].y,
            q("1/1000000000000000000000000000000")
        );
        assert_eq!(polys[0].interiors[0][2], Point::new(q("3/10"), q("1/5")));
        let multi = r#"{"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[1,1],[0,0]]], [], [[[5,5],[6,5],[6,6],[5,5]]]]}"#;
        assert_eq!(read(multi).unwrap().len(), 2);
        let collection =
            format!(r#"{{"type": "GeometryCollection", "geometries": [{multi}, {text}]}}"#);
        assert_eq!(read(&collection).unwrap().len(), 3);
        assert!(read(r#"{"type": "Polygon", "coordinates": []}"#)
            .unwrap()
            .is_empty());
    }

    #[test]
    fn reads_features_with_their_properties() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {"operation": "union", "n": 1.50}, "geometry":
                {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]}},
            {"type": "Feature", "properties": null, "geometry": null},
            {"type": "Feature", "geometry": {"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[1,1],[0,0]]], [[[2,0],[3,0],[3,1],[2,0]]]]}}
        ]}"#;
        let features = read_features::<Rational>(text).unwrap();
        assert_eq!(features.len(), 3);
        assert_eq!(features[0].properties["operation"], "union");
        assert_eq!(features[0].properties["n"].to_string(), "1.50");
        assert_eq!(
            features
                .iter()
                .map(|f| f.polygons.len())
                .collect::<Vec<_>>(),
            [1, 0, 2]
        );
        assert!(features[1].properties.is_empty());
        assert_eq!(read(text).unwrap().len(), 3);
        let bare = read_features::<Rational>(
            r#"{"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]}"#,
        );
        assert_eq!(bare.unwrap().len(), 1);
    }

    #[test]
    fn write_then_read_is_exact_for_terminating_decimals() {
        let polys = vec![
            Polygon {
                exterior: vec![
                    Point::int(0, 0),
                    Point::new(q("1/8"), q("-0.1")),
                    Point::new(q("1e-20"), q("12345678901234567890123")),
                ],
                interiors: vec![vec![Point::int(1, 1), Point::int(2, 1), Point::int(1, 2)]],
            },
            Polygon {
                exterior: vec![Point::int(5, 5), Point::int(6, 5), Point::int(6, 6)],
                interiors: vec![],
            },
        ];
        let text = write_multipolygon(&polys, NumberStyle::Exact).unwrap();
        assert!(text.starts_with(r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[0.125,-0.1],[0.00000000000000000001,12345678901234567890123],[0,0]],"#), "{text}");
        assert_eq!(read(&text).unwrap(), polys);
        let third = vec![Polygon {
            exterior: vec![
                Point::new(q("1/3"), q("-2/3")),
                Point::int(1, 0),
                Point::int(0, 1),
            ],
            interiors: vec![],
        }];
        let e = write_multipolygon(&third, NumberStyle::Exact).unwrap_err();
        assert!(e.to_string().contains("1/3 has no finite decimal"), "{e}");
        assert_eq!(
            write_multipolygon(&third, NumberStyle::Decimal).unwrap(),
            r#"{"type":"MultiPolygon","coordinates":[[[[0.3333333333333333,-0.6666666666666666],[1,0],[0,1],[0.3333333333333333,-0.6666666666666666]]]]}"#
        );
        for style in [NumberStyle::Exact, NumberStyle::Decimal] {
            let empty = write_multipolygon::<Rational>(&[], style).unwrap();
            assert_eq!(empty, r#"{"type":"MultiPolygon","coordinates":[]}"#);
            assert!(read(&empty).unwrap().is_empty());
        }
    }

    #[test]
    fn errors_name_what_and_where() {
        let cases = [
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, "x"], [0, 1]]]}"#,
                (1, 52),
                "invalid type: string \"x\", expected a number or an array",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1], [0, 1]]]}"#,
                (1, 48),
                "expected a position [x, y] of 2 numbers, found 1",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0, 0], [1, 0], [0, 1]]]}"#,
                (1, 46),
                "found 3 (only 2D is supported)",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[0, 0], [1, 0]]}"#,
                (1, 52),
                "`coordinates[0][0]` should be an array, found a number",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]]]}"#,
                (1, 64),
                "`coordinates[0][0]` should be a position [x, y] of two numbers",
            ),
            (
                r#"{"type": "MultiPolygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}"#,
                (1, 67),
                "`coordinates[0][0][0]` should be an array, found a number",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, {"a": 1}]]]}"#,
                (1, 45),
                "invalid type: map, expected a number or an array",
            ),
            (
                "{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1, 0], [0, 1]]",
                (2, 41),
                "truncated JSON: EOF while parsing a list",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]]}"#,
                (1, 62),
                "invalid JSON: expected `,` or `}`",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 1e99999999], [0, 1]]]}"#,
                (1, 59),
                "has an exponent outside",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, NaN], [0, 1]]]}"#,
                (1, 50),
                "invalid JSON: expected value",
            ),
            (
                r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, -Infinity], [0, 1]]]}"#,
                (1, 51),
                "invalid JSON: invalid number",
            ),
            (
                r#"{"type": "Polygon"}"#,
                (1, 19),
                "a Polygon needs a `coordinates` member",
            ),
            (
                r#"{"type": "Polygonal", "coordinates": []}"#,
                (1, 40),
                "unknown GeoJSON type `Polygonal`",
            ),
            (
                r#"{"type": "LineString", "coordinates": [[0, 0], [1, 1]]}"#,
                (1, 55),
                "`LineString` is not polygonal",
            ),
            (r#"{"coordinates": []}"#, (1, 19), "needs a `type` member"),
            (
                r#"{"type": "FeatureCollection", "features": [{"type": "Polygon", "coordinates": []}]}"#,
                (1, 83),
                "`features[0]` is not a Feature",
            ),
            (
                r#"{"type": "Feature", "properties": {}}"#,
                (1, 37),
                "a Feature needs a `geometry` member",
            ),
            (
                r#"{"type": "Feature", "geometry": {"type": "Feature", "geometry": null}}"#,
                (1, 70),
                "`geometry` is not a geometry",
            ),
            (
                r#"{"type": "GeometryCollection", "geometries": [{"type": "Point", "coordinates": [0, 0]}]}"#,
                (1, 86),
                "`Point` is not polygonal",
            ),
            (
                r#"{"type": "Feature", "properties": 5, "geometry": null}"#,
                (1, 35),
                "invalid type: integer `5`, expected a map",
            ),
            (
                "[1, 2]",
                (1, 1),
                "invalid type: sequence, expected a GeoJSON object",
            ),
            (
                "\n\n  \"é\" 5",
                (3, 5),
                "invalid type: string \"é\", expected a GeoJSON object",
            ),
        ];
        for (text, (line, column), message) in cases {
            let e = read(text).unwrap_err();
            assert!(e.message.contains(message), "{text}: {e}");
            assert_eq!((e.line, e.column), (line, column), "{text}: {e}");
        }
    }

    #[test]
    fn polygonal_parts_skip_points_and_lines() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {"name": "capital"}, "geometry": {"type": "Point", "coordinates": [1, 2]}},
            {"type": "Feature", "properties": null, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]}},
            {"type": "Feature", "properties": null, "geometry": {"type": "GeometryCollection", "geometries": [
                {"type": "LineString", "coordinates": [[0, 0], [1, 1]]},
                {"type": "MultiPoint", "coordinates": [[0, 0], [1, 1]]},
                {"type": "MultiLineString", "coordinates": [[[0, 0], [1, 1]]]},
                {"type": "MultiPolygon", "coordinates": [[[[2,0],[3,0],[3,1],[2,0]]]]}]}}
        ]}"#;
        let e = read(text).unwrap_err();
        assert!(e.message.contains("`Point` is not polygonal"), "{e}");
        let polys = read_polygonal_parts::<Rational>(text).unwrap();
        assert_eq!(polys.len(), 2);
        assert_eq!(polys[1].exterior[0], Point::int(2, 0));
        let features = read_polygonal_features::<Rational>(text).unwrap();
        assert_eq!(features[0].properties["name"], "capital");
        assert!(features[0].polygons.is_empty());
        // Still checked: the JSON, the types, the positions.
        for bad in [
            r#"{"type": "Point", "coordinates": [1, 2, 3]}"#,
            r#"{"type": "Pointy", "coordinates": [1, 2]}"#,
            r#"{"type": "Point", "coordinates": [1, 2]"#,
        ] {
            assert!(read_polygonal_parts::<Rational>(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn a_byte_order_mark_is_ignored() {
        let text = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]}"#;
        assert_eq!(read(&format!("\u{feff}{text}")), read(text));
        let e = read("\u{feff}[1]").unwrap_err();
        assert_eq!((e.line, e.column), (1, 1));
    }

    #[test]
    fn adversarial_inputs_never_panic() {
        for text in [
            "",
            "\n\n \n",
            "null",
            "5",
            "1e99999999",
            "\"Polygon\"",
            "{",
            "}",
            "{\"type\": \"Polygon\", \"coordinates\": [[[0,",
        ] {
            assert!(read(text).is_err(), "{text:?} accepted");
        }
        let deep = format!(
            r#"{{"type": "Polygon", "coordinates": {}0{}}}"#,
            "[".repeat(100_000),
            "]".repeat(100_000)
        );
        assert!(read(&deep).unwrap_err().message.contains("recursion limit"));
        let nested = format!(
            "{}{}",
            r#"{"type": "GeometryCollection", "geometries": ["#.repeat(10_000),
            "]}".repeat(10_000)
        );
        assert!(read(&nested)
            .unwrap_err()
            .message
            .contains("recursion limit"));
    }

    #[test]
    fn martinez_fixtures_parse() {
        if !testdata::available() {
            return;
        }
        let files = testdata::files("2d/martinez", ".geojson");
        assert_eq!(files.len(), 25);
        let (mut features, mut polygons) = (0, 0);
        for (name, text) in &files {
            let read = read_features::<Rational>(text).unwrap_or_else(|e| panic!("{name}: {e}"));
            features += read.len();
            polygons += read.iter().map(|f| f.polygons.len()).sum::<usize>();
            assert!(
                read[2..]
                    .iter()
                    .all(|f| f.properties.contains_key("operation")),
                "{name}"
            );
        }
        assert_eq!((features, polygons), (96, 228));
    }

    #[test]
    fn gis_fixtures_parse() {
        if !testdata::available() {
            return;
        }
        let counts: Vec<(String, usize, usize, usize)> = testdata::files("2d/gis", ".geojson")
            .into_iter()
            .map(|(name, text)| {
                let features =
                    read_features::<Rational>(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
                let polygons: Vec<&Polygon<Rational>> =
                    features.iter().flat_map(|f| &f.polygons).collect();
                let points = polygons
                    .iter()
                    .flat_map(|p| p.rings())
                    .map(|r| r.len() + 1)
                    .sum();
                (name, features.len(), polygons.len(), points)
            })
            .collect();
        let expected = [
            ("asia.geojson", 3, 376, 28616),
            ("hole_hole.geojson", 3, 2, 20),
            ("states_source.geojson", 3, 39, 2316),
        ];
        let expected: Vec<_> = expected
            .iter()
            .map(|&(n, f, p, c)| (n.to_string(), f, p, c))
            .collect();
        assert_eq!(counts, expected);
    }
}
