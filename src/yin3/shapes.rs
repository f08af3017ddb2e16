//! Face lists of simple solids, for building Yin sets by hand (examples, tests, the demo).

use super::error::Yin3Error;
use super::set::YinSet3;
use crate::kernel::Point3;
use crate::num::Num;

/// A face list: vertices, and faces as vertex indices counterclockwise seen from outside.
pub type Mesh<N> = (Vec<Point3<N>>, Vec<Vec<usize>>);

/// The corners and six outward quads of the box [lo, hi]; corner `i` takes the `hi`
/// coordinate where bit 0, 1, 2 of `i` (x, y, z) is set.
pub fn cuboid<N: Num>(lo: &Point3<N>, hi: &Point3<N>) -> Mesh<N> {
    let c = |i: usize, k: usize| {
        if i >> k & 1 == 0 {
            lo.coord(k)
        } else {
            hi.coord(k)
        }
        .clone()
    };
    let corners = (0..8)
        .map(|i| Point3::new(c(i, 0), c(i, 1), c(i, 2)))
        .collect();
    let faces = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    (corners, faces.map(|f| f.to_vec()).to_vec())
}

/// Several face lists as one (each keeps its own vertices).
pub fn concat<N: Num>(meshes: Vec<Mesh<N>>) -> Mesh<N> {
    let (mut vertices, mut faces) = (Vec::new(), Vec::new());
    for (v, f) in meshes {
        let offset = vertices.len();
        faces.extend(
            f.into_iter()
                .map(|f| f.into_iter().map(|i| i + offset).collect()),
        );
        vertices.extend(v);
    }
    (vertices, faces)
}

impl<N: Num> YinSet3<N> {
    /// The open box (lo, hi); an error if it is flat (some coordinate of `lo` is not below
    /// `hi`'s: a degenerate face).
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let b = YinSet3::<Rational>::cuboid(&Point3::int(0, 0, 0), &Point3::int(1, 2, 3))?;
    /// assert_eq!(b.volume(), Some(Rational::from_i64(6)));
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn cuboid(lo: &Point3<N>, hi: &Point3<N>) -> Result<YinSet3<N>, Yin3Error> {
        let (vertices, faces) = cuboid(lo, hi);
        YinSet3::from_triangles(vertices, faces)
    }
}
