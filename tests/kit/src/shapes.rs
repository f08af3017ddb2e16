//! Integer meshes of the test shapes (boxes, tetrahedra), for building operands exactly on a
//! lattice, and the description of a 3D set in failure messages. Boxes take their faces from
//! [`yinset::yin3::shapes::cuboid`].

use yinset::kernel::Point3;
use yinset::num::{Num, Rational};
use yinset::yin3::{shapes, YinSet3};

/// A mesh with integer vertices: points and faces (vertex indices, counterclockwise seen from
/// outside).
pub type Mesh = (Vec<[i64; 3]>, Vec<Vec<usize>>);

/// The box [lo, hi] (lo < hi in each coordinate): the corners and outward quads of
/// [`shapes::cuboid`], corner `i` taking the `hi` coordinate where bit 0, 1, 2 of `i` is set.
pub fn box_mesh(lo: [i64; 3], hi: [i64; 3]) -> Mesh {
    let (_, faces) = shapes::cuboid(&Point3::<Rational>::int(0, 0, 0), &Point3::int(1, 1, 1));
    let pts = (0..8)
        .map(|i| [0, 1, 2].map(|k| if i >> k & 1 == 0 { lo[k] } else { hi[k] }))
        .collect();
    (pts, faces)
}

/// det(b − a, c − a, d − a): six times the signed volume of the tetrahedron abcd.
pub fn det(a: [i64; 3], b: [i64; 3], c: [i64; 3], d: [i64; 3]) -> i64 {
    let (u, v, w) = (
        [0, 1, 2].map(|k| b[k] - a[k]),
        [0, 1, 2].map(|k| c[k] - a[k]),
        [0, 1, 2].map(|k| d[k] - a[k]),
    );
    u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0])
}

/// The tetrahedron with corners `v`, faces outward; `None` if the corners are coplanar.
pub fn tet_mesh(v: [[i64; 3]; 4]) -> Option<Mesh> {
    // For det(b−a, c−a, d−a) > 0 the faces acb, abd, adc, bcd point outward; else their
    // reverses.
    let faces = match det(v[0], v[1], v[2], v[3]).signum() {
        0 => return None,
        1 => [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        _ => [[0, 1, 2], [0, 2, 3], [0, 3, 1], [2, 1, 3]],
    };
    Some((v.to_vec(), faces.map(|f| f.to_vec()).to_vec()))
}

/// A short description of a set for failure messages: 0̂, 1̂, or whether it is bounded and its
/// triangles (float vertices as the shortest decimals that read back to them).
pub fn show3<N: Num>(y: &YinSet3<N>) -> String {
    if y.is_empty() {
        return "0̂".into();
    }
    if y.is_full() {
        return "1̂".into();
    }
    let v = y.vertices();
    let tris: Vec<String> = y
        .triangles()
        .iter()
        .map(|t| format!("[{} {} {}]", v[t[0]], v[t[1]], v[t[2]]))
        .collect();
    let kind = if y.is_bounded() {
        "bounded"
    } else {
        "unbounded"
    };
    format!("{{{kind}, {} triangles: {}}}", tris.len(), tris.join(", "))
}
