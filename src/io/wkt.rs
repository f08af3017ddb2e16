//! Well-known text (OGC WKT): polygonal geometries read, multipolygons written, numbers exact.
//!
//! Read: `POLYGON`, `MULTIPOLYGON` and `GEOMETRYCOLLECTION`s of them (nested collections too),
//! each possibly `EMPTY`; keywords are case-insensitive. Coordinates are two numbers per
//! point, read exactly (decimals, and also fractions `p/q`, which are not OGC WKT). Rings must
//! be closed, their first point repeated at the end, as OGC requires (an unclosed ring is an
//! error at its `(`), and are returned open. Z and M
//! coordinates and non-polygonal types (`POINT`, `LINESTRING`, …) are rejected with an error,
//! except by [`read_polygonal_parts`], which skips the points and curves of any geometry.
//!
//! Written: a `MULTIPOLYGON` with each ring closed by repeating its first point, as OGC
//! requires; coordinates as [`NumberStyle`] says (by default the shortest decimal of the
//! nearest `f64`, which every WKT reader accepts; exactly on request, with fractions `p/q`
//! where the expansion does not terminate).

use super::error::line_column;
use super::{ogc_ring, polygon_texts, without_bom, NumberStyle, ParseError, Polygon, WriteError};
use crate::kernel::Point;
use crate::num::Num;

/// Deepest nesting of `GEOMETRYCOLLECTION`s read (bounds the parser's recursion).
const MAX_NESTING: usize = 64;

/// The one-character tokens.
const PUNCTUATION: [&str; 3] = ["(", ")", ","];

/// What the reader accepts, for the message rejecting other geometries.
const POLYGONAL_ONLY: &str = "only POLYGON, MULTIPOLYGON and GEOMETRYCOLLECTION are read";

/// Geometry types of WKT that have no area, rejected with a specific message.
const NON_POLYGONAL: [&str; 10] = [
    "POINT",
    "MULTIPOINT",
    "LINESTRING",
    "LINEARRING",
    "MULTILINESTRING",
    "CIRCULARSTRING",
    "COMPOUNDCURVE",
    "MULTICURVE",
    "TRIANGLE",
    "TIN",
];

/// Geometry types of dimension 0 or 1, which [`read_polygonal_parts`] skips.
const LOWER_DIMENSIONAL: [&str; 8] = [
    "POINT",
    "MULTIPOINT",
    "LINESTRING",
    "LINEARRING",
    "MULTILINESTRING",
    "CIRCULARSTRING",
    "COMPOUNDCURVE",
    "MULTICURVE",
];

/// Read the polygons of one WKT geometry (a collection's polygons in order, a multipolygon's
/// parts, one polygon, or none for `EMPTY`).
pub fn read_polygons<N: Num>(text: &str) -> Result<Vec<Polygon<N>>, ParseError> {
    read(text, false)
}

/// Read the polygons of one WKT geometry of any type, skipping its points and curves (the parts
/// that have no area, such as the `LINESTRING`s of an overlay result's `GEOMETRYCOLLECTION`).
pub fn read_polygonal_parts<N: Num>(text: &str) -> Result<Vec<Polygon<N>>, ParseError> {
    read(text, true)
}

/// Read one geometry, skipping lower-dimensional parts if `skip_lower`.
fn read<N: Num>(text: &str, skip_lower: bool) -> Result<Vec<Polygon<N>>, ParseError> {
    let text = without_bom(text);
    let mut parser = Parser {
        text,
        pos: 0,
        skip_lower,
    };
    let polygons = parser.geometry(0)?;
    match parser.next() {
        None => Ok(polygons),
        Some((at, ")")) => Err(parser.error(at, "unbalanced parentheses: unexpected `)`")),
        Some((at, token)) => {
            Err(parser.error(at, format!("unexpected `{token}` after the geometry")))
        }
    }
}

/// The WKT `MULTIPOLYGON` of `polys` (`MULTIPOLYGON EMPTY` for none), coordinates in
/// `style`; rings must be non-empty.
pub fn write_multipolygon<N: Num>(
    polys: &[Polygon<N>],
    style: NumberStyle,
) -> Result<String, WriteError> {
    if polys.is_empty() {
        return Ok("MULTIPOLYGON EMPTY".to_string());
    }
    let point = |x, y| format!("{x} {y}");
    let parts = polygon_texts(polys, style, true, point, ["(", ")"], ", ")?;
    Ok(format!("MULTIPOLYGON ({})", parts.join(", ")))
}

/// A recursive-descent reader over the text; tokens are `(`, `)`, `,` and maximal runs of
/// other non-blank characters (words and numbers).
struct Parser<'a> {
    text: &'a str,
    pos: usize,
    skip_lower: bool,
}

impl<'a> Parser<'a> {
    /// The next token and its byte offset, without consuming it.
    fn peek(&mut self) -> Option<(usize, &'a str)> {
        let rest = &self.text[self.pos..];
        let start = self.pos + (rest.len() - rest.trim_start().len());
        let tail = &self.text[start..];
        let len = match tail.chars().next()? {
            '(' | ')' | ',' => 1,
            _ => tail
                .find(|c: char| c.is_whitespace() || "(),".contains(c))
                .unwrap_or(tail.len()),
        };
        Some((start, &tail[..len]))
    }

    /// The next token and its byte offset.
    fn next(&mut self) -> Option<(usize, &'a str)> {
        let token = self.peek();
        if let Some((at, t)) = token {
            self.pos = at + t.len();
        }
        token
    }

    /// Consume the next token if it is the keyword `word` (case-insensitive).
    fn keyword(&mut self, word: &str) -> bool {
        let found = matches!(self.peek(), Some((_, t)) if t.eq_ignore_ascii_case(word));
        if found {
            self.next();
        }
        found
    }

    /// Consume and return the next token if it is a word or number (not punctuation).
    fn word(&mut self) -> Option<(usize, &'a str)> {
        let token = self.peek().filter(|(_, t)| !PUNCTUATION.contains(t))?;
        self.next();
        Some(token)
    }

    /// The error `message` at byte `at`.
    fn error(&self, at: usize, message: impl Into<String>) -> ParseError {
        ParseError::at(self.text, at, message)
    }

    /// The error for a missing `what` where the next token (or the end) is.
    fn expected(&mut self, what: &str) -> ParseError {
        match self.peek() {
            Some((at, token)) => self.error(at, format!("expected {what}, found `{token}`")),
            None => self.error(
                self.text.len(),
                format!("expected {what}, found the end of the input"),
            ),
        }
    }

    /// One tagged geometry, `depth` collections deep.
    fn geometry<N: Num>(&mut self, depth: usize) -> Result<Vec<Polygon<N>>, ParseError> {
        let Some((at, word)) = self.word() else {
            return Err(self.expected("a geometry type such as POLYGON"));
        };
        let upper = word.to_ascii_uppercase();
        let glued = ["ZM", "Z", "M"]
            .iter()
            .any(|d| upper.strip_suffix(d).is_some_and(known));
        if glued || (known(&upper) && ["Z", "M", "ZM"].iter().any(|d| self.keyword(d))) {
            let message = format!("`{word}` with Z or M coordinates: only 2D is supported");
            return Err(self.error(at, message));
        }
        if self.skip_lower && LOWER_DIMENSIONAL.contains(&upper.as_str()) {
            if !self.keyword("EMPTY") {
                self.list(Self::skip_item)?;
            }
            return Ok(Vec::new());
        }
        if NON_POLYGONAL.contains(&upper.as_str()) {
            let message = format!("`{word}` is not polygonal: {POLYGONAL_ONLY}");
            return Err(self.error(at, message));
        }
        if !known(&upper) {
            return Err(self.error(at, format!("unknown geometry type `{word}`")));
        }
        if self.keyword("EMPTY") {
            return Ok(Vec::new());
        }
        match upper.as_str() {
            "POLYGON" => Ok(vec![self.polygon()?]),
            "MULTIPOLYGON" => Ok(self.list(Self::part)?.into_iter().flatten().collect()),
            _ if depth >= MAX_NESTING => {
                let message = format!("geometry collections nested deeper than {MAX_NESTING}");
                Err(self.error(at, message))
            }
            _ => Ok(self.list(|p| p.geometry(depth + 1))?.concat()),
        }
    }

    /// `( item, item, … )`.
    fn list<T>(
        &mut self,
        mut item: impl FnMut(&mut Self) -> Result<T, ParseError>,
    ) -> Result<Vec<T>, ParseError> {
        let Some((open, "(")) = self.peek() else {
            return Err(self.expected("`(`"));
        };
        self.next();
        let mut items = vec![item(self)?];
        loop {
            match self.next() {
                Some((_, ",")) => items.push(item(self)?),
                Some((_, ")")) => return Ok(items),
                Some((at, token)) => {
                    return Err(self.error(at, format!("expected `,` or `)`, found `{token}`")))
                }
                None => {
                    let (line, column) = line_column(self.text, open);
                    let message = format!(
                        "unbalanced parentheses: `(` at line {line}, column {column} not closed"
                    );
                    return Err(self.error(self.text.len(), message));
                }
            }
        }
    }

    /// One item of a skipped list: words and parenthesized lists, in any sequence.
    fn skip_item(&mut self) -> Result<(), ParseError> {
        loop {
            match self.peek() {
                Some((_, "(")) => {
                    self.list(Self::skip_item)?;
                }
                Some((_, ")" | ",")) | None => return Ok(()),
                Some(_) => {
                    self.next();
                }
            }
        }
    }

    /// `( ring, ring, … )`: the exterior, then the holes.
    fn polygon<N: Num>(&mut self) -> Result<Polygon<N>, ParseError> {
        let mut rings = self.list(Self::ring)?.into_iter();
        let exterior = rings.next().unwrap_or_default();
        Ok(Polygon {
            exterior,
            interiors: rings.collect(),
        })
    }

    /// `( point, point, … )`, a closed ring, returned open.
    fn ring<N: Num>(&mut self) -> Result<Vec<Point<N>>, ParseError> {
        let at = self.peek().map_or(self.text.len(), |(at, _)| at);
        let points = self.list(Self::point)?;
        ogc_ring(points).map_err(|message| self.error(at, message))
    }

    /// A multipolygon's part: a polygon, or `EMPTY`.
    fn part<N: Num>(&mut self) -> Result<Option<Polygon<N>>, ParseError> {
        if self.keyword("EMPTY") {
            return Ok(None);
        }
        self.polygon().map(Some)
    }

    /// `x y`.
    fn point<N: Num>(&mut self) -> Result<Point<N>, ParseError> {
        let point = Point::new(self.number()?, self.number()?);
        match self.word() {
            Some((at, token)) => Err(self.error(
                at,
                format!(
                    "a point has 2 coordinates, found more: `{token}` (Z and M are not supported)"
                ),
            )),
            None => Ok(point),
        }
    }

    /// A number token, read exactly.
    fn number<N: Num>(&mut self) -> Result<N, ParseError> {
        match self.word() {
            Some((at, token)) => N::parse(token).map_err(|e| self.error(at, e.to_string())),
            None => Err(self.expected("a number")),
        }
    }
}

/// Whether `upper` is a WKT geometry type this reader knows, polygonal or not.
fn known(upper: &str) -> bool {
    ["POLYGON", "MULTIPOLYGON", "GEOMETRYCOLLECTION"].contains(&upper)
        || NON_POLYGONAL.contains(&upper)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::testdata;
    use crate::num::Rational;

    fn read(text: &str) -> Result<Vec<Polygon<Rational>>, ParseError> {
        read_polygons(text)
    }

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    fn square(x: i64, size: i64) -> Vec<Point<Rational>> {
        let p = Point::int;
        vec![p(x, 0), p(x + size, 0), p(x + size, size), p(x, size)]
    }

    #[test]
    fn reads_polygons_with_holes_exactly() {
        let polys = read("polygon((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 0.1 2, 1 1))").unwrap();
        assert_eq!(polys.len(), 1);
        assert_eq!(polys[0].exterior, square(0, 4));
        assert_eq!(polys[0].interiors.len(), 1);
        assert_eq!(polys[0].interiors[0][2], Point::new(q("1/10"), q("2")));
        let multi =
            read(" MultiPolygon (((0 0,1 0,1 1,0 1,0 0)),\n ((5 0, 7 0, 7 2, 5 2, 5 0)) ) ")
                .unwrap();
        assert_eq!(multi.len(), 2);
        assert_eq!(multi[1].exterior, square(5, 2));
    }

    #[test]
    fn reads_empty_and_collections() {
        assert!(read("POLYGON EMPTY").unwrap().is_empty());
        assert!(read("multipolygon empty").unwrap().is_empty());
        assert!(read("GEOMETRYCOLLECTION EMPTY").unwrap().is_empty());
        let multi = read("MULTIPOLYGON (EMPTY, ((0 0, 1 0, 1 1, 0 0)), EMPTY)").unwrap();
        assert_eq!(multi.len(), 1);
        let text =
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)), GEOMETRYCOLLECTION (POLYGON EMPTY,\
                    MULTIPOLYGON (((2 2, 3 2, 3 3, 2 2)), ((4 4, 5 4, 5 5, 4 4)))))";
        assert_eq!(read(text).unwrap().len(), 3);
    }

    #[test]
    fn write_then_read_round_trips_exact_rationals() {
        let polys = vec![
            Polygon {
                exterior: vec![
                    Point::int(0, 0),
                    Point::new(q("1/3"), q("0")),
                    Point::new(q("1/3"), q("-2/7")),
                ],
                interiors: vec![
                    square(0, 1),
                    vec![Point::new(q("0.1"), q("1e-20")), Point::int(1, 1)],
                ],
            },
            Polygon {
                exterior: square(3, 1),
                interiors: vec![],
            },
        ];
        let text = write_multipolygon(&polys, NumberStyle::Exact).unwrap();
        assert!(text.starts_with(
            "MULTIPOLYGON (((0 0, 1/3 0, 1/3 -2/7, 0 0), (0 0, 1 0, 1 1, 0 1, 0 0), (0.1 0.00000"
        ));
        assert!(text.ends_with("((3 0, 4 0, 4 1, 3 1, 3 0)))"), "{text}");
        assert_eq!(read(&text).unwrap(), polys);
        for style in [NumberStyle::Exact, NumberStyle::Decimal] {
            let empty = write_multipolygon::<Rational>(&[], style).unwrap();
            assert_eq!(empty, "MULTIPOLYGON EMPTY");
            assert!(read(&empty).unwrap().is_empty());
        }
    }

    #[test]
    fn decimal_output_is_the_nearest_f64_shortest() {
        let polys = vec![Polygon {
            exterior: vec![
                Point::int(0, 0),
                Point::new(q("1/3"), q("0")),
                Point::new(q("1/3"), q("-2/7")),
                Point::new(q("1e-20"), q("0.1")),
            ],
            interiors: vec![],
        }];
        assert_eq!(
            write_multipolygon(&polys, NumberStyle::Decimal).unwrap(),
            "MULTIPOLYGON (((0 0, 0.3333333333333333 0, 0.3333333333333333 -0.2857142857142857, \
             0.00000000000000000001 0.1, 0 0)))"
        );
        let far = vec![Polygon {
            exterior: vec![Point::new(q("1e400"), q("0"))],
            interiors: vec![],
        }];
        let e = write_multipolygon(&far, NumberStyle::Decimal).unwrap_err();
        assert!(e.to_string().contains("beyond the range of f64"), "{e}");
    }

    #[test]
    fn errors_name_what_and_where() {
        let cases = [
            ("POLYGON ((0 0, 1 x, 0 1))", (1, 18), "`x` is not a number"),
            (
                "POLYGON ((0 0, 1, 0 1))",
                (1, 17),
                "expected a number, found `,`",
            ),
            (
                "POLYGON ((0 0 0, 1 0 0, 0 1 0))",
                (1, 15),
                "a point has 2 coordinates",
            ),
            ("POLYGON Z ((0 0 0, 1 0 0, 0 1 0))", (1, 1), "Z or M"),
            ("polygonm ((0 0 0, 1 0 0, 0 1 0))", (1, 1), "Z or M"),
            (
                "POLYGON ((0 0, 1 0, 0 1, 0 0)",
                (1, 30),
                "`(` at line 1, column 9 not closed",
            ),
            (
                "POLYGON ((0 0, 1 0, 0 1, 0 0)))",
                (1, 31),
                "unbalanced parentheses",
            ),
            (
                "POLYGON (0 0, 1 0, 0 1)",
                (1, 10),
                "expected `(`, found `0`",
            ),
            (
                "POLYGON ((0 0, 1 0 0 1))",
                (1, 20),
                "a point has 2 coordinates",
            ),
            ("POLYGON ((0 0, 1 0; 0 1))", (1, 18), "`0;` is not a number"),
            ("POLYGON () ", (1, 10), "expected `(`, found `)`"),
            (
                "\n  POLYGONE ((0 0, 1 0, 0 1))",
                (2, 3),
                "unknown geometry type `POLYGONE`",
            ),
            (
                "LINESTRING (0 0, 1 1)",
                (1, 1),
                "`LINESTRING` is not polygonal",
            ),
            ("POINT EMPTY", (1, 1), "not polygonal"),
            (
                "POLYGON EMPTY x",
                (1, 15),
                "unexpected `x` after the geometry",
            ),
            (
                "(",
                (1, 1),
                "expected a geometry type such as POLYGON, found `(`",
            ),
            (
                "POLYGON",
                (1, 8),
                "expected `(`, found the end of the input",
            ),
            (
                "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0))",
                (1, 37),
                "not closed",
            ),
            (
                "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)),\n ((5 0, 7 0, 7 2)))",
                (2, 3),
                "a ring of 3 points is not closed: its last point is not its first",
            ),
            (
                "POLYGON ((0 0, 4 0, 4 4, 0 0), (1 1, 2 1, 2 2))",
                (1, 32),
                "a ring of 3 points is not closed",
            ),
            (
                "MULTIPOLYGON (EMPTY, (EMPTY))",
                (1, 23),
                "expected `(`, found `EMPTY`",
            ),
            (
                "GEOMETRYCOLLECTION (POINT (1 2))",
                (1, 21),
                "`POINT` is not polygonal",
            ),
        ];
        for (text, (line, column), message) in cases {
            let e = read(text).unwrap_err();
            assert_eq!((e.line, e.column), (line, column), "{text}: {e}");
            assert!(e.message.contains(message), "{text}: {e}");
        }
    }

    #[test]
    fn a_byte_order_mark_is_ignored() {
        let text = "POLYGON ((0 0, 1 0, 1 1, 0 0))";
        assert_eq!(read(&format!("\u{feff}{text}")), read(text));
        let e = read("\u{feff}POLYGON ((0 x, 1 0, 1 1))").unwrap_err();
        assert_eq!((e.line, e.column), (1, 13));
    }

    #[test]
    fn adversarial_inputs_never_panic() {
        for text in [
            "",
            "   \n\n  ",
            ")",
            ",",
            "EMPTY",
            "POLYGON EMPTY EMPTY",
            "POLYGON ((",
            "POLYGON ((1e99999999 0, 1 1, 0 1))",
            "POLYGON ((NaN 0, 1 1, 0 1))",
            "POLYGON ((inf 0, 1 1, 0 1))",
            "POLYGON ((0/0 0, 1 1, 0 1))",
            "POLYGON ((é 0, 1 1, 0 1))",
        ] {
            assert!(read(text).is_err(), "{text:?} accepted");
        }
        let deep = format!(
            "{}POLYGON EMPTY{}",
            "GEOMETRYCOLLECTION (".repeat(100_000),
            ")".repeat(100_000)
        );
        assert!(read(&deep).unwrap_err().message.contains("nested deeper"));
        let ok = format!(
            "{}POLYGON EMPTY{}",
            "GEOMETRYCOLLECTION (".repeat(MAX_NESTING),
            ")".repeat(MAX_NESTING)
        );
        assert!(read(&ok).unwrap().is_empty());
    }

    #[test]
    fn polygonal_parts_skip_points_and_curves() {
        let text = "GEOMETRYCOLLECTION (POINT (200 240), LINESTRING (0 0, 1 1), POINT EMPTY, \
                    POLYGON ((0 0, 1 0, 1 1, 0 0)), MULTILINESTRING ((0 0, 1 1), (2 2, 3 3)), \
                    COMPOUNDCURVE (CIRCULARSTRING (0 0, 1 1, 2 0), (2 0, 3 0)), \
                    MULTIPOLYGON (((2 2, 3 2, 3 3, 2 2))))";
        let polys = read_polygonal_parts::<Rational>(text).unwrap();
        assert_eq!(polys.len(), 2);
        assert_eq!(polys[1].exterior[0], Point::int(2, 2));
        assert!(
            read_polygonal_parts::<Rational>("MULTIPOINT ((1 2), (3 4))")
                .unwrap()
                .is_empty()
        );
        // Still checked: balance, what follows, and area types that are not read.
        for (bad, message) in [
            ("LINESTRING (0 0, 1 1", "not closed"),
            ("POINT (1 2) x", "unexpected `x`"),
            ("TRIANGLE ((0 0, 1 0, 0 1, 0 0))", "not polygonal"),
        ] {
            let e = read_polygonal_parts::<Rational>(bad).unwrap_err();
            assert!(e.message.contains(message), "{bad}: {e}");
        }
    }

    /// The texts of the `<a>`, `<b>` and `<op …>` elements of a JTS test-suite XML document.
    fn jts_wkt(xml: &str) -> Vec<&str> {
        let mut texts = Vec::new();
        let mut rest = xml;
        while let Some(lt) = rest.find('<') {
            rest = &rest[lt + 1..];
            let name = &rest[..rest
                .find(|c: char| c == '>' || c.is_whitespace())
                .unwrap_or(rest.len())];
            if !["a", "b", "op"].contains(&name) {
                continue;
            }
            let body = &rest[rest.find('>').map_or(rest.len(), |gt| gt + 1)..];
            let end = body.find(&format!("</{name}>")).expect("element is closed");
            texts.push(body[..end].trim());
            rest = &body[end..];
        }
        texts
    }

    #[test]
    fn jts_overlay_suites_parse() {
        if !testdata::available() {
            return;
        }
        // Counts of (POLYGON or MULTIPOLYGON read, collections of polygons read, other texts
        // rejected as not polygonal).
        let mut counts = (0, 0, 0);
        for (name, xml) in testdata::files("2d/jts", ".xml") {
            for wkt in jts_wkt(&xml) {
                let head: String = wkt.chars().take_while(char::is_ascii_alphabetic).collect();
                match (head.to_ascii_uppercase().as_str(), read(wkt)) {
                    ("POLYGON" | "MULTIPOLYGON", result) => {
                        result.unwrap_or_else(|e| panic!("{name}: {wkt}: {e}"));
                        counts.0 += 1;
                    }
                    (_, Ok(_)) => counts.1 += 1,
                    (_, Err(e)) => {
                        assert!(e.message.contains("is not polygonal"), "{name}: {wkt}: {e}");
                        counts.2 += 1;
                    }
                }
            }
        }
        assert_eq!(counts, (186, 0, 12));
    }
}
