//! PNG pictures of 3D sets: shaded triangles in an orthographic view, drawn by a z-buffer.
//!
//! Negatively oriented glued surfaces (cavities, and the surface of an unbounded set) are drawn
//! opaque in [`NEGATIVE`] orange; positively oriented ones (outer surfaces) on top of them,
//! translucent in [`POSITIVE`] blue (opacity [`OPACITY`]), so that cavities show through the
//! surfaces that enclose them. Shading is by the angle to a light over the viewer's shoulder,
//! the same on both sides of a triangle. Pixels are 2×2 supersampled; the background is white.

use super::scene3::{Facet, View, NEGATIVE, OPACITY, POSITIVE};
/// Samples per pixel along each axis.
const SUPERSAMPLE: usize = 2;
/// Blank border, as a fraction of the picture's side.
const MARGIN: f64 = 0.04;

/// The PNG bytes of a `size`×`size` picture of `facets` seen from `view`.
pub fn write_png(facets: &[Facet], view: View, size: u32) -> Result<Vec<u8>, png::EncodingError> {
    let side = size as usize * SUPERSAMPLE;
    let mut canvas = Canvas::new(side);
    let camera = view.camera();
    let projected: Vec<([[f64; 3]; 3], f32, bool)> = facets
        .iter()
        .map(|f| {
            let shade = camera.shade(&f.corners) as f32;
            (f.corners.map(|p| camera.project(p)), shade, f.positive)
        })
        .collect();
    let fit = Fit::new(projected.iter().flat_map(|(c, _, _)| c), side);
    let negative = NEGATIVE.map(f32::from);
    for (c, shade, _) in projected.iter().filter(|f| !f.2) {
        canvas.fill(fit.place(c), |depth, pixel| {
            if depth > pixel.depth {
                pixel.depth = depth;
                pixel.colour = negative.map(|x| x * shade);
            }
        });
    }
    let mut positive: Vec<_> = projected.iter().filter(|f| f.2).collect();
    positive.sort_by(|a, b| centroid_depth(&a.0).total_cmp(&centroid_depth(&b.0)));
    let blue = POSITIVE.map(f32::from);
    for (c, shade, _) in positive {
        canvas.fill(fit.place(c), |depth, pixel| {
            if depth > pixel.depth {
                for (out, p) in pixel.colour.iter_mut().zip(blue) {
                    *out = OPACITY * p * shade + (1.0 - OPACITY) * *out;
                }
            }
        });
    }
    encode(&canvas.downsampled(size as usize), size)
}

/// The mean depth of projected corners `c`.
fn centroid_depth(c: &[[f64; 3]; 3]) -> f64 {
    (c[0][2] + c[1][2] + c[2][2]) / 3.0
}

/// The map from camera coordinates to sample coordinates that fits the scene in the picture.
struct Fit {
    /// Camera x and y of the picture's centre.
    centre: [f64; 2],
    /// Samples per unit length.
    scale: f64,
    /// Samples along each side.
    side: f64,
}

impl Fit {
    /// The fit of `points` (camera coordinates) into `side`×`side` samples, with a margin.
    fn new<'a>(points: impl Iterator<Item = &'a [f64; 3]>, side: usize) -> Fit {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let side = side as f64;
        let scale = if extent > 0.0 && extent.is_finite() {
            side * (1.0 - 2.0 * MARGIN) / extent
        } else {
            1.0
        };
        Fit {
            centre: [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0],
            scale,
            side,
        }
    }

    /// Corners `c` in sample coordinates: x right, y down, depth kept.
    fn place(&self, c: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
        c.map(|p| {
            [
                self.side / 2.0 + (p[0] - self.centre[0]) * self.scale,
                self.side / 2.0 - (p[1] - self.centre[1]) * self.scale,
                p[2],
            ]
        })
    }
}

/// One sample: its colour and the depth of the nearest opaque surface drawn there.
#[derive(Clone, Copy)]
struct Sample {
    colour: [f32; 3],
    depth: f64,
}

/// The supersampled picture.
struct Canvas {
    side: usize,
    samples: Vec<Sample>,
}

impl Canvas {
    /// A white `side`×`side` canvas with nothing drawn.
    fn new(side: usize) -> Canvas {
        let blank = Sample {
            colour: [255.0; 3],
            depth: f64::NEG_INFINITY,
        };
        Canvas {
            side,
            samples: vec![blank; side * side],
        }
    }

    /// Call `paint(depth, sample)` on every sample whose centre is inside the triangle `c`
    /// (sample coordinates), with the triangle's depth there.
    fn fill(&mut self, c: [[f64; 3]; 3], mut paint: impl FnMut(f64, &mut Sample)) {
        let edge = |a: [f64; 3], b: [f64; 3], x: f64, y: f64| {
            (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        };
        let area = edge(c[0], c[1], c[2][0], c[2][1]);
        if area == 0.0 || !area.is_finite() {
            return;
        }
        let max = self.side as f64 - 1.0;
        let range = |k: usize| {
            let lo = c.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
            let hi = c.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
            ((lo - 0.5).ceil().clamp(0.0, max) as usize)
                ..=((hi - 0.5).floor().clamp(0.0, max) as usize)
        };
        for y in range(1) {
            for x in range(0) {
                let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                let w = [
                    edge(c[1], c[2], px, py) / area,
                    edge(c[2], c[0], px, py) / area,
                    edge(c[0], c[1], px, py) / area,
                ];
                if w.iter().all(|&w| w >= 0.0) {
                    let depth = w[0] * c[0][2] + w[1] * c[1][2] + w[2] * c[2][2];
                    paint(depth, &mut self.samples[y * self.side + x]);
                }
            }
        }
    }

    /// The RGB bytes of the `size`×`size` picture, each pixel the mean of its samples.
    fn downsampled(&self, size: usize) -> Vec<u8> {
        let mut rgb = Vec::with_capacity(size * size * 3);
        let n = (SUPERSAMPLE * SUPERSAMPLE) as f32;
        for y in 0..size {
            for x in 0..size {
                let mut sum = [0f32; 3];
                for dy in 0..SUPERSAMPLE {
                    for dx in 0..SUPERSAMPLE {
                        let s = &self.samples
                            [(y * SUPERSAMPLE + dy) * self.side + x * SUPERSAMPLE + dx];
                        for (total, c) in sum.iter_mut().zip(s.colour) {
                            *total += c;
                        }
                    }
                }
                rgb.extend(sum.map(|v| (v / n).round().clamp(0.0, 255.0) as u8));
            }
        }
        rgb
    }
}

/// The PNG file of `size`×`size` RGB bytes.
fn encode(rgb: &[u8], size: u32) -> Result<Vec<u8>, png::EncodingError> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, size, size);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The decoded `(width, height, rgb)` of PNG `bytes`.
    fn decode(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut rgb = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut rgb).unwrap();
        (info.width, info.height, rgb)
    }

    #[test]
    fn an_opaque_triangle_behind_a_translucent_one_shows_through() {
        // Seen from +x (azimuth 0, elevation 0): right is +y, up is +z, depth is x.
        let view = View {
            azimuth: 0.0,
            elevation: 0.0,
        };
        let big = [[0.0, -1.0, -1.0], [0.0, 1.0, -1.0], [0.0, -1.0, 1.0]];
        let front = Facet {
            corners: big.map(|p| [1.0, p[1], p[2]]),
            positive: true,
        };
        let back = Facet {
            corners: big,
            positive: false,
        };
        let (w, h, rgb) = decode(&write_png(&[front, back], view, 40).unwrap());
        assert_eq!((w, h), (40, 40));
        let pixel = |x: usize, y: usize| &rgb[(y * 40 + x) * 3..][..3];
        // Both triangles face the camera; the light comes from (1, −0.3, 0.5) in world terms
        // (toward + up/2 − right·0.3), so the brightness is 0.3 + 0.7 / √1.34.
        let shade = 0.3 + 0.7 / 1.34f64.sqrt();
        let near = |got: &[u8], want: [f64; 3]| {
            got.iter()
                .zip(want)
                .all(|(&g, w)| (f64::from(g) - w * shade).abs() <= 1.0)
        };
        // Lower left: both; the orange one shows through the blue one at 40 % opacity:
        // 0.4 · (40, 100, 230) + 0.6 · (240, 110, 20).
        let both = pixel(8, 30);
        assert!(near(both, [160.0, 106.0, 104.0]), "{both:?}");
        // Upper right: outside both, white.
        assert_eq!(pixel(36, 4), &[255, 255, 255]);
        // Drawn alone, the opaque triangle is shaded orange.
        let (_, _, alone) = decode(&write_png(&[back], view, 40).unwrap());
        let p = &alone[(30 * 40 + 8) * 3..][..3];
        assert!(near(p, [240.0, 110.0, 20.0]), "{p:?}");
        // The translucent one alone, over white: 0.4 · blue · shade + 0.6 · white.
        let (_, _, blue) = decode(&write_png(&[front], view, 40).unwrap());
        let p = &blue[(30 * 40 + 8) * 3..][..3];
        let over_white = [40.0, 100.0, 230.0].map(|c| 0.4 * c * shade + 0.6 * 255.0);
        assert!(
            p.iter()
                .zip(over_white)
                .all(|(&g, w)| (f64::from(g) - w).abs() <= 1.0),
            "{p:?}"
        );
    }

    #[test]
    fn nothing_to_draw_is_a_white_picture() {
        let (w, h, rgb) = decode(&write_png(&[], View::default(), 8).unwrap());
        assert_eq!((w, h), (8, 8));
        assert!(rgb.iter().all(|&b| b == 255));
    }
}
