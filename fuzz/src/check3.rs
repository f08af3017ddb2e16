//! The properties of the 3D targets: building operands from lattice solids, the checks on the
//! constructor (`YinSet3::from_triangles`) and on the exact Boolean operations, and the OBJ
//! reader.

use crate::check::fail;
use crate::input3::{
    Combine, Construct3Input, LatticePoint, Operand, Ops3Input, Probe3, Solid, ROTATE,
};
use crate::text::check_parse_error;
use std::fmt::Debug;
use yinset::io::mesh;
use yinset::io::obj::{read_obj, write_obj};
use yinset::num::{Float, Num, Rational};
use yinset::yin3::{Yin3Error, YinSet3};
use yinset_testkit::cells::Cells;
use yinset_testkit::cells3::Grid3;
use yinset_testkit::membership::{self, Truth};
use yinset_testkit::rotation::{Rot, GENERAL};
use yinset_testkit::shapes::{box_mesh, show3, tet_mesh, Mesh};
use yinset_testkit::{P3, Y3};

/// The exact point of doubled integer coordinates, rotated if asked by the unit quaternion
/// [`GENERAL`] about the origin: no face of a rotated box is parallel to a coordinate plane.
fn point(d: [i64; 3], rotate: bool) -> P3 {
    let rot = if rotate {
        Rot::Quaternion(GENERAL)
    } else {
        Rot::None
    };
    rot.apply(d, [0; 3], 2)
}

fn lattice(p: LatticePoint, rotate: bool) -> P3 {
    point(p.0.map(|c| 2 * i64::from(c)), rotate)
}

/// Assert that `set` passes the exact validator.
fn valid<D: Debug>(what: &str, set: &Y3, input: &D) {
    if let Err(e) = set.validate() {
        fail!(
            input,
            "{what} fails the validator: {e}\n{what} = {}",
            show3(set)
        );
    }
}

/// The boundary of a solid as integer vertices (doubled coordinates) and outward faces;
/// `None` for the empty set.
pub fn solid_mesh(s: &Solid) -> Option<Mesh> {
    let doubled = |p: [u8; 3]| p.map(|c| 2 * i64::from(c));
    match s {
        Solid::None => None,
        Solid::Box { lo, hi } => Some(box_mesh(doubled(*lo), doubled(*hi))),
        Solid::Tetra(p) => tet_mesh(p.map(|q| doubled(q.0))),
        Solid::Cells { offset, mask } => {
            if *mask == 0 {
                return None;
            }
            let (pts, faces) = Grid3::cube(2).mesh(Cells::new(u64::from(*mask), false));
            let o = offset.map(i64::from);
            let pts = pts
                .into_iter()
                .map(|w| [0, 1, 2].map(|k| 2 * (w[k] + o[k])))
                .collect();
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
            show3(&meet),
            show3(&ba)
        );
    }
    if lhs != rhs {
        fail!(
            input,
            "(A∨B)' ≠ A'∧B'\n(A∨B)' = {}\nA'∧B' = {}",
            show3(&lhs),
            show3(&rhs)
        );
    }
    let caa = ca.complement();
    if caa != a {
        fail!(input, "A'' ≠ A\nA'' = {}\nA = {}", show3(&caa), show3(&a));
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
    let ops: [(&str, &Y3, Truth); 4] = [
        ("A∧B", &meet, membership::MEET),
        ("A∨B", &join, membership::JOIN),
        ("A'", &ca, membership::COMPLEMENT_A),
        ("A−B", &diff, membership::DIFFERENCE),
    ];
    for (name, set, f) in ops {
        if let Some((k, got, want)) = membership::first_failure(&la, &lb, &set.locate(&points), f) {
            fail!(
                input,
                "membership oracle: {name} at {} is {got:?}, expected {want:?} (A: {:?}, B: {:?})\nA = {}\nB = {}\n{name} = {}",
                points[k],
                la[k],
                lb[k],
                show3(&a),
                show3(&b),
                show3(set)
            );
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
                fail!(input, "A'' ≠ A for the set built\nA = {}", show3(&set));
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
                    show3(&set)
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
