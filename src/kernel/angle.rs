//! Exact angular order of edges around a vertex, for S2R-b of seed 000 Lemma 4.2 (no atan2).

use super::point::{orient, Point};
use crate::num::Num;
use std::cmp::Ordering;

/// Compare the rays `v → p` and `v → q` by the clockwise angle from the ray `v → r`, each
/// angle taken in (0, 2π]: the ray along `v → r` itself comes last.
///
/// The edge `β_out` chosen by S2R-b, the one whose counterclockwise angle ∠β_out v β_in is
/// smallest, is the minimum of this order with `r` the start of `β_in`.
pub fn cmp_clockwise_from<N: Num>(
    v: &Point<N>,
    r: &Point<N>,
    p: &Point<N>,
    q: &Point<N>,
    ctx: &N::Ctx,
) -> Ordering {
    let half_p = half(v, r, p, ctx);
    let half_q = half(v, r, q, ctx);
    half_p.cmp(&half_q).then_with(|| orient(v, p, q, ctx))
}

/// 0 if the clockwise angle from `v → r` to `v → p` is in (0, π], 1 if in (π, 2π].
fn half<N: Num>(v: &Point<N>, r: &Point<N>, p: &Point<N>, ctx: &N::Ctx) -> u8 {
    match orient(v, r, p, ctx) {
        Ordering::Less => 0,
        Ordering::Greater => 1,
        Ordering::Equal => {
            // On one line through v: the same direction (angle 2π) iff p lies on r's side of v
            // along an axis on which r is off v (the one where it is farther by the values'
            // `f64` approximations, which differ only where the values do; where these cannot
            // tell, x if r is off v along it), else the opposite one (π).
            let off = |a: &N, b: &N| (a.approx() - b.approx()).abs();
            let (dx, dy) = (off(&r.x, &v.x), off(&r.y, &v.y));
            let along_x = match dx.partial_cmp(&dy) {
                Some(Ordering::Greater) => true,
                Some(Ordering::Less) => false,
                _ => r.x != v.x,
            };
            let same = match along_x {
                true => p.x.cmp(&v.x) == r.x.cmp(&v.x),
                false => p.y.cmp(&v.y) == r.y.cmp(&v.y),
            };
            u8::from(same)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn p(x: i64, y: i64) -> Point<Rational> {
        Point::int(x, y)
    }

    #[test]
    fn clockwise_order_around_origin() {
        let v = p(0, 0);
        let r = p(0, -1); // reference: down
                          // clockwise from down: left (π/2), up (π), right (3π/2), down itself (2π)
        let mut rays = vec![p(0, -3), p(5, 0), p(0, 2), p(-1, 0), p(1, 1), p(-1, -1)];
        rays.sort_by(|a, b| cmp_clockwise_from(&v, &r, a, b, &()));
        assert_eq!(
            rays,
            vec![p(-1, -1), p(-1, 0), p(0, 2), p(1, 1), p(5, 0), p(0, -3)]
        );
    }

    /// Rays on the reference's own line, the same way (2π) or the opposite (π), for references
    /// along an axis, along a diagonal (a tie of the axes) and steep or flat, about a vertex
    /// off the origin, against the sign of the dot product.
    #[test]
    fn rays_on_the_reference_line_are_at_pi_or_two_pi() {
        let v = p(3, -2);
        for (dx, dy) in [(1, 0), (0, -2), (2, 2), (-1, 1), (3, -1), (-1, -4)] {
            let r = p(3 + dx, -2 + dy);
            for k in [-3, -1, 1, 2] {
                let q = p(3 + k * dx, -2 + k * dy);
                // The ray a quarter-turn counterclockwise from v → r lies at 3π/2 clockwise:
                // q comes after it iff q points the way r does (2π), before it if not (π).
                let off = p(3 - dy, -2 + dx);
                let want = if k > 0 {
                    Ordering::Greater
                } else {
                    Ordering::Less
                };
                assert_eq!(
                    cmp_clockwise_from(&v, &r, &q, &off, &()),
                    want,
                    "{dx} {dy} {k}"
                );
            }
        }
    }
}
