//! Exact sums of determinants of rational points on a common lattice: the area and the volume
//! of an exact set whose coordinates share a modest common denominator (decimal input: every
//! denominator divides a power of ten), with one division at the end instead of a reduced
//! rational sum, and a gcd, at every term.
//!
//! With L the lcm of the coordinates' denominators, every coordinate times L is an integer;
//! the determinants of those integers are summed exactly ([`Relative::det_sum`]) and the sum
//! divided by L^D.

use super::dyadic::Relative;
use super::Rational;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

/// The widest common denominator, in bits, taken to the lattice: beyond it the integers grow
/// as large as the fractions' own terms and the reduced rational sum is no slower.
const WIDEST: u64 = 192;

/// Σ over `simplices` of det[p₁ − o, …, p_D − o], o the first point, for the points given by
/// their coordinates' fractions (numerator, positive denominator); `None` if the lcm of the
/// denominators is wider than [`WIDEST`] bits or there are no points.
pub(crate) fn lattice_det_sum<const D: usize>(
    fractions: &[[(BigInt, BigInt); D]],
    simplices: impl Iterator<Item = [usize; D]>,
) -> Option<Rational> {
    if fractions.is_empty() {
        return None;
    }
    let mut l = BigInt::one();
    for (_, d) in fractions.iter().flatten() {
        if !(&l % d).is_zero() {
            l = l.lcm(d);
            if l.bits() > WIDEST {
                return None;
            }
        }
    }
    let ints: Vec<[BigInt; D]> = (fractions.iter())
        .map(|p| p.each_ref().map(|(n, d)| n * (&l / d)))
        .collect();
    let sum = Relative::of(&ints).det_sum(simplices);
    Some(Rational::new(sum, l.pow(D as u32)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    use crate::num::dyadic::tests::rational_det_sum;
    use crate::num::Num;

    /// Points with decimal coordinates of up to 18 places (the narrow `i128` path for few
    /// places and small values, big integers beyond) or with denominators up to 10⁹ (a lattice
    /// of up to ~270 bits: none past [`WIDEST`]), and simplices of random indices.
    fn case<const D: usize>() -> impl Strategy<Value = (Vec<[Rational; D]>, Vec<[usize; D]>, bool)>
    {
        let decimal = (any::<i64>(), 0u32..18)
            .prop_map(|(n, k)| Rational::new(BigInt::from(n >> 20), BigInt::from(10).pow(k)));
        let wild = (any::<i32>(), 1i64..1_000_000_000)
            .prop_map(|(n, d)| Rational::new(BigInt::from(n), BigInt::from(d)));
        let value = prop_oneof![decimal.clone(), wild];
        prop_oneof![
            proptest::collection::vec(proptest::array::uniform::<_, D>(decimal), 1..12)
                .prop_map(|p| (p, true)),
            proptest::collection::vec(proptest::array::uniform::<_, D>(value), 1..12)
                .prop_map(|p| (p, false)),
        ]
        .prop_flat_map(|(points, decimal)| {
            let n = points.len();
            let simplex = proptest::array::uniform::<_, D>(0..n);
            (
                Just(points),
                proptest::collection::vec(simplex, 0..20),
                Just(decimal),
            )
        })
    }

    fn check<const D: usize>(points: &[[Rational; D]], simplices: &[[usize; D]], decimal: bool) {
        let fractions: Vec<[(BigInt, BigInt); D]> = points
            .iter()
            .map(|p| p.each_ref().map(|v| v.fraction()))
            .collect();
        let got = lattice_det_sum(&fractions, simplices.iter().copied());
        // Decimals of at most 18 places share the lattice of 10⁻¹⁸ (60 bits).
        assert!(!decimal || got.is_some(), "decimals are on a lattice");
        if let Some(sum) = got {
            assert_eq!(sum, rational_det_sum(points, simplices));
        }
    }

    proptest! {
        #[test]
        fn lattice_det_sum_2d_is_the_rational_sum((p, s, decimal) in case::<2>()) {
            check(&p, &s, decimal);
        }

        #[test]
        fn lattice_det_sum_3d_is_the_rational_sum((p, s, decimal) in case::<3>()) {
            check(&p, &s, decimal);
        }
    }
}
