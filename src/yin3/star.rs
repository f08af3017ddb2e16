//! Flat stars of a triangle complex: at a vertex, the triangles that lie in one plane of
//! constant coordinate (faces of boxes, voxels and extrusions, which rounding keeps in their
//! plane), shown to meet only in shared corners and edges all at once — by following their fan
//! about the vertex, or by sorting their corners' wedges there — instead of by a test of every
//! pair ([`super::validate::conforming_after_moves`]).
//!
//! Two triangles with a corner `v` meet only in their shared corners and edges iff their
//! wedges at `v` (the cones from `v` over each triangle) meet only in `v` and in the rays of
//! shared edges: a point common to both triangles lies on a ray common to both wedges, and a
//! ray common to both wedges holds points of both triangles near `v`. In one plane the wedges
//! are arcs of directions, each less than a half turn; sorted by where they begin, they meet
//! only as allowed iff each ends before the next begins, or where it begins if that is the
//! same corner (a shared edge, whose two triangles then lie on opposite sides of it).

use super::geom::Chart;
use crate::kernel::Point3;
use crate::num::Num;
use smallvec::SmallVec;
use std::cmp::Ordering::{self, Equal, Greater, Less};
use std::sync::OnceLock;

/// No flat axis: the triangle lies in no plane of constant coordinate.
const NONE: u8 = 3;

/// The flat stars of a triangle complex, each shown (or not) at the first pair of its
/// triangles that asks.
pub(crate) struct FlatStars<'a, N: Num> {
    points: &'a [Point3<N>],
    tris: &'a [[usize; 3]],
    ctx: &'a N::Ctx,
    /// Each triangle's axis whose coordinate its three corners share, else [`NONE`].
    axis: Vec<u8>,
    /// The flat triangles at each vertex, as triangle · 4 + its corner there: those at vertex
    /// `v` are `at[from[v]..from[v + 1]]`.
    at: Vec<usize>,
    /// Where each vertex's run in `at` begins, then the end of the last.
    from: Vec<usize>,
    /// Each vertex's axes (bit k) whose flat star there was shown, made at the first pair
    /// that asks (pairs are tested on rayon's threads).
    shown: Vec<OnceLock<u8>>,
}

impl<'a, N: Num> FlatStars<'a, N> {
    /// The flat stars of the triangles `tris` over `points`, to be checked with the
    /// orientations of `ctx`.
    pub(crate) fn of(
        points: &'a [Point3<N>],
        tris: &'a [[usize; 3]],
        ctx: &'a N::Ctx,
    ) -> FlatStars<'a, N> {
        let axis: Vec<u8> = tris
            .iter()
            .map(|t| flat_axis(t.map(|v| &points[v])))
            .collect();
        // No flat triangle: no star to index, and none is ever asked for.
        let n = match axis.iter().any(|&k| k != NONE) {
            true => points.len(),
            false => 0,
        };
        let flat = || (tris.iter().enumerate()).filter(|&(ti, _)| axis[ti] != NONE);
        let mut from = vec![0usize; n + 1];
        for v in flat().flat_map(|(_, t)| t) {
            from[v + 1] += 1;
        }
        for v in 0..n {
            from[v + 1] += from[v];
        }
        let mut next = from.clone();
        let mut at = vec![0usize; from[n]];
        for (ti, t) in flat() {
            for (j, &v) in t.iter().enumerate() {
                at[next[v]] = 4 * ti + j;
                next[v] += 1;
            }
        }
        FlatStars {
            points,
            tris,
            ctx,
            axis,
            at,
            from,
            shown: (0..n).map(|_| OnceLock::new()).collect(),
        }
    }

    /// True if the triangles `t` and `s` (indices into the triangles) lie in one flat star
    /// that is shown, so that they meet only in their shared corners and edges.
    pub(crate) fn meet_only_in_shared(&self, t: usize, s: usize) -> bool {
        let k = self.axis[t];
        if k == NONE || k != self.axis[s] {
            return false;
        }
        let (t, s) = (self.tris[t], self.tris[s]);
        (t.iter()).any(|&v| s.contains(&v) && self.shown_at(v) >> k & 1 == 1)
    }

    /// The axes whose flat star at vertex `v` is shown.
    fn shown_at(&self, v: usize) -> u8 {
        *self.shown[v].get_or_init(|| {
            let here = &self.at[self.from[v]..self.from[v + 1]];
            (0..3u8)
                .filter(|&k| {
                    let wedges = (here.iter()).filter(|&&c| self.axis[c / 4] == k).map(|&c| {
                        let (t, j) = (self.tris[c / 4], c % 4);
                        [t[(j + 1) % 3], t[(j + 2) % 3]]
                    });
                    let wedges: SmallVec<[[usize; 2]; 16]> = wedges.collect();
                    wedges.len() >= 2
                        && wedges_apart(self.points, v, usize::from(k), &wedges, self.ctx)
                })
                .fold(0, |bits, k| bits | 1 << k)
        })
    }
}

/// The axis whose coordinate the triangle's three corners share ([`NONE`] if none; a
/// nondegenerate triangle has at most one).
fn flat_axis<N: Num>(p: [&Point3<N>; 3]) -> u8 {
    let flat = |k: usize| p[0].coord(k) == p[1].coord(k) && p[1].coord(k) == p[2].coord(k);
    [0u8, 1, 2]
        .into_iter()
        .find(|&k| flat(usize::from(k)))
        .unwrap_or(NONE)
}

/// The rays from a vertex `v` in the plane through it of constant coordinate `k`, in that
/// plane's chart dropping `k`.
struct Rays<'a, N: Num> {
    points: &'a [Point3<N>],
    v: usize,
    chart: Chart,
    ctx: &'a N::Ctx,
}

impl<N: Num> Rays<'_, N> {
    /// The image of point `x`.
    fn image(&self, x: usize) -> [&N; 2] {
        self.chart.image_of(&self.points[x])
    }

    /// The orientation of v and the points `a` and `b`: `Greater` if the ray to `b` is a
    /// counterclockwise turn of less than a half from the ray to `a`.
    fn turn(&self, a: usize, b: usize) -> Ordering {
        N::orient2d(self.image(self.v), self.image(a), self.image(b), self.ctx)
    }

    /// The half-turn of the ray to `x` (x's image is not v's): 0 for angles in [0, π), 1 in
    /// [π, 2π).
    fn half(&self, x: usize) -> u8 {
        let ([px, py], [vx, vy]) = (self.image(x), self.image(self.v));
        match py.cmp(vy) {
            Greater => 0,
            Less => 1,
            Equal => u8::from(px < vx),
        }
    }

    /// The rays to `a` and to `b` by angle, in [0, 2π).
    fn by_angle(&self, (a, ha): (usize, u8), (b, hb): (usize, u8)) -> Ordering {
        ha.cmp(&hb).then_with(|| self.turn(a, b).reverse())
    }
}

/// A wedge at v as an arc of directions, counterclockwise and less than a half-turn: the
/// corners it begins and ends at, with their half-turns ([`Rays::half`]).
#[derive(Clone, Copy)]
struct Arc {
    from: (usize, u8),
    to: (usize, u8),
}

impl Arc {
    /// True if the arc passes the direction of angle 0 (ends at it or beyond): it begins in
    /// the second half-turn and ends in the first.
    fn wraps(&self) -> bool {
        self.from.1 == 1 && self.to.1 == 0
    }
}

/// True if the wedges at `v` of the triangles `v a b` for `[a, b]` in `wedges` (indices into
/// `points`, all in the plane through `v` of constant coordinate `k`) are nondegenerate and
/// meet only in `v` and in the rays of shared edges (module docs): as [`one_fan`] tells, else
/// as [`sorted_apart`] does.
fn wedges_apart<N: Num>(
    points: &[Point3<N>],
    v: usize,
    k: usize,
    wedges: &[[usize; 2]],
    ctx: &N::Ctx,
) -> bool {
    let chart = Chart::of_axis(k, Ordering::Greater);
    let rays = Rays {
        points,
        v,
        chart,
        ctx,
    };
    let mut arcs: SmallVec<[Arc; 16]> = SmallVec::new();
    for &[a, b] in wedges {
        let (from, to) = match rays.turn(a, b) {
            Greater => (a, b),
            Less => (b, a),
            Equal => return false,
        };
        let at = |x: usize| (x, rays.half(x));
        arcs.push(Arc {
            from: at(from),
            to: at(to),
        });
    }
    one_fan(&rays, &arcs).unwrap_or_else(|| sorted_apart(&rays, &mut arcs))
}

/// Where the arcs form one fan — each but the first beginning at the corner where the one
/// before ends, closed if the last ends where the first begins — whether they meet only as
/// allowed: consecutive arcs lie on the two sides of their shared edge, so they do iff the fan
/// turns less than once about v if open, exactly once if closed. It turns by the arcs' passes
/// of angle 0 ([`Arc::wraps`]) in whole turns, plus the angle from where it begins to where it
/// ends. `None` if the arcs are not one fan.
fn one_fan<N: Num>(rays: &Rays<'_, N>, arcs: &[Arc]) -> Option<bool> {
    let m = arcs.len();
    // The arcs by the corner they begin at, and the corners they end at, sorted for lookup
    // (a star may hold many triangles); two arcs beginning at one corner are no fan.
    let mut starts: SmallVec<[(usize, usize); 16]> = (arcs.iter().enumerate())
        .map(|(i, a)| (a.from.0, i))
        .collect();
    starts.sort_unstable();
    if starts.windows(2).any(|w| w[0].0 == w[1].0) {
        return None;
    }
    let mut ends: SmallVec<[usize; 16]> = arcs.iter().map(|a| a.to.0).collect();
    ends.sort_unstable();
    let beginning_at = |corner: usize| {
        (starts.binary_search_by_key(&corner, |&(c, _)| c).ok()).map(|k| starts[k].1)
    };
    // The first arc: one that begins where none ends, else any (a closed fan).
    let first = (0..m)
        .find(|&i| ends.binary_search(&arcs[i].from.0).is_err())
        .unwrap_or(0);
    let (mut last, mut passes) = (first, 0);
    for n in 1..=m {
        passes += usize::from(arcs[last].wraps());
        match beginning_at(arcs[last].to.0) {
            Some(next) if next == first => return (n == m).then_some(passes == 1),
            Some(next) if n < m => last = next,
            Some(_) => return None,
            None => {
                let (from, to) = (arcs[first].from, arcs[last].to);
                return (n == m).then(|| match passes {
                    0 => true,
                    1 => rays.by_angle(to, from) == Less,
                    _ => false,
                });
            }
        }
    }
    None
}

/// True if the arcs meet only as allowed: sorted by the angle where they begin, each ends
/// before the next begins, or where it begins at the same corner.
fn sorted_apart<N: Num>(rays: &Rays<'_, N>, arcs: &mut [Arc]) -> bool {
    arcs.sort_unstable_by(|p, q| rays.by_angle(p.from, q.from));
    let m = arcs.len();
    (0..m).all(|n| {
        let (arc, next) = (arcs[n], arcs[(n + 1) % m].from);
        if rays.by_angle(arc.from, next) == Equal {
            // Two wedges begin on one ray (or one wedge alone, which meets nothing).
            return m == 1;
        }
        // The arc is less than a half-turn; the next begins after it, or where it ends at
        // the same corner.
        match rays.turn(arc.from.0, next.0) {
            Less | Equal => true,
            Greater => match rays.turn(arc.to.0, next.0) {
                Greater => true,
                Equal => arc.to.0 == next.0,
                Less => false,
            },
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use crate::yin3::tri::intersect;

    fn p(x: i64, y: i64, z: i64) -> Point3<Rational> {
        Point3::int(x, y, z)
    }

    /// The constructed intersection of two triangles lies in their shared corners.
    fn only_shared(points: &[Point3<Rational>], t: [usize; 3], s: [usize; 3]) -> bool {
        let (tp, sp) = (t.map(|v| &points[v]), s.map(|v| &points[v]));
        let shared: Vec<&Point3<Rational>> = (t.iter().filter(|v| s.contains(v)))
            .map(|&v| &points[v])
            .collect();
        intersect(tp, sp, &())
            .is_none_or(|c| !c.interiors_meet && c.points.iter().all(|x| shared.contains(&x)))
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(512)))]
        /// A star of triangles at the origin in the plane z = 0 (or x = 0, or y = 0), their
        /// other corners on a small lattice, is shown exactly when none of them is degenerate
        /// and every pair of them meets only in shared corners and edges by the constructed
        /// intersection. The corners are a fan's — in angular order from any one of them,
        /// open or closed, some going round again (in part or whole) on copies of the first
        /// corners — or drawn at random: repeated rays, opposite rays, shared edges, overlaps
        /// and gaps all occur.
        #[test]
        fn a_flat_star_is_shown_iff_its_pairs_meet_only_in_shared(
            rim in proptest::collection::vec((-3i64..=3, -3i64..=3), 2..8),
            fan in proptest::bool::ANY,
            (turn, closed, again) in (0usize..8, proptest::bool::ANY, 0usize..4),
            pick in proptest::collection::vec((0usize..8, 0usize..8, proptest::bool::ANY), 1..6),
            k in 0usize..3,
        ) {
            let mut rim = rim;
            rim.retain(|&(x, y)| (x, y) != (0, 0));
            if fan {
                // By angle, on integer cross products: [0, π) before [π, 2π).
                let lower = |&(x, y): &(i64, i64)| y < 0 || (y == 0 && x < 0);
                let cross = |a: &(i64, i64), b: &(i64, i64)| a.0 * b.1 - a.1 * b.0;
                rim.sort_by(|a, b| lower(a).cmp(&lower(b)).then(cross(a, b).cmp(&0).reverse()));
                rim.dedup();
                if !rim.is_empty() {
                    let turn = turn % rim.len();
                    rim.rotate_left(turn);
                    // 3: a whole second lap.
                    let again = if again == 3 { rim.len() } else { again };
                    let again: Vec<(i64, i64)> = rim.iter().copied().take(again).collect();
                    rim.extend(again);
                }
            }
            proptest::prop_assume!(rim.len() >= 2);
            // The plane of constant coordinate k: the lattice's two coordinates go to the
            // other two axes.
            let lift = |(x, y): (i64, i64)| {
                let mut c = [0i64; 3];
                c[(k + 1) % 3] = x;
                c[(k + 2) % 3] = y;
                p(c[0], c[1], c[2])
            };
            let points: Vec<Point3<Rational>> =
                std::iter::once(lift((0, 0))).chain(rim.iter().map(|&q| lift(q))).collect();
            let n = rim.len();
            let tris: Vec<[usize; 3]> = if fan {
                let open = (0..n - 1).map(|i| [0, 1 + i, 2 + i]);
                open.chain(closed.then_some([0, n, 1])).collect()
            } else {
                (pick.iter())
                    .map(|&(a, b, flip)| (1 + a % n, 1 + b % n, flip))
                    .filter(|&(a, b, _)| a != b)
                    .map(|(a, b, flip)| if flip { [0, b, a] } else { [0, a, b] })
                    .collect()
            };
            proptest::prop_assume!(tris.len() >= 2);
            // A triangle degenerate along a lattice axis is flat in a second axis too; where
            // that is the axis it is filed under, it is in no star of this plane: skipped.
            let axis = |t: &[usize; 3]| usize::from(flat_axis(t.map(|v| &points[v])));
            proptest::prop_assume!(tris.iter().all(|t| axis(t) == k));
            let stars = FlatStars::of(&points, &tris, &());
            let shown = stars.shown_at(0) >> k & 1 == 1;
            let nondegenerate = tris.iter().all(|t| {
                let [a, b, c] = t.map(|v| &points[v]);
                !crate::yin3::geom::collinear(a, b, c)
            });
            let apart = nondegenerate
                && (0..tris.len()).all(|t| (0..t).all(|s| only_shared(&points, tris[t], tris[s])));
            proptest::prop_assert_eq!(shown, apart);
            if shown {
                for t in 0..tris.len() {
                    for s in 0..tris.len() {
                        proptest::prop_assert!(t == s || stars.meet_only_in_shared(t, s));
                    }
                }
            }
        }
    }

    /// A closed fan of 8 000 triangles about one vertex (its rim the boundary of a square) is
    /// shown, and so is every pair of its triangles; with one triangle repeated it is not.
    #[test]
    fn a_large_closed_fan_is_shown() {
        let n = 1000;
        let right = (1 - n..=n).map(|y| (n, y));
        let top = (-n..n).rev().map(|x| (x, n));
        let left = (-n..n).rev().map(|y| (-n, y));
        let bottom = (1 - n..=n).map(|x| (x, -n));
        let rim: Vec<(i64, i64)> = right.chain(top).chain(left).chain(bottom).collect();
        assert_eq!(rim.len(), 8000);
        let points: Vec<Point3<Rational>> = std::iter::once(p(0, 0, 0))
            .chain(rim.iter().map(|&(x, y)| p(x, y, 0)))
            .collect();
        let m = rim.len();
        let mut tris: Vec<[usize; 3]> = (0..m).map(|i| [0, 1 + i, 1 + (i + 1) % m]).collect();
        let stars = FlatStars::of(&points, &tris, &());
        assert_eq!(stars.shown_at(0), 1 << 2);
        assert!(stars.meet_only_in_shared(0, m / 2) && stars.meet_only_in_shared(m - 1, 0));
        tris.push(tris[m / 3]);
        assert_eq!(FlatStars::of(&points, &tris, &()).shown_at(0), 0);
    }

    /// Two flat triangles in different planes through one vertex are never taken as one star,
    /// though each plane's star there is shown.
    #[test]
    fn triangles_of_different_planes_are_not_shown_together() {
        let points = [
            p(0, 0, 0),
            p(1, 0, 0),
            p(0, 1, 0),
            p(0, 0, 1),
            p(1, 1, 0),
            p(1, 0, -1),
        ];
        // Two triangles in z = 0 and two in y = 0, all at the origin and the first edge of
        // each plane's pair (0 to (1, 0, 0)) shared across the planes.
        let tris = [[0, 1, 4], [0, 4, 2], [0, 3, 1], [0, 1, 5]];
        let stars = FlatStars::of(&points, &tris, &());
        assert!(stars.meet_only_in_shared(0, 1));
        assert!(stars.meet_only_in_shared(2, 3));
        assert!(!stars.meet_only_in_shared(0, 2));
        assert!(!stars.meet_only_in_shared(1, 3));
    }
}
