//! Generators of 3D Yin sets biased to degeneracy, for proptest and quickcheck, and the
//! measured statistics that show the degenerate cases really occur.
//!
//! A [`Shape3`] is a short program on a coarse rational lattice (coordinates k/2, k = 0..=4,
//! so the shapes live in [0, 2]³ and a little beyond): starting from 0̂, each [`Step3`] joins or
//! subtracts a primitive (the first step joins), the whole is turned by a rational rotation
//! ([`Rot`]: none, about z with cos = 3/5, sin = 4/5, or about an oblique axis, composed with a
//! rotation about x with cos = 12/13, sin = 5/13, all about the lattice's centre (1, 1, 1)),
//! and it may be complemented (unbounded sets; an empty program gives 0̂ or 1̂). The primitives
//! are boxes, corner tetrahedra (three faces on lattice planes, one slanted), general lattice
//! tetrahedra, and 2×2×2 blocks of lattice cells built by the independent cell builder of
//! the test kit (tests/kit/src/cells3.rs) (shared faces, and cells meeting along an edge or at a vertex only:
//! non-manifold edges and points). Because the lattice is tiny, independent primitives share
//! vertices, overlap in coplanar faces and touch faces with vertices and edges all the time.
//!
//! Pairs and triples are biased further: the second (third) shape is often *derived* from the
//! first by keeping some of its steps (coplanar faces of equal orientation), swapping join and
//! subtract or complementing the whole program (opposite orientation), shifting by one lattice
//! step (partial coplanar overlaps, edge and vertex contacts), adding a step, or turning it by
//! another rotation (crossings off the lattice). Shrinking works on the programs: fewer steps,
//! smaller primitives, no rotation, no complement.
//!
//! [`Features3`] measures the degenerate features of a pair from the boundaries' geometry
//! (vertices and triangles, with the exact integer predicates of the kit's geom3.rs), not from the
//! kernel's internals.

use super::cells::Cells;
use super::cells3::Grid3;
use super::geom3::{
    common_den, coplanar_overlap, in_coplanar_triangle, normal, on_triangle, orient,
    segment_triangle, Hit, IntGeom, V,
};
use super::rotation::Rot;
use super::runner::{qc_bool, qc_range, Program, Shares};
use super::shapes::{box_mesh, det, tet_mesh, Mesh};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use quickcheck::{Arbitrary, Gen};
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};
use yinset::kernel::Point3;
use yinset::yin3::YinSet3;
use yinset_testkit::Y3;

/// The largest lattice coordinate of a primitive's anchor (in half units).
pub const L: i64 = 4;
/// The lattice step is 1/DEN.
pub const DEN: i64 = 2;
/// The centre of the rotations, in half units.
pub const CENTRE: [i64; 3] = [2, 2, 2];

/// A primitive solid with vertices on the lattice (half units).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Prim3 {
    /// The box [at, at + size].
    Box { at: [i64; 3], size: [i64; 3] },
    /// The tetrahedron with vertices at, at ± size_x e_x, at ± size_y e_y, at ± size_z e_z
    /// (signs from the bits of `octant`).
    Corner {
        at: [i64; 3],
        size: [i64; 3],
        octant: u8,
    },
    /// A lattice tetrahedron (made non-degenerate when built).
    Tet { v: [[i64; 3]; 4] },
    /// The union of the cells [at + c, at + c + 1] (c ∈ {0,1}³) whose bit c_x + 2c_y + 4c_z is
    /// set in `mask` (non-zero).
    Cells { at: [i64; 3], mask: u8 },
}

/// Join (`add`) or subtract a primitive.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Step3 {
    pub add: bool,
    pub prim: Prim3,
}

/// A 3D Yin set as a program: fold the steps from 0̂, rotate, then complement if asked.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Shape3 {
    pub steps: Vec<Step3>,
    pub rot: Rot,
    pub complement: bool,
}

/// How a second shape is derived from a first one.
#[derive(Clone, Debug)]
pub struct Derive3 {
    /// Steps of the first shape kept (index modulo its length), and whether join and subtract
    /// are swapped.
    pub keep: Vec<(usize, bool)>,
    /// Translation of the kept steps (−1..=1 lattice steps in each coordinate).
    pub shift: [i64; 3],
    /// Further steps.
    pub extra: Vec<Step3>,
    /// Turn the derived shape: by this rotation if the first shape is not rotated, else back to
    /// no rotation (so that a rotated shape meets an unrotated one, never two rotations: their
    /// crossings have large denominators and cost too much for CI).
    pub turn: Option<Rot>,
    pub complement: bool,
}

/// A non-degenerate tetrahedron near the given lattice points.
fn fix_tet(mut v: [[i64; 3]; 4]) -> [[i64; 3]; 4] {
    for k in 0..12 {
        if det(v[0], v[1], v[2], v[3]) != 0 {
            return v;
        }
        v[1 + k % 3][k % 3] += 1;
    }
    [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
}

impl Prim3 {
    /// The primitive's boundary, in half units.
    pub fn mesh(&self) -> Mesh {
        match *self {
            Prim3::Box { at, size } => box_mesh(at, [0, 1, 2].map(|k| at[k] + size[k])),
            Prim3::Corner { at, size, octant } => {
                let mut v = [at; 4];
                for k in 0..3 {
                    let s = if octant >> k & 1 == 1 { -1 } else { 1 };
                    v[k + 1][k] += s * size[k];
                }
                tet_mesh(v).expect("a corner tetrahedron has three edges along the axes")
            }
            Prim3::Tet { v } => {
                tet_mesh(fix_tet(v)).expect("fix_tet makes the corners non-coplanar")
            }
            Prim3::Cells { at, mask } => {
                let (pts, faces) = Grid3::cube(2).mesh(Cells::new(mask as u64, false));
                let pts = pts
                    .into_iter()
                    .map(|p| [0, 1, 2].map(|k| p[k] + at[k]))
                    .collect();
                (pts, faces)
            }
        }
    }

    /// The primitive's Yin set under the rotation.
    pub fn yin(&self, rot: Rot) -> Y3 {
        let (pts, faces) = self.mesh();
        let pts = pts.into_iter().map(|p| rot.apply(p, CENTRE, DEN)).collect();
        YinSet3::from_triangles(pts, faces)
            .unwrap_or_else(|e| panic!("generator built an invalid primitive {self:?}: {e}"))
    }

    /// The same primitive translated.
    pub fn shifted(&self, d: [i64; 3]) -> Prim3 {
        let sh = |p: [i64; 3]| [0, 1, 2].map(|k| p[k] + d[k]);
        match self.clone() {
            Prim3::Box { at, size } => Prim3::Box { at: sh(at), size },
            Prim3::Corner { at, size, octant } => Prim3::Corner {
                at: sh(at),
                size,
                octant,
            },
            Prim3::Tet { v } => Prim3::Tet { v: v.map(sh) },
            Prim3::Cells { at, mask } => Prim3::Cells { at: sh(at), mask },
        }
    }

    /// Smaller variants, for quickcheck's shrinking.
    fn shrink_prim(&self) -> Vec<Prim3> {
        let mut v = Vec::new();
        let smaller = |size: [i64; 3]| -> Vec<[i64; 3]> {
            (0..3)
                .filter(|&k| size[k] > 1)
                .map(|k| {
                    let mut s = size;
                    s[k] -= 1;
                    s
                })
                .collect()
        };
        let lower = |at: [i64; 3]| -> Vec<[i64; 3]> {
            (0..3)
                .filter(|&k| at[k] > 0)
                .map(|k| {
                    let mut s = at;
                    s[k] -= 1;
                    s
                })
                .collect()
        };
        match *self {
            Prim3::Box { at, size } => {
                v.extend(
                    smaller(size)
                        .into_iter()
                        .map(|size| Prim3::Box { at, size }),
                );
                v.extend(lower(at).into_iter().map(|at| Prim3::Box { at, size }));
            }
            Prim3::Corner { at, size, octant } => {
                v.push(Prim3::Box { at, size: [1; 3] });
                if octant != 0 {
                    v.push(Prim3::Corner {
                        at,
                        size,
                        octant: 0,
                    });
                }
                v.extend(
                    smaller(size)
                        .into_iter()
                        .map(|size| Prim3::Corner { at, size, octant }),
                );
            }
            Prim3::Tet { v: t } => {
                v.push(Prim3::Corner {
                    at: t[0],
                    size: [1; 3],
                    octant: 0,
                });
                for k in 0..4 {
                    for c in lower(t[k]) {
                        let mut t = t;
                        t[k] = c;
                        v.push(Prim3::Tet { v: t });
                    }
                }
            }
            Prim3::Cells { at, mask } => {
                v.push(Prim3::Box { at, size: [1; 3] });
                for b in 0..8 {
                    if mask >> b & 1 == 1 && mask & !(1 << b) != 0 {
                        v.push(Prim3::Cells {
                            at,
                            mask: mask & !(1 << b),
                        });
                    }
                }
                v.extend(lower(at).into_iter().map(|at| Prim3::Cells { at, mask }));
            }
        }
        v
    }
}

impl Shape3 {
    /// The Yin set of the program, computed with the kernel's join and difference (the laws
    /// validate it as an input).
    pub fn build(&self) -> Y3 {
        let mut acc: Y3 = YinSet3::empty();
        for s in &self.steps {
            let p = s.prim.yin(self.rot);
            acc = if s.add { &acc | &p } else { &acc - &p };
        }
        if self.complement {
            !&acc
        } else {
            acc
        }
    }

    /// The second shape of a derived pair.
    pub fn derive(&self, d: &Derive3) -> Shape3 {
        let mut steps = Vec::new();
        if !self.steps.is_empty() {
            for &(k, flip) in &d.keep {
                let s = &self.steps[k % self.steps.len()];
                steps.push(Step3 {
                    add: s.add != flip,
                    prim: s.prim.shifted(d.shift),
                });
            }
        }
        steps.extend(d.extra.iter().cloned());
        steps.truncate(2); // bounded size (CI time)
        Shape3 {
            steps,
            rot: match (d.turn, self.rot) {
                (None, r) => r,
                (Some(t), Rot::None) => t,
                (Some(_), _) => Rot::None,
            },
            complement: d.complement,
        }
    }

    /// The same program complemented (every face reversed).
    pub fn flipped(&self) -> Shape3 {
        Shape3 {
            complement: !self.complement,
            ..self.clone()
        }
    }

    /// Smaller programs, for quickcheck's shrinking.
    pub fn shrink_shape(&self) -> Vec<Shape3> {
        let mut v = Vec::new();
        if self.complement {
            v.push(Shape3 {
                complement: false,
                ..self.clone()
            });
        }
        if self.rot != Rot::None {
            v.push(Shape3 {
                rot: Rot::None,
                ..self.clone()
            });
        }
        for k in 0..self.steps.len() {
            let mut s = self.clone();
            s.steps.remove(k);
            v.push(s);
        }
        for k in 0..self.steps.len() {
            if !self.steps[k].add {
                let mut s = self.clone();
                s.steps[k].add = true;
                v.push(s);
            }
            for p in self.steps[k].prim.shrink_prim() {
                let mut s = self.clone();
                s.steps[k].prim = p;
                v.push(s);
            }
        }
        v
    }
}

/// The mask with its lowest set bits cleared until at most three cells remain (bounded size:
/// boundaries of many cells cost too much for CI).
pub fn at_most_3_cells(mut m: u8) -> u8 {
    while m.count_ones() > 3 {
        m &= m - 1;
    }
    m
}

/// Masks of 2×2×2 cells with contacts along an edge or at a vertex only (two cells on a face
/// diagonal, on the body diagonal, a checkerboard, an edge contact beside a face contact).
pub const CONTACT_MASKS: [u8; 8] = [
    0b0000_1001,
    0b1000_0001,
    0b0110_1001,
    0b1001_0110,
    0b0001_1000,
    0b0100_0001,
    0b1000_0011,
    0b0010_0100,
];

// ---------------------------------------------------------------------------------------------
// proptest strategies

pub mod strategies {
    use super::*;

    fn lattice(hi: i64) -> impl Strategy<Value = [i64; 3]> {
        [0..=hi, 0..=hi, 0..=hi]
    }

    fn sizes() -> impl Strategy<Value = [i64; 3]> {
        [1..=3i64, 1..=3i64, 1..=3i64]
    }

    pub fn prim() -> impl Strategy<Value = Prim3> {
        prop_oneof![
            4 => (lattice(L - 1), sizes()).prop_map(|(at, size)| Prim3::Box { at, size }),
            2 => (lattice(L), sizes(), 0..8u8)
                .prop_map(|(at, size, octant)| Prim3::Corner { at, size, octant }),
            1 => [lattice(L), lattice(L), lattice(L), lattice(L)].prop_map(|v| Prim3::Tet { v }),
            3 => (
                lattice(L - 2),
                prop_oneof![
                    1 => proptest::sample::select(CONTACT_MASKS.to_vec()),
                    1 => (1..=255u8).prop_map(at_most_3_cells)
                ]
            )
                .prop_map(|(at, mask)| Prim3::Cells { at, mask }),
        ]
    }

    pub fn step() -> impl Strategy<Value = Step3> {
        (proptest::bool::weighted(0.7), prim()).prop_map(|(add, prim)| Step3 { add, prim })
    }

    pub fn rot() -> impl Strategy<Value = Rot> {
        prop_oneof![6 => Just(Rot::None), 3 => Just(Rot::Z), 2 => Just(Rot::Oblique)]
    }

    fn turn() -> impl Strategy<Value = Rot> {
        prop_oneof![3 => Just(Rot::Z), 2 => Just(Rot::Oblique)]
    }

    pub fn shape() -> impl Strategy<Value = Shape3> {
        (
            prop_oneof![1 => Just(0usize), 14 => Just(1), 4 => Just(2)],
            proptest::collection::vec(step(), 2),
            rot(),
            proptest::bool::weighted(0.25),
        )
            .prop_map(|(n, mut steps, rot, complement)| {
                steps.truncate(n);
                if let Some(s) = steps.first_mut() {
                    s.add = true; // a program starting with a subtraction is wasted
                }
                Shape3 {
                    steps,
                    rot,
                    complement,
                }
            })
    }

    pub fn derive() -> impl Strategy<Value = Derive3> {
        (
            prop_oneof![
                3 => proptest::collection::vec((0..2usize, proptest::bool::weighted(0.3)), 1),
                1 => proptest::collection::vec((0..2usize, proptest::bool::weighted(0.3)), 2),
            ],
            prop_oneof![3 => Just([0i64; 3]), 2 => [-1..=1i64, -1..=1i64, -1..=1i64]],
            proptest::collection::vec(step(), 0..=1),
            prop_oneof![4 => Just(None), 1 => turn().prop_map(Some)],
            proptest::bool::weighted(0.25),
        )
            .prop_map(|(keep, shift, extra, turn, complement)| Derive3 {
                keep,
                shift,
                extra,
                turn,
                complement,
            })
    }

    /// A shape related to `a` about two thirds of the time: derived from it, or its
    /// complement program; otherwise a fresh shape, turned as `a` or not at all.
    fn related(a: Shape3) -> impl Strategy<Value = Shape3> {
        let flipped = a.flipped();
        let rot = a.rot;
        prop_oneof![
            2 => (shape(), proptest::bool::ANY).prop_map(move |(mut s, same)| {
                s.rot = if same { rot } else { Rot::None };
                s
            }),
            3 => derive().prop_map(move |d| a.derive(&d)),
            1 => Just(flipped),
        ]
    }

    pub fn pair() -> impl Strategy<Value = (Shape3, Shape3)> {
        shape().prop_flat_map(|a| (Just(a.clone()), related(a)))
    }

    pub fn triple() -> impl Strategy<Value = (Shape3, Shape3, Shape3)> {
        shape().prop_flat_map(|a| (Just(a.clone()), related(a.clone()), related(a)))
    }
}

// ---------------------------------------------------------------------------------------------
// quickcheck: Arbitrary + shrink

fn qc_lattice(g: &mut Gen, hi: i64) -> [i64; 3] {
    [0; 3].map(|_| qc_range(g, 0, hi))
}

fn qc_sizes(g: &mut Gen) -> [i64; 3] {
    [0; 3].map(|_| qc_range(g, 1, 3))
}

fn qc_rot(g: &mut Gen) -> Rot {
    match qc_range(g, 0, 10) {
        0..=5 => Rot::None,
        6..=8 => Rot::Z,
        _ => Rot::Oblique,
    }
}

impl Arbitrary for Prim3 {
    fn arbitrary(g: &mut Gen) -> Prim3 {
        match qc_range(g, 0, 9) {
            0..=3 => Prim3::Box {
                at: qc_lattice(g, L - 1),
                size: qc_sizes(g),
            },
            4..=5 => Prim3::Corner {
                at: qc_lattice(g, L),
                size: qc_sizes(g),
                octant: qc_range(g, 0, 7) as u8,
            },
            6 => Prim3::Tet {
                v: [0; 4].map(|_| qc_lattice(g, L)),
            },
            _ => Prim3::Cells {
                at: qc_lattice(g, L - 2),
                mask: if qc_bool(g, 0.5) {
                    CONTACT_MASKS[qc_range(g, 0, 7) as usize]
                } else {
                    at_most_3_cells(qc_range(g, 1, 255) as u8)
                },
            },
        }
    }

    fn shrink(&self) -> Box<dyn Iterator<Item = Prim3>> {
        Box::new(self.shrink_prim().into_iter())
    }
}

impl Arbitrary for Step3 {
    fn arbitrary(g: &mut Gen) -> Step3 {
        Step3 {
            add: qc_bool(g, 0.7),
            prim: Prim3::arbitrary(g),
        }
    }
}

impl Arbitrary for Shape3 {
    fn arbitrary(g: &mut Gen) -> Shape3 {
        let n = match qc_range(g, 0, 18) {
            0 => 0,
            1..=14 => 1,
            _ => 2,
        };
        let mut steps: Vec<Step3> = (0..n).map(|_| Step3::arbitrary(g)).collect();
        if let Some(s) = steps.first_mut() {
            s.add = true;
        }
        Shape3 {
            steps,
            rot: qc_rot(g),
            complement: qc_bool(g, 0.25),
        }
    }

    fn shrink(&self) -> Box<dyn Iterator<Item = Shape3>> {
        Box::new(self.shrink_shape().into_iter())
    }
}

fn qc_related(g: &mut Gen, a: &Shape3) -> Shape3 {
    match qc_range(g, 0, 5) {
        0..=1 => {
            let mut s = Shape3::arbitrary(g);
            if qc_bool(g, 0.5) {
                s.rot = Rot::None;
            } else {
                s.rot = a.rot;
            }
            return s;
        }
        2 => return a.flipped(),
        _ => {}
    }
    let k = if qc_bool(g, 0.75) { 1 } else { 2 };
    let shift = if qc_bool(g, 0.6) {
        [0; 3]
    } else {
        [0; 3].map(|_| qc_range(g, -1, 1))
    };
    let d = Derive3 {
        keep: (0..k)
            .map(|_| (qc_range(g, 0, 1) as usize, qc_bool(g, 0.3)))
            .collect(),
        shift,
        extra: if qc_bool(g, 0.4) {
            vec![Step3::arbitrary(g)]
        } else {
            vec![]
        },
        turn: if qc_bool(g, 0.2) {
            Some(if qc_bool(g, 0.6) {
                Rot::Z
            } else {
                Rot::Oblique
            })
        } else {
            None
        },
        complement: qc_bool(g, 0.25),
    };
    a.derive(&d)
}

impl Program for Shape3 {
    fn related(g: &mut Gen, a: &Shape3) -> Shape3 {
        qc_related(g, a)
    }
    fn smaller(&self) -> Vec<Shape3> {
        self.shrink_shape()
    }
}

// ---------------------------------------------------------------------------------------------
// Degenerate-case statistics

pub const FEATURES3: [&str; 12] = [
    "shared vertex",
    "coplanar overlap, same orientation",
    "coplanar overlap, opposite orientation",
    "vertex of one boundary on the other, not a vertex",
    "edge of one boundary inside a face of the other",
    "boundaries cross transversally",
    "non-manifold edge in A or B",
    "non-manifold point in A or B",
    "unbounded (A or B)",
    "0̂ or 1̂",
    "rotated faces (A or B)",
    "vertices off the lattice",
];

/// Which degenerate features a pair (A, B) shows, computed from the boundaries' vertices and
/// triangles with exact integer predicates.
pub fn features3(a: &Y3, b: &Y3) -> [bool; 12] {
    let den = common_den(a.vertices().iter().chain(b.vertices()));
    let (ga, gb) = (IntGeom::new(a, &den), IntGeom::new(b, &den));
    let mut f = [false; 12];
    let va: HashSet<&V> = ga.verts.iter().collect();
    f[0] = gb.verts.iter().any(|v| va.contains(v));
    for s in &ga.tris {
        for t in &gb.tris {
            match coplanar_overlap(s, t) {
                Some(true) => f[1] = true,
                Some(false) => f[2] = true,
                None => {}
            }
        }
    }
    for (x, y) in [(&ga, &gb), (&gb, &ga)] {
        let yv: HashSet<&V> = y.verts.iter().collect();
        f[3] |= x
            .verts
            .iter()
            .any(|v| !yv.contains(v) && y.tris.iter().any(|t| on_triangle(t, v)));
        let edges = edges_of(x);
        f[4] |= edges.iter().any(|(p, q)| {
            let mid: V = [0, 1, 2].map(|k| &p[k] + &q[k]);
            y.tris.iter().any(|t| {
                let t2 = t.clone().map(|c| c.map(|z| z * 2));
                orient(&t2[0], &t2[1], &t2[2], &mid) == Ordering::Equal
                    && in_coplanar_triangle(&t2, &mid, true)
                    && on_triangle(t, p)
                    && on_triangle(t, q)
            })
        });
        f[5] |= edges.iter().any(|(p, q)| {
            y.tris
                .iter()
                .any(|t| matches!(segment_triangle(p, q, t), Hit::Cross(_)))
        });
    }
    for (y, g) in [(a, &ga), (b, &gb)] {
        let (edge, point) = non_manifold(y);
        f[6] |= edge;
        f[7] |= point;
        f[8] |= y.is_full() || g.volume6().is_negative();
        f[9] |= y.is_empty() || y.is_full();
        f[10] |= g.tris.iter().any(rotated_face);
        let d = BigInt::from(DEN);
        f[11] |= y
            .vertices()
            .iter()
            .any(|p| p.coords().iter().any(|c| !(&d % &c.denom()).is_zero()));
    }
    f
}

/// The distinct undirected edges of the triangles.
fn edges_of(g: &IntGeom) -> Vec<(V, V)> {
    let mut seen = HashSet::new();
    let mut v = Vec::new();
    for t in &g.tris {
        for k in 0..3 {
            let (p, q) = (&t[k], &t[(k + 1) % 3]);
            let key = if p < q { (p, q) } else { (q, p) };
            if seen.insert(key) {
                v.push((p.clone(), q.clone()));
            }
        }
    }
    v
}

/// Is the face parallel to a face of a rotated lattice box (normal along R e_k)?
fn rotated_face(t: &[V; 3]) -> bool {
    let n = normal(t);
    // The images of e_x and e_y under Rot::Z, and of e_x, e_y, e_z under Rot::Oblique.
    let dirs: [[i64; 3]; 5] = [
        [3, 4, 0],
        [-4, 3, 0],
        [39, 48, 20],
        [-52, 36, 15],
        [0, -25, 60],
    ];
    dirs.iter().any(|d| {
        let d = d.map(BigInt::from);
        let c = [
            &n[1] * &d[2] - &n[2] * &d[1],
            &n[2] * &d[0] - &n[0] * &d[2],
            &n[0] * &d[1] - &n[1] * &d[0],
        ];
        c.iter().all(|x| x.is_zero())
    })
}

/// (A non-manifold edge: an edge with four or more triangles; a non-manifold point: a vertex
/// whose link — the edges opposite it in its triangles — is disconnected.)
pub fn non_manifold(y: &Y3) -> (bool, bool) {
    let mut per_edge: HashMap<(usize, usize), usize> = HashMap::new();
    let mut link: HashMap<usize, Vec<(usize, usize)>> = HashMap::new();
    for t in y.triangles() {
        for k in 0..3 {
            let (p, q, r) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            *per_edge.entry((p.min(q), p.max(q))).or_default() += 1;
            link.entry(p).or_default().push((q, r));
        }
    }
    let edge = per_edge.values().any(|&c| c >= 4);
    let point = link.values().any(|l| {
        let mut parent: HashMap<usize, usize> = HashMap::new();
        fn find(p: &mut HashMap<usize, usize>, x: usize) -> usize {
            let up = *p.entry(x).or_insert(x);
            if up == x {
                x
            } else {
                let r = find(p, up);
                p.insert(x, r);
                r
            }
        }
        for &(a, b) in l {
            let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
            parent.insert(ra, rb);
        }
        let keys: Vec<usize> = parent.keys().copied().collect();
        let roots: HashSet<usize> = keys.into_iter().map(|k| find(&mut parent, k)).collect();
        roots.len() > 1
    });
    (edge, point)
}

/// The statistics of [`features3`] over a sample of pairs, asserted on samples of at least 100
/// pairs.
pub const fn shares3() -> Shares<12> {
    Shares::new(&FEATURES3, 100)
}

/// The minimum shares asserted by the suites (in the order of [`FEATURES3`]): about four
/// standard deviations (of 300 pairs) below the lowest share measured in two runs of each
/// suite.
pub const MINIMUM_SHARES3: [f64; 12] = [
    0.30, 0.07, 0.15, 0.08, 0.03, 0.03, 0.09, 0.03, 0.35, 0.08, 0.20, 0.25,
];

/// Points for the membership law: a lattice offset by odd multiples of 1/38 and 1/46 so that
/// they rarely lie on a boundary (those that do are skipped by the law).
pub fn probe_points3() -> Vec<Point3<yinset::num::Rational>> {
    use yinset_testkit::q;
    let mut v = Vec::new();
    for i in -1..=5i64 {
        for j in -1..=5i64 {
            for k in -1..=5i64 {
                v.push(Point3::new(
                    q(38 * i + 7, 76),
                    q(46 * j + 5, 92),
                    q(58 * k + 3, 116),
                ));
            }
        }
    }
    v
}
