//! PNG pictures: the SVG of [`super::svg`] rasterized by `resvg` (pure Rust), at the SVG's own
//! size. No fonts are bundled, so SVG text elements are not drawn: the legend's words come as
//! shapes of a bitmap font ([`super::svg::Lettering::Bitmap`]).

use resvg::{tiny_skia, usvg};

/// The PNG image of the SVG document `svg`, or why it cannot be drawn.
pub fn svg_to_png(svg: &str) -> Result<Vec<u8>, String> {
    let tree = usvg::Tree::from_str(svg, &usvg::Options::default())
        .map_err(|e| format!("the SVG picture cannot be read back: {e}"))?;
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| format!("no room for a {}×{} image", size.width(), size.height()))?;
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap
        .encode_png()
        .map_err(|e| format!("PNG encoding failed: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_red_square_on_white_is_drawn_where_the_svg_puts_it() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20" viewBox="0 0 40 20">
            <rect x="0" y="0" width="40" height="20" fill="white"/>
            <rect x="20" y="0" width="20" height="20" fill="red"/></svg>"#;
        let png = svg_to_png(svg).unwrap();
        assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
        let image = tiny_skia::Pixmap::decode_png(&png).unwrap();
        assert_eq!((image.width(), image.height()), (40, 20));
        let rgba = |x, y| {
            let p = image.pixel(x, y).unwrap();
            (p.red(), p.green(), p.blue(), p.alpha())
        };
        assert_eq!(rgba(5, 10), (255, 255, 255, 255));
        assert_eq!(rgba(30, 10), (255, 0, 0, 255));
    }

    #[test]
    fn malformed_svg_is_an_error() {
        assert!(svg_to_png("<svg")
            .unwrap_err()
            .contains("cannot be read back"));
    }
}
