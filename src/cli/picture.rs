//! `render`: which picture the output file asks for (SVG or PNG of 2D sets; PNG or HTML of 3D
//! sets), and drawing it; any other extension is an error rather than bytes under a misleading
//! name.

use super::args::RenderArgs;
use super::error::CliError;
use super::format::is_std;
use super::progress;
use crate::io::html3::write_html;
use crate::io::png::svg_to_png;
use crate::io::png3::write_png;
use crate::io::scene3::facets;
use crate::io::svg::{write_svg, write_svg_lettered, Lettering};
use crate::io::WriteError;
use crate::num::Num;
use crate::yin2::YinSet2;
use crate::yin3::YinSet3;
use std::path::Path;

/// Side of a PNG picture when `--size` is not given.
const DEFAULT_SIZE: u32 = 800;

/// A kind of picture file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Picture {
    Svg,
    Png,
    Html,
}

/// The kind of picture `output` asks for by its extension (none or `-`: none).
fn picture(output: Option<&Path>) -> Result<Option<Picture>, CliError> {
    let Some(path) = output.filter(|p| !is_std(p)) else {
        return Ok(None);
    };
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => Ok(Some(Picture::Svg)),
        Some("png") => Ok(Some(Picture::Png)),
        Some("html" | "htm") => Ok(Some(Picture::Html)),
        _ => Err(CliError::Usage(format!(
            "render cannot write `{}`: use the extension .svg or .png (2D sets), .png or .html \
             (3D sets)",
            path.display()
        ))),
    }
}

/// The SVG picture of the 2D `layers`, rasterized (resvg) for a PNG output with the legend's
/// words drawn as bitmap glyphs; a usage error for an HTML output or 3D options.
pub fn render2<N: Num>(
    layers: &[(&str, &YinSet2<N>)],
    args: &RenderArgs,
) -> Result<Vec<u8>, CliError> {
    if args.view.is_some() || args.size.is_some() {
        return Err(CliError::Usage(
            "--view and --size apply to pictures of 3D sets; 2D sets are drawn as SVG or PNG"
                .to_string(),
        ));
    }
    match picture(args.output.as_deref())? {
        None | Some(Picture::Svg) => Ok(write_svg(layers).into_bytes()),
        Some(Picture::Png) => {
            svg_to_png(&write_svg_lettered(layers, Lettering::Bitmap)).map_err(|e| {
                CliError::Unwritable {
                    format: "PNG",
                    source: WriteError(e),
                }
            })
        }
        Some(Picture::Html) => Err(CliError::Usage(
            "2D sets are drawn as SVG or PNG: give -o FILE.svg, -o FILE.png (or no -o for \
             standard output)"
                .to_string(),
        )),
    }
}

/// The PNG or HTML picture of the 3D `layers` (all drawn together), as the output's extension
/// says; a usage error for SVG, no output file, or the whole space (nothing to draw).
pub fn render3<N: Num>(
    layers: &[(&str, &YinSet3<N>)],
    args: &RenderArgs,
) -> Result<Vec<u8>, CliError> {
    if let Some((label, _)) = layers.iter().find(|(_, s)| s.is_full()) {
        return Err(CliError::Usage(format!(
            "{label} is the whole space, which has no boundary surface to draw"
        )));
    }
    let sets: Vec<&YinSet3<N>> = layers.iter().map(|(_, s)| *s).collect();
    let view = args.view.unwrap_or_default();
    let vertices = sets.iter().map(|s| s.vertices().len()).sum();
    let message = || format!("drawing {vertices} vertices");
    match picture(args.output.as_deref())? {
        Some(Picture::Png) => {
            let size = args.size.unwrap_or(DEFAULT_SIZE);
            progress::while_working(message, vertices, || write_png(&facets(&sets), view, size))
                .map_err(|e| CliError::Write {
                    name: "the PNG picture".to_string(),
                    source: std::io::Error::other(e),
                })
        }
        Some(Picture::Html) if args.size.is_none() => {
            let title: Vec<&str> = layers.iter().map(|(label, _)| *label).collect();
            Ok(write_html(&facets(&sets), view, &title.join(", ")).into_bytes())
        }
        Some(Picture::Html) => Err(CliError::Usage(
            "--size applies to PNG pictures; the HTML viewer fills its window".to_string(),
        )),
        None | Some(Picture::Svg) => Err(CliError::Usage(
            "3D sets are drawn as PNG or as an interactive HTML page: give -o FILE.png or \
             -o FILE.html"
                .to_string(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extension_picks_the_picture_and_refuses_others() {
        let kind = |out: &str| picture(Some(Path::new(out)));
        assert_eq!(kind("-").unwrap(), None);
        assert_eq!(kind("a.SVG").unwrap(), Some(Picture::Svg));
        assert_eq!(kind("d/a.png").unwrap(), Some(Picture::Png));
        assert_eq!(kind("a.htm").unwrap(), Some(Picture::Html));
        for bad in ["a.pdf", "a", "a.png.txt"] {
            let e = kind(bad).unwrap_err().to_string();
            assert!(
                e.contains(&format!("`{bad}`")) && e.contains(".svg or .png"),
                "{e}"
            );
        }
    }
}
