//! SVG pictures of Yin sets: regions filled, positively oriented curves solid and negatively
//! oriented ones dashed (seed 000 Fig. 13), non-manifold points (vertices shared by two or more
//! curves, where curves touch) marked with dots.
//!
//! Coordinates are the picture's own (`io::picture_frame`): offsets from the lower-left
//! corner of the sets' bounding box over its larger side, computed exactly and then written
//! as `f64`, so sets at any position and scale are drawn alike; the y axis points up. An
//! unbounded set is filled to the edge of the picture.

use super::lettering::text_path;
use super::picture_frame::PictureFrame;
use crate::kernel::{BBox, Point};
use crate::num::Num;
use crate::yin2::{Curve, YinSet2};
use std::collections::HashMap;
use std::fmt::Write;

/// Width of the picture in pixels; the height follows the drawing's aspect ratio.
const WIDTH_PX: f64 = 800.0;

/// Colours of successive layers.
const PALETTE: [&str; 6] = [
    "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
];

/// How the legend's words are set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lettering {
    /// As SVG text, in the viewer's sans-serif font.
    Text,
    /// As shapes of an 8×8 bitmap font, for rasterizing without fonts (the PNG picture).
    Bitmap,
}

/// The SVG document drawing each `(label, set)`, later layers on top, with a legend of labels.
pub fn write_svg<N: Num>(layers: &[(&str, &YinSet2<N>)]) -> String {
    write_svg_lettered(layers, Lettering::Text)
}

/// [`write_svg`] with the legend's words set as `lettering` says.
pub fn write_svg_lettered<N: Num>(layers: &[(&str, &YinSet2<N>)], lettering: Lettering) -> String {
    let boxes: Vec<BBox<N>> = layers.iter().filter_map(|(_, set)| set.bbox()).collect();
    let corners = |b: &BBox<N>| {
        let xy = |p: &Point<N>| vec![p.x.clone(), p.y.clone()];
        (xy(&b.min), xy(&b.max))
    };
    let picture = PictureFrame::around(boxes.iter().map(corners));
    let place = |p: &Point<N>| [picture.coordinate(0, &p.x), picture.coordinate(1, &p.y)];
    let corners = boxes.iter().flat_map(|b| [place(&b.min), place(&b.max)]);
    let frame = Frame::around(corners, layers.len());
    let mut svg = frame.header();
    let mut labels = Vec::new();
    for (k, (label, set)) in layers.iter().enumerate() {
        let colour = PALETTE[k % PALETTE.len()];
        let _ = writeln!(svg, "<g><title>{}</title>", escape(label));
        frame.layer(&mut svg, set, colour, &place);
        svg.push_str("</g>\n");
        labels.push((*label, colour));
    }
    frame.legend(&mut svg, &labels, lettering);
    svg.push_str("</svg>\n");
    svg
}

/// The drawn window in world coordinates, with the sizes derived from it.
struct Frame {
    /// Lower-left corner.
    min: [f64; 2],
    /// Upper-right corner.
    max: [f64; 2],
    /// A length for strokes, dots and text: the larger side over 400.
    unit: f64,
    /// Decimals written for coordinates.
    decimals: usize,
}

impl Frame {
    /// The window around `points` with a margin (the unit square around the origin if none),
    /// and room at the top for a legend of `labels` lines.
    fn around(points: impl Iterator<Item = [f64; 2]>, labels: usize) -> Frame {
        let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points.filter(|p| p[0].is_finite() && p[1].is_finite()) {
            for i in 0..2 {
                min[i] = min[i].min(p[i]);
                max[i] = max[i].max(p[i]);
            }
        }
        if min[0] > max[0] {
            (min, max) = ([-1.0; 2], [1.0; 2]);
        }
        let side = (max[0] - min[0]).max(max[1] - min[1]);
        let side = if side > 0.0 { side } else { 1.0 };
        let (margin, unit) = (side * 0.05, side / 400.0);
        let legend = (30 + 18 * labels) as f64 * unit;
        Frame {
            min: [min[0] - margin, min[1] - margin],
            max: [max[0] + margin, max[1] + margin + legend],
            unit,
            decimals: (5.0 - side.log10().floor()).clamp(0.0, 15.0) as usize,
        }
    }

    /// A world point in SVG user space (y flipped).
    fn xy(&self, p: [f64; 2]) -> String {
        format!("{:.*} {:.*}", self.decimals, p[0], self.decimals, -p[1])
    }

    /// The opening `<svg>` element, sized to the window's aspect ratio, on a white background.
    fn header(&self) -> String {
        let (w, h) = (self.max[0] - self.min[0], self.max[1] - self.min[1]);
        let height_px = (WIDTH_PX * h / w).clamp(50.0, 4.0 * WIDTH_PX);
        let d = self.decimals;
        let mut s = String::new();
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH_PX}" height="{height_px:.0}" viewBox="{:.d$} {:.d$} {w:.d$} {h:.d$}">"#,
            self.min[0], -self.max[1]
        );
        let _ = writeln!(
            s,
            r#"<rect x="{:.d$}" y="{:.d$}" width="{w:.d$}" height="{h:.d$}" fill="white"/>"#,
            self.min[0], -self.max[1]
        );
        s
    }

    /// Path data of closed polygons.
    fn path<I: IntoIterator<Item = [f64; 2]>>(&self, rings: impl Iterator<Item = I>) -> String {
        let mut d = String::new();
        for ring in rings {
            for (k, p) in ring.into_iter().enumerate() {
                d.push_str(if k == 0 { "M" } else { " L" });
                d.push_str(&self.xy(p));
            }
            d.push_str(" Z ");
        }
        d
    }

    /// The window as a counterclockwise ring (the far part of an unbounded set).
    fn window_ring(&self) -> [[f64; 2]; 4] {
        let (a, b) = (self.min, self.max);
        [a, [b[0], a[1]], b, [a[0], b[1]]]
    }

    /// Draw `set` in `colour`, its points placed in the picture by `place`: fill, curves,
    /// non-manifold points.
    fn layer<N: Num>(
        &self,
        svg: &mut String,
        set: &YinSet2<N>,
        colour: &str,
        place: &impl Fn(&Point<N>) -> [f64; 2],
    ) {
        let ring = |c: &Curve<N>| c.vertices().iter().map(place).collect::<Vec<_>>();
        let window = (!set.is_bounded()).then(|| self.window_ring().to_vec());
        let fill = self.path(window.into_iter().chain(set.curves().iter().map(ring)));
        if !fill.is_empty() {
            let _ = writeln!(
                svg,
                r#"<path d="{fill}" fill="{colour}" fill-opacity="0.3" fill-rule="nonzero" stroke="none"/>"#
            );
        }
        let u = self.unit;
        for (positive, dash) in [
            (true, String::new()),
            (
                false,
                format!(
                    r#" stroke-dasharray="{:.*} {:.*}""#,
                    self.decimals,
                    5.0 * u,
                    self.decimals,
                    3.0 * u
                ),
            ),
        ] {
            let d = self.path(
                set.curves()
                    .iter()
                    .filter(|c| c.is_positive() == positive)
                    .map(ring),
            );
            if !d.is_empty() {
                let _ = writeln!(
                    svg,
                    r#"<path d="{d}" fill="none" stroke="{colour}" stroke-width="{:.*}" stroke-linejoin="round"{dash}/>"#,
                    self.decimals, u
                );
            }
        }
        for p in non_manifold_points(set) {
            let [x, y] = place(&p);
            let _ = writeln!(
                svg,
                r#"<circle cx="{:.*}" cy="{:.*}" r="{:.*}" fill="black"/>"#,
                self.decimals,
                x,
                self.decimals,
                -y,
                self.decimals,
                3.0 * u
            );
        }
    }

    /// The legend at the top left: a swatch and label per layer, then the key to the line
    /// styles; drawn in a local frame of [`Frame::unit`] so that text is set at a normal size,
    /// its words as `lettering` says.
    fn legend(&self, svg: &mut String, labels: &[(&str, &str)], lettering: Lettering) {
        let _ = writeln!(
            svg,
            r#"<g transform="translate({:.*} {:.*}) scale({})" font-family="sans-serif">"#,
            self.decimals, self.min[0], self.decimals, -self.max[1], self.unit
        );
        for (k, (label, colour)) in labels.iter().enumerate() {
            let y = 10 + 18 * k;
            let _ = write!(
                svg,
                r#"<rect x="10" y="{y}" width="12" height="12" fill="{colour}" fill-opacity="0.5"/>"#,
            );
            words(svg, lettering, label, [28, y + 11], 12, "black");
        }
        let key =
            "solid: positively oriented, dashed: negatively oriented, dot: non-manifold point";
        words(
            svg,
            lettering,
            key,
            [10, 24 + 18 * labels.len()],
            10,
            "dimgray",
        );
        svg.push_str("</g>\n");
    }
}

/// One line of words from `at` on its baseline, at font size `size`, in `colour`: an SVG text
/// element, or its glyphs' shapes (crisp edges, as a bitmap font's pixels are).
fn words(
    svg: &mut String,
    lettering: Lettering,
    text: &str,
    at: [usize; 2],
    size: usize,
    colour: &str,
) {
    let [x, y] = at;
    let _ = match lettering {
        Lettering::Text => writeln!(
            svg,
            r#"<text x="{x}" y="{y}" font-size="{size}" fill="{colour}">{}</text>"#,
            escape(text)
        ),
        Lettering::Bitmap => writeln!(
            svg,
            r#"<path d="{}" fill="{colour}" shape-rendering="crispEdges"/>"#,
            text_path(text, x as f64, y as f64, size as f64)
        ),
    };
}

/// The vertices shared by two or more curves of `set` (where its curves touch), sorted.
pub fn non_manifold_points<N: Num>(set: &YinSet2<N>) -> Vec<Point<N>> {
    let mut count: HashMap<&Point<N>, usize> = HashMap::new();
    for c in set.curves() {
        for p in c.vertices() {
            *count.entry(p).or_default() += 1;
        }
    }
    let mut shared: Vec<Point<N>> = count
        .into_iter()
        .filter(|&(_, n)| n >= 2)
        .map(|(p, _)| p.clone())
        .collect();
    shared.sort();
    shared
}

/// `text` with the XML (and HTML) special characters escaped.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Vec<Point<Rational>> {
        [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            .iter()
            .map(|&(x, y)| Point::int(x, y))
            .collect()
    }

    #[test]
    fn touching_squares_have_one_non_manifold_point() {
        let set = YinSet2::from_curves(vec![rect(0, 0, 1, 1), rect(1, 1, 2, 2)]).unwrap();
        assert_eq!(non_manifold_points(&set), vec![Point::int(1, 1)]);
        let svg = write_svg(&[("two squares", &set)]);
        assert_eq!(svg.matches("<circle").count(), 1);
        // The point (1, 1) of the box [0, 2]² is halfway across the picture's unit box.
        assert!(svg.contains(r#"cx="0.50000" cy="-0.50000""#), "{svg}");
        assert!(
            !svg.contains("stroke-dasharray"),
            "no negative curve: {svg}"
        );
    }

    #[test]
    fn holes_are_dashed_and_complements_fill_the_window() {
        let mut hole = rect(1, 1, 2, 2);
        hole.reverse();
        let set = YinSet2::from_curves(vec![rect(0, 0, 3, 3), hole]).unwrap();
        let svg = write_svg(&[("a & <b>", &set), ("outside", &set.complement())]);
        assert_eq!(svg.matches("stroke-dasharray").count(), 2);
        assert_eq!(svg.matches("fill-rule=\"nonzero\"").count(), 2);
        assert!(svg.contains("a &amp; &lt;b&gt;"));
        // The complement's fill starts with the window ring, then its curves.
        let fills: Vec<&str> = svg
            .lines()
            .filter(|l| l.contains("fill-opacity=\"0.3\""))
            .collect();
        assert_eq!(fills[1].matches('M').count(), 3, "{}", fills[1]);
        assert!(svg.starts_with("<svg ") && svg.ends_with("</svg>\n"));
    }

    /// The PNG's legend shows its words: dark pixels on each label's line right of its swatch
    /// and on the key's line, where the same picture with SVG text (which resvg cannot draw
    /// without fonts) has none.
    #[test]
    #[cfg(feature = "png")]
    fn the_png_legend_has_its_words() {
        let (a, b) = (rect(0, 0, 10, 10), rect(2, 2, 8, 8));
        let (a, b) = (
            YinSet2::from_curves(vec![a]).unwrap(),
            YinSet2::from_curves(vec![b]).unwrap(),
        );
        let layers = [("first.wkt", &a), ("second.wkt", &b)];
        // The window is 11 wide (a margin of 0.5 each side) over 800 pixels, the legend's unit
        // 10 / 400: 800 / 11 · 0.025 pixels per legend unit.
        let scale = 800.0 / 11.0 * 0.025;
        let dark_in = |lettering, x: [f64; 2], y: [f64; 2]| {
            let png = crate::io::png::svg_to_png(&write_svg_lettered(&layers, lettering)).unwrap();
            let image = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
            let px = |v: f64| (v * scale) as u32;
            let mut dark = 0;
            for i in px(x[0])..px(x[1]) {
                for j in px(y[0])..px(y[1]) {
                    let p = image.pixel(i, j).unwrap();
                    dark += usize::from(p.red().max(p.green()).max(p.blue()) < 128);
                }
            }
            dark
        };
        // Label k: from x = 28 on the baseline 21 + 18k, 6 units a character, 8.4 high.
        for k in 0..2 {
            let (x, y) = (
                [28.0, 28.0 + 6.0 * 10.0],
                [12.0 + 18.0 * k as f64, 21.0 + 18.0 * k as f64],
            );
            let words = dark_in(Lettering::Bitmap, x, y);
            assert!(words > 40, "label {k}: {words} dark pixels");
            assert_eq!(
                dark_in(Lettering::Text, x, y),
                0,
                "label {k} without glyphs"
            );
        }
        // The key: from x = 10 on the baseline 60, 5 units a character, 80 characters.
        let (x, y) = ([10.0, 410.0], [53.0, 60.0]);
        assert!(dark_in(Lettering::Bitmap, x, y) > 200);
        assert_eq!(dark_in(Lettering::Text, x, y), 0);
        // Left of the swatches there is nothing dark in either.
        assert_eq!(dark_in(Lettering::Bitmap, [0.0, 9.0], [0.0, 60.0]), 0);
    }

    #[test]
    fn empty_and_full_sets_draw_without_curves() {
        let svg = write_svg(&[
            ("none", &YinSet2::<Rational>::empty()),
            ("all", &YinSet2::full()),
        ]);
        assert_eq!(svg.matches("fill-opacity=\"0.3\"").count(), 1);
        assert!(
            svg.contains(r#"viewBox="-1.10000 -1.43000 2.20000 2.53000""#),
            "{svg}"
        );
    }
}
