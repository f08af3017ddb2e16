//! The file formats — five of 2D sets, four of 3D sets — and how a file's format is chosen: by
//! option, else by extension.

use super::error::CliError;
use clap::ValueEnum;
use std::path::Path;

/// A text format of Yin sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Curve lists: blocks of `x y` lines, blank lines between curves.
    Yin2,
    /// Well-known text: POLYGON, MULTIPOLYGON.
    Wkt,
    /// GeoJSON: Polygon, MultiPolygon, Feature, FeatureCollection.
    Geojson,
    /// Well-known binary (f64 coordinates): Polygon, MultiPolygon, GeometryCollection; read
    /// as hex too when the input is all hex digits.
    Wkb,
    /// Well-known binary as hex digits (as PostGIS prints it).
    WkbHex,
    /// Wavefront OBJ: the triangles bounding a 3D set, one object per glued surface.
    Obj,
    /// STL, ASCII or binary when read; ASCII (exact) when written.
    Stl,
    /// Binary STL when written (32-bit float coordinates: only sets whose coordinates are such
    /// floats); read as `stl`.
    StlBinary,
    /// OFF (Object File Format), ASCII.
    Off,
    /// PLY (Stanford polygon file), ASCII or binary when read; ASCII when written.
    Ply,
}

/// The extensions of the formats, for messages.
pub const EXTENSIONS: &str =
    ".txt/.yin2, .wkt, .geojson/.json, .wkb (2D); .obj, .stl, .off, .ply (3D)";
/// The format names, for messages.
pub const NAMES: &str = "yin2|wkt|geojson|wkb|wkb-hex|obj|stl|stl-binary|off|ply";

/// The dimension of the sets a format holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    /// Plane sets: yin2, WKT, GeoJSON, WKB.
    Two,
    /// Sets in space: OBJ, STL, OFF, PLY.
    Three,
}

impl Dimension {
    /// The format standard input is read in (without --from) and results are written in
    /// (without --to or an --output extension).
    fn default_format(self) -> Format {
        match self {
            Dimension::Two => Format::Yin2,
            Dimension::Three => Format::Obj,
        }
    }

    /// "2D" or "3D".
    pub fn name(self) -> &'static str {
        match self {
            Dimension::Two => "2D",
            Dimension::Three => "3D",
        }
    }
}

/// True if `path` is `-`, standard input or output.
pub fn is_std(path: &Path) -> bool {
    path.as_os_str() == "-"
}

impl Format {
    /// The format named by `path`'s extension, if it names one.
    fn of_extension(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "txt" | "yin2" => Some(Format::Yin2),
            "wkt" => Some(Format::Wkt),
            "geojson" | "json" => Some(Format::Geojson),
            "wkb" => Some(Format::Wkb),
            "obj" => Some(Format::Obj),
            "stl" => Some(Format::Stl),
            "off" => Some(Format::Off),
            "ply" => Some(Format::Ply),
            _ => None,
        }
    }

    /// The format of input `path` if `from` or its extension says it (not for standard input).
    pub fn declared(path: &Path, from: Option<Format>) -> Option<Format> {
        from.or_else(|| Format::of_extension(path).filter(|_| !is_std(path)))
    }

    /// The format of input `path`, one of `dimension`'s: `from` if given, else by extension
    /// (standard input: yin2 in 2D, OBJ in 3D); a `from` that contradicts the extension of a
    /// file is an error (it names the format of every input).
    pub fn of_input(
        path: &Path,
        from: Option<Format>,
        dimension: Dimension,
    ) -> Result<Format, CliError> {
        let format = match from {
            Some(f) => match Format::of_extension(path).filter(|_| !is_std(path)) {
                Some(e) if !f.writes_extension_of(e) => {
                    return Err(CliError::Usage(format!(
                        "conflicting options: --from {} but `{}` has the extension of {}: \
                         --from names the format of every input, so give it only with inputs \
                         of that format (or without an extension, or standard input)",
                        f.name(),
                        path.display(),
                        e.name()
                    )))
                }
                _ => f,
            },
            None if is_std(path) => dimension.default_format(),
            None => Format::of_extension(path).ok_or_else(|| {
                CliError::Usage(format!(
                    "cannot tell the format of `{}` from its extension ({EXTENSIONS}): \
                     give --from {NAMES}",
                    path.display()
                ))
            })?,
        };
        format.holds(dimension)?;
        Ok(format)
    }

    /// The dimension of the sets this format holds.
    pub fn dimension(self) -> Dimension {
        match self {
            Format::Obj | Format::Stl | Format::StlBinary | Format::Off | Format::Ply => {
                Dimension::Three
            }
            Format::Yin2 | Format::Wkt | Format::Geojson | Format::Wkb | Format::WkbHex => {
                Dimension::Two
            }
        }
    }

    /// An error unless this format holds sets of `dimension`.
    fn holds(self, dimension: Dimension) -> Result<(), CliError> {
        if self.dimension() == dimension {
            return Ok(());
        }
        let instead = match dimension {
            Dimension::Two => "yin2, wkt, geojson, wkb or wkb-hex",
            Dimension::Three => "obj, stl, stl-binary, off or ply",
        };
        Err(CliError::Usage(format!(
            "{} holds {} sets, but these are {} sets: use {instead}",
            self.name(),
            self.dimension().name(),
            dimension.name()
        )))
    }

    /// The format of an output of `dimension`: `to`, else by `output`'s extension, else yin2 in
    /// 2D and OBJ in 3D; a `to` that contradicts the extension, or a format of the other
    /// dimension, is an error.
    pub fn of_output(
        output: Option<&Path>,
        to: Option<Format>,
        dimension: Dimension,
    ) -> Result<Format, CliError> {
        let format = Format::of_output_any(output, to, dimension.default_format())?;
        format.holds(dimension)?;
        Ok(format)
    }

    /// The format of the output: `to`, else by `output`'s extension, else `default`.
    fn of_output_any(
        output: Option<&Path>,
        to: Option<Format>,
        default: Format,
    ) -> Result<Format, CliError> {
        let by_ext = output
            .filter(|p| !is_std(p))
            .map(|p| (p, Format::of_extension(p)));
        match (to, by_ext) {
            (Some(t), Some((p, Some(e)))) if !t.writes_extension_of(e) => {
                Err(CliError::Usage(format!(
                    "conflicting options: --to {} but --output `{}` has the extension of {}",
                    t.name(),
                    p.display(),
                    e.name()
                )))
            }
            (Some(t), _) => Ok(t),
            (None, Some((_, Some(e)))) => Ok(e),
            (None, Some((p, None))) => Err(CliError::Usage(format!(
                "cannot tell the output format from `{}`: give --to {NAMES} or use \
                 one of the extensions {EXTENSIONS}",
                p.display()
            ))),
            (None, None) => Ok(default),
        }
    }

    /// True if output in this format may have the extension of format `ext` (binary STL is
    /// `.stl` too, WKB hex `.wkb`).
    fn writes_extension_of(self, ext: Format) -> bool {
        self == ext
            || [
                (Format::StlBinary, Format::Stl),
                (Format::WkbHex, Format::Wkb),
            ]
            .contains(&(self, ext))
    }

    /// The format of input `bytes` declared `self`: WKB hex if they are all hex digits and
    /// were declared WKB, or came from standard input without `--from` (as yin2 by default:
    /// a yin2 text has blanks between its numbers, WKB hex none).
    pub fn sniffed(self, bytes: &[u8], path: &Path, from: Option<Format>) -> Format {
        let may_be_hex = self == Format::Wkb || (is_std(path) && from.is_none());
        if may_be_hex && crate::io::wkb::is_hex(bytes) {
            Format::WkbHex
        } else {
            self
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Yin2 => "yin2",
            Format::Wkt => "wkt",
            Format::Geojson => "geojson",
            Format::Wkb => "wkb",
            Format::WkbHex => "wkb-hex",
            Format::Obj => "obj",
            Format::Stl => "stl",
            Format::StlBinary => "stl-binary",
            Format::Off => "off",
            Format::Ply => "ply",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Dimension::{Three, Two};

    fn p(s: &str) -> &Path {
        Path::new(s)
    }

    #[test]
    fn input_format_by_option_extension_or_stdin() {
        assert_eq!(
            Format::of_input(p("a.TXT"), None, Two).unwrap(),
            Format::Yin2
        );
        assert_eq!(
            Format::of_input(p("d/a.json"), None, Two).unwrap(),
            Format::Geojson
        );
        assert_eq!(Format::of_input(p("-"), None, Two).unwrap(), Format::Yin2);
        assert_eq!(
            Format::of_input(p("-"), Some(Format::Wkt), Two).unwrap(),
            Format::Wkt
        );
        assert!(Format::of_input(p("a.txt"), Some(Format::Wkt), Two).is_err());
        let e = Format::of_input(p("a.dat"), None, Two)
            .unwrap_err()
            .to_string();
        assert!(e.contains("`a.dat`") && e.contains("--from"), "{e}");
        assert_eq!(
            Format::of_input(p("a.dat"), Some(Format::Wkt), Two).unwrap(),
            Format::Wkt
        );
        assert_eq!(
            Format::of_input(p("a.wkb"), Some(Format::WkbHex), Two).unwrap(),
            Format::WkbHex
        );
        let e = Format::of_input(p("sq.txt"), Some(Format::Obj), Three)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("--from obj but `sq.txt` has the extension of yin2"),
            "{e}"
        );
    }

    #[test]
    fn output_format_by_option_or_extension_and_conflicts() {
        assert_eq!(Format::of_output(None, None, Two).unwrap(), Format::Yin2);
        assert_eq!(
            Format::of_output(Some(p("-")), Some(Format::Wkt), Two).unwrap(),
            Format::Wkt
        );
        assert_eq!(
            Format::of_output(Some(p("o.wkt")), None, Two).unwrap(),
            Format::Wkt
        );
        assert_eq!(
            Format::of_output(Some(p("o.out")), Some(Format::Geojson), Two).unwrap(),
            Format::Geojson
        );
        let e = Format::of_output(Some(p("o.geojson")), Some(Format::Wkt), Two).unwrap_err();
        assert!(e.to_string().starts_with("conflicting options"), "{e}");
        assert!(Format::of_output(Some(p("o.out")), None, Two).is_err());
    }

    #[test]
    fn obj_is_the_3d_format_in_and_out() {
        assert_eq!(
            Format::of_input(p("a.OBJ"), None, Three).unwrap(),
            Format::Obj
        );
        assert_eq!(Format::of_input(p("-"), None, Three).unwrap(), Format::Obj);
        assert_eq!(Format::declared(p("a.obj"), None), Some(Format::Obj));
        assert_eq!(Format::declared(p("-"), None), None);
        assert_eq!(
            Format::declared(p("-"), Some(Format::Obj)),
            Some(Format::Obj)
        );
        assert_eq!(Format::of_output(None, None, Three).unwrap(), Format::Obj);
        assert_eq!(
            Format::of_output(Some(p("r.obj")), None, Three).unwrap(),
            Format::Obj
        );
        let e = Format::of_output(Some(p("r.wkt")), None, Three).unwrap_err();
        assert!(e.to_string().contains("wkt holds 2D sets"), "{e}");
        let e = Format::of_output(None, Some(Format::Obj), Two).unwrap_err();
        assert!(e.to_string().contains("obj holds 3D sets"), "{e}");
        assert!(Format::of_input(p("a.obj"), None, Two).is_err());
    }

    #[test]
    fn wkb_by_extension_and_hex_by_content() {
        let wkb = Format::of_input(p("a.WKB"), None, Two).unwrap();
        assert_eq!(wkb, Format::Wkb);
        let hex = b"0106000000\n";
        assert_eq!(wkb.sniffed(hex, p("a.wkb"), None), Format::WkbHex);
        assert_eq!(wkb.sniffed(&[1, 6, 0], p("a.wkb"), None), Format::Wkb);
        assert_eq!(Format::Yin2.sniffed(hex, p("-"), None), Format::WkbHex);
        assert_eq!(
            Format::Yin2.sniffed(b"0 0\n1 0\n", p("-"), None),
            Format::Yin2
        );
        let yin2 = Some(Format::Yin2);
        assert_eq!(Format::Yin2.sniffed(hex, p("-"), yin2), Format::Yin2);
        assert_eq!(Format::Yin2.sniffed(hex, p("a.txt"), None), Format::Yin2);
        assert_eq!(
            Format::of_output(Some(p("o.wkb")), None, Two).unwrap(),
            Format::Wkb
        );
        assert_eq!(
            Format::of_output(Some(p("o.wkb")), Some(Format::WkbHex), Two).unwrap(),
            Format::WkbHex
        );
        assert!(Format::of_output(Some(p("o.wkt")), Some(Format::Wkb), Two).is_err());
    }
}
