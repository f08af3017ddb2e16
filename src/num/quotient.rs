//! The nearest `f64` of a quotient of big integers from their leading bits alone: the top
//! 128 bits of the numerator divided by the top 64 of the denominator give a 64-bit quotient
//! within a few units of the true one, which settles the rounding to 53 bits unless a
//! rounding midpoint lies that close (then the caller divides exactly).

use num_bigint::BigUint;

/// A positive integer as its leading 128 bits, normalized (top bit set), and its bit length:
/// x = top·2^(bits − 128) + r with 0 ≤ r < 2^(bits − 128) (r = 0 when bits ≤ 128).
#[derive(Clone, Copy)]
pub(super) struct Leading {
    top: u128,
    bits: u64,
}

impl Leading {
    /// The leading bits of a positive `u64`.
    pub(super) fn of_u64(x: u64) -> Leading {
        debug_assert!(x > 0);
        let bits = u64::from(64 - x.leading_zeros());
        Leading {
            top: u128::from(x) << (128 - bits),
            bits,
        }
    }

    /// The leading bits of a positive big integer (its three most significant 64-bit digits).
    pub(super) fn of_big(x: &BigUint) -> Leading {
        let mut digits = x.iter_u64_digits().rev();
        let hi = digits.next().unwrap_or(0);
        debug_assert!(hi > 0);
        let (mid, lo) = (digits.next().unwrap_or(0), digits.next().unwrap_or(0));
        let z = hi.leading_zeros();
        let two = (u128::from(hi) << 64) | u128::from(mid);
        let top = match z {
            0 => two,
            _ => (two << z) | u128::from(lo >> (64 - z)),
        };
        Leading {
            top,
            bits: x.bits(),
        }
    }
}

/// The nearest `f64` to n / d for positive n and d given by their leading bits, or `None`
/// where those bits cannot settle it: a rounding midpoint within the quotient's error, or a
/// result outside the normal range.
pub(super) fn nearest_f64(n: Leading, d: Leading) -> Option<f64> {
    // With n = N·2^(ln − 128) + r (N the top 128 bits) and d = D·2^(ld − 64) + s (D the top
    // 64), n/d = R·2^e where R = (N + ρ)/(D + σ) for some ρ, σ in [0, 1): R lies strictly
    // between N/D − N/D² > q − 4 and (N + 1)/D < q + 2, with q = ⌊N/D⌋ in [2^63, 2^65).
    let dh = d.top >> 64;
    let q = n.top / dh;
    let e = (n.bits as i64 - 128) - (d.bits as i64 - 64);
    // Rounding R to 53 bits drops `shift` bits; every real in (q − 4, q + 2) rounds as q
    // does unless the midpoint of its block, at `half`, lies within that distance of q. (Near
    // a power of two, where R and q may differ in length, both round to that power.)
    let shift = 128 - q.leading_zeros() - 53;
    let (low, half) = (q & ((1 << shift) - 1), 1u128 << (shift - 1));
    if low.abs_diff(half) <= 8 {
        return None;
    }
    let m = (q >> shift) + u128::from(low > half);
    let exponent = e + i64::from(shift);
    // m in [2^52, 2^53]: m·2^exponent is normal and finite.
    if exponent + 52 < -1022 || exponent + 53 > 1023 {
        return None;
    }
    Some(m as f64 * pow2(exponent))
}

/// 2^k for k in [−1074, 1023], exactly.
fn pow2(k: i64) -> f64 {
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1 << (k + 1074))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::ToPrimitive;

    /// num-rational's correctly rounded quotient (one big division), the reference.
    fn reference(n: &BigUint, d: &BigUint) -> f64 {
        let r = BigRational::new_raw(BigInt::from(n.clone()), BigInt::from(d.clone()));
        r.to_f64().expect("a finite quotient")
    }

    /// The integer whose 64-bit digits, least significant first, are `digits`.
    fn from_digits(digits: &[u64]) -> BigUint {
        let halves: Vec<u32> = digits
            .iter()
            .flat_map(|&x| [x as u32, (x >> 32) as u32])
            .collect();
        BigUint::from_slice(&halves)
    }

    fn leading(x: &BigUint) -> Leading {
        match x.to_u64() {
            Some(v) => Leading::of_u64(v),
            None => Leading::of_big(x),
        }
    }

    /// A quotient exactly halfway between two `f64`s, and one an ulp-fraction off it: the
    /// leading bits cannot tell, so both are left to the exact division.
    #[test]
    fn near_midpoints_are_deferred() {
        let d = BigUint::from(3u32) << 200u32;
        let half = (BigUint::from((1u64 << 53) + 1) << 199u32) * 3u32;
        assert_eq!(nearest_f64(leading(&half), leading(&d)), None);
        let off = &half + 1u32;
        assert_eq!(nearest_f64(leading(&off), leading(&d)), None);
        assert_eq!(
            nearest_f64(leading(&(BigUint::from(1u32) << 80u32)), leading(&d)),
            Some(2f64.powi(80 - 200) / 3.0)
        );
    }

    /// The worst case of the error bound: a denominator whose dropped digits are all ones
    /// under the smallest leading digit, so that R lies almost 4 units below q. With q 3
    /// units above a midpoint, R is below it and rounds down while q would round up: the
    /// leading bits must defer. Nine units above, they settle it.
    #[test]
    fn a_quotient_almost_four_units_off_defers() {
        let d = (BigUint::from(1u32) << 127u32) + (BigUint::from(1u32) << 64u32) - 1u32;
        for (above, settled) in [(3u64, false), (9, true)] {
            let q = (BigUint::from((1u64 << 53) - 1) << 12u32) + (1u64 << 11) + above;
            let n = q << 63u32;
            let got = nearest_f64(leading(&n), leading(&d));
            assert_eq!(got.is_some(), settled, "{above} units above a midpoint");
            assert_eq!(got.unwrap_or(reference(&n, &d)), reference(&n, &d));
        }
    }

    /// Quotients outside the normal range are left to the exact division: below it, a
    /// product of the mantissa and a subnormal power of two would round a second time; above
    /// it, near 2¹⁰²⁴, the power of two has no `f64`.
    #[test]
    fn quotients_outside_the_normal_range_are_deferred() {
        let (one, three) = (BigUint::from(1u32), BigUint::from(3u32));
        let tiny = &three << 1050u32;
        assert!(reference(&one, &tiny) < f64::MIN_POSITIVE);
        assert_eq!(nearest_f64(leading(&one), leading(&tiny)), None);
        let huge = &three << 1023u32;
        assert_eq!(reference(&huge, &three), 2f64.powi(1023));
        assert_eq!(
            nearest_f64(leading(&(&huge << 1u32)), leading(&three)),
            None
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The leading 128 bits of integers of 1 to 640 bits are the integer shifted to 128
        /// bits exactly.
        #[test]
        fn leading_bits_are_the_shifted_integer(
            digits in proptest::collection::vec(proptest::num::u64::ANY, 1..10),
        ) {
            let x = from_digits(&digits);
            proptest::prop_assume!(x.bits() > 0);
            let l = Leading::of_big(&x);
            let shifted = match x.bits() {
                b if b > 128 => &x >> (b - 128),
                b => &x << (128 - b),
            };
            proptest::prop_assert_eq!(l.bits, x.bits());
            proptest::prop_assert_eq!(Some(l.top), shifted.to_u128());
        }

        /// Wherever the leading bits give a value it is num-rational's correctly rounded one:
        /// numerators and denominators of 1 to 600 bits (past three 64-bit digits, so the
        /// dropped digits matter), quotients near rounding midpoints (m + 1/2 ulp, moved by
        /// up to 2⁻⁸ ulp either side, across the error bound the deferral allows for), and
        /// quotients from 2⁻¹⁰⁴⁸ to 2¹¹⁵² (past both ends of the normal range).
        #[test]
        fn the_leading_bits_round_correctly(
            n_digits in proptest::collection::vec(proptest::num::u64::ANY, 1..10),
            d_digits in proptest::collection::vec(proptest::num::u64::ANY, 1..10),
            m in (1u64 << 52)..(1u64 << 53),
            nudge in -(1i64 << 13)..=(1 << 13),
            scale in -1100i64..1100,
        ) {
            let (n, d) = (from_digits(&n_digits), from_digits(&d_digits) | BigUint::from(1u32));
            proptest::prop_assume!(n.bits() > 0);
            let mut cases = vec![(n.clone(), d.clone())];
            // (m + 1/2 + nudge·2⁻²¹)·2^scale: near the midpoint after the 53-bit m.
            let near = (BigUint::from(2 * m + 1) << 20u32) * &d;
            let near = if nudge >= 0 {
                near + &d * BigUint::from(nudge as u64)
            } else {
                near - &d * BigUint::from(nudge.unsigned_abs())
            };
            let (n2, d2) = match scale >= 0 {
                true => (near << scale as u64, d.clone() << 21u32),
                false => (near, d.clone() << (21 + scale.unsigned_abs())),
            };
            cases.push((n2, d2));
            for (n, d) in cases {
                if let Some(got) = nearest_f64(leading(&n), leading(&d)) {
                    proptest::prop_assert_eq!(got, reference(&n, &d), "{} / {}", n, d);
                }
            }
        }
    }
}
