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
            // Parallel: opposite direction is angle π, same direction is 2π.
            let dot = (r.x.clone() - v.x.clone()) * (p.x.clone() - v.x.clone())
                + (r.y.clone() - v.y.clone()) * (p.y.clone() - v.y.clone());
            if dot.sign() == Ordering::Less {
                0
            } else {
                1
            }
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
}
