//! What the pictures of a 3D set (PNG in `super::png3`, [`super::html3`]) draw and from where:
//! its boundary triangles in the pictures' own `f64` coordinates (a picture is not exact), each
//! marked with the orientation of its glued surface and drawn in that orientation's colour, and
//! an orthographic view given by azimuth and elevation.

use super::picture_frame::PictureFrame;
use crate::kernel::Point3;
use crate::num::Num;
use crate::yin3::YinSet3;

/// Colour of positively oriented glued surfaces (outer surfaces).
pub const POSITIVE: [u8; 3] = [40, 100, 230];
/// Colour of negatively oriented glued surfaces (cavities; an unbounded set's surface).
pub const NEGATIVE: [u8; 3] = [240, 110, 20];
/// Opacity of positively oriented surfaces.
pub const OPACITY: f32 = 0.4;

/// One boundary triangle to draw: its corners (counterclockwise seen from outside the set) and
/// whether its glued surface is positively oriented (seed 003 Def. 7.3: an outer surface)
/// rather than negatively (a cavity's, or the surface of an unbounded set).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Facet {
    /// The corners.
    pub corners: [[f64; 3]; 3],
    /// True if its glued surface is positively oriented.
    pub positive: bool,
}

/// The boundary triangles of `sets` with their surfaces' orientations, in the pictures' own
/// coordinates (`io::picture_frame`: offsets from the lower corner of the sets' bounding
/// box over its larger side, computed exactly, then rounded to `f64`), so that sets at any
/// position and scale are drawn alike.
pub fn facets<N: Num>(sets: &[&YinSet3<N>]) -> Vec<Facet> {
    let xyz = |p: &Point3<N>| p.coords().map(N::clone).to_vec();
    let boxes = sets.iter().filter_map(|s| s.bbox());
    let picture = PictureFrame::around(boxes.map(|b| (xyz(&b.min), xyz(&b.max))));
    let place = |p: &Point3<N>| {
        let [x, y, z] = p.coords();
        let c = |axis, n| picture.coordinate(axis, n);
        [c(0, x), c(1, y), c(2, z)]
    };
    sets.iter()
        .flat_map(|set| {
            set.surfaces().iter().flat_map(move |s| {
                s.triangles.iter().map(move |&t| Facet {
                    corners: set.triangles()[t].map(|v| place(&set.vertices()[v])),
                    positive: s.positive,
                })
            })
        })
        .collect()
}

/// An orthographic view direction: the camera looks at the scene from `azimuth` degrees
/// (counterclockwise about the z axis, from the x axis) and `elevation` degrees (above the
/// xy plane).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    /// Degrees about the z axis, from the x axis towards the y axis.
    pub azimuth: f64,
    /// Degrees above the xy plane.
    pub elevation: f64,
}

impl Default for View {
    /// The default view: from the front right, a little above.
    fn default() -> Self {
        View {
            azimuth: -60.0,
            elevation: 25.0,
        }
    }
}

/// A view that is not `AZIMUTH,ELEVATION` in degrees.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{0}` is not a view: expected AZIMUTH,ELEVATION in degrees, e.g. -60,25 (elevation from -90 to 90)")]
pub struct BadView(pub String);

impl std::str::FromStr for View {
    type Err = BadView;

    /// `AZIMUTH,ELEVATION` in degrees, the elevation within [−90, 90].
    fn from_str(s: &str) -> Result<View, BadView> {
        let bad = || BadView(s.to_string());
        let (a, e) = s.split_once(',').ok_or_else(bad)?;
        let azimuth: f64 = a.trim().parse().map_err(|_| bad())?;
        let elevation: f64 = e.trim().parse().map_err(|_| bad())?;
        if !azimuth.is_finite() || !(-90.0..=90.0).contains(&elevation) {
            return Err(bad());
        }
        Ok(View { azimuth, elevation })
    }
}

/// The camera's frame: `right` and `up` span the picture plane, `toward` points from the scene
/// to the viewer (depth grows towards the viewer).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Unit vector to the right in the picture.
    pub right: [f64; 3],
    /// Unit vector up in the picture.
    pub up: [f64; 3],
    /// Unit vector from the scene towards the viewer.
    pub toward: [f64; 3],
}

impl View {
    /// The camera frame of this view (z is up in the picture unless looking straight down or
    /// up).
    pub fn camera(self) -> Camera {
        let (a, e) = (self.azimuth.to_radians(), self.elevation.to_radians());
        let toward = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
        let right = [-a.sin(), a.cos(), 0.0];
        Camera {
            right,
            up: cross(toward, right),
            toward,
        }
    }
}

impl Camera {
    /// `p` in camera coordinates: `[right, up, depth]`.
    pub fn project(&self, p: [f64; 3]) -> [f64; 3] {
        [dot(p, self.right), dot(p, self.up), dot(p, self.toward)]
    }

    /// The brightness in [0.3, 1] of a facet with corners `c`, lit from over the viewer's
    /// shoulder, both sides alike (cavities are seen from inside).
    pub fn shade(&self, c: &[[f64; 3]; 3]) -> f64 {
        let n = cross(sub(c[1], c[0]), sub(c[2], c[0]));
        let light = add(
            self.toward,
            add(scale(self.up, 0.5), scale(self.right, -0.3)),
        );
        let len = (dot(n, n) * dot(light, light)).sqrt();
        if len == 0.0 || !len.is_finite() {
            return 0.3;
        }
        0.3 + 0.7 * (dot(n, light) / len).abs()
    }
}

/// `a · b`.
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a − b`.
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a + b`.
fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `s · a`.
fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    a.map(|x| x * s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    #[test]
    fn views_parse_and_give_right_handed_cameras() {
        let v: View = " 90 , -30".parse().unwrap();
        assert_eq!((v.azimuth, v.elevation), (90.0, -30.0));
        for bad in ["90", "a,b", "0,91", "inf,0", "1,2,3"] {
            assert!(bad.parse::<View>().is_err(), "{bad}");
        }
        let c = View {
            azimuth: 0.0,
            elevation: 0.0,
        }
        .camera();
        assert!(close(c.toward, [1.0, 0.0, 0.0]) && close(c.up, [0.0, 0.0, 1.0]));
        assert!(close(c.right, [0.0, 1.0, 0.0]));
        // right × up = toward: a right-handed frame, so pictures are not mirrored.
        let c = View::default().camera();
        assert!(close(cross(c.right, c.up), c.toward));
        assert!(close(
            c.project([1.0, 2.0, 3.0]),
            [
                dot([1.0, 2.0, 3.0], c.right),
                dot([1.0, 2.0, 3.0], c.up),
                dot([1.0, 2.0, 3.0], c.toward)
            ]
        ));
    }

    #[test]
    fn facets_carry_their_surface_orientation() {
        let p = |c: i64| Point3::int(c, c, c);
        let hollow = &YinSet3::<Rational>::cuboid(&p(0), &p(3)).unwrap()
            - &YinSet3::cuboid(&p(1), &p(2)).unwrap();
        let f = facets(&[&hollow]);
        assert_eq!(f.len(), hollow.triangles().len());
        let inner = f.iter().filter(|f| !f.positive).collect::<Vec<_>>();
        assert!(inner.len() >= 12 && f.len() - inner.len() >= 12);
        // The cavity [1, 2]³ of the box [0, 3]³, placed in the unit box.
        assert!(inner.iter().all(|f| f
            .corners
            .iter()
            .flatten()
            .all(|&x| x == 1.0 / 3.0 || x == 2.0 / 3.0)));
    }
}
