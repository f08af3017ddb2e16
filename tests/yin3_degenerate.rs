//! The degenerate configurations of 3D Yin sets (shared faces, edges and vertices, coplanar
//! overlaps, point and edge contacts, cavities, star vertices, unbounded operands), one test each,
//! plus the errors `from_triangles` must report.
//!
//! All shapes have integer coordinates; C = [0,1]³. The expected values (volumes, Betti
//! numbers (b0, b1, b2) of the open set, glued surfaces and how many are positive, point
//! locations) are computed by hand from the geometry, as stated in each test's comment; none
//! comes from the code under test. Besides those, every test checks that inputs and outputs
//! validate, that (A')' = A, and, for two bounded operands, |A∧B| + |A∨B| = |A| + |B|.
//!
//! Builders: `boxed` (the 6 outward quads of the test kit's `box_mesh`), `tetra` and `prism`
//! (faces turned outward by an integer test against an interior point), and `cells`, which builds the boundary of a union of unit
//! cubes directly (2 triangles per unit face between a cell in the set and one not in it), an
//! independent construction for the complex shapes.

use std::collections::{BTreeSet, HashMap};
use yinset::kernel::Point3;
use yinset::num::{Num, Rational};
use yinset::yin2::Location::{self, Inside, OnBoundary, Outside};
use yinset::yin3::{Yin3Error, YinSet3};

use yinset_testkit::shapes::{box_mesh, Mesh};

type Y = YinSet3<Rational>;
type P = Point3<Rational>;

// ---------------------------------------------------------------------------------------------
// Numbers and points

/// The rational n/d.
fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// The integer n.
fn int(n: i64) -> Rational {
    Rational::from_i64(n)
}

/// The point (x, y, z).
fn p(x: i64, y: i64, z: i64) -> P {
    Point3::int(x, y, z)
}

/// The point (x/2, y/2, z/2).
fn h(x: i64, y: i64, z: i64) -> P {
    Point3::new(q(x, 2), q(y, 2), q(z, 2))
}

// ---------------------------------------------------------------------------------------------
// Meshes (integer vertices, faces as vertex index lists) and builders

/// Build a set from a mesh, panicking with the validator's message if it is rejected.
fn build((pts, faces): Mesh) -> Y {
    let v = pts.iter().map(|c| p(c[0], c[1], c[2])).collect();
    YinSet3::from_triangles(v, faces).unwrap_or_else(|e| panic!("invalid test shape: {e}"))
}

/// The error `from_triangles` reports for a mesh (panics if it accepts it).
fn rejected((pts, faces): Mesh) -> Yin3Error {
    let v = pts.iter().map(|c| p(c[0], c[1], c[2])).collect();
    match YinSet3::<Rational>::from_triangles(v, faces) {
        Ok(_) => panic!("an invalid mesh was accepted"),
        Err(e) => e,
    }
}

/// The box [x0,x1]×[y0,y1]×[z0,z1].
fn boxed(x0: i64, y0: i64, z0: i64, x1: i64, y1: i64, z1: i64) -> Y {
    build(box_mesh([x0, y0, z0], [x1, y1, z1]))
}

/// Newell's normal (twice the vector area) of a planar face, in integers.
fn newell(pts: &[[i64; 3]], face: &[usize]) -> [i64; 3] {
    let mut n = [0i64; 3];
    for i in 0..face.len() {
        let (a, b) = (pts[face[i]], pts[face[(i + 1) % face.len()]]);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    n
}

/// The face, reversed if needed so that its normal points away from the interior point
/// `inside / den` (which must lie strictly off the face's plane).
fn outward(pts: &[[i64; 3]], mut face: Vec<usize>, inside: [i64; 3], den: i64) -> Vec<usize> {
    let n = newell(pts, &face);
    let v0 = pts[face[0]];
    let d: i64 = (0..3).map(|k| n[k] * (inside[k] - den * v0[k])).sum();
    assert!(
        d != 0,
        "test builder: interior point on the plane of a face"
    );
    if d > 0 {
        face.reverse();
    }
    face
}

/// The mesh of the tetrahedron abcd, faces outward.
fn tetra_mesh(a: [i64; 3], b: [i64; 3], c: [i64; 3], d: [i64; 3]) -> Mesh {
    let pts = vec![a, b, c, d];
    let centroid4 = [0, 1, 2].map(|k| a[k] + b[k] + c[k] + d[k]);
    let faces = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
        .iter()
        .map(|f| outward(&pts, f.to_vec(), centroid4, 4))
        .collect();
    (pts, faces)
}

/// The tetrahedron abcd.
fn tetra(a: [i64; 3], b: [i64; 3], c: [i64; 3], d: [i64; 3]) -> Y {
    build(tetra_mesh(a, b, c, d))
}

/// The mesh of the prism {x0 ≤ x ≤ x1} × triangle (y,z) abc, faces outward.
fn prism_mesh(x0: i64, x1: i64, tri: [[i64; 2]; 3]) -> Mesh {
    let mut pts = Vec::new();
    for x in [x0, x1] {
        for [y, z] in tri {
            pts.push([x, y, z]);
        }
    }
    let sum6 = [0, 1, 2].map(|k| pts.iter().map(|v| v[k]).sum::<i64>());
    let faces = [
        vec![0, 1, 2],
        vec![3, 4, 5],
        vec![0, 1, 4, 3],
        vec![1, 2, 5, 4],
        vec![2, 0, 3, 5],
    ]
    .into_iter()
    .map(|f| outward(&pts, f, sum6, 6))
    .collect();
    (pts, faces)
}

/// The prism {x0 ≤ x ≤ x1} × triangle (y,z) abc.
fn prism(x0: i64, x1: i64, tri: [[i64; 2]; 3]) -> Y {
    build(prism_mesh(x0, x1, tri))
}

/// Several meshes as ONE face list; a mesh with `true` has every face reversed.
fn combine(parts: Vec<(Mesh, bool)>) -> Mesh {
    let (mut pts, mut faces) = (Vec::new(), Vec::new());
    for ((p, f), flip) in parts {
        let off = pts.len();
        pts.extend(p);
        for mut face in f {
            if flip {
                face.reverse();
            }
            faces.push(face.into_iter().map(|v| v + off).collect());
        }
    }
    (pts, faces)
}

/// The union of the closed unit cells [i,i+1]×[j,j+1]×[k,k+1], built directly: two triangles
/// per unit face between a cell in the set and one not in it, oriented outward.
fn cells(list: &[(i64, i64, i64)]) -> Y {
    let set: BTreeSet<[i64; 3]> = list.iter().map(|&(i, j, k)| [i, j, k]).collect();
    let mut index: HashMap<[i64; 3], usize> = HashMap::new();
    let mut pts: Vec<[i64; 3]> = Vec::new();
    let mut faces = Vec::new();
    let mut vid = |v: [i64; 3], pts: &mut Vec<[i64; 3]>| {
        *index.entry(v).or_insert_with(|| {
            pts.push(v);
            pts.len() - 1
        })
    };
    for &c in &set {
        for a in 0..3 {
            let (u, v) = ((a + 1) % 3, (a + 2) % 3);
            for s in [-1i64, 1] {
                let mut n = c;
                n[a] += s;
                if set.contains(&n) {
                    continue;
                }
                let mut base = c;
                if s == 1 {
                    base[a] += 1;
                }
                let (mut bu, mut buv, mut bv) = (base, base, base);
                bu[u] += 1;
                buv[u] += 1;
                buv[v] += 1;
                bv[v] += 1;
                // base → +e_u → +e_u+e_v → +e_v turns about e_u × e_v = e_a.
                let mut quad = [base, bu, buv, bv].map(|w| vid(w, &mut pts));
                if s == -1 {
                    quad.reverse();
                }
                faces.push(vec![quad[0], quad[1], quad[2]]);
                faces.push(vec![quad[0], quad[2], quad[3]]);
            }
        }
    }
    build((pts, faces))
}

/// All cells of [x0,x1)×[y0,y1)×[z0,z1) except those listed.
fn block_cells(
    x: (i64, i64),
    y: (i64, i64),
    z: (i64, i64),
    except: &[(i64, i64, i64)],
) -> Vec<(i64, i64, i64)> {
    let mut v = Vec::new();
    for i in x.0..x.1 {
        for j in y.0..y.1 {
            for k in z.0..z.1 {
                if !except.contains(&(i, j, k)) {
                    v.push((i, j, k));
                }
            }
        }
    }
    v
}

// ---------------------------------------------------------------------------------------------
// Checks

fn betti(y: &Y) -> (usize, usize, usize) {
    let b = y.betti();
    (b.b0, b.b1, b.b2)
}

/// Checks a set: it validates, its volume (None: unbounded), Betti numbers (b0, b1, b2), number
/// of glued surfaces and of positive ones, #atoms = b0, and (Y')' = Y.
#[track_caller]
fn check(
    y: &Y,
    volume: Option<Rational>,
    b: (usize, usize, usize),
    surfaces: usize,
    positive: usize,
) {
    if let Err(e) = y.validate() {
        panic!("validate() failed: {e}");
    }
    assert_eq!(y.volume(), volume, "volume");
    assert_eq!(y.is_bounded(), volume.is_some(), "is_bounded");
    assert_eq!(betti(y), b, "Betti numbers (b0, b1, b2)");
    assert_eq!(y.surfaces().len(), surfaces, "number of glued surfaces");
    assert_eq!(
        y.surfaces().iter().filter(|s| s.positive).count(),
        positive,
        "number of positive glued surfaces"
    );
    if !y.is_empty() && !y.is_full() {
        assert_eq!(y.atoms().len(), b.0, "#atoms = b0");
    }
    let back = !&!y;
    if let Err(e) = back.validate() {
        panic!("validate() failed on (Y')': {e}");
    }
    assert!(back == *y, "(Y')' != Y");
}

/// (positive, genus) of each glued surface, sorted.
fn genera(y: &Y) -> Vec<(bool, usize)> {
    let mut g: Vec<(bool, usize)> = y.surfaces().iter().map(|s| (s.positive, s.genus)).collect();
    g.sort();
    g
}

/// Meet and join of two sets, both validated, with |A∧B| + |A∨B| = |A| + |B| when all four
/// are bounded.
#[track_caller]
fn meet_join(a: &Y, b: &Y) -> (Y, Y) {
    for (name, s) in [("A", a), ("B", b)] {
        if let Err(e) = s.validate() {
            panic!("validate() failed on {name}: {e}");
        }
    }
    let m = a & b;
    let j = a | b;
    for (name, s) in [("A∧B", &m), ("A∨B", &j)] {
        if let Err(e) = s.validate() {
            panic!("validate() failed on {name}: {e}");
        }
    }
    if let (Some(va), Some(vb), Some(vm), Some(vj)) =
        (a.volume(), b.volume(), m.volume(), j.volume())
    {
        assert_eq!(vm + vj, va + vb, "|A∧B| + |A∨B| = |A| + |B|");
    }
    (m, j)
}

/// Each point's location.
#[track_caller]
fn locs(y: &Y, cases: &[(P, Location)]) {
    let pts: Vec<P> = cases.iter().map(|c| c.0.clone()).collect();
    let got = y.locate(&pts);
    assert_eq!(got.len(), cases.len(), "locate: one answer per point");
    for ((pt, want), got) in cases.iter().zip(got) {
        assert_eq!(got, *want, "locate {pt}");
    }
}

/// Set equality with a readable failure.
#[track_caller]
fn same(a: &Y, b: &Y, what: &str) {
    assert!(
        a == b,
        "{what}: the sets differ (volumes {:?} and {:?})",
        a.volume(),
        b.volume()
    );
}

// ---------------------------------------------------------------------------------------------
// §3.1–3.5: boxes in contact

/// §3.1. C and [1,2]×[0,1]² share the face x = 1: meet 0̂; join the box [0,2]×[0,1]² (volume
/// 2, a ball: (1,0,0), one positive surface); its complement is ℝ³ minus a ball (1,0,1).
#[test]
fn cubes_sharing_a_face() {
    let a = boxed(0, 0, 0, 1, 1, 1);
    let b = boxed(1, 0, 0, 2, 1, 1);
    check(&a, Some(int(1)), (1, 0, 0), 1, 1);
    check(&b, Some(int(1)), (1, 0, 0), 1, 1);
    let (m, j) = meet_join(&a, &b);
    assert!(m.is_empty(), "meet of face-adjacent cubes is 0̂");
    check(&m, Some(int(0)), (0, 0, 0), 0, 0);
    check(&j, Some(int(2)), (1, 0, 0), 1, 1);
    same(&j, &boxed(0, 0, 0, 2, 1, 1), "C ∨ B = [0,2]×[0,1]²");
    same(&(&a - &b), &a, "C − B = C");
    same(&(&a ^ &b), &j, "C ⊕ B = C ∨ B");
    check(&!&j, None, (1, 0, 1), 1, 0);
    // (1,½,½) is on the glued face, now interior.
    locs(
        &j,
        &[
            (h(2, 1, 1), Inside),
            (h(1, 1, 1), Inside),
            (h(3, 1, 1), Inside),
            (h(2, 0, 1), OnBoundary),
            (p(1, 1, 1), OnBoundary),
            (h(5, 1, 1), Outside),
        ],
    );
    locs(&m, &[(h(2, 1, 1), Outside)]);
}

/// §3.2. C and [1,2]²×[0,1] share the edge x = y = 1: one 4-fin edge. Meet 0̂; join volume 2
/// with two components (2,0,0) and two positive surfaces. The complement is connected with one
/// bounded closed component (the two cubes): (1,0,1), two touching negative surfaces.
#[test]
fn cubes_sharing_an_edge() {
    let a = boxed(0, 0, 0, 1, 1, 1);
    let b = boxed(1, 1, 0, 2, 2, 1);
    let (m, j) = meet_join(&a, &b);
    assert!(m.is_empty());
    check(&j, Some(int(2)), (2, 0, 0), 2, 2);
    same(
        &j,
        &cells(&[(0, 0, 0), (1, 1, 0)]),
        "join = the two cells built directly",
    );
    same(&(&a - &b), &a, "C − B = C");
    same(&(&a ^ &b), &j, "C ⊕ B = C ∨ B");
    let c = !&j;
    check(&c, None, (1, 0, 1), 2, 0);
    locs(
        &j,
        &[
            (h(2, 2, 1), OnBoundary),
            (h(1, 1, 1), Inside),
            (h(3, 3, 1), Inside),
            (h(3, 1, 1), Outside),
            (h(1, 3, 1), Outside),
        ],
    );
    locs(
        &c,
        &[
            (h(2, 2, 1), OnBoundary),
            (h(1, 1, 1), Outside),
            (h(3, 1, 1), Inside),
            (h(1, 3, 1), Inside),
        ],
    );
}

/// §3.3 ([003] Fig. 1a). C and [1,2]³ share the vertex (1,1,1): meet 0̂; join volume 2, (2,0,0),
/// two positive surfaces (never glued through a vertex); complement (1,0,1), two negative.
#[test]
fn cubes_sharing_a_vertex() {
    let a = boxed(0, 0, 0, 1, 1, 1);
    let b = boxed(1, 1, 1, 2, 2, 2);
    let (m, j) = meet_join(&a, &b);
    assert!(m.is_empty());
    check(&j, Some(int(2)), (2, 0, 0), 2, 2);
    same(
        &j,
        &cells(&[(0, 0, 0), (1, 1, 1)]),
        "join = the two cells built directly",
    );
    same(&(&a - &b), &a, "C − B = C");
    check(&!&j, None, (1, 0, 1), 2, 0);
    locs(
        &j,
        &[
            (p(1, 1, 1), OnBoundary),
            (h(2, 2, 3), OnBoundary),
            (h(1, 1, 1), Inside),
            (h(3, 3, 3), Inside),
            (h(3, 3, 1), Outside),
            (h(1, 1, 3), Outside),
        ],
    );
}

/// §3.4. A = [0,2]²×[0,1], B = [1,3]²×[0,1]: bottoms and tops coplanar, same orientation.
/// A∧B = [1,2]²×[0,1] (volume 1); A∨B: 4 + 4 − 1 = 7; A − B an L of 3 cells; A ⊕ B two Ls of 3
/// cells touching along the edges x=2,y=1 and x=1,y=2: volume 6, (2,0,0), two positive surfaces
/// (the column over [1,2]² is open at top and bottom, so no cavity).
#[test]
fn coplanar_overlap_same_orientation() {
    let a = boxed(0, 0, 0, 2, 2, 1);
    let b = boxed(1, 1, 0, 3, 3, 1);
    let (m, j) = meet_join(&a, &b);
    check(&m, Some(int(1)), (1, 0, 0), 1, 1);
    same(&m, &boxed(1, 1, 0, 2, 2, 1), "A ∧ B");
    check(&j, Some(int(7)), (1, 0, 0), 1, 1);
    same(
        &j,
        &cells(&[
            (0, 0, 0),
            (1, 0, 0),
            (0, 1, 0),
            (1, 1, 0),
            (2, 1, 0),
            (1, 2, 0),
            (2, 2, 0),
        ]),
        "A ∨ B",
    );
    let d = &a - &b;
    check(&d, Some(int(3)), (1, 0, 0), 1, 1);
    same(&d, &cells(&[(0, 0, 0), (1, 0, 0), (0, 1, 0)]), "A − B");
    assert_eq!(
        m.volume().unwrap() + d.volume().unwrap(),
        int(4),
        "|A| = |A∧B| + |A∧B'|"
    );
    let x = &a ^ &b;
    check(&x, Some(int(6)), (2, 0, 0), 2, 2);
    same(
        &x,
        &cells(&[
            (0, 0, 0),
            (1, 0, 0),
            (0, 1, 0),
            (2, 1, 0),
            (2, 2, 0),
            (1, 2, 0),
        ]),
        "A ⊕ B",
    );
    locs(
        &m,
        &[
            (h(3, 3, 1), Inside),
            (h(1, 1, 1), Outside),
            (h(2, 3, 1), OnBoundary),
        ],
    );
    locs(
        &j,
        &[
            (h(2, 3, 1), Inside),
            (h(5, 1, 1), Outside),
            (h(4, 1, 1), OnBoundary),
            (h(3, 3, 2), OnBoundary),
        ],
    );
    locs(
        &x,
        &[
            (h(3, 3, 1), Outside),
            (h(4, 2, 1), OnBoundary),
            (h(1, 1, 1), Inside),
            (h(5, 5, 1), Inside),
        ],
    );
}

/// §3.5. A = [0,2]²×[0,1], B = [1,3]²×[1,2]: A's top and B's bottom overlap on [1,2]² at z = 1
/// with opposite orientations. Meet 0̂; join 4 + 4 = 8, one ball (1,0,0), one positive
/// surface; its complement (1,0,1).
#[test]
fn coplanar_overlap_opposite_orientation() {
    let a = boxed(0, 0, 0, 2, 2, 1);
    let b = boxed(1, 1, 1, 3, 3, 2);
    let (m, j) = meet_join(&a, &b);
    assert!(m.is_empty());
    check(&j, Some(int(8)), (1, 0, 0), 1, 1);
    same(
        &j,
        &cells(&[
            (0, 0, 0),
            (1, 0, 0),
            (0, 1, 0),
            (1, 1, 0),
            (1, 1, 1),
            (2, 1, 1),
            (1, 2, 1),
            (2, 2, 1),
        ]),
        "A ∨ B",
    );
    same(&(&a - &b), &a, "A − B = A");
    check(&!&j, None, (1, 0, 1), 1, 0);
    // (3/2,3/2,1) lies on the shared patch: interior of the join.
    locs(
        &j,
        &[
            (h(3, 3, 2), Inside),
            (h(1, 1, 2), OnBoundary),
            (h(5, 5, 2), OnBoundary),
            (h(5, 1, 1), Outside),
            (h(1, 5, 3), Outside),
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// §3.6–3.10: tetrahedra and boxes touching faces

/// The cube [0,4]³ of §3.6–3.10 and §3.14.
fn k4() -> Y {
    boxed(0, 0, 0, 4, 4, 4)
}

/// §3.6 [004], outside. K = [0,4]³; T has base (1,1,4),(3,1,4),(2,3,4) (area 2) inside K's top
/// face and apex (2,2,6) (height 2): |T| = 4/3. Meet 0̂; join 64 + 4/3 = 196/3, a ball.
#[test]
fn tetrahedron_base_inside_cube_face_outside() {
    let k = k4();
    let t = tetra([1, 1, 4], [3, 1, 4], [2, 3, 4], [2, 2, 6]);
    check(&t, Some(q(4, 3)), (1, 0, 0), 1, 1);
    let (m, j) = meet_join(&k, &t);
    assert!(m.is_empty());
    check(&j, Some(q(196, 3)), (1, 0, 0), 1, 1);
    same(&(&k - &t), &k, "K − T = K");
    check(&!&j, None, (1, 0, 1), 1, 0);
    // (2,2) is inside the base triangle (x ∈ (3/2,5/2) at y = 2), and inside T's section at z = 5.
    locs(
        &j,
        &[
            (p(2, 2, 4), Inside),
            (p(2, 2, 5), Inside),
            (h(1, 1, 8), OnBoundary),
            (p(0, 0, 5), Outside),
            (p(3, 3, 5), Outside),
        ],
    );
}

/// §3.6 [004], inside. The same base with apex (2,2,2): T ⊂ K, |T| = 4/3. Meet T; join K;
/// K − T a dent, 64 − 4/3 = 188/3, a ball. (2,2,4) is in the removed base: outside K − T.
#[test]
fn tetrahedron_base_inside_cube_face_inside() {
    let k = k4();
    let t = tetra([1, 1, 4], [3, 1, 4], [2, 3, 4], [2, 2, 2]);
    let (m, j) = meet_join(&k, &t);
    check(&m, Some(q(4, 3)), (1, 0, 0), 1, 1);
    same(&m, &t, "K ∧ T = T");
    same(&j, &k, "K ∨ T = K");
    let d = &k - &t;
    check(&d, Some(q(188, 3)), (1, 0, 0), 1, 1);
    locs(
        &d,
        &[
            (p(2, 2, 3), Outside),
            (p(2, 2, 4), Outside),
            (p(1, 1, 4), OnBoundary),
            (p(0, 0, 4), OnBoundary),
            (p(2, 2, 1), Inside),
        ],
    );
}

/// §3.7. K = [0,4]³ minus T = (2,2,0),(1,1,2),(3,1,2),(2,3,2) (base area 2 at z = 2, height 2:
/// 4/3), whose apex touches the floor at (2,2,0): 64 − 4/3 = 188/3; S⁺ cube and S⁻ tetrahedron
/// meet at one point, b = (1,0,0). The complement: outside ∪ T, (2,0,1). Also built as ONE
/// face list (apex on the diagonal of the floor quad: a T-junction).
#[test]
fn cavity_touching_wall_at_a_point() {
    let k = k4();
    let tm = tetra_mesh([2, 2, 0], [1, 1, 2], [3, 1, 2], [2, 3, 2]);
    let t = build(tm.clone());
    check(&t, Some(q(4, 3)), (1, 0, 0), 1, 1);
    let (m, j) = meet_join(&k, &t);
    same(&m, &t, "K ∧ T = T");
    same(&j, &k, "K ∨ T = K");
    let y = &k - &t;
    check(&y, Some(q(188, 3)), (1, 0, 0), 2, 1);
    let direct = build(combine(vec![
        (box_mesh([0, 0, 0], [4, 4, 4]), false),
        (tm, true),
    ]));
    check(&direct, Some(q(188, 3)), (1, 0, 0), 2, 1);
    same(&direct, &y, "one face list = K − T");
    check(&!&y, None, (2, 0, 1), 2, 1);
    let base_centroid = Point3::new(int(2), q(5, 3), int(2));
    locs(
        &y,
        &[
            (p(2, 2, 0), OnBoundary),
            (p(2, 2, 1), Outside),
            (h(4, 4, 1), Outside),
            (base_centroid, OnBoundary),
            (h(1, 1, 1), Inside),
            (p(2, 2, 3), Inside),
            (p(2, 2, -1), Outside),
        ],
    );
}

/// §3.8. Two cavities T1 = (2,2,2),(1,1,1),(3,1,1),(2,3,1) and T2 = (2,2,2),(1,1,3),(3,1,3),
/// (2,3,3) (2/3 each) touching at their apexes (2,2,2): 64 − 4/3 = 188/3, one bounded closed
/// complement component T1∪T2: (1,0,1); cube S⁺, two S⁻. The complement: outside, T1, T2 with
/// connected closure of Y: (3,0,1), 3 surfaces, 2 positive.
#[test]
fn two_cavities_touching_at_apexes() {
    let k = k4();
    let t1 = tetra([2, 2, 2], [1, 1, 1], [3, 1, 1], [2, 3, 1]);
    let t2 = tetra([2, 2, 2], [1, 1, 3], [3, 1, 3], [2, 3, 3]);
    check(&t1, Some(q(2, 3)), (1, 0, 0), 1, 1);
    let (m, u) = meet_join(&t1, &t2);
    assert!(m.is_empty());
    check(&u, Some(q(4, 3)), (2, 0, 0), 2, 2);
    let y = &k - &u;
    check(&y, Some(q(188, 3)), (1, 0, 1), 3, 1);
    same(&y, &(&(&k - &t1) - &t2), "K − (T1 ∨ T2) = (K − T1) − T2");
    check(&!&y, None, (3, 0, 1), 3, 2);
    locs(
        &y,
        &[
            (p(2, 2, 2), OnBoundary),
            (h(4, 4, 3), Outside),
            (h(4, 4, 5), Outside),
            (h(4, 4, 1), Inside),
            (h(1, 4, 4), Inside),
        ],
    );
}

/// §3.9. K minus T = (1,2,0),(3,2,0),(2,1,2),(2,3,2), whose edge (1,2,0)–(3,2,0) lies on the
/// floor: |T| = |det((2,0,0),(1,−1,2),(1,1,2))|/6 = 8/6 = 4/3, so 188/3; S⁺ cube and S⁻
/// tetrahedron share a segment, (1,0,0). Complement (2,0,1). T's section at height z is
/// [1+z/2, 3−z/2] × [2−z/2, 2+z/2].
#[test]
fn cavity_edge_on_wall() {
    let k = k4();
    let tm = tetra_mesh([1, 2, 0], [3, 2, 0], [2, 1, 2], [2, 3, 2]);
    let t = build(tm.clone());
    check(&t, Some(q(4, 3)), (1, 0, 0), 1, 1);
    let (m, j) = meet_join(&k, &t);
    same(&m, &t, "K ∧ T = T");
    same(&j, &k, "K ∨ T = K");
    let y = &k - &t;
    check(&y, Some(q(188, 3)), (1, 0, 0), 2, 1);
    same(
        &build(combine(vec![
            (box_mesh([0, 0, 0], [4, 4, 4]), false),
            (tm, true),
        ])),
        &y,
        "one face list = K − T",
    );
    check(&!&y, None, (2, 0, 1), 2, 1);
    locs(
        &y,
        &[
            (p(2, 2, 0), OnBoundary),
            (p(1, 2, 0), OnBoundary),
            (p(2, 1, 0), OnBoundary),
            (p(2, 2, 1), Outside),
            (h(4, 2, 1), Inside),
            (p(2, 2, 3), Inside),
        ],
    );
}

/// §3.10. The dent [0,4]³ ∧ ([1,3]²×[0,1])': 64 − 4 = 60, a ball, one positive surface;
/// the floor patch (2,2,0) is outside (removed on both sides); complement (1,0,1).
#[test]
fn dent_from_box_on_floor() {
    let k = k4();
    let b = boxed(1, 1, 0, 3, 3, 1);
    let (m, j) = meet_join(&k, &b);
    same(&m, &b, "K ∧ B = B");
    same(&j, &k, "K ∨ B = K");
    let y = &k & &!&b;
    check(&y, Some(int(60)), (1, 0, 0), 1, 1);
    same(
        &y,
        &cells(&block_cells(
            (0, 4),
            (0, 4),
            (0, 4),
            &[(1, 1, 0), (2, 1, 0), (1, 2, 0), (2, 2, 0)],
        )),
        "dent = 60 cells",
    );
    check(&!&y, None, (1, 0, 1), 1, 0);
    locs(
        &y,
        &[
            (p(2, 2, 0), Outside),
            (h(4, 4, 1), Outside),
            (p(2, 2, 1), OnBoundary),
            (h(1, 4, 0), OnBoundary),
            (p(1, 1, 0), OnBoundary),
            (p(2, 2, 2), Inside),
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// §3.11: [003] Fig. 6

/// The polyhedral ring R of §3.11: with s = min(x, y, 6−x, 6−y),
/// R = {0 ≤ s ≤ 2, |z − 3| ≤ min(s, 2 − s)}, a square frame of diamond section with vertex
/// rings O (offset 0, z=3), B (offset 1, z=2), I (offset 2, z=3), T (offset 1, z=4); 16 planar
/// trapezoids (e.g. wall y=0: y+z=3, z−y=1, y+z=5, z−y=3). Its outer rim O is the closed
/// square z = 3 on the four walls of [0,6]³.
fn ring_mesh() -> Mesh {
    let rings = [(0, 3), (1, 2), (2, 3), (1, 4)];
    let mut pts = Vec::new();
    for (o, z) in rings {
        for (x, y) in [(o, o), (6 - o, o), (6 - o, 6 - o), (o, 6 - o)] {
            pts.push([x, y, z]);
        }
    }
    // A point of R on the centre line of side k (the side from corner k to corner k+1).
    let centre = [[3, 1, 3], [5, 3, 3], [3, 5, 3], [1, 3, 3]];
    let mut faces = Vec::new();
    for r in 0..4 {
        for (k, c) in centre.into_iter().enumerate() {
            let (r1, k1) = ((r + 1) % 4, (k + 1) % 4);
            faces.push(outward(
                &pts,
                vec![4 * r + k, 4 * r + k1, 4 * r1 + k1, 4 * r1 + k],
                c,
                1,
            ));
        }
    }
    (pts, faces)
}

/// §3.11 ([003] Fig. 6 analogue). Built: [0,6]³ minus the ring R of `ring_mesh`, which touches
/// all four walls along the closed polygonal curve z = 3 (through the midpoints (0,0,3), (6,0,3),
/// (6,6,3), (0,6,3) of the vertical edges). |R| = ∫₀² 2·min(t,2−t)·4(6−2t) dt = 56/3 + 40/3 = 32
/// (Pappus: section 2 × centre line 16), so 216 − 32 = 184. R's closure glued to the outside
/// along a longitude is contractible: (1,0,0); 2 surfaces, cube S⁺ (genus 0), ring S⁻ (genus 1).
/// The complement (outside ∪ open solid torus, closure of Y connected): (2,1,1).
#[test]
fn ring_touching_four_walls_fig6() {
    let k = boxed(0, 0, 0, 6, 6, 6);
    let r = build(ring_mesh());
    check(&r, Some(int(32)), (1, 1, 0), 1, 1);
    assert_eq!(genera(&r), vec![(true, 1)], "the ring is a torus");
    let (m, j) = meet_join(&k, &r);
    same(&m, &r, "K ∧ R = R");
    same(&j, &k, "K ∨ R = K");
    let y = &k - &r;
    check(&y, Some(int(184)), (1, 0, 0), 2, 1);
    assert_eq!(
        genera(&y),
        vec![(false, 1), (true, 0)],
        "ring S⁻ of genus 1, cube S⁺ of genus 0"
    );
    same(
        &build(combine(vec![
            (box_mesh([0, 0, 0], [6, 6, 6]), false),
            (ring_mesh(), true),
        ])),
        &y,
        "one face list = K − R",
    );
    let c = !&y;
    check(&c, None, (2, 1, 1), 2, 1);
    assert_eq!(genera(&c), vec![(false, 0), (true, 1)]);
    locs(
        &y,
        &[
            (p(3, 3, 3), Inside),
            (p(3, 3, 1), Inside),
            (h(1, 6, 10), Inside),
            (p(0, 3, 3), OnBoundary),
            (p(0, 0, 3), OnBoundary),
            (p(3, 0, 3), OnBoundary),
            (p(1, 3, 2), OnBoundary),
            (p(1, 3, 3), Outside),
            (p(3, 1, 3), Outside),
            (p(-1, 3, 3), Outside),
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// §3.12–3.14

/// §3.12 ([003] Fig. 1b). [0,2]³ and [2,4]²×[1,3] touch along the segment (2,2,1)–(2,2,2):
/// meet 0̂; join 8 + 8 = 16, two components (2,0,0), two positive surfaces; complement (1,0,1).
#[test]
fn boxes_touching_along_a_segment_fig1b() {
    let a = boxed(0, 0, 0, 2, 2, 2);
    let b = boxed(2, 2, 1, 4, 4, 3);
    let (m, j) = meet_join(&a, &b);
    assert!(m.is_empty());
    check(&j, Some(int(16)), (2, 0, 0), 2, 2);
    let mut list = block_cells((0, 2), (0, 2), (0, 2), &[]);
    list.extend(block_cells((2, 4), (2, 4), (1, 3), &[]));
    same(&j, &cells(&list), "join = 16 cells");
    same(&(&a - &b), &a, "A − B = A");
    check(&!&j, None, (1, 0, 1), 2, 0);
    locs(
        &j,
        &[
            (h(4, 4, 3), OnBoundary),
            (h(4, 4, 1), OnBoundary),
            (h(4, 4, 5), OnBoundary),
            (p(3, 3, 2), Inside),
            (p(1, 1, 1), Inside),
            (h(6, 2, 3), Outside),
            (h(2, 6, 3), Outside),
        ],
    );
}

/// §3.13. Unit cubes in octants +++, +−−, −+−, −−+: each pair shares a half-axis (six 4-fin
/// edges), all meet at the origin (star vertex). Volume 4, four balls (4,0,0), four positive
/// surfaces. The union's closure is contractible (nerve a simplex): complement (1,0,1), four S⁻.
#[test]
fn four_cubes_star_vertex() {
    let list = [(0, 0, 0), (0, -1, -1), (-1, 0, -1), (-1, -1, 0)];
    let direct = cells(&list);
    check(&direct, Some(int(4)), (4, 0, 0), 4, 4);
    let mut y = YinSet3::empty();
    for &(i, j, k) in &list {
        let (m, u) = meet_join(&y, &boxed(i, j, k, i + 1, j + 1, k + 1));
        assert!(m.is_empty(), "octant cubes have disjoint interiors");
        y = u;
    }
    check(&y, Some(int(4)), (4, 0, 0), 4, 4);
    same(&y, &direct, "join of boxes = cells built directly");
    check(&!&y, None, (1, 0, 1), 4, 0);
    locs(
        &y,
        &[
            (p(0, 0, 0), OnBoundary),
            (h(1, 0, 0), OnBoundary),
            (h(0, -1, 0), OnBoundary),
            (h(1, 1, 1), Inside),
            (h(1, -1, -1), Inside),
            (h(-1, -1, 1), Inside),
            (h(-1, -1, -1), Outside),
            (h(1, 1, -1), Outside),
        ],
    );
}

/// §3.14, outside. The prism x ∈ [1,3] × triangle (y,z) (2,4),(1,5),(3,5) (area 1, length 2:
/// volume 2) stands on its edge y=2, z=4 inside K's top face: meet 0̂; join 66, two components
/// (2,0,0), two positive surfaces; complement (1,0,1).
#[test]
fn prism_edge_on_cube_face_outside() {
    let k = k4();
    let pr = prism(1, 3, [[2, 4], [1, 5], [3, 5]]);
    check(&pr, Some(int(2)), (1, 0, 0), 1, 1);
    let (m, j) = meet_join(&k, &pr);
    assert!(m.is_empty());
    check(&j, Some(int(66)), (2, 0, 0), 2, 2);
    same(&(&k - &pr), &k, "K − P = K");
    check(&!&j, None, (1, 0, 1), 2, 0);
    // At z = 9/2 the prism's section is y ∈ [3/2, 5/2].
    locs(
        &j,
        &[
            (p(2, 2, 4), OnBoundary),
            (h(4, 4, 9), Inside),
            (h(4, 2, 9), Outside),
            (p(2, 2, 3), Inside),
            (h(1, 4, 9), Outside),
        ],
    );
}

/// §3.14, inside. The prism x ∈ [1,3] × (2,4),(1,3),(3,3) (volume 2) hangs inside K from its
/// edge y=2, z=4 on the top face: K − P = 62, a cavity touching the wall along a segment:
/// (1,0,0), cube S⁺ and prism S⁻; complement (2,0,1).
#[test]
fn prism_edge_on_cube_face_inside() {
    let k = k4();
    let pr = prism(1, 3, [[2, 4], [1, 3], [3, 3]]);
    let (m, j) = meet_join(&k, &pr);
    same(&m, &pr, "K ∧ P = P");
    same(&j, &k, "K ∨ P = K");
    let y = &k - &pr;
    check(&y, Some(int(62)), (1, 0, 0), 2, 1);
    check(&!&y, None, (2, 0, 1), 2, 1);
    locs(
        &y,
        &[
            (p(2, 2, 4), OnBoundary),
            (h(2, 4, 8), OnBoundary),
            (p(0, 2, 4), OnBoundary),
            (h(4, 4, 7), Outside),
            (h(4, 2, 7), Inside),
            (p(2, 2, 2), Inside),
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// §3.15–3.17

/// §3.15. For an L of 3 cells, the cube with a point-contact cavity and the edge-sharing cubes:
/// A∧A = A∨A = A (same volume), A∧A' = A − A = A ⊕ A = 0̂, A∨A' = A ⊕ A' = 1̂.
#[test]
fn idempotence_and_complement_laws() {
    let k = k4();
    let cavity = &k - &tetra([2, 2, 0], [1, 1, 2], [3, 1, 2], [2, 3, 2]);
    let shapes = [
        (cells(&[(0, 0, 0), (1, 0, 0), (0, 1, 0)]), int(3)),
        (cavity, q(188, 3)),
        (cells(&[(0, 0, 0), (1, 1, 0)]), int(2)),
    ];
    for (a, v) in &shapes {
        assert_eq!(a.volume().as_ref(), Some(v));
        let c = !a;
        let (m, j) = meet_join(a, a);
        same(&m, a, "A ∧ A = A");
        same(&j, a, "A ∨ A = A");
        assert_eq!(m.volume().as_ref(), Some(v));
        let (m, j) = meet_join(a, &c);
        assert!(m.is_empty(), "A ∧ A' = 0̂");
        assert!(j.is_full(), "A ∨ A' = 1̂");
        assert!((a - a).is_empty(), "A − A = 0̂");
        assert!((a ^ a).is_empty(), "A ⊕ A = 0̂");
        assert!((a ^ &c).is_full(), "A ⊕ A' = 1̂");
        let (m, j) = meet_join(&c, &c);
        same(&m, &c, "A' ∧ A' = A'");
        same(&j, &c, "A' ∨ A' = A'");
    }
    let (m, j) = meet_join(&YinSet3::empty(), &YinSet3::full());
    assert!(m.is_empty() && j.is_full());
    check(&YinSet3::empty(), Some(int(0)), (0, 0, 0), 0, 0);
    check(&YinSet3::full(), None, (1, 0, 0), 0, 0);
}

/// §3.16. C' ∧ [−1,2]³ = the big cube with a cavity: 27 − 1 = 26, (1,0,1), cube S⁺ and C S⁻;
/// C' ∨ [−1,2]³ = 1̂. With D = [2,3]×[0,1]² (disjoint from C): C' ∧ D' = ℝ³ minus two cubes,
/// (1,0,2), two S⁻, its complement C ∨ D (2,0,0); C' ∨ D' = (C ∧ D)' = 1̂. With E = [1,2]×[0,1]²
/// (sharing a face with C): C' ∧ E' = ([0,2]×[0,1]²)', (1,0,1), one S⁻.
#[test]
fn unbounded_operands() {
    let c = boxed(0, 0, 0, 1, 1, 1);
    let big = boxed(-1, -1, -1, 2, 2, 2);
    let nc = !&c;
    check(&nc, None, (1, 0, 1), 1, 0);
    let (m, j) = meet_join(&nc, &big);
    check(&m, Some(int(26)), (1, 0, 1), 2, 1);
    assert!(j.is_full(), "C' ∨ [−1,2]³ = 1̂");
    same(
        &m,
        &cells(&block_cells((-1, 2), (-1, 2), (-1, 2), &[(0, 0, 0)])),
        "C' ∧ big = 26 cells",
    );
    same(&m, &(&big - &c), "C' ∧ big = big − C");
    assert_eq!(
        (&big & &c).volume().unwrap() + m.volume().unwrap(),
        int(27),
        "|B| = |B∧C| + |B∧C'|"
    );
    locs(
        &m,
        &[
            (h(1, 1, 1), Outside),
            (h(3, 3, 3), Inside),
            (p(1, 1, 1), OnBoundary),
            (p(2, 0, 0), OnBoundary),
            (h(5, 0, 0), Outside),
        ],
    );

    let d = boxed(2, 0, 0, 3, 1, 1);
    let (mm, jj) = meet_join(&nc, &!&d);
    check(&mm, None, (1, 0, 2), 2, 0);
    assert!(jj.is_full(), "C' ∨ D' = 1̂");
    let cd = !&mm;
    check(&cd, Some(int(2)), (2, 0, 0), 2, 2);
    same(&cd, &(&c | &d), "(C' ∧ D')' = C ∨ D");
    locs(
        &mm,
        &[
            (p(100, 0, 0), Inside),
            (h(1, 1, 1), Outside),
            (h(5, 1, 1), Outside),
            (h(3, 1, 1), Inside),
            (p(2, 0, 0), OnBoundary),
        ],
    );

    let e = boxed(1, 0, 0, 2, 1, 1);
    let (me, _) = meet_join(&nc, &!&e);
    check(&me, None, (1, 0, 1), 1, 0);
    same(&me, &!&boxed(0, 0, 0, 2, 1, 1), "C' ∧ E' = (C ∨ E)'");
    locs(&me, &[(h(2, 1, 1), Outside), (h(5, 1, 1), Inside)]);
}

/// §3.17. The slab [0,3]×[0,5]×[0,1] with the cells (1,1,0) and (1,3,0) removed: 15 − 2 = 13, a
/// genus-2 handlebody (1,2,0), one positive surface of genus 2; its complement (1,2,1). Built
/// from cells and as slab − hole − hole (coplanar tops/bottoms).
#[test]
fn genus_two_slab_from_cubes() {
    let y = cells(&block_cells(
        (0, 3),
        (0, 5),
        (0, 1),
        &[(1, 1, 0), (1, 3, 0)],
    ));
    check(&y, Some(int(13)), (1, 2, 0), 1, 1);
    assert_eq!(genera(&y), vec![(true, 2)]);
    let slab = boxed(0, 0, 0, 3, 5, 1);
    let hole1 = boxed(1, 1, 0, 2, 2, 1);
    let hole2 = boxed(1, 3, 0, 2, 4, 1);
    let (m, j) = meet_join(&slab, &hole1);
    same(&m, &hole1, "slab ∧ hole = hole");
    same(&j, &slab, "slab ∨ hole = slab");
    let b = &(&slab - &hole1) - &hole2;
    check(&b, Some(int(13)), (1, 2, 0), 1, 1);
    same(&b, &y, "slab − holes = cells");
    let c = !&y;
    check(&c, None, (1, 2, 1), 1, 0);
    assert_eq!(genera(&c), vec![(false, 2)]);
    locs(
        &y,
        &[
            (h(3, 3, 1), Outside),
            (h(3, 7, 1), Outside),
            (h(1, 1, 1), Inside),
            (h(3, 5, 1), Inside),
            (h(2, 3, 1), OnBoundary),
        ],
    );
}

/// A solid torus from cubes: the 3×3×1 block without its centre cell: volume 8, (1,1,0), one
/// positive surface of genus 1; its complement (1,1,1).
#[test]
fn solid_torus_from_cubes() {
    let y = cells(&block_cells((0, 3), (0, 3), (0, 1), &[(1, 1, 0)]));
    check(&y, Some(int(8)), (1, 1, 0), 1, 1);
    assert_eq!(genera(&y), vec![(true, 1)]);
    let b = &boxed(0, 0, 0, 3, 3, 1) - &boxed(1, 1, 0, 2, 2, 1);
    check(&b, Some(int(8)), (1, 1, 0), 1, 1);
    same(&b, &y, "block − centre = cells");
    check(&!&y, None, (1, 1, 1), 1, 0);
    locs(
        &y,
        &[
            (h(3, 3, 1), Outside),
            (h(1, 1, 1), Inside),
            (p(1, 1, 0), OnBoundary),
            (h(2, 3, 1), OnBoundary),
        ],
    );
}

// ---------------------------------------------------------------------------------------------
// Errors of from_triangles

/// A box without its top face: the rim edges have one face each.
#[test]
fn open_box_is_rejected_naming_the_open_edge() {
    let (pts, mut faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    faces.remove(1); // the top [4,5,7,6]; faces now bottom, y0, y1, x0, x1
    let top: Vec<String> = [4, 5, 6, 7]
        .iter()
        .map(|&i: &usize| p(pts[i][0], pts[i][1], pts[i][2]).to_string())
        .collect();
    let e = rejected((pts, faces));
    let msg = e.to_string();
    match &e {
        Yin3Error::OpenEdge {
            from,
            to,
            count,
            face,
        } => {
            assert_eq!(*count, 1, "{msg}");
            assert!(
                top.contains(&from.to_string()) && top.contains(&to.to_string()) && from != to,
                "the open edge is on the top rim: {msg}"
            );
            assert!(
                (1..5).contains(face),
                "a side face is on the open edge: {msg}"
            );
            assert!(
                msg.contains(&from.to_string()) && msg.contains(&to.to_string()),
                "message names the edge: {msg}"
            );
            assert!(msg.contains("open"), "{msg}");
        }
        _ => panic!("expected OpenEdge, got {e:?}: {msg}"),
    }
}

/// [0,2]³ and [1,3]³ as one face list: the side faces cross.
#[test]
fn crossing_boxes_in_one_face_list_are_rejected() {
    let e = rejected(combine(vec![
        (box_mesh([0, 0, 0], [2, 2, 2]), false),
        (box_mesh([1, 1, 1], [3, 3, 3]), false),
    ]));
    match &e {
        Yin3Error::Crossing { a, b, .. } => {
            assert!((*a < 6) != (*b < 6), "one face of each box: {e}")
        }
        _ => panic!("expected Crossing, got {e:?}: {e}"),
    }
}

/// [0,2]³ and [0,1]³ as one face list: three faces of the small box lie in faces of the big one
/// with the same orientation (area overlap).
#[test]
fn overlapping_coplanar_faces_in_one_face_list_are_rejected() {
    let e = rejected(combine(vec![
        (box_mesh([0, 0, 0], [2, 2, 2]), false),
        (box_mesh([0, 0, 0], [1, 1, 1]), false),
    ]));
    match &e {
        Yin3Error::Overlap { a, b, .. } => {
            assert!((*a < 6) != (*b < 6), "one face of each box: {e}")
        }
        _ => panic!("expected Overlap, got {e:?}: {e}"),
    }
}

/// The unit box with corner 7 moved to (1,1,2): the three quads through it are not planar.
#[test]
fn non_planar_quad_is_rejected() {
    let (mut pts, faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    pts[7] = [1, 1, 2];
    let e = rejected((pts, faces));
    match &e {
        Yin3Error::NonPlanarFace { face, count, .. } => {
            assert!([1, 3, 5].contains(face), "a quad through corner 7: {e}");
            assert_eq!(*count, 4, "{e}");
        }
        _ => panic!("expected NonPlanarFace, got {e:?}: {e}"),
    }
}

/// The box [0,2]³ plus a triangle (0,0,0),(1,0,0),(2,0,0) of collinear vertices (face 6).
#[test]
fn collinear_face_is_rejected() {
    let (mut pts, mut faces) = box_mesh([0, 0, 0], [2, 2, 2]);
    pts.push([1, 0, 0]);
    faces.push(vec![0, 8, 1]);
    let e = rejected((pts, faces));
    assert!(
        matches!(e, Yin3Error::DegenerateFace { face: 6, .. }),
        "expected DegenerateFace on face 6, got {e:?}: {e}"
    );
}

/// A quad naming one vertex twice, and a face of two vertices.
#[test]
fn repeated_vertex_and_short_faces_are_rejected() {
    let (pts, mut faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    faces[2] = vec![0, 1, 1, 4];
    let e = rejected((pts.clone(), faces));
    assert!(
        matches!(e, Yin3Error::DegenerateFace { face: 2, .. }),
        "got {e:?}: {e}"
    );
    let (_, mut faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    faces[3] = vec![2, 6];
    let e = rejected((pts, faces));
    assert!(
        matches!(e, Yin3Error::DegenerateFace { face: 3, .. }),
        "got {e:?}: {e}"
    );
}

/// Face 0 names vertex 8 of 8.
#[test]
fn out_of_range_index_is_rejected() {
    let (pts, mut faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    faces[0] = vec![0, 2, 8, 1];
    let e = rejected((pts, faces));
    assert_eq!(
        e,
        Yin3Error::IndexOutOfRange {
            face: 0,
            index: 8,
            count: 8
        },
        "{e}"
    );
}

/// No faces at all.
#[test]
fn no_faces_is_rejected() {
    let e = rejected((vec![[0, 0, 0]], vec![]));
    assert_eq!(e, Yin3Error::NoFaces);
}

/// The unit box with its top face (face 1) reversed: around each rim edge the two faces run the
/// same way, so they do not alternate.
#[test]
fn box_with_one_flipped_face_is_rejected() {
    let (pts, mut faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    faces[1].reverse();
    let e = rejected((pts, faces));
    match &e {
        Yin3Error::Inconsistent { a, b, .. } => {
            assert!(*a == 1 || *b == 1, "the flipped face is named: {e}")
        }
        Yin3Error::Orientation { face, .. } => assert_eq!(*face, 1, "{e}"),
        _ => panic!("expected an orientation error (Inconsistent), got {e:?}: {e}"),
    }
}

/// [0,4]³ with [1,2]³ inside, both outward: the inner surface's outer side has winding 1 where
/// a bounded set needs 0 (the cavity must be oriented inward).
#[test]
fn nested_boxes_with_the_same_orientation_are_rejected() {
    let e = rejected(combine(vec![
        (box_mesh([0, 0, 0], [4, 4, 4]), false),
        (box_mesh([1, 1, 1], [2, 2, 2]), false),
    ]));
    match &e {
        Yin3Error::Orientation {
            face,
            winding,
            expected,
        } => {
            assert!((6..12).contains(face), "a face of the inner box: {e}");
            assert_eq!((*winding, *expected), (1, 0), "{e}");
        }
        _ => panic!("expected Orientation, got {e:?}: {e}"),
    }
}

/// Not an error: the unit box with every face reversed is its complement (unbounded, (1,0,1)),
/// and the same two nested boxes with the inner one reversed are the cube with a cavity.
#[test]
fn reversed_box_is_the_complement() {
    let (pts, faces) = box_mesh([0, 0, 0], [1, 1, 1]);
    let r = build(combine(vec![((pts, faces), true)]));
    check(&r, None, (1, 0, 1), 1, 0);
    same(&r, &!&boxed(0, 0, 0, 1, 1, 1), "reversed box = C'");
    let cav = build(combine(vec![
        (box_mesh([0, 0, 0], [4, 4, 4]), false),
        (box_mesh([1, 1, 1], [2, 2, 2]), true),
    ]));
    check(&cav, Some(int(63)), (1, 0, 1), 2, 1);
    same(
        &cav,
        &(&k4() - &boxed(1, 1, 1, 2, 2, 2)),
        "nested faces = K − [1,2]³",
    );
}

// ---------------------------------------------------------------------------------------------
// Order and the Hasse diagram

/// a ≤ b: [1,2]³ lies in [0,3]³ and not the other way; [3,4]×[0,1]² shares only a face with
/// [0,3]³, so neither lies in the other; every set lies in itself.
#[test]
fn boxes_inside_others_are_subsets() {
    let (small, big, beside) = (
        boxed(1, 1, 1, 2, 2, 2),
        boxed(0, 0, 0, 3, 3, 3),
        boxed(3, 0, 0, 4, 1, 1),
    );
    assert!(small.is_subset(&big));
    assert!(!big.is_subset(&small));
    assert!(!beside.is_subset(&big) && !big.is_subset(&beside));
    assert!(big.is_subset(&big));
}

/// The boxes [k, 9−k]³, k = 0..3, given in several orders, box k reversed for odd k (a box, a
/// cavity in it, a box in that, a cavity in that): each surface's parent, the smallest surface
/// whose bounded complement contains it, is the next larger box's, and the outermost has none;
/// the surfaces of k = 0 and 2 are the positive ones.
#[test]
fn nested_boxes_hang_from_the_next_larger() {
    for order in [[0, 1, 2, 3], [3, 2, 1, 0], [1, 3, 0, 2]] {
        let parts = order
            .iter()
            .map(|&k| (box_mesh([k; 3], [9 - k; 3]), k % 2 == 1));
        let y = build(combine(parts.collect()));
        let (surfaces, parents) = (y.surfaces(), y.parents());
        assert_eq!(parents.len(), 4, "{order:?}");
        // The surface of box k: the one whose least x is k.
        let of = |k: i64| {
            let least = |s: usize| {
                (surfaces[s].triangles.iter())
                    .flat_map(|&t| y.triangles()[t])
                    .map(|v| y.vertices()[v].x.clone())
                    .min()
            };
            (0..surfaces.len())
                .find(|&s| least(s) == Some(int(k)))
                .expect("a surface")
        };
        assert_eq!(parents[of(0)], None, "{order:?}");
        for k in 1..4 {
            assert_eq!(parents[of(k)], Some(of(k - 1)), "box {k}, {order:?}");
        }
        for k in 0..4 {
            assert_eq!(surfaces[of(k)].positive, k % 2 == 0, "box {k}, {order:?}");
        }
    }
}

/// A needle tetrahedron, 2¹⁰⁰⁰ long in x and 2⁻⁵⁷⁰ in y and z, holding a box cavity deep
/// inside (x within 2⁻¹⁰ of the length, y and z within 2⁻⁹ of the width), is a valid bounded
/// set: its volume is the needle's 2¹⁰⁰⁰·2⁻¹¹⁴⁰/6 less the box's 2⁹⁸⁰·2⁻⁵⁸⁰·2⁻⁵⁸⁰ (by hand),
/// though the products of its coordinates underflow `f64`.
#[test]
fn a_needle_with_a_cavity_across_two_thousand_binades() {
    let two = |e: i32| Rational::from_f64(2f64.powi(e)).expect("a power of two");
    let (x, w) = (two(1000), two(-570));
    let zero = || int(0);
    let needle = vec![
        Point3::new(zero(), zero(), zero()),
        Point3::new(x.clone(), zero(), zero()),
        Point3::new(zero(), w.clone(), zero()),
        Point3::new(zero(), zero(), w.clone()),
    ];
    let needle_faces = vec![vec![0, 2, 1], vec![0, 1, 3], vec![0, 3, 2], vec![1, 2, 3]];
    let lo = Point3::new(two(990), two(-580), two(-580));
    let hi = Point3::new(two(990) + two(980), two(-579), two(-579));
    let (box_corners, box_faces) = yinset::yin3::shapes::cuboid(&lo, &hi);
    let cavity = box_faces
        .into_iter()
        .map(|f| f.into_iter().rev().collect())
        .collect();
    let (pts, faces) =
        yinset::yin3::shapes::concat(vec![(needle, needle_faces), (box_corners, cavity)]);
    let set = YinSet3::from_triangles(pts, faces).expect("a valid set");
    let expected = x * w.clone() * w / int(6) - two(980) * two(-580) * two(-580);
    assert_eq!(set.volume(), Some(expected));
}
