//! The three file formats and how a file's format is chosen: by option, else by extension.

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
            _ => None,
        }
    }

    /// The format of input `path`: `from` if given, else by extension (yin2 for standard input).
    pub fn of_input(path: &Path, from: Option<Format>) -> Result<Format, CliError> {
        match from {
            Some(f) => Ok(f),
            None if is_std(path) => Ok(Format::Yin2),
            None => Format::of_extension(path).ok_or_else(|| {
                CliError::Usage(format!(
                    "cannot tell the format of `{}` from its extension \
                     (.txt/.yin2, .wkt, .geojson/.json): give --from yin2|wkt|geojson",
                    path.display()
                ))
            }),
        }
    }

    /// The format of the output: `to`, else by `output`'s extension, else yin2; a `to` that
    /// contradicts the extension is an error.
    pub fn of_output(output: Option<&Path>, to: Option<Format>) -> Result<Format, CliError> {
        let by_ext = output
            .filter(|p| !is_std(p))
            .map(|p| (p, Format::of_extension(p)));
        match (to, by_ext) {
            (Some(t), Some((p, Some(e)))) if t != e => Err(CliError::Usage(format!(
                "conflicting options: --to {} but --output `{}` has the extension of {}",
                t.name(),
                p.display(),
                e.name()
            ))),
            (Some(t), _) => Ok(t),
            (None, Some((_, Some(e)))) => Ok(e),
            (None, Some((p, None))) => Err(CliError::Usage(format!(
                "cannot tell the output format from `{}`: give --to yin2|wkt|geojson or use \
                 the extension .txt/.yin2, .wkt or .geojson/.json",
                p.display()
            ))),
            (None, None) => Ok(Format::Yin2),
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Format::Yin2 => "yin2",
            Format::Wkt => "wkt",
            Format::Geojson => "geojson",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(s: &str) -> &Path {
        Path::new(s)
    }

    #[test]
    fn input_format_by_option_extension_or_stdin() {
        assert_eq!(Format::of_input(p("a.TXT"), None).unwrap(), Format::Yin2);
        assert_eq!(
            Format::of_input(p("d/a.json"), None).unwrap(),
            Format::Geojson
        );
        assert_eq!(Format::of_input(p("-"), None).unwrap(), Format::Yin2);
        assert_eq!(
            Format::of_input(p("a.txt"), Some(Format::Wkt)).unwrap(),
            Format::Wkt
        );
        let e = Format::of_input(p("a.dat"), None).unwrap_err().to_string();
        assert!(e.contains("`a.dat`") && e.contains("--from"), "{e}");
    }

    #[test]
    fn output_format_by_option_or_extension_and_conflicts() {
        assert_eq!(Format::of_output(None, None).unwrap(), Format::Yin2);
        assert_eq!(
            Format::of_output(Some(p("-")), Some(Format::Wkt)).unwrap(),
            Format::Wkt
        );
        assert_eq!(
            Format::of_output(Some(p("o.wkt")), None).unwrap(),
            Format::Wkt
        );
        assert_eq!(
            Format::of_output(Some(p("o.out")), Some(Format::Geojson)).unwrap(),
            Format::Geojson
        );
        let e = Format::of_output(Some(p("o.geojson")), Some(Format::Wkt)).unwrap_err();
        assert!(e.to_string().starts_with("conflicting options"), "{e}");
        assert!(Format::of_output(Some(p("o.out")), None).is_err());
    }
}
