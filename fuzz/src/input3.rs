//! The fuzz input formats of the structured 3D targets: solids and meshes on a coarse integer
//! lattice (coordinates 0..=4), so that shared faces, edges and vertices, coplanar overlaps and
//! vertices or edges on faces dominate.
//!
//! As in [`crate::input`], bytes are read one `u8` at a time with `arbitrary`'s
//! [`Unstructured`] (a missing byte reads as 0), and every decoded value has an `encode` that
//! gives the bytes back, for the seed generator.
//!
//! ```text
//! Ops3Input       := flags:u8 Operand Operand Probes3 Place3
//! flags           := bit 0: rotate everything by the rational rotation ROTATION
//! Operand         := flags:u8 Solid Solid       bit 0: complement; bits 1-2: how the two
//!                                               solids combine (0: the first alone, 1: ∨, 2: ∧,
//!                                               3: first − second)
//! Solid           := kind:u8 payload            kind % 4: 0 none, 1 box, 2 tetrahedron, 3 cells
//! box             := xs:u8 ys:u8 zs:u8          per axis: two coordinates (byte % 5, byte / 5 % 5),
//!                                               sorted; equal ones are widened to a unit
//! tetrahedron     := point:u8{4}                coplanar corners give the empty set
//! cells           := offset:u8 mask:u8          the unit cells (i, j, k) ∈ {0,1}³ of the mask
//!                                               (bit i + 2j + 4k), moved by the offset point
//!                                               (each coordinate % 3)
//! point           := byte % 125 = x + 5y + 25z  (lattice 0..=4)
//! Probes3         := n:u8 probe:u8{n % (MAX_PROBES3+1)}
//! probe           := byte % 216 = i + 6j + 36k: the point (i − ½, j − ½, k − ½)
//! Place3          := mode:u8 k:i8{3} exp:u8 eps:u8 scale:i8    (ops3_float only; absent
//!                    bytes read 0: B not moved, the default ε, unit scale)
//! mode            := % 4: how B's f64 values leave the lattice, with d = 2^-(exp % 64):
//!                    0 not at all; 1 shifted by (k0, k1, k2)·d (exact unless rounded);
//!                    2 scaled about (2, 2, 2) by 1 + k_c·d along axis c; 3 shifted by the
//!                    f64 nearest k_c·d/3 (full mantissas)
//! eps             := % 56: 0 the default ε (relative to each operand's extent), else
//!                    ε = 2^-eps (times the scale; fine ones are ToleranceTooFine)
//! scale           := everything times 2^(7·scale): 2^-896 … 2^889
//!
//! The Place3 bytes come last so that inputs without them (the seeds written before they
//! existed) decode as before: B on the lattice, the default ε, unit scale.
//!
//! Construct3Input := nverts:u8 point:u8{nverts % (MAX_VERTICES3+1)}
//!                    nfaces:u8 Face{nfaces % (MAX_FACES3+1)}
//! Face            := len:u8 index:u8{3 + len % 4}   index % (nverts + 1): one past the end
//!                                                   is out of range on purpose
//! ```

use arbitrary::{Arbitrary, Result, Unstructured};

/// Lattice coordinates are 0..LATTICE.
pub const LATTICE: u8 = 5;
/// Most membership probes.
pub const MAX_PROBES3: usize = 8;
/// Most vertices of a constructor mesh.
pub const MAX_VERTICES3: usize = 40;
/// Most faces of a constructor mesh.
pub const MAX_FACES3: usize = 80;

/// Operand flag: take the complement.
pub const COMPLEMENT3: u8 = 1;
/// Global flag: rotate both operands and the probes by the rational rotation.
pub const ROTATE: u8 = 1;

/// A lattice point (coordinates 0..LATTICE).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LatticePoint(pub [u8; 3]);

impl LatticePoint {
    /// The point (x, y, z) (panics if off the lattice: for the seed generator).
    pub fn new(x: u8, y: u8, z: u8) -> LatticePoint {
        assert!(
            x < LATTICE && y < LATTICE && z < LATTICE,
            "({x}, {y}, {z}) is off the lattice"
        );
        LatticePoint([x, y, z])
    }

    fn from_byte(b: u8) -> LatticePoint {
        let v = b % 125;
        LatticePoint([v % 5, v / 5 % 5, v / 25])
    }

    fn byte(self) -> u8 {
        let [x, y, z] = self.0;
        x + 5 * y + 25 * z
    }
}

/// A solid on the lattice.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub enum Solid {
    /// The box [lo, hi] (lo < hi in each coordinate).
    Box { lo: [u8; 3], hi: [u8; 3] },
    /// The tetrahedron with these corners (empty if they are coplanar).
    Tetra([LatticePoint; 4]),
    /// The unit cells (i, j, k) ∈ {0,1}³ whose bit i + 2j + 4k is set, moved by `offset`
    /// (each coordinate 0..3).
    Cells { offset: [u8; 3], mask: u8 },
    /// The empty set.
    #[default]
    None,
}

fn interval(b: u8) -> (u8, u8) {
    let (p, q) = (b % 5, b / 5 % 5);
    let (lo, hi) = (p.min(q), p.max(q));
    if lo < hi {
        (lo, hi)
    } else if hi < 4 {
        (lo, lo + 1)
    } else {
        (3, 4)
    }
}

impl Solid {
    /// The box [lo, hi] (panics unless lo < hi ≤ 4 in each coordinate).
    pub fn cuboid(lo: [u8; 3], hi: [u8; 3]) -> Solid {
        assert!((0..3).all(|k| lo[k] < hi[k] && hi[k] < LATTICE), "bad box");
        Solid::Box { lo, hi }
    }

    fn decode(u: &mut Unstructured<'_>) -> Result<Solid> {
        Ok(match u8::arbitrary(u)? % 4 {
            0 => Solid::None,
            1 => {
                let mut lo = [0; 3];
                let mut hi = [0; 3];
                for k in 0..3 {
                    (lo[k], hi[k]) = interval(u8::arbitrary(u)?);
                }
                Solid::Box { lo, hi }
            }
            2 => {
                let mut p = [LatticePoint([0; 3]); 4];
                for q in &mut p {
                    *q = LatticePoint::from_byte(u8::arbitrary(u)?);
                }
                Solid::Tetra(p)
            }
            _ => {
                let o = u8::arbitrary(u)?;
                let mask = u8::arbitrary(u)?;
                Solid::Cells {
                    offset: [o % 3, o / 3 % 3, o / 9 % 3],
                    mask,
                }
            }
        })
    }

    fn encode(&self, out: &mut Vec<u8>) {
        match self {
            Solid::Box { lo, hi } => {
                out.push(1);
                for k in 0..3 {
                    assert!(lo[k] < hi[k] && hi[k] < LATTICE, "bad box");
                    out.push(lo[k] + 5 * hi[k]);
                }
            }
            Solid::Tetra(p) => {
                out.push(2);
                out.extend(p.iter().map(|q| q.byte()));
            }
            Solid::Cells { offset, mask } => {
                assert!(offset.iter().all(|&o| o < 3), "bad offset");
                out.push(3);
                out.push(offset[0] + 3 * offset[1] + 9 * offset[2]);
                out.push(*mask);
            }
            Solid::None => out.push(0),
        }
    }
}

/// How an operand's two solids combine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Combine {
    /// The first solid alone.
    #[default]
    First,
    /// Their join.
    Join,
    /// Their meet.
    Meet,
    /// The first minus the second.
    Minus,
}

/// One operand: two solids combined, optionally complemented.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Operand {
    pub complement: bool,
    pub combine: Combine,
    pub first: Solid,
    pub second: Solid,
}

impl Operand {
    /// One solid.
    pub fn solid(s: Solid) -> Operand {
        Operand {
            first: s,
            ..Operand::default()
        }
    }

    /// The complement of this operand.
    pub fn complemented(mut self) -> Operand {
        self.complement = !self.complement;
        self
    }

    /// Two solids combined.
    pub fn two(combine: Combine, first: Solid, second: Solid) -> Operand {
        Operand {
            complement: false,
            combine,
            first,
            second,
        }
    }

    fn decode(u: &mut Unstructured<'_>) -> Result<Operand> {
        let flags = u8::arbitrary(u)?;
        Ok(Operand {
            complement: flags & COMPLEMENT3 != 0,
            combine: match (flags >> 1) & 3 {
                0 => Combine::First,
                1 => Combine::Join,
                2 => Combine::Meet,
                _ => Combine::Minus,
            },
            first: Solid::decode(u)?,
            second: Solid::decode(u)?,
        })
    }

    fn encode(&self, out: &mut Vec<u8>) {
        let c = match self.combine {
            Combine::First => 0,
            Combine::Join => 1,
            Combine::Meet => 2,
            Combine::Minus => 3,
        };
        out.push(u8::from(self.complement) | c << 1);
        self.first.encode(out);
        self.second.encode(out);
    }
}

/// A probe (i − ½, j − ½, k − ½), i, j, k in 0..6: the centre of a lattice cube (or one
/// around the lattice), off every box and cell face.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Probe3(pub [u8; 3]);

impl Probe3 {
    /// Doubled coordinates (2i − 1, …): odd integers.
    pub fn doubled(self) -> [i64; 3] {
        self.0.map(|c| 2 * i64::from(c) - 1)
    }
}

fn decode_probes(u: &mut Unstructured<'_>) -> Result<Vec<Probe3>> {
    let n = usize::from(u8::arbitrary(u)?) % (MAX_PROBES3 + 1);
    (0..n)
        .map(|_| {
            let b = u8::arbitrary(u)? % 216;
            Ok(Probe3([b % 6, b / 6 % 6, b / 36]))
        })
        .collect()
}

fn encode_probes(probes: &[Probe3], out: &mut Vec<u8>) {
    assert!(probes.len() <= MAX_PROBES3, "too many probes");
    out.push(probes.len() as u8);
    for p in probes {
        assert!(p.0.iter().all(|&c| c < 6), "probe off the range");
        out.push(p.0[0] + 6 * p.0[1] + 36 * p.0[2]);
    }
}

/// How B's `f64` values leave the lattice ([`Place3::mode`]).
pub const MOVE_NONE: u8 = 0;
/// B shifted by k·d (d = 2^-exp).
pub const MOVE_SHIFT: u8 = 1;
/// B scaled about (2, 2, 2) by 1 + k_c·d along each axis c.
pub const MOVE_SCALE: u8 = 2;
/// B shifted by the `f64` nearest k·d/3.
pub const MOVE_THIRDS: u8 = 3;
/// Largest ε exponent: ε = 2^-eps, eps < EPS3_STEPS.
pub const EPS3_STEPS: u8 = 56;
/// The scale is 2^(SCALE3_STEP · scale).
pub const SCALE3_STEP: i32 = 7;

/// Where float mode (target `ops3_float`) puts the operands: B optionally moved off the lattice
/// by a small shift or scale, everything optionally scaled by a power of two, and ε.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Place3 {
    /// [`MOVE_NONE`], [`MOVE_SHIFT`], [`MOVE_SCALE`] or [`MOVE_THIRDS`].
    pub mode: u8,
    /// The multiples k_c of the unit, per axis.
    pub k: [i8; 3],
    /// The unit d = 2^-exp (exp < 64).
    pub exp: u8,
    /// 0: the default ε; else ε = 2^-eps (eps < [`EPS3_STEPS`]), before scaling.
    pub eps: u8,
    /// Every coordinate and ε times 2^(SCALE3_STEP · scale).
    pub scale: i8,
}

impl Place3 {
    fn decode(u: &mut Unstructured<'_>) -> Result<Place3> {
        let mode = u8::arbitrary(u)? % 4;
        let mut k = [0i8; 3];
        for c in &mut k {
            *c = u8::arbitrary(u)? as i8;
        }
        Ok(Place3 {
            mode,
            k,
            exp: u8::arbitrary(u)? % 64,
            eps: u8::arbitrary(u)? % EPS3_STEPS,
            scale: u8::arbitrary(u)? as i8,
        })
    }

    /// The bytes of a placement; none for the default one (missing bytes read as 0), so that
    /// inputs without it keep their earlier encoding.
    fn encode(&self, out: &mut Vec<u8>) {
        assert!(
            self.mode < 4 && self.exp < 64 && self.eps < EPS3_STEPS,
            "bad placement"
        );
        if *self != Place3::default() {
            out.extend([
                self.mode,
                self.k[0] as u8,
                self.k[1] as u8,
                self.k[2] as u8,
                self.exp,
                self.eps,
                self.scale as u8,
            ]);
        }
    }

    /// True if B leaves the lattice (a move with some k_c ≠ 0).
    pub fn moves(&self) -> bool {
        self.mode != MOVE_NONE && self.k != [0; 3]
    }

    /// The exponent of the scale 2^s.
    pub fn exponent(&self) -> i32 {
        SCALE3_STEP * i32::from(self.scale)
    }

    /// ε before scaling; 0 asks for the default.
    pub fn eps(&self) -> f64 {
        if self.eps == 0 {
            0.0
        } else {
            2f64.powi(-i32::from(self.eps))
        }
    }
}

/// Input of the 3D binary-operation targets.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Ops3Input {
    /// [`ROTATE`].
    pub flags: u8,
    pub a: Operand,
    pub b: Operand,
    pub probes: Vec<Probe3>,
    /// Float mode only (`ops3_float`): B's move, ε and the scale.
    pub place: Place3,
}

impl<'a> Arbitrary<'a> for Ops3Input {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(Ops3Input {
            flags: u8::arbitrary(u)? & ROTATE,
            a: Operand::decode(u)?,
            b: Operand::decode(u)?,
            probes: decode_probes(u)?,
            place: Place3::decode(u)?,
        })
    }
}

impl Ops3Input {
    /// The bytes that decode to `self`.
    pub fn encode(&self) -> Vec<u8> {
        let mut out = vec![self.flags];
        self.a.encode(&mut out);
        self.b.encode(&mut out);
        encode_probes(&self.probes, &mut out);
        self.place.encode(&mut out);
        out
    }
}

/// Input of the 3D constructor target: a mesh on the lattice, faces as vertex index lists
/// (possibly out of range, repeated, non-planar: anything).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Construct3Input {
    pub vertices: Vec<LatticePoint>,
    pub faces: Vec<Vec<u8>>,
}

impl<'a> Arbitrary<'a> for Construct3Input {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let nv = usize::from(u8::arbitrary(u)?) % (MAX_VERTICES3 + 1);
        let vertices = (0..nv)
            .map(|_| Ok(LatticePoint::from_byte(u8::arbitrary(u)?)))
            .collect::<Result<Vec<_>>>()?;
        let nf = usize::from(u8::arbitrary(u)?) % (MAX_FACES3 + 1);
        let mut faces = Vec::with_capacity(nf);
        for _ in 0..nf {
            let len = 3 + usize::from(u8::arbitrary(u)?) % 4;
            let face = (0..len)
                .map(|_| Ok(u8::arbitrary(u)? % (nv as u8 + 1)))
                .collect::<Result<Vec<_>>>()?;
            faces.push(face);
        }
        Ok(Construct3Input { vertices, faces })
    }
}

impl Construct3Input {
    /// The bytes that decode to `self` (panics if it has too many vertices or faces, or a face
    /// of the wrong length or with an index beyond one past the end).
    pub fn encode(&self) -> Vec<u8> {
        assert!(self.vertices.len() <= MAX_VERTICES3, "too many vertices");
        assert!(self.faces.len() <= MAX_FACES3, "too many faces");
        let mut out = vec![self.vertices.len() as u8];
        out.extend(self.vertices.iter().map(|p| p.byte()));
        out.push(self.faces.len() as u8);
        for f in &self.faces {
            assert!((3..=6).contains(&f.len()), "faces have 3 to 6 corners");
            assert!(
                f.iter().all(|&i| usize::from(i) <= self.vertices.len()),
                "index beyond one past the end"
            );
            out.push((f.len() - 3) as u8);
            out.extend(f);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::decode;

    #[test]
    fn encode_then_decode_round_trips() {
        let input = Ops3Input {
            flags: ROTATE,
            a: Operand::two(
                Combine::Minus,
                Solid::cuboid([0, 0, 0], [4, 3, 2]),
                Solid::Tetra([
                    LatticePoint::new(0, 0, 0),
                    LatticePoint::new(4, 0, 0),
                    LatticePoint::new(0, 4, 1),
                    LatticePoint::new(2, 2, 4),
                ]),
            )
            .complemented(),
            b: Operand::solid(Solid::Cells {
                offset: [2, 0, 1],
                mask: 0b1001_0110,
            }),
            probes: vec![Probe3([0, 5, 3]), Probe3([5, 5, 5])],
            place: Place3::default(),
        };
        assert_eq!(decode::<Ops3Input>(&input.encode()).unwrap(), input);
        let placed = Ops3Input {
            place: Place3 {
                mode: MOVE_THIRDS,
                k: [-128, 0, 127],
                exp: 63,
                eps: EPS3_STEPS - 1,
                scale: -128,
            },
            ..input.clone()
        };
        assert_eq!(placed.encode().len(), input.encode().len() + 7);
        assert_eq!(decode::<Ops3Input>(&placed.encode()).unwrap(), placed);
        let c = Construct3Input {
            vertices: vec![LatticePoint::new(4, 4, 4), LatticePoint::new(0, 1, 2)],
            faces: vec![vec![0, 1, 2], vec![1, 0, 1, 0, 2, 2]],
        };
        assert_eq!(decode::<Construct3Input>(&c.encode()).unwrap(), c);
    }

    #[test]
    fn short_input_reads_zeros() {
        assert_eq!(decode::<Ops3Input>(&[]).unwrap(), Ops3Input::default());
        assert_eq!(
            decode::<Construct3Input>(&[]).unwrap(),
            Construct3Input::default()
        );
    }

    #[test]
    fn boxes_are_never_flat() {
        for b in 0..=255u8 {
            let (lo, hi) = interval(b);
            assert!(lo < hi && hi < LATTICE, "{b}: {lo}..{hi}");
        }
    }
}
