//! What the 3D formats ([`super::obj`], [`super::stl`], [`super::off`], [`super::ply`]) share:
//! the polygon mesh they read, the error of a malformed file, exact coordinates, and the
//! vertex bookkeeping of their writers.

use super::decimal::push_exact;
use super::ParseError;
use crate::kernel::Point3;
use crate::num::Num;
use foldhash::{HashMap, HashMapExt};

/// A polygon mesh as a file gives it: vertices and faces (0-based vertex indices, any number
/// ≥ 3 of them), and where each face is in the file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mesh<N> {
    /// The vertices, in the order of the file.
    pub vertices: Vec<Point3<N>>,
    /// The faces, in the order of the file: 0-based indices into `vertices`, at least 3.
    pub faces: Vec<Vec<usize>>,
    /// 1-based line of each face in a text file (empty for binary files, whose faces are
    /// named by their index), for error messages that name the face.
    pub face_lines: Vec<usize>,
}

/// The mesh without vertices or faces.
impl<N> Default for Mesh<N> {
    fn default() -> Self {
        Mesh {
            vertices: Vec::new(),
            faces: Vec::new(),
            face_lines: Vec::new(),
        }
    }
}

/// A mesh file that cannot be read: malformed text (line and column), a malformed binary
/// file (byte offset), or vertices without faces.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MeshError {
    /// Malformed text, or the text header of a binary file.
    #[error(transparent)]
    Text(#[from] ParseError),
    /// A malformed binary body: `offset` is the 0-based byte where the fault is.
    #[error("byte {offset}: {message}")]
    Binary {
        /// 0-based byte offset of the fault.
        offset: usize,
        /// What is wrong there.
        message: String,
    },
    /// Vertices without faces (a point cloud): no boundary, so no set, rather than 0̂ read
    /// silently.
    #[error("the file has {vertices} vertices but no faces: a 3D set is read from the faces that bound it (the file of the empty set has no vertices either)")]
    NoFaces {
        /// How many vertices the file has.
        vertices: usize,
    },
}

impl<N> Mesh<N> {
    /// The mesh, or [`MeshError::NoFaces`] if it has vertices but no faces.
    pub fn with_faces(self) -> Result<Mesh<N>, MeshError> {
        if self.faces.is_empty() && !self.vertices.is_empty() {
            return Err(MeshError::NoFaces {
                vertices: self.vertices.len(),
            });
        }
        Ok(self)
    }
}

/// The coordinate written as `token` (a subslice of `text`): exact decimals and fractions
/// `p/q` by [`Num::parse`]; an error at the token if it is not a finite number.
pub(crate) fn coordinate<N: Num>(text: &str, token: &str) -> Result<N, ParseError> {
    let n = N::parse(token).map_err(|e| ParseError::at_token(text, token, e.to_string()))?;
    if n.is_finite() {
        Ok(n)
    } else {
        let message = format!("`{token}` is out of range");
        Err(ParseError::at_token(text, token, message))
    }
}

/// The binary coordinate `value` (an IEEE float, whose value is an exact rational) at byte
/// `offset` of `what`; an error if it is NaN or infinite.
pub(crate) fn binary_coordinate<N: Num>(
    value: f64,
    offset: usize,
    what: &str,
) -> Result<N, MeshError> {
    N::from_f64(value).map_err(|_| MeshError::Binary {
        offset,
        message: format!("{what}: the coordinate {value} is not a finite number"),
    })
}

/// Welds equal points into one vertex (formats such as STL repeat a vertex in every facet).
pub(crate) struct Welder<N> {
    /// The index of each distinct point.
    index: HashMap<Point3<N>, usize>,
    /// The distinct points, in order of first appearance.
    pub vertices: Vec<Point3<N>>,
}

impl<N: Num> Welder<N> {
    /// No points yet.
    pub fn new() -> Welder<N> {
        Welder {
            index: HashMap::new(),
            vertices: Vec::new(),
        }
    }

    /// The index of `p`, a new one if `p` is new.
    pub fn weld(&mut self, p: Point3<N>) -> usize {
        let next = self.vertices.len();
        let k = *self.index.entry(p.clone()).or_insert(next);
        if k == next {
            self.vertices.push(p);
        }
        k
    }
}

/// The vertices that `triangles` use, once each in order of first use, and the triangles
/// renumbered into them (the writers' vertex list).
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub(crate) fn used<'a, N>(
    vertices: &'a [Point3<N>],
    triangles: impl IntoIterator<Item = &'a [usize; 3]>,
) -> (Vec<&'a Point3<N>>, Vec<[usize; 3]>) {
    let mut number: Vec<Option<usize>> = vec![None; vertices.len()];
    let mut kept = Vec::new();
    let renumbered = triangles
        .into_iter()
        .map(|t| {
            t.map(|i| {
                *number[i].get_or_insert_with(|| {
                    kept.push(&vertices[i]);
                    kept.len() - 1
                })
            })
        })
        .collect();
    (kept, renumbered)
}

/// The text shared by OFF and ASCII PLY: `header(vertex count, triangle count)`, then one
/// `x y z` line per vertex that `triangles` use (coordinates exact, see [`used`]), then one
/// `3 a b c` line per triangle (0-based).
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub(crate) fn indexed_text<N: Num>(
    vertices: &[Point3<N>],
    triangles: &[[usize; 3]],
    header: impl FnOnce(usize, usize) -> String,
) -> String {
    let (kept, renumbered) = used(vertices, triangles);
    let mut out = header(kept.len(), renumbered.len());
    out.reserve(text_size(kept.len(), renumbered.len()));
    for p in kept {
        push_coords(&mut out, p);
        out.push('\n');
    }
    for t in renumbered {
        push_triangle(&mut out, "3", t);
    }
    out
}

/// A guess at the length of the text of `vertices` points and `triangles` triangles, to
/// reserve at once: 20 bytes a coordinate and 8 a vertex number.
pub(crate) fn text_size(vertices: usize, triangles: usize) -> usize {
    vertices * 60 + triangles * 24
}

/// Append the line `head a b c` of the vertex numbers of a triangle to `out`.
pub(crate) fn push_triangle(out: &mut String, head: &str, triangle: [usize; 3]) {
    let mut digits = itoa::Buffer::new();
    out.push_str(head);
    for i in triangle {
        out.push(' ');
        out.push_str(digits.format(i));
    }
    out.push('\n');
}

/// Append the coordinates of `p` to `out`, exactly (see [`push_exact`]) and separated by
/// blanks: `x y z`.
pub(crate) fn push_coords<N: Num>(out: &mut String, p: &Point3<N>) {
    for (k, n) in p.coords().into_iter().enumerate() {
        if k > 0 {
            out.push(' ');
        }
        push_exact(out, n);
    }
}

/// `(line, column, message)` of a reader's text error (a test helper).
#[cfg(test)]
pub(crate) fn text_error<N: std::fmt::Debug>(
    read: Result<Mesh<N>, MeshError>,
) -> (usize, usize, String) {
    match read {
        Err(MeshError::Text(e)) => (e.line, e.column, e.message),
        other => panic!("not a text error: {other:?}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    #[test]
    fn welder_merges_equal_points_only() {
        let mut w = Welder::<Rational>::new();
        let half = Rational::parse("1/2").unwrap();
        let p = Point3::new(half.clone(), half.clone(), half);
        assert_eq!(w.weld(p.clone()), 0);
        assert_eq!(w.weld(Point3::int(1, 0, 0)), 1);
        assert_eq!(
            w.weld(Point3::new(Rational::parse("0.5").unwrap(), p.y, p.z)),
            0
        );
        assert_eq!(w.vertices.len(), 2);
    }

    #[test]
    fn used_vertices_are_renumbered_in_order_of_first_use() {
        let v: Vec<Point3<Rational>> = (0..5).map(|i| Point3::int(i, 0, 0)).collect();
        let (kept, tris) = used(&v, &[[4, 2, 3], [3, 2, 0]]);
        assert_eq!(kept, vec![&v[4], &v[2], &v[3], &v[0]]);
        assert_eq!(tris, vec![[0, 1, 2], [2, 1, 3]]);
    }

    #[test]
    fn coordinates_are_exact_and_finite() {
        let text = "v 0.1 1e99999999";
        let x: Rational = coordinate(text, &text[2..5]).unwrap();
        assert_eq!(x, Rational::parse("1/10").unwrap());
        let e = coordinate::<Rational>(text, &text[6..]).unwrap_err();
        assert_eq!(e.column, 7);
        let e = binary_coordinate::<Rational>(f64::NAN, 90, "facet 0").unwrap_err();
        assert_eq!(
            e.to_string(),
            "byte 90: facet 0: the coordinate NaN is not a finite number"
        );
        let third: Rational = binary_coordinate(f64::from(1.0f32 / 3.0), 0, "x").unwrap();
        assert_eq!(third.to_f64(), f64::from(1.0f32 / 3.0));
    }
}
