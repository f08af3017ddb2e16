//! The properties of the 3D targets: building operands from lattice solids, the checks on the
//! constructor (`YinSet3::from_triangles`) and on the exact Boolean operations, and the OBJ
//! reader.

use crate::check::fail;
use crate::input3::{
    Combine, Construct3Input, LatticePoint, Operand, Ops3Input, Probe3, Solid, ROTATE,
};
use num_bigint::BigInt;
use std::fmt::Debug;
use yinset::io::mesh;
use yinset::io::obj::{read_obj, write_obj};
use yinset::io::ParseError;
use yinset::kernel::Point3;
use yinset::num::{Float, Num, Rational};
use yinset::yin2::Location;
use yinset::yin3::{Yin3Error, YinSet3};

type Y3 = YinSet3<Rational>;
type P3 = Point3<Rational>;

/// The rotation of rotated inputs: the unit quaternion (4 + i + 2j + 3k)/√30 (axis (1, 2, 3),
/// cos θ = 1/15), whose rational matrix has no zero entry: no face of a rotated box is
/// parallel to a coordinate plane. Integer entries over 30.
const ROTATION: [[i64; 3]; 3] = [[4, -20, 22], [28, 10, 4], [-10, 20, 20]];

/// The exact point of doubled integer coordinates, rotated if asked.
fn point(d: [i64; 3], rotate: bool) -> P3 {
    let q = |n: i64, den: i64| Rational::new(BigInt::from(n), BigInt::from(den));
    if rotate {
        let r = ROTATION.map(|row| (0..3).map(|k| row[k] * d[k]).sum::<i64>());
        Point3::new(q(r[0], 60), q(r[1], 60), q(r[2], 60))
    } else {
        Point3::new(q(d[0], 2), q(d[1], 2), q(d[2], 2))
    }
}

fn lattice(p: LatticePoint, rotate: bool) -> P3 {
    point(p.0.map(|c| 2 * i64::from(c)), rotate)
}

/// A short description of a set for failure messages: 0̂, 1̂, or its triangles (float
/// vertices as the shortest decimals that read back to them).
pub fn show<N: Num>(y: &YinSet3<N>) -> String {
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

/// Assert that `set` passes the exact validator.
fn valid<D: Debug>(what: &str, set: &Y3, input: &D) {
    if let Err(e) = set.validate() {
        fail!(
            input,
            "{what} fails the validator: {e}\n{what} = {}",
            show(set)
        );
    }
}

/// Box corners numbered by bits (x: 1, y: 2, z: 4) and its outward quads.
const BOX_FACES: [[usize; 4]; 6] = [
    [0, 2, 3, 1],
    [4, 5, 7, 6],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
];

/// A mesh: integer vertices (doubled coordinates) and faces (vertex index lists, outward).
pub type Mesh = (Vec<[i64; 3]>, Vec<Vec<usize>>);

/// The boundary of a solid as integer vertices (doubled coordinates) and outward faces;
/// `None` for the empty set.
pub fn solid_mesh(s: &Solid) -> Option<Mesh> {
    match s {
        Solid::None => None,
        Solid::Box { lo, hi } => {
            let pts = (0..8)
                .map(|i| {
                    [0, 1, 2].map(|k| 2 * i64::from(if i >> k & 1 == 0 { lo[k] } else { hi[k] }))
                })
                .collect();
            Some((pts, BOX_FACES.iter().map(|f| f.to_vec()).collect()))
        }
        Solid::Tetra(p) => {
            let v: Vec<[i64; 3]> = p.iter().map(|q| q.0.map(|c| 2 * i64::from(c))).collect();
            let sub = |a: [i64; 3], b: [i64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
            let (x, y, z) = (sub(v[1], v[0]), sub(v[2], v[0]), sub(v[3], v[0]));
            let det = x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0])
                + x[2] * (y[0] * z[1] - y[1] * z[0]);
            // For det(b−a, c−a, d−a) > 0 the faces acb, abd, adc, bcd point outward.
            let faces = match det.signum() {
                0 => return None,
                1 => vec![vec![0, 2, 1], vec![0, 1, 3], vec![0, 3, 2], vec![1, 2, 3]],
                _ => vec![vec![0, 1, 2], vec![0, 2, 3], vec![0, 3, 1], vec![2, 1, 3]],
            };
            Some((v, faces))
        }
        Solid::Cells { offset, mask } => {
            if *mask == 0 {
                return None;
            }
            let inside = |c: [i64; 3]| {
                c.iter().all(|&x| (0..2).contains(&x))
                    && mask >> (c[0] + 2 * c[1] + 4 * c[2]) & 1 == 1
            };
            let mut index = std::collections::HashMap::new();
            let mut pts = Vec::new();
            let mut faces = Vec::new();
            let o = offset.map(i64::from);
            for a in 0..3 {
                let (u, v) = ((a + 1) % 3, (a + 2) % 3);
                // Unit faces x_a = t between cells c (below) and c + e_a (above).
                for t in -1..2 {
                    for i in 0..2 {
                        for j in 0..2 {
                            let mut c = [0; 3];
                            (c[a], c[u], c[v]) = (t, i, j);
                            let mut d = c;
                            d[a] += 1;
                            let (lo, hi) = (inside(c), inside(d));
                            if lo == hi {
                                continue;
                            }
                            let corner = |du: i64, dv: i64| {
                                let mut w = d;
                                w[u] += du;
                                w[v] += dv;
                                [0, 1, 2].map(|k| 2 * (w[k] + o[k]))
                            };
                            // base → +u → +u+v → +v turns about e_a: outward iff the set is below.
                            let mut quad: Vec<usize> =
                                [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)]
                                    .into_iter()
                                    .map(|w| {
                                        *index.entry(w).or_insert_with(|| {
                                            pts.push(w);
                                            pts.len() - 1
                                        })
                                    })
                                    .collect();
                            if hi {
                                quad.reverse();
                            }
                            faces.push(quad);
                        }
                    }
                }
            }
            Some((pts, faces))
        }
    }
}

/// The Yin set of a solid (its boundary built directly, validated by `from_triangles`, which
/// must accept it).
pub fn build_solid<D: Debug>(s: &Solid, rotate: bool, input: &D) -> Y3 {
    let Some((pts, faces)) = solid_mesh(s) else {
        return YinSet3::empty();
    };
    let v = pts.iter().map(|&d| point(d, rotate)).collect();
    YinSet3::from_triangles(v, faces)
        .unwrap_or_else(|e| fail!(input, "from_triangles rejects the solid {s:?}: {e}"))
}

/// The operand: two solids combined, complemented if asked.
pub fn build_operand<D: Debug>(op: &Operand, rotate: bool, input: &D) -> Y3 {
    let first = build_solid(&op.first, rotate, input);
    let set = match op.combine {
        Combine::First => first,
        c => {
            let second = build_solid(&op.second, rotate, input);
            match c {
                Combine::Join => first.join(&second),
                Combine::Meet => first.meet(&second),
                _ => first.difference(&second),
            }
        }
    };
    if op.complement {
        set.complement()
    } else {
        set
    }
}

/// The exact point of a probe.
pub fn probe_point(p: &Probe3, rotate: bool) -> P3 {
    point(p.doubled(), rotate)
}

/// The 3D binary operations, exact: every output valid, A∧B = B∧A, (A∨B)' = A'∧B',
/// A'' = A, |A∧B| + |A∨B| = |A| + |B| (bounded operands), and the membership oracle at the
/// probes off both operands' boundaries for ∧, ∨, ' and −.
pub fn ops3_exact(input: &Ops3Input) {
    let rotate = input.flags & ROTATE != 0;
    let a = build_operand(&input.a, rotate, input);
    let b = build_operand(&input.b, rotate, input);
    valid("A", &a, input);
    valid("B", &b, input);
    let meet = a.meet(&b);
    let join = a.join(&b);
    let (ca, cb) = (a.complement(), b.complement());
    let diff = a.difference(&b);
    let ba = b.meet(&a);
    let lhs = join.complement();
    let rhs = ca.meet(&cb);
    for (name, set) in [
        ("A∧B", &meet),
        ("A∨B", &join),
        ("A'", &ca),
        ("B'", &cb),
        ("A−B", &diff),
        ("B∧A", &ba),
        ("(A∨B)'", &lhs),
        ("A'∧B'", &rhs),
    ] {
        valid(name, set, input);
    }
    if meet != ba {
        fail!(
            input,
            "A∧B ≠ B∧A\nA∧B = {}\nB∧A = {}",
            show(&meet),
            show(&ba)
        );
    }
    if lhs != rhs {
        fail!(
            input,
            "(A∨B)' ≠ A'∧B'\n(A∨B)' = {}\nA'∧B' = {}",
            show(&lhs),
            show(&rhs)
        );
    }
    let caa = ca.complement();
    if caa != a {
        fail!(input, "A'' ≠ A\nA'' = {}\nA = {}", show(&caa), show(&a));
    }
    if let (Some(x), Some(y), Some(m), Some(j)) =
        (a.volume(), b.volume(), meet.volume(), join.volume())
    {
        if m.clone() + j.clone() != x.clone() + y.clone() {
            fail!(
                input,
                "volume identity: |A∧B| + |A∨B| = {m} + {j} ≠ |A| + |B| = {x} + {y}"
            );
        }
    }
    let points: Vec<P3> = input
        .probes
        .iter()
        .map(|p| probe_point(p, rotate))
        .collect();
    if points.is_empty() {
        return;
    }
    let (la, lb) = (a.locate(&points), b.locate(&points));
    type Op = fn(bool, bool) -> bool;
    let ops: [(&str, &Y3, Op); 4] = [
        ("A∧B", &meet, |p, q| p && q),
        ("A∨B", &join, |p, q| p || q),
        ("A'", &ca, |p, _| !p),
        ("A−B", &diff, |p, q| p && !q),
    ];
    for (name, set, f) in ops {
        let got = set.locate(&points);
        for k in 0..points.len() {
            if la[k] == Location::OnBoundary || lb[k] == Location::OnBoundary {
                continue;
            }
            let want = if f(la[k] == Location::Inside, lb[k] == Location::Inside) {
                Location::Inside
            } else {
                Location::Outside
            };
            if got[k] != want {
                fail!(
                    input,
                    "membership oracle: {name} at {} is {:?}, expected {want:?} (A: {:?}, B: {:?})\nA = {}\nB = {}\n{name} = {}",
                    points[k],
                    got[k],
                    la[k],
                    lb[k],
                    show(&a),
                    show(&b),
                    show(set)
                );
            }
        }
    }
}

/// A constructor error must name faces and vertices that exist (and never be internal).
fn check_error<D: Debug>(e: &Yin3Error, vertices: usize, faces: usize, input: &D) {
    let face_ok = |f: usize| f < faces;
    let ok = match e {
        Yin3Error::NoFaces => faces == 0,
        Yin3Error::NotFinite { vertex } => *vertex < vertices,
        Yin3Error::IndexOutOfRange { face, index, count } => {
            face_ok(*face) && *count == vertices && index >= count
        }
        Yin3Error::DegenerateFace { face, .. } | Yin3Error::OpenEdge { face, .. } => face_ok(*face),
        Yin3Error::NonPlanarFace { face, .. } => face_ok(*face),
        Yin3Error::Crossing { a, b, .. }
        | Yin3Error::Overlap { a, b, .. }
        | Yin3Error::Inconsistent { a, b, .. } => face_ok(*a) && face_ok(*b),
        Yin3Error::Orientation { face, .. } => face_ok(*face),
        // Float mode's errors cannot come from an exact constructor.
        Yin3Error::Internal(_)
        | Yin3Error::ToleranceTooFine { .. }
        | Yin3Error::Unrepresentable(_) => false,
    };
    if !ok {
        fail!(
            input,
            "from_triangles error names what does not exist ({vertices} vertices, {faces} faces), or is internal: {e:?}"
        );
    }
}

/// Six times the signed volume enclosed by the faces (each a fan from its first vertex), exact.
fn signed_volume6(v: &[P3], faces: &[Vec<usize>]) -> Rational {
    let det = |p: &P3, q: &P3, r: &P3| p.dot(&q.cross(r));
    let mut s = Rational::from_i64(0);
    for f in faces {
        for k in 1..f.len() - 1 {
            s = s + det(&v[f[0]], &v[f[k]], &v[f[k + 1]]);
        }
    }
    s
}

/// `from_triangles` on any mesh: no panic; an error names faces and vertices that exist; an
/// accepted set is valid, its complement is valid and complements back to it, and its
/// volume is the signed volume enclosed by the faces given (if that is positive; a negative
/// one means an unbounded set).
fn construct_mesh<D: Debug>(v: Vec<P3>, faces: Vec<Vec<usize>>, input: &D) {
    let (nv, nf) = (v.len(), faces.len());
    let in_range = faces.iter().flatten().all(|&i| i < nv) && faces.iter().all(|f| f.len() >= 3);
    let enclosed = in_range.then(|| signed_volume6(&v, &faces));
    match YinSet3::from_triangles(v, faces) {
        Err(e) => check_error(&e, nv, nf, input),
        Ok(set) => {
            valid("the set built", &set, input);
            let c = set.complement();
            valid("its complement", &c, input);
            if c.complement() != set {
                fail!(input, "A'' ≠ A for the set built\nA = {}", show(&set));
            }
            let six = Rational::from_i64(6);
            let zero = Rational::from_i64(0);
            match (set.volume(), enclosed) {
                (Some(vol), Some(e)) if vol.clone() * six.clone() == e && e > zero => {}
                (None, Some(e)) if e < zero => {}
                (got, e) => fail!(
                    input,
                    "volume {got:?} of the set built, but the faces enclose 6 × {:?}\nset = {}",
                    e.map(|e| e / six),
                    show(&set)
                ),
            }
        }
    }
}

/// The constructor on a lattice mesh.
pub fn construct3(input: &Construct3Input) {
    let v: Vec<P3> = input.vertices.iter().map(|&p| lattice(p, false)).collect();
    let faces = input
        .faces
        .iter()
        .map(|f| f.iter().map(|&i| usize::from(i)).collect())
        .collect();
    construct_mesh(v, faces, input);
}

/// A parse error must point into the text.
fn check_parse_error(e: &ParseError, text: &str) {
    let lines: Vec<&str> = text.split('\n').collect();
    let ok = e.line >= 1
        && e.line <= lines.len()
        && e.column >= 1
        && e.column <= lines[e.line - 1].chars().count() + 1
        && !e.message.is_empty();
    if !ok {
        fail!(text, "parse error outside the text: {e:?}");
    }
}

/// Most faces of a mesh read that is built into a set (time per input).
const MAX_BUILD_FACES: usize = 64;
/// Largest coordinate text (characters) of a mesh read that is built into a set.
const MAX_BUILD_DIGITS: usize = 60;

/// The OBJ reader, exact and float: no panic, errors point into the text, both modes read the
/// same faces when both succeed; the exact reading's triangles write back to OBJ that reads
/// the same triangles; and a small mesh read goes through the constructor's checks.
pub fn obj(text: &str) {
    let exact = read_obj::<Rational>(text);
    let float = read_obj::<Float>(text);
    for e in [exact.as_ref().err(), float.as_ref().err()]
        .into_iter()
        .flatten()
    {
        check_parse_error(e, text);
    }
    if let (Ok(x), Ok(f)) = (&exact, &float) {
        if x.vertices.len() != f.vertices.len()
            || x.faces != f.faces
            || x.face_lines != f.face_lines
        {
            fail!(text, "exact and float readings differ in their faces");
        }
    }
    let Ok(mesh) = exact else {
        return;
    };
    check_mesh_shape(&mesh, text);
    round_trip(&mesh, text);
    let small = mesh.faces.len() <= MAX_BUILD_FACES
        && mesh.vertices.iter().all(|p| {
            p.coords()
                .iter()
                .all(|c| c.to_string().len() <= MAX_BUILD_DIGITS)
        });
    if small {
        construct_mesh(mesh.vertices, mesh.faces, &text);
    }
}

/// Faces of at least 3 in-range vertices, one line number each, increasing.
fn check_mesh_shape(m: &mesh::Mesh<Rational>, text: &str) {
    let lines = text.split('\n').count();
    let ok = m.faces.len() == m.face_lines.len()
        && m.faces
            .iter()
            .all(|f| f.len() >= 3 && f.iter().all(|&i| i < m.vertices.len()))
        && m.face_lines.windows(2).all(|w| w[0] < w[1])
        && m.face_lines.iter().all(|&l| l >= 1 && l <= lines);
    if !ok {
        fail!(
            text,
            "read_obj returned faces out of range or misnumbered lines"
        );
    }
}

/// The triangles of a mesh read, written with `write_obj` and read again: the same triangles
/// (as point triples), in order.
fn round_trip(m: &mesh::Mesh<Rational>, text: &str) {
    let tris: Vec<[usize; 3]> = m
        .faces
        .iter()
        .filter(|f| f.len() == 3)
        .map(|f| [f[0], f[1], f[2]])
        .collect();
    let written = write_obj(&m.vertices, &[("mesh".to_string(), tris.clone())]);
    let again = read_obj::<Rational>(&written)
        .unwrap_or_else(|e| fail!(text, "write_obj output does not read back: {e}\n{written}"));
    let points = |v: &[P3], f: &[usize]| f.iter().map(|&i| v[i].clone()).collect::<Vec<_>>();
    let before: Vec<Vec<P3>> = tris.iter().map(|t| points(&m.vertices, t)).collect();
    let after: Vec<Vec<P3>> = again
        .faces
        .iter()
        .map(|f| points(&again.vertices, f))
        .collect();
    if before != after {
        fail!(
            text,
            "write then read changes the triangles\nwritten: {written:?}"
        );
    }
}
