//! Closed intervals of `f64` that enclose an exact value: the floating-point filter of the
//! predicates on implicit points (CGAL's interval stage; Attene 2020, §3). Every operation
//! widens its rounded bounds outward by one ulp, which covers round-to-nearest's half-ulp error
//! without switching rounding modes; a NaN anywhere gives the whole line, which decides nothing.

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// An interval `[lo, hi]` known to contain some exact value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Interval {
    lo: f64,
    hi: f64,
}

impl Interval {
    /// The whole line: an unknown value.
    pub const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// [0, 1]: the parameters of a segment's points.
    pub const UNIT: Interval = Interval { lo: 0.0, hi: 1.0 };

    /// `[lo, hi]` widened outward by one ulp each way (a NaN bound gives [`Interval::ENTIRE`]).
    fn widened(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return Interval::ENTIRE;
        }
        Interval {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }

    /// The values within 8 ulps (relative) and 2⁻¹⁰²⁴ (absolute, for results below the normal
    /// range) of `v`: encloses a value whose approximation `v` is within 4 ulps
    /// ([`crate::num::Num::approx`]). NaN or an infinity gives [`Interval::ENTIRE`].
    pub fn around(v: f64) -> Interval {
        if !v.is_finite() {
            return Interval::ENTIRE;
        }
        let r = v.abs() * (8.0 * f64::EPSILON) + f64::from_bits(0x0010_0000_0000_0000) / 4.0;
        Interval::widened(v - r, v + r)
    }

    /// The sign of every value in the interval, if it is the same for all of them.
    pub fn sign(self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else {
            None
        }
    }

    /// The order of every value of `self` against every value of `o`, if it is the same.
    pub fn cmp(self, o: Interval) -> Option<Ordering> {
        if self.hi < o.lo {
            Some(Ordering::Less)
        } else if self.lo > o.hi {
            Some(Ordering::Greater)
        } else {
            None
        }
    }

    /// The quotient, if `d` excludes zero (`None` otherwise).
    pub fn div(self, d: Interval) -> Option<Interval> {
        d.sign()?;
        let q = [
            self.lo / d.lo,
            self.lo / d.hi,
            self.hi / d.lo,
            self.hi / d.hi,
        ];
        Some(Interval::hull(q))
    }

    /// The common part of two intervals holding the same value (`self` if they do not meet,
    /// which rounding cannot cause).
    pub fn meet(self, o: Interval) -> Interval {
        let (lo, hi) = (self.lo.max(o.lo), self.hi.min(o.hi));
        if lo <= hi {
            Interval { lo, hi }
        } else {
            self
        }
    }

    /// The ends `(lo, hi)`.
    pub fn bounds(self) -> (f64, f64) {
        (self.lo, self.hi)
    }

    /// The smallest interval holding two exact values (`a` and `b` of a segment's ends).
    pub fn span(a: Interval, b: Interval) -> Interval {
        Interval {
            lo: a.lo.min(b.lo),
            hi: a.hi.max(b.hi),
        }
    }

    /// The widened hull of four rounded results (any NaN: [`Interval::ENTIRE`]).
    fn hull(v: [f64; 4]) -> Interval {
        if v.iter().any(|x| x.is_nan()) {
            return Interval::ENTIRE;
        }
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::widened(lo, hi)
    }
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval::widened(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        Interval::widened(self.lo - o.hi, self.hi - o.lo)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        Interval::hull([
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Num, Rational};
    use proptest::prelude::*;

    /// Encloses `v`, checked exactly.
    fn encloses(i: Interval, v: &Rational) -> bool {
        let q = |x: f64| Rational::from_f64(x).ok();
        (i.lo == f64::NEG_INFINITY || q(i.lo).is_some_and(|l| &l <= v))
            && (i.hi == f64::INFINITY || q(i.hi).is_some_and(|h| v <= &h))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The interval of `a ∘ b` for point intervals `a`, `b` encloses the exact rational
        /// result, for values of any magnitude (including subnormal products and overflow to
        /// infinity): the outward widening alone covers the rounding.
        #[test]
        fn operations_enclose_exact_results(
            a in -1e6f64..1e6, b in -1e6f64..1e6, ea in -330i32..300, eb in -330i32..300,
        ) {
            let (x, y) = (a * 2f64.powi(ea), b * 2f64.powi(eb));
            let (rx, ry) = (Rational::from_f64(x).unwrap(), Rational::from_f64(y).unwrap());
            let (ix, iy) = (Interval { lo: x, hi: x }, Interval { lo: y, hi: y });
            prop_assert!(encloses(ix + iy, &(rx.clone() + ry.clone())));
            prop_assert!(encloses(ix - iy, &(rx.clone() - ry.clone())));
            prop_assert!(encloses(ix * iy, &(rx.clone() * ry.clone())));
            if let Some(q) = ix.div(iy) {
                prop_assert!(encloses(q, &(rx / ry)));
            }
        }
    }

    /// Intervals wider than a point: the product of [1, 2] and [3, 4] encloses [3, 8], the
    /// quotient of [1, 2] by [4, 4] encloses [1/4, 1/2], and an interval below zero is negative.
    #[test]
    fn wide_intervals_by_hand() {
        let r = |n: i64| Rational::from_i64(n);
        let (x, y) = (Interval { lo: 1.0, hi: 2.0 }, Interval { lo: 3.0, hi: 4.0 });
        let p = x * y;
        assert!(encloses(p, &r(3)) && encloses(p, &r(8)));
        assert!(p.lo > 2.9 && p.hi < 8.1);
        let q = x
            .div(Interval { lo: 4.0, hi: 4.0 })
            .expect("4 excludes zero");
        let quarter = Rational::new(1.into(), 4.into());
        assert!(encloses(q, &quarter) && encloses(q, &(quarter.clone() + quarter)));
        assert!(q.lo > 0.24 && q.hi < 0.51);
        assert_eq!(Interval { lo: -2.0, hi: -1.0 }.sign(), Some(Ordering::Less));
        assert_eq!(Interval { lo: -2.0, hi: 0.0 }.sign(), None);
    }

    #[test]
    fn signs_are_decided_only_when_certain() {
        let one = Interval::around(1.0);
        assert_eq!(one.sign(), Some(Ordering::Greater));
        assert_eq!((one - one).sign(), None);
        assert_eq!(Interval::ENTIRE.sign(), None);
        assert_eq!(Interval::around(f64::NAN), Interval::ENTIRE);
        assert_eq!((Interval::ENTIRE * Interval::around(0.0)).sign(), None);
        assert!(one.div(one - one).is_none());
        // around(v) encloses every value whose approximation v is within 4 ulps.
        let v = 3.0f64;
        let four_ulps =
            Rational::from_f64(v).unwrap() * Rational::parse("1.0000000000000009").unwrap();
        assert!(encloses(Interval::around(v), &four_ulps));
        let tiny = Rational::from_f64(f64::from_bits(1)).unwrap() * Rational::from_i64(3);
        assert!(encloses(Interval::around(0.0), &tiny));
    }
}
