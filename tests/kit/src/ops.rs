//! The Boolean operations by name, and the exact reading of a float result, for the suites
//! that run each operation in exact and in 3D float mode on the same operands and compare the
//! results.

use crate::membership::{self, Truth};
use crate::Y3;
use num_bigint::BigInt;
use std::fmt;
use yinset::kernel::Point3;
use yinset::num::{Float, Num, Rational};
use yinset::yin3::{Yin3Error, YinSet3};

/// One of the operations a ∧ b, a ∨ b, a − b, a ⊕ b and a'.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// a ∧ b.
    Meet,
    /// a ∨ b.
    Join,
    /// a − b.
    Difference,
    /// a ⊕ b.
    SymmetricDifference,
    /// a'.
    Complement,
}

/// Every [`Op`].
pub const OPS: [Op; 5] = [
    Op::Meet,
    Op::Join,
    Op::Difference,
    Op::SymmetricDifference,
    Op::Complement,
];

impl Op {
    /// The result on `a` and `b` (`b` unused by the complement).
    pub fn apply<N: Num>(self, a: &YinSet3<N>, b: &YinSet3<N>) -> YinSet3<N> {
        match self {
            Op::Meet => a.meet(b),
            Op::Join => a.join(b),
            Op::Difference => a.difference(b),
            Op::SymmetricDifference => a.symmetric_difference(b),
            Op::Complement => a.complement(),
        }
    }

    /// The result in float mode by the fallible methods (`try_meet` and so on): an error
    /// where a rounded result would not be a Yin set.
    pub fn try_float(
        self,
        a: &YinSet3<Float>,
        b: &YinSet3<Float>,
    ) -> Result<YinSet3<Float>, Yin3Error> {
        match self {
            Op::Meet => a.try_meet(b),
            Op::Join => a.try_join(b),
            Op::Difference => a.try_difference(b),
            Op::SymmetricDifference => a.try_symmetric_difference(b),
            Op::Complement => Ok(a.complement()),
        }
    }

    /// Its truth table, for the membership oracle.
    pub fn truth(self) -> Truth {
        match self {
            Op::Meet => membership::MEET,
            Op::Join => membership::JOIN,
            Op::Difference => membership::DIFFERENCE,
            Op::SymmetricDifference => membership::SYMMETRIC_DIFFERENCE,
            Op::Complement => membership::COMPLEMENT_A,
        }
    }
}

impl fmt::Display for Op {
    /// The operation on A and B, as failure messages name it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Op::Meet => "A∧B",
            Op::Join => "A∨B",
            Op::Difference => "A−B",
            Op::SymmetricDifference => "A⊕B",
            Op::Complement => "A'",
        })
    }
}

/// 2^k, exactly.
pub fn pow2(k: i32) -> Rational {
    let p = BigInt::from(1) << k.unsigned_abs();
    if k >= 0 {
        Rational::from_integer(p)
    } else {
        Rational::new(BigInt::from(1), p)
    }
}

/// The exact set of a float set's `f64` values divided by 2^s (exact: a power of two), built
/// with `from_triangles` independently of the kernel's float code.
pub fn exact_of(y: &YinSet3<Float>, s: i32) -> Result<Y3, Yin3Error> {
    if y.is_empty() {
        return Ok(YinSet3::empty());
    }
    if y.is_full() {
        return Ok(YinSet3::full());
    }
    let down = pow2(-s);
    let r = |v: &Float| {
        let q = Rational::from_f64(v.get()).expect("a float set has finite values");
        if s == 0 {
            q
        } else {
            q * down.clone()
        }
    };
    let pts = y
        .vertices()
        .iter()
        .map(|p| Point3::new(r(&p.x), r(&p.y), r(&p.z)))
        .collect();
    YinSet3::from_triangles(pts, y.triangles().iter().map(|t| t.to_vec()).collect())
}
