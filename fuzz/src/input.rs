//! The fuzz input formats of the structured targets: shapes on a coarse grid, so that shared
//! vertices, collinear overlapping edges and touching curves dominate.
//!
//! Decoding reads bytes with `arbitrary`'s [`Unstructured`] one `u8` at a time (a missing byte
//! reads as 0), and every decoded value has an [`encode`](OpsInput::encode) that gives the bytes
//! back, so that the seed generator can write the paper's figure configurations as inputs.
//!
//! ```text
//! OpsInput       := tol:u8 Shape Shape Probes Scale
//! ConstructInput := tol:u8 Shape Probes Scale
//! Shape          := flags:u8 ncurves:u8 (len:u8 point:u8{len % (MAX_POINTS+1)}){ncurves % (MAX_CURVES+1)}
//! point          := bits 0-2 x, bits 3-5 y (grid 0..8), bits 6-7 float-mode jitter
//! Probes         := n:u8 probe:u8{n % (MAX_PROBES+1)}
//! probe          := low nibble % 10 = i, high nibble % 10 = j: the point (i - 1/2, j - 1/2)
//! tol            := bits 0-2 ε (float mode), bits 3-4 jitter size (float mode)
//! Scale          := mode:u8 exp:u8 shift:u8 eps:u8   (float mode only; absent bytes read 0)
//! mode           := bits 0-1 scale s (1: 2^k, 2: 10^k, else 1), bits 2-3 offset (0: none,
//!                   1: +s·2^shift in x, 2: in y, 3: −s·2^shift in both)
//! exp            := k over the whole range: 2^k for k in −997..=993, 10^k for k in −300..=299
//! shift          := % 64 (lowered until the offset is at most 10^300)
//! eps            := 0: tol's ε times s; 1..=15: an absolute ε from SPECIAL_EPS (subnormal
//!                   to f64::MAX); 16..=255: s·2^(eps − 136)
//! ```
//!
//! The Scale bytes come last so that inputs without them (every seed written before they
//! existed) decode as before: unit scale, no offset, tol's ε.

use arbitrary::{Arbitrary, Result, Unstructured};

/// Grid coordinates are 0..GRID.
pub const GRID: u8 = 8;
/// Most curves in one shape.
pub const MAX_CURVES: usize = 6;
/// Most points in one curve.
pub const MAX_POINTS: usize = 12;
/// Most membership probes.
pub const MAX_PROBES: usize = 6;

/// Flag bit: take the complement of the set built.
pub const COMPLEMENT: u8 = 1;
/// Flag bit: skip the validating constructor and fill the curves as polygon soup.
pub const FILL_ONLY: u8 = 2;
/// Flag bit: fill with the non-zero rule instead of even-odd.
pub const NONZERO: u8 = 4;

/// A grid point with its float-mode jitter selector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridPoint {
    /// 0..GRID.
    pub x: u8,
    /// 0..GRID.
    pub y: u8,
    /// 0: none, 1: +δ in x, 2: +δ in y, 3: −δ in both (float mode only).
    pub jitter: u8,
}

impl GridPoint {
    /// The point (x, y) without jitter.
    pub fn new(x: u8, y: u8) -> GridPoint {
        assert!(x < GRID && y < GRID, "({x}, {y}) is off the grid");
        GridPoint { x, y, jitter: 0 }
    }

    fn from_byte(b: u8) -> GridPoint {
        GridPoint {
            x: b & 7,
            y: (b >> 3) & 7,
            jitter: b >> 6,
        }
    }

    fn byte(self) -> u8 {
        self.x | (self.y << 3) | (self.jitter << 6)
    }
}

/// One operand: curves of grid points and how to turn them into a Yin set.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Shape {
    /// [`COMPLEMENT`], [`FILL_ONLY`], [`NONZERO`].
    pub flags: u8,
    /// The curves (vertex cycles, any orientation, possibly invalid).
    pub curves: Vec<Vec<GridPoint>>,
}

impl Shape {
    /// Curves given as integer pairs (panics if off the grid: for the seed generator).
    pub fn of(flags: u8, curves: &[&[(u8, u8)]]) -> Shape {
        Shape {
            flags,
            curves: curves
                .iter()
                .map(|c| c.iter().map(|&(x, y)| GridPoint::new(x, y)).collect())
                .collect(),
        }
    }

    fn decode(u: &mut Unstructured<'_>) -> Result<Shape> {
        let flags = u8::arbitrary(u)? & 7;
        let n = usize::from(u8::arbitrary(u)?) % (MAX_CURVES + 1);
        let mut curves = Vec::with_capacity(n);
        for _ in 0..n {
            let len = usize::from(u8::arbitrary(u)?) % (MAX_POINTS + 1);
            let mut curve = Vec::with_capacity(len);
            for _ in 0..len {
                curve.push(GridPoint::from_byte(u8::arbitrary(u)?));
            }
            curves.push(curve);
        }
        Ok(Shape { flags, curves })
    }

    fn encode(&self, out: &mut Vec<u8>) {
        assert!(self.curves.len() <= MAX_CURVES, "too many curves");
        out.push(self.flags);
        out.push(self.curves.len() as u8);
        for c in &self.curves {
            assert!(c.len() <= MAX_POINTS, "too many points");
            out.push(c.len() as u8);
            out.extend(c.iter().map(|p| p.byte()));
        }
    }
}

/// A probe point (i − 1/2, j − 1/2), i, j in 0..10: off the grid, so usually off boundaries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Probe {
    /// i in 0..10.
    pub i: u8,
    /// j in 0..10.
    pub j: u8,
}

impl Probe {
    /// Doubled coordinates (2i − 1, 2j − 1): integers, odd.
    pub fn doubled(self) -> (i64, i64) {
        (2 * i64::from(self.i) - 1, 2 * i64::from(self.j) - 1)
    }
}

fn decode_probes(u: &mut Unstructured<'_>) -> Result<Vec<Probe>> {
    let n = usize::from(u8::arbitrary(u)?) % (MAX_PROBES + 1);
    (0..n)
        .map(|_| {
            let b = u8::arbitrary(u)?;
            Ok(Probe {
                i: (b & 15) % 10,
                j: (b >> 4) % 10,
            })
        })
        .collect()
}

fn encode_probes(probes: &[Probe], out: &mut Vec<u8>) {
    assert!(probes.len() <= MAX_PROBES, "too many probes");
    out.push(probes.len() as u8);
    out.extend(probes.iter().map(|p| p.i | (p.j << 4)));
}

/// Float mode's ε (index: the tol byte's bits 0-2); 0 means "from the input's extent".
pub const EPS: [f64; 8] = [0.0, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.25];

/// Absolute ε values of the Scale byte `eps` in 1..=15: subnormal, the smallest normal, and
/// up to the largest finite `f64`.
pub const SPECIAL_EPS: [f64; 15] = [
    5e-324,
    1e-323,
    1e-310,
    f64::MIN_POSITIVE,
    // The largest subnormal.
    f64::from_bits(0x000f_ffff_ffff_ffff),
    1e-300,
    1e-200,
    1e-100,
    1e-10,
    1.0,
    1e10,
    1e100,
    1e200,
    1e300,
    f64::MAX,
];

/// Where float mode puts the grid shapes: coordinates s·(x + jitter) + offset, with s and the
/// offset over the whole `f64` range (10⁻³⁰⁰ … 10³⁰⁰), and the ε chosen with them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Scale {
    /// Bits 0-1: the kind of s; bits 2-3: the offset's direction.
    pub mode: u8,
    /// The exponent k of s.
    pub exp: u8,
    /// The offset is s·2^shift.
    pub shift: u8,
    /// The ε selector.
    pub eps: u8,
}

impl Scale {
    fn decode(u: &mut Unstructured<'_>) -> Result<Scale> {
        Ok(Scale {
            mode: u8::arbitrary(u)?,
            exp: u8::arbitrary(u)?,
            shift: u8::arbitrary(u)?,
            eps: u8::arbitrary(u)?,
        })
    }

    /// The bytes of a placement; none for the default one (missing bytes read as 0), so that
    /// unscaled inputs keep their earlier encoding.
    fn encode(&self, out: &mut Vec<u8>) {
        if *self != Scale::default() {
            out.extend([self.mode, self.exp, self.shift, self.eps]);
        }
    }

    /// The scale factor s (an `f64`: 10^k rounded to nearest).
    pub fn factor(&self) -> f64 {
        let e = i32::from(self.exp);
        match self.mode & 3 {
            1 => 2f64.powi(-997 + e * 1990 / 255),
            2 => format!("1e{}", -300 + e * 599 / 255)
                .parse()
                .expect("a decimal power of ten"),
            _ => 1.0,
        }
    }

    /// The offset (x, y) added to every scaled coordinate.
    pub fn offset(&self) -> (f64, f64) {
        let s = self.factor();
        let mut shift = i32::from(self.shift % 64);
        while shift > 0 && s * 2f64.powi(shift) > 1e300 {
            shift -= 1;
        }
        let o = s * 2f64.powi(shift);
        match (self.mode >> 2) & 3 {
            1 => (o, 0.0),
            2 => (0.0, o),
            3 => (-o, -o),
            _ => (0.0, 0.0),
        }
    }
}

/// Input of the binary-operation targets.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct OpsInput {
    /// Float mode: ε and jitter size.
    pub tol: u8,
    /// First operand.
    pub a: Shape,
    /// Second operand.
    pub b: Shape,
    /// Membership probes.
    pub probes: Vec<Probe>,
    /// Float mode: scale, offset and ε.
    pub scale: Scale,
}

impl<'a> Arbitrary<'a> for OpsInput {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(OpsInput {
            tol: u8::arbitrary(u)?,
            a: Shape::decode(u)?,
            b: Shape::decode(u)?,
            probes: decode_probes(u)?,
            scale: Scale::decode(u)?,
        })
    }
}

impl OpsInput {
    /// The bytes that decode to `self`.
    pub fn encode(&self) -> Vec<u8> {
        let mut out = vec![self.tol];
        self.a.encode(&mut out);
        self.b.encode(&mut out);
        encode_probes(&self.probes, &mut out);
        self.scale.encode(&mut out);
        out
    }
}

/// Input of the constructor target.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct ConstructInput {
    /// Float mode: ε and jitter size.
    pub tol: u8,
    /// The curves (its flags are ignored: every path is tried).
    pub shape: Shape,
    /// Membership probes.
    pub probes: Vec<Probe>,
    /// Float mode: scale, offset and ε.
    pub scale: Scale,
}

impl<'a> Arbitrary<'a> for ConstructInput {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        Ok(ConstructInput {
            tol: u8::arbitrary(u)?,
            shape: Shape::decode(u)?,
            probes: decode_probes(u)?,
            scale: Scale::decode(u)?,
        })
    }
}

impl ConstructInput {
    /// The bytes that decode to `self`.
    pub fn encode(&self) -> Vec<u8> {
        let mut out = vec![self.tol];
        self.shape.encode(&mut out);
        encode_probes(&self.probes, &mut out);
        self.scale.encode(&mut out);
        out
    }
}

/// Decode `T` from raw bytes the way `fuzz_target!` does.
pub fn decode<'a, T: Arbitrary<'a>>(data: &'a [u8]) -> Result<T> {
    T::arbitrary(&mut Unstructured::new(data))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encode_then_decode_round_trips() {
        let input = OpsInput {
            tol: 0x1b,
            a: Shape::of(COMPLEMENT, &[&[(0, 0), (7, 0), (7, 7)], &[]]),
            b: Shape {
                flags: FILL_ONLY | NONZERO,
                curves: vec![vec![GridPoint {
                    x: 3,
                    y: 5,
                    jitter: 2,
                }]],
            },
            probes: vec![Probe { i: 9, j: 0 }, Probe { i: 1, j: 4 }],
            scale: Scale {
                mode: 13,
                exp: 200,
                shift: 40,
                eps: 3,
            },
        };
        assert_eq!(decode::<OpsInput>(&input.encode()).unwrap(), input);
        let c = ConstructInput {
            tol: 7,
            shape: input.a.clone(),
            probes: input.probes.clone(),
            scale: Scale::default(),
        };
        assert_eq!(decode::<ConstructInput>(&c.encode()).unwrap(), c);
    }

    #[test]
    fn scales_span_the_float_range() {
        let s = |mode, exp| Scale {
            mode,
            exp,
            ..Scale::default()
        };
        assert_eq!(s(0, 200).factor(), 1.0);
        assert_eq!(s(1, 0).factor(), 2f64.powi(-997));
        assert_eq!(s(1, 255).factor(), 2f64.powi(993));
        assert_eq!(s(2, 0).factor(), 1e-300);
        assert_eq!(s(2, 255).factor(), 1e299);
        let far = Scale {
            mode: 1 | 4,
            exp: 255,
            shift: 63,
            eps: 0,
        };
        let (x, y) = far.offset();
        assert!(x <= 1e300 && x > 1e299 / 8.0 && y == 0.0, "{x}");
    }

    #[test]
    fn short_input_reads_zeros() {
        assert_eq!(decode::<OpsInput>(&[]).unwrap(), OpsInput::default());
    }
}
