//! The canonical form that decides equality of 3D Yin sets (yin3 docs: *Data model*): the oriented
//! 2-chain ∂𝒴 determines 𝒴, and per plane the chain is the pair of 2D Yin sets covered by the
//! triangles whose normals point to either side, which no re-triangulation changes.

use super::geom::{plane_key, Chart, PlaneKey};
use crate::kernel::{Point, Point3};
use crate::num::Num;
use crate::yin2::{FillRule, YinSet2};
use std::collections::BTreeMap;

/// Per plane, the regions covered by triangles with normal along (index 0) and against
/// (index 1) the plane key's normal, in the key's chart.
pub(crate) type Canon<N> = BTreeMap<PlaneKey<N>, [YinSet2<N>; 2]>;

/// Per plane, the triangles (as 2D rings) with normal along and against the key's normal.
type Rings<N> = BTreeMap<PlaneKey<N>, [Vec<Vec<Point<N>>>; 2]>;

/// The canonical form of the triangles `tris` over `points`.
pub(crate) fn canonical<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    ctx: &N::Ctx,
) -> Canon<N> {
    let mut rings: Rings<N> = BTreeMap::new();
    for t in tris {
        let [a, b, c] = t.map(|v| &points[v]);
        let (key, along) = plane_key(a, b, c);
        let chart = Chart::of_normal(&Point3::new(
            key.n[0].clone(),
            key.n[1].clone(),
            key.n[2].clone(),
        ));
        // Counterclockwise in the chart either way, so that the nonzero fill is the union.
        let ring = if along {
            vec![chart.project(a), chart.project(b), chart.project(c)]
        } else {
            vec![chart.project(a), chart.project(c), chart.project(b)]
        };
        rings.entry(key).or_default()[usize::from(!along)].push(ring);
    }
    rings
        .into_iter()
        .map(|(key, [up, down])| {
            let fill = |r: Vec<Vec<Point<N>>>| {
                YinSet2::from_rings_filled_with(r, FillRule::NonZero, *ctx)
                    .expect("finite coordinates")
            };
            (key, [fill(up), fill(down)])
        })
        .collect()
}
