//! Words as shapes: text set in the public-domain 8×8 bitmap font of `font8x8`, as SVG path
//! data, so that a picture rasterized without fonts (the PNG of `render`) still shows them.

use font8x8::{UnicodeFonts, BASIC_FONTS, GREEK_FONTS, LATIN_FONTS, MISC_FONTS};
use std::fmt::Write;

/// The advance of one character, in units of the font size (about a sans-serif's average).
pub(crate) const ADVANCE: f64 = 0.5;

/// The height of one glyph row, in units of the font size: capitals (rows 0–6) are 0.7 high.
const ROW: f64 = 0.1;

/// The glyph drawn for a character that the font lacks: an empty box, so that no character is
/// silently left out.
const MISSING: [u8; 8] = [0x7f, 0x41, 0x41, 0x41, 0x41, 0x41, 0x7f, 0x00];

/// The 8×8 glyph of `c`: rows from the top, bit k of a row the k-th pixel from the left.
fn glyph(c: char) -> [u8; 8] {
    BASIC_FONTS
        .get(c)
        .or_else(|| LATIN_FONTS.get(c))
        .or_else(|| GREEK_FONTS.get(c))
        .or_else(|| MISC_FONTS.get(c))
        .unwrap_or(MISSING)
}

/// SVG path data drawing `text` from `x` on the baseline `y` at font size `size` (user units):
/// one rectangle per run of set pixels in a glyph row.
pub(crate) fn text_path(text: &str, x: f64, y: f64, size: f64) -> String {
    let (w, h) = (size * ADVANCE / 8.0, size * ROW);
    let top = y - 7.0 * h;
    let mut d = String::new();
    for (k, c) in text.chars().enumerate() {
        let left = x + k as f64 * size * ADVANCE;
        for (row, bits) in glyph(c).iter().enumerate() {
            let mut col = 0;
            while col < 8 {
                if (bits >> col) & 1 == 0 {
                    col += 1;
                    continue;
                }
                let start = col;
                while col < 8 && (bits >> col) & 1 == 1 {
                    col += 1;
                }
                let run = (col - start) as f64 * w;
                let _ = write!(
                    d,
                    "M{:.3} {:.3}h{run:.3}v{h:.3}h{:.3}z",
                    left + start as f64 * w,
                    top + row as f64 * h,
                    -run
                );
            }
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_of_pixels_become_rectangles() {
        // 'I' in font8x8: a bar of 4 pixels (columns 1–4) on rows 0 and 6, columns 2–3 between.
        assert_eq!(glyph('I')[0], 0x1e);
        let d = text_path("I", 0.0, 7.0, 10.0);
        assert_eq!(d.matches('M').count(), 7, "{d}");
        assert!(d.starts_with("M0.625 0.000h2.500v1.000h-2.500z"), "{d}");
        // A space draws nothing, a second character starts one advance (5) on.
        assert_eq!(text_path(" ", 0.0, 7.0, 10.0), "");
        assert!(text_path(" I", 0.0, 7.0, 10.0).starts_with("M5.625 "));
    }

    #[test]
    fn characters_outside_the_font_are_boxes_not_dropped() {
        assert_eq!(glyph('é'), LATIN_FONTS.get('é').unwrap());
        assert_eq!(glyph('中'), MISSING);
        assert!(!text_path("中", 0.0, 7.0, 10.0).is_empty());
    }
}
