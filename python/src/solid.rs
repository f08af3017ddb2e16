//! `Solid3`: a 3D Yin set, exact (`YinSet3<Rational>`) or float (`YinSet3<Float>`: exact on
//! the f64 values, results rounded to f64), with the Boolean algebra, measures, location and
//! the mesh formats.

use crate::bytes::{float_bytes, floats, indices, location_codes, measure, points3, Measure};
use crate::error;
use crate::mode::{map, on, Modal};
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use yinset::io::mesh::Mesh;
use yinset::io::{obj, off, ply, stl};
use yinset::num::{Float, Num, Rational};
use yinset::yin3::{Yin3Error, YinSet3};

/// A 3D Yin set in either mode (float: `f64` vertices, operations exact on them and rounded).
type Set3 = Modal<YinSet3<Rational>, YinSet3<Float>>;

/// A 3D Yin set (regular open semianalytic subset of space), exact or float.
#[pyclass(frozen, module = "yinset._yinset")]
#[derive(Clone)]
pub struct Solid3(Set3);

/// The set bounded by `faces` (0-based vertex indices) on `vertices`, with context `ctx`;
/// 0̂ if there are no faces.
fn build<N: Num>(
    vertices: Vec<yinset::kernel::Point3<N>>,
    faces: Vec<Vec<usize>>,
    ctx: N::Ctx,
) -> PyResult<YinSet3<N>> {
    if faces.is_empty() {
        return Ok(YinSet3::empty());
    }
    YinSet3::from_triangles_with(vertices, faces, ctx).map_err(error)
}

/// The mesh of a file's `data` in `format` ("obj", "stl", "off" or "ply").
fn read_mesh<N: Num>(data: &[u8], format: &str) -> PyResult<Mesh<N>> {
    let text = || std::str::from_utf8(data).map_err(|e| error(format!("not UTF-8 text: {e}")));
    match format {
        "obj" => obj::read_obj(text()?).map_err(error),
        "off" => off::read_off(text()?).map_err(error),
        "stl" => stl::read_stl(data).map_err(error),
        "ply" => ply::read_ply(data).map_err(error),
        other => Err(error(format!(
            "unknown mesh format {other:?}: obj, stl, off or ply"
        ))),
    }
}

/// The set of a mesh file's `data` in `format`.
fn of_file<N: Num>(data: &[u8], format: &str, ctx: N::Ctx) -> PyResult<YinSet3<N>> {
    let mesh = read_mesh::<N>(data, format)?;
    build(mesh.vertices, mesh.faces, ctx)
}

/// The file of `set` in `format` ("obj": one object per glued surface; "stl" ASCII,
/// "stl-binary", "off", "ply"), normals out of the set.
fn write<N: Num>(set: &YinSet3<N>, format: &str) -> PyResult<Vec<u8>> {
    if set.is_full() {
        return Err(error("the whole space has no boundary triangles to write"));
    }
    let (v, t) = (set.vertices(), set.triangles());
    Ok(match format {
        "obj" => obj::write_obj(v, &obj::surface_groups(set)).into_bytes(),
        "stl" => stl::write_stl_ascii(v, t).into_bytes(),
        "stl-binary" => stl::write_stl_binary(v, t).map_err(error)?,
        "off" => off::write_off(v, t).into_bytes(),
        "ply" => ply::write_ply(v, t).into_bytes(),
        other => {
            return Err(error(format!(
                "unknown mesh format {other:?}: obj, stl, stl-binary, off or ply"
            )))
        }
    })
}

/// A binary operation of either mode, fallible in float mode.
type Op<N> = fn(&YinSet3<N>, &YinSet3<N>) -> Result<YinSet3<N>, Yin3Error>;

impl Solid3 {
    /// `op(self, other)` without the GIL; both in the same mode.
    fn binary(
        &self,
        py: Python<'_>,
        other: &Solid3,
        exact: Op<Rational>,
        float: Op<Float>,
    ) -> PyResult<Solid3> {
        self.0
            .pair(
                &other.0,
                |a, b| py.detach(|| exact(a, b)).map_err(error),
                |a, b| py.detach(|| float(a, b)).map_err(error),
            )
            .map(Solid3)
    }
}

/// An exact operation as an infallible `Op`.
macro_rules! exact_op {
    ($f:ident) => {
        |a, b| Ok(YinSet3::$f(a, b))
    };
}

#[pymethods]
impl Solid3 {
    /// The solid bounded by the faces `faces` (little-endian i64 indices, `width` per face)
    /// on the vertices `xyz` (little-endian f64 triples); exact if `eps` is None.
    #[staticmethod]
    #[pyo3(signature = (xyz, faces, width, eps=None))]
    fn from_arrays(
        py: Python<'_>,
        xyz: &[u8],
        faces: &[u8],
        width: usize,
        eps: Option<f64>,
    ) -> PyResult<Solid3> {
        let xyz = floats(xyz, 3)?;
        let flat = indices(faces, "face index")?;
        if width < 3 || flat.len() % width != 0 {
            return Err(error(format!(
                "faces of {width} vertices: a face needs at least 3, and the array must be (m, {width})"
            )));
        }
        let faces: Vec<Vec<usize>> = flat.chunks_exact(width).map(<[usize]>::to_vec).collect();
        py.detach(|| {
            Modal::new_in(
                eps,
                || build(points3(&xyz)?, faces.clone(), ()),
                |t| build(points3(&xyz)?, faces.clone(), t),
            )
            .map(Solid3)
        })
    }

    /// The solid of a mesh file's bytes `data` in `format` ("obj", "stl", "off", "ply").
    #[staticmethod]
    #[pyo3(signature = (data, format, eps=None))]
    fn from_file(py: Python<'_>, data: &[u8], format: &str, eps: Option<f64>) -> PyResult<Solid3> {
        py.detach(|| {
            Modal::new_in(
                eps,
                || of_file(data, format, ()),
                |t| of_file(data, format, t),
            )
            .map(Solid3)
        })
    }

    /// The empty solid 0̂.
    #[staticmethod]
    #[pyo3(signature = (eps=None))]
    fn empty(eps: Option<f64>) -> PyResult<Solid3> {
        Modal::new_in(eps, || Ok(YinSet3::empty()), |_| Ok(YinSet3::empty())).map(Solid3)
    }

    /// The whole space 1̂.
    #[staticmethod]
    #[pyo3(signature = (eps=None))]
    fn full(eps: Option<f64>) -> PyResult<Solid3> {
        Modal::new_in(eps, || Ok(YinSet3::full()), |_| Ok(YinSet3::full())).map(Solid3)
    }

    /// True in exact mode.
    #[getter]
    fn exact(&self) -> bool {
        matches!(self.0, Set3::Exact(_))
    }

    /// A ∧ B.
    fn meet(&self, py: Python<'_>, other: &Solid3) -> PyResult<Solid3> {
        self.binary(py, other, exact_op!(meet), YinSet3::try_meet)
    }

    /// A ∨ B.
    fn join(&self, py: Python<'_>, other: &Solid3) -> PyResult<Solid3> {
        self.binary(py, other, exact_op!(join), YinSet3::try_join)
    }

    /// A ∧ B′.
    fn difference(&self, py: Python<'_>, other: &Solid3) -> PyResult<Solid3> {
        self.binary(py, other, exact_op!(difference), YinSet3::try_difference)
    }

    /// (A ∧ B′) ∨ (A′ ∧ B).
    fn symmetric_difference(&self, py: Python<'_>, other: &Solid3) -> PyResult<Solid3> {
        self.binary(
            py,
            other,
            exact_op!(symmetric_difference),
            YinSet3::try_symmetric_difference,
        )
    }

    /// A′.
    fn complement(&self, py: Python<'_>) -> Solid3 {
        Solid3(py.detach(|| map!(&self.0, s => s.complement())))
    }

    /// Set equality; false across modes.
    fn equals(&self, other: &Solid3) -> bool {
        match (&self.0, &other.0) {
            (Set3::Exact(a), Set3::Exact(b)) => a == b,
            (Set3::Float(a), Set3::Float(b)) => a == b,
            _ => false,
        }
    }

    /// True for 0̂.
    fn is_empty(&self) -> bool {
        on!(&self.0, s => s.is_empty())
    }

    /// True for 1̂.
    fn is_full(&self) -> bool {
        on!(&self.0, s => s.is_full())
    }

    /// True if the closure is compact.
    fn is_bounded(&self) -> bool {
        on!(&self.0, s => s.is_bounded())
    }

    /// The volume: exact (numerator, denominator) texts in exact mode, the f64 in float mode;
    /// None if unbounded.
    fn volume(&self) -> Option<Measure> {
        on!(&self.0, s => measure(s.volume()))
    }

    /// The Betti numbers (b0, b1, b2).
    fn betti(&self, py: Python<'_>) -> (usize, usize, usize) {
        let b = py.detach(|| on!(&self.0, s => s.betti()));
        (b.b0, b.b1, b.b2)
    }

    /// The glued surfaces: (triangle indices, positively oriented, genus) each.
    fn surfaces(&self) -> Vec<(Vec<usize>, bool, usize)> {
        on!(&self.0, s => s
            .surfaces()
            .iter()
            .map(|g| (g.triangles.clone(), g.positive, g.genus))
            .collect())
    }

    /// The location codes (i8 bytes) of the points `xyz` (little-endian f64 triples).
    fn locate<'py>(&self, py: Python<'py>, xyz: &[u8]) -> PyResult<Bound<'py, PyBytes>> {
        let xyz = floats(xyz, 3)?;
        let codes = py.detach(|| -> PyResult<Vec<u8>> {
            on!(&self.0, s => Ok(location_codes(&s.locate(&points3(&xyz)?))))
        })?;
        Ok(PyBytes::new(py, &codes))
    }

    /// Check the stored boundary (I1–I4); raises YinsetError if invalid.
    fn validate(&self, py: Python<'_>) -> PyResult<()> {
        py.detach(|| on!(&self.0, s => s.validate())).map_err(error)
    }

    /// The boundary's vertices (f64 triples, each nearest to the exact one) and triangles
    /// (i64 triples, normals out of the set), as bytes.
    fn arrays<'py>(&self, py: Python<'py>) -> (Bound<'py, PyBytes>, Bound<'py, PyBytes>) {
        on!(&self.0, s => {
            let xyz = float_bytes(s.vertices().iter().flat_map(|p| p.coords()));
            let tris: Vec<u8> = s
                .triangles()
                .iter()
                .flatten()
                .flat_map(|&i| (i as i64).to_le_bytes())
                .collect();
            (PyBytes::new(py, &xyz), PyBytes::new(py, &tris))
        })
    }

    /// The mesh file of the solid in `format` ("obj", "stl", "stl-binary", "off", "ply").
    fn to_file<'py>(&self, py: Python<'py>, format: &str) -> PyResult<Bound<'py, PyBytes>> {
        let bytes = py.detach(|| on!(&self.0, s => write(s, format)))?;
        Ok(PyBytes::new(py, &bytes))
    }
}
