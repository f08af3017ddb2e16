//! `render`'s output: SVG, or PNG for an `--output` ending in `.png`; any other extension is an
//! error rather than SVG bytes under a misleading name.

use super::error::CliError;
use super::format::is_std;
use crate::io::png::svg_to_png;
use crate::io::WriteError;
use std::path::Path;

/// The bytes of the picture `svg` for `output`: SVG for standard output or a `.svg` file, PNG
/// for a `.png` file; a usage error for any other extension.
pub fn picture(svg: String, output: Option<&Path>) -> Result<Vec<u8>, CliError> {
    let Some(path) = output.filter(|p| !is_std(p)) else {
        return Ok(svg.into_bytes());
    };
    let ext = path.extension().and_then(|e| e.to_str());
    match ext.map(str::to_ascii_lowercase).as_deref() {
        Some("svg") => Ok(svg.into_bytes()),
        Some("png") => svg_to_png(&svg).map_err(|e| CliError::Unwritable {
            format: "PNG",
            source: WriteError(e),
        }),
        _ => Err(CliError::Usage(format!(
            "render cannot write `{}`: give an output ending in .svg or .png",
            path.display()
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extension_picks_svg_or_png_and_refuses_others() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="4" height="4"></svg>"#;
        let bytes = |out: Option<&str>| picture(svg.to_string(), out.map(Path::new));
        assert_eq!(bytes(None).unwrap(), svg.as_bytes());
        assert_eq!(bytes(Some("-")).unwrap(), svg.as_bytes());
        assert_eq!(bytes(Some("a.SVG")).unwrap(), svg.as_bytes());
        assert!(bytes(Some("d/a.png")).unwrap().starts_with(b"\x89PNG"));
        for bad in ["a.pdf", "a", "a.png.txt"] {
            let e = bytes(Some(bad)).unwrap_err().to_string();
            assert!(
                e.contains(&format!("`{bad}`")) && e.contains(".svg or .png"),
                "{e}"
            );
        }
    }
}
