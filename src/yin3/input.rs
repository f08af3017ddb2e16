//! Construction from user triangles (yin3 docs: *Validation*; *Float mode*, *Validity*): the
//! faces are validated by [`super::validate`], a float input's on its exact values, whose
//! boundary is then rounded as an operation's result is ([`super::float`]).

use super::error::Yin3Error;
use super::float::rounded_brep;
use super::set::YinSet3;
use super::validate::{build, resolve_for};
use super::values::exact_points;
use crate::kernel::Point3;
use crate::num::Num;

impl<N: Num> YinSet3<N> {
    /// The 3D Yin set bounded by the given faces: `vertices` and, per face, its vertex indices
    /// (0-based) in counterclockwise order seen from outside (normals point out of the set by
    /// the right-hand rule). Planar n-gons are triangulated; T-junctions and vertices or edges
    /// lying on faces are made conforming. Errors name the face or edge at fault.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let v: Vec<Point3<Rational>> = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    ///     .iter().map(|&(x, y, z)| Point3::int(x, y, z)).collect();
    /// let faces = vec![vec![0, 3, 2, 1], vec![4, 5, 6, 7], vec![0, 1, 5, 4], vec![1, 2, 6, 5], vec![2, 3, 7, 6], vec![3, 0, 4, 7]];
    /// let cube = YinSet3::from_triangles(v, faces)?;
    /// assert_eq!(cube.volume(), Some(Rational::from_i64(1)));
    /// assert_eq!((cube.betti().b0, cube.betti().b1, cube.betti().b2), (1, 0, 0));
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn from_triangles(
        vertices: Vec<Point3<N>>,
        faces: Vec<Vec<usize>>,
    ) -> Result<YinSet3<N>, Yin3Error> {
        YinSet3::from_triangles_with(vertices, faces, N::Ctx::default())
    }

    /// As [`YinSet3::from_triangles`], with the given number context.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Float, Tolerance}, yin3::YinSet3};
    /// let p = |x: f64, y: f64, z: f64| Point3::new(Float::new(x), Float::new(y), Float::new(z));
    /// // A tetrahedron with f64 corners, faces counterclockwise seen from outside.
    /// let corners = vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, 0.0, 1.0)];
    /// let faces = vec![vec![0, 2, 1], vec![0, 1, 3], vec![0, 3, 2], vec![1, 2, 3]];
    /// let t = YinSet3::from_triangles_with(corners, faces, Tolerance::new(1e-9))?;
    /// assert!((t.volume().unwrap().get() - 1.0 / 6.0).abs() < 1e-15);
    /// t.validate()?;
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn from_triangles_with(
        vertices: Vec<Point3<N>>,
        faces: Vec<Vec<usize>>,
        ctx: N::Ctx,
    ) -> Result<YinSet3<N>, Yin3Error> {
        if faces.is_empty() {
            return Err(Yin3Error::NoFaces);
        }
        if let Some(v) = vertices
            .iter()
            .position(|p| p.coords().iter().any(|c| !c.is_finite()))
        {
            return Err(Yin3Error::NotFinite { vertex: v });
        }
        let ctx = resolve_for(&vertices, ctx)?;
        let brep = if N::EXACT {
            build(&vertices, &faces, false)?
        } else {
            // Float mode: validity is decided on the exact values; a vertex that the
            // conforming boundary adds (edges crossing on a face) is rounded like a result's.
            rounded_brep(build(&exact_points(&vertices), &faces, true)?)?
        };
        Ok(YinSet3::from_brep(brep, ctx))
    }
}
