//! Workloads of the 3D benches, as `f64` triangle meshes written to OBJ files that
//! every contender reads: yinset exact (each decimal of the file as the rational it is, as
//! CGAL reads it), yinset float, Manifold, CGAL and boolmesh.
//!
//! - V1: two octaspheres (an octahedron's faces cut into m² triangles each, vertices pushed
//!   onto the sphere) of n = 8m² triangles, the second moved by (1/2, 1/4, 1/8);
//! - V2: a k³ checkerboard of unit cubes (cubes sharing only edges and corners: one Yin set with
//!   many non-manifold edges and vertices), against itself shifted by half a cell along x
//!   (coplanar faces everywhere) and against itself turned by atan(1/16) about z and then
//!   about x (the map (x, y) ↦ (x − y/16, x/16 + y): a rotation scaled by √(1 + 1/256), exact
//!   on the lattice, so faces stay planar and the file is exact);
//! - V3: the meshes of ../shared/data/3d, with torusbig translated by (1/2, 1/4, 1/8) and the
//!   heart halved and moved to (−5/2, 5/4, 1/4), inside the rabbit's box;
//! - V4: a sphere of radius 1 about (1/64, 1/32, 3/64) and the N³ cells of the cube
//!   [−9/8, 9/8]³.

#![allow(dead_code)] // each bench target uses a part of this module

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use yinset::io::obj::read_obj;
use yinset::kernel::Point3;
use yinset::num::{Num, Rational};
use yinset::yin3::shapes::cuboid;
use yinset::yin3::YinSet3;

/// A closed triangle mesh, outward oriented.
#[derive(Clone, Debug, Default)]
pub struct Mesh3 {
    /// Vertex coordinates.
    pub points: Vec<[f64; 3]>,
    /// Triangles as indices into `points`, counterclockwise seen from outside.
    pub tris: Vec<[usize; 3]>,
}

impl Mesh3 {
    /// The mesh with every point mapped by `f`.
    pub fn map(&self, f: impl Fn([f64; 3]) -> [f64; 3]) -> Mesh3 {
        Mesh3 {
            points: self.points.iter().map(|&p| f(p)).collect(),
            tris: self.tris.clone(),
        }
    }

    /// The OBJ text: `v x y z` with Rust's shortest round-trip decimals, 1-based `f a b c`.
    pub fn obj(&self) -> String {
        let mut s = String::new();
        for [x, y, z] in &self.points {
            writeln!(s, "v {x:?} {y:?} {z:?}").expect("writing to a String");
        }
        for [a, b, c] in &self.tris {
            writeln!(s, "f {} {} {}", a + 1, b + 1, c + 1).expect("writing to a String");
        }
        s
    }
}

/// The translation by `d`.
pub fn shift(d: [f64; 3]) -> impl Fn([f64; 3]) -> [f64; 3] {
    move |p| [p[0] + d[0], p[1] + d[1], p[2] + d[2]]
}

/// An octasphere of radius `r` about `c`: each face of the octahedron |x|+|y|+|z| = m cut into
/// m² triangles on its lattice points, every vertex then scaled onto the sphere (8m²
/// triangles).
pub fn octasphere(m: usize, c: [f64; 3], r: f64) -> Mesh3 {
    let mut index: HashMap<[i64; 3], usize> = HashMap::new();
    let mut mesh = Mesh3::default();
    let m = m as i64;
    let mut vertex = |l: [i64; 3], mesh: &mut Mesh3| -> usize {
        *index.entry(l).or_insert_with(|| {
            let v = l.map(|x| x as f64);
            let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            mesh.points.push([0, 1, 2].map(|k| c[k] + r * v[k] / len));
            mesh.points.len() - 1
        })
    };
    for s in 0..8 {
        let sign = [0, 1, 2].map(|k| if s >> k & 1 == 1 { -1 } else { 1 });
        // Lattice point (m − i − j, i, j) of this octant's face.
        let at = |i: i64, j: i64| [sign[0] * (m - i - j), sign[1] * i, sign[2] * j];
        let outward = sign[0] * sign[1] * sign[2] > 0;
        let mut tri = |a: [i64; 3], b: [i64; 3], c: [i64; 3], mesh: &mut Mesh3| {
            let t = [vertex(a, mesh), vertex(b, mesh), vertex(c, mesh)];
            mesh.tris.push(if outward { t } else { [t[0], t[2], t[1]] });
        };
        for i in 0..m {
            for j in 0..m - i {
                tri(at(i, j), at(i + 1, j), at(i, j + 1), &mut mesh);
                if i + j < m - 1 {
                    tri(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), &mut mesh);
                }
            }
        }
    }
    mesh
}

/// The octasphere parameter m whose 8m² triangles are nearest to `n`.
pub fn sphere_m(n: usize) -> usize {
    ((n as f64 / 8.0).sqrt().round() as usize).max(1)
}

/// V1 at about `n` triangles per sphere: the unit sphere about the origin and a copy moved by
/// (1/2, 1/4, 1/8).
pub fn v1(n: usize) -> (Mesh3, Mesh3) {
    let a = octasphere(sphere_m(n), [0.0; 3], 1.0);
    let b = a.map(shift([0.5, 0.25, 0.125]));
    (a, b)
}

/// The boundary of the union of axis-parallel boxes `[lo, lo + size]` given by their `lo`,
/// 12 triangles each, corners shared through their lattice coordinates `lo / size`.
fn boxes(cells: &[[i64; 3]], size: f64, origin: [f64; 3]) -> Mesh3 {
    let mut index: HashMap<[i64; 3], usize> = HashMap::new();
    let mut mesh = Mesh3::default();
    // The faces of the unit cube as corner bit patterns (x + 2y + 4z), outward: the library's
    // box face list, whose corner i takes the upper coordinate where bit k of i is set.
    let unit = |v: i64| Point3::<Rational>::int(v, v, v);
    let (_, faces) = cuboid(&unit(0), &unit(1));
    for cell in cells {
        let corner: Vec<usize> = (0..8)
            .map(|b| {
                let l = [0, 1, 2].map(|k| cell[k] + (b >> k & 1) as i64);
                *index.entry(l).or_insert_with(|| {
                    mesh.points
                        .push([0, 1, 2].map(|k| origin[k] + l[k] as f64 * size));
                    mesh.points.len() - 1
                })
            })
            .collect();
        for f in &faces {
            mesh.tris.push([corner[f[0]], corner[f[1]], corner[f[2]]]);
            mesh.tris.push([corner[f[0]], corner[f[2]], corner[f[3]]]);
        }
    }
    mesh
}

/// The k³ checkerboard of unit cubes: cube (i, j, l) for i + j + l even.
pub fn checkerboard(k: usize) -> Mesh3 {
    let k = k as i64;
    let cells: Vec<[i64; 3]> = (0..k)
        .flat_map(|i| (0..k).flat_map(move |j| (0..k).map(move |l| [i, j, l])))
        .filter(|c| (c[0] + c[1] + c[2]) % 2 == 0)
        .collect();
    boxes(&cells, 1.0, [0.0; 3])
}

/// The slight rotation of V2: (x, y) ↦ (x − y/16, x/16 + y) about z, then (y, z) ↦ (y − z/16,
/// y/16 + z) about x (each a rotation by atan(1/16) scaled by √(1 + 1/256)).
pub fn turn([x, y, z]: [f64; 3]) -> [f64; 3] {
    let (x, y) = (x - y / 16.0, x / 16.0 + y);
    let (y, z) = (y - z / 16.0, y / 16.0 + z);
    [x, y, z]
}

/// V2 at k: the checkerboard, its copy shifted by half a cell along x, and its turned copy.
pub fn v2(k: usize) -> (Mesh3, Mesh3, Mesh3) {
    let a = checkerboard(k);
    let shifted = a.map(shift([0.5, 0.0, 0.0]));
    let turned = a.map(turn);
    (a, shifted, turned)
}

/// The sphere of V4 (about `n` triangles).
pub fn v4_sphere(n: usize) -> Mesh3 {
    octasphere(sphere_m(n), [1.0 / 64.0, 1.0 / 32.0, 3.0 / 64.0], 1.0)
}

/// The N³ cells of [−9/8, 9/8]³, each a cube mesh.
pub fn v4_cells(n: usize) -> Vec<Mesh3> {
    let size = 2.25 / n as f64;
    let n = n as i64;
    (0..n)
        .flat_map(|i| (0..n).flat_map(move |j| (0..n).map(move |l| [i, j, l])))
        .map(|c| boxes(&[c], size, [-1.125; 3]))
        .collect()
}

/// A mesh of ../shared/data/3d (`$YINSET_DATA/3d` if set).
pub fn data_path(name: &str) -> PathBuf {
    let root = std::env::var_os("YINSET_DATA").map_or_else(
        || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/data"),
        PathBuf::from,
    );
    let p = root.join("3d").join(name);
    assert!(p.is_file(), "bench data missing: {}", p.display());
    p
}

/// The `v` and `f` lines of an OBJ file as `f64` (fan-triangulated), for deriving V3 copies.
pub fn read_f64(path: &Path) -> Mesh3 {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let m =
        read_obj::<yinset::num::Float>(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    Mesh3 {
        points: m.vertices.iter().map(|p| p.to_f64()).collect(),
        tris: m
            .faces
            .iter()
            .flat_map(|f| (1..f.len() - 1).map(move |k| [f[0], f[k], f[k + 1]]))
            .collect(),
    }
}

/// Where the workload files go: target/yin3_workloads.
pub fn out_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/yin3_workloads");
    std::fs::create_dir_all(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display()));
    d
}

/// Write `mesh` as target/yin3_workloads/`name`.obj and return the path.
pub fn write(name: &str, mesh: &Mesh3) -> PathBuf {
    let p = out_dir().join(format!("{name}.obj"));
    std::fs::write(&p, mesh.obj()).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    p
}

/// The V3 pairs as files: (label, A, B); the derived copies are written beside the others.
pub fn v3_files() -> Vec<(String, PathBuf, PathBuf)> {
    let torusbig = data_path("torusbig.obj");
    let moved = write(
        "v3_torusbig_moved",
        &read_f64(&torusbig).map(shift([0.5, 0.25, 0.125])),
    );
    let heart = write(
        "v3_heart_scaled",
        &read_f64(&data_path("heart.obj"))
            .map(|p| [0.5 * p[0] - 2.5, 0.5 * p[1] + 1.25, 0.5 * p[2] + 0.25]),
    );
    vec![
        (
            "ballmid∧ballright".into(),
            data_path("ballmid.obj"),
            data_path("ballright.obj"),
        ),
        (
            "torus∧innerball".into(),
            data_path("torus.obj"),
            data_path("innerball.obj"),
        ),
        ("torusbig∧moved".into(), torusbig, moved),
        (
            "rabbit∧heart".into(),
            data_path("Rabbit_Lowpoly_2.obj"),
            heart,
        ),
    ]
}

/// The Yin set bounded by an OBJ file, read in the backend `N` (exact: every decimal as the
/// rational it is).
pub fn load<N: Num>(path: &Path) -> YinSet3<N> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let m = read_obj::<N>(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    YinSet3::from_triangles(m.vertices, m.faces)
        .unwrap_or_else(|e| panic!("{}: not a Yin set: {e}", path.display()))
}

/// The value after the command-line option `name` in `args`, if any.
pub fn option<'a>(args: &'a [String], name: &str) -> Option<&'a String> {
    let i = args.iter().position(|a| a == name)?;
    args.get(i + 1)
}
