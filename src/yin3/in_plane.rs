//! How two coplanar triangles of different operands meet (seed 004 step 1, the coplanar case;
//! yin3 docs: *Triangle–triangle*), decided from orientations of their corners' images in a
//! chart of the plane ([`Corners::orient2d`]), each point named by what defines it: a corner
//! of one in the closed other, or an edge of each crossing the other's inside both
//! (constructed once, where it is first needed, by [`Corners::crossing`]). The closed
//! triangles meet in a convex polygon whose corners are those points; each triangle is cut
//! along the part of each of the other's edges inside it, whose ends are the points on that
//! edge.

use super::contact::{key, Edge};
use super::corners::Corners;
use super::geom::Chart;
use smallvec::{smallvec, SmallVec};
use std::cmp::Ordering::{self, Equal, Less};

/// A point where two coplanar triangles meet, by what defines it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum InPlane {
    /// A corner of one triangle (global index) in the other closed triangle.
    Corner(usize),
    /// Where an edge of the first triangle crosses an edge of the second inside both.
    Edges(Edge, Edge),
}

/// How two coplanar triangles meet: the corners of their common polygon, the segments each is
/// cut along, and whether they overlap in an area.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Overlap {
    /// The chart of the plane in which the points were found.
    pub chart: Chart,
    /// The corners of the common polygon; none if the triangles are disjoint.
    pub points: SmallVec<[InPlane; 6]>,
    /// The segments the first triangle is cut along (parts of the second's edges), then those
    /// the second is cut along, as indices into `points`.
    pub cuts: [SmallVec<[(usize, usize); 3]>; 2],
    /// True if the relative interiors meet: no edge line of either has the other on its closed
    /// outer side (the separating-axis theorem for convex polygons, weakly).
    pub area: bool,
}

/// How the coplanar triangles `t` and `s` (global vertex indices, distinct indices being
/// distinct points; shared corners are corners of both) meet; `None` if either is degenerate,
/// or if an edge were found to hold more than the two ends of its part inside the other (which
/// convexity rules out), so that the arrangement constructs the pair's contact instead.
pub(super) fn overlap(p: &impl Corners, t: [usize; 3], s: [usize; 3]) -> Option<Overlap> {
    let chart = p.chart(t)?;
    let o = |a: usize, b: usize, c: usize| p.orient2d(&chart, [a, b, c]);
    let mut s = s;
    match o(s[0], s[1], s[2]) {
        Equal => return None,
        Less => s.swap(1, 2),
        _ => {}
    }
    // sides[0][i][j]: the side of the edge i of t (from corner i to i + 1) on which corner j of
    // s lies; sides[1][j][i] the same with the triangles swapped. Both run counterclockwise, so
    // Greater is inside.
    let sides =
        [(t, s), (s, t)].map(|(x, y)| [0, 1, 2].map(|i| y.map(|v| o(x[i], x[(i + 1) % 3], v))));
    let outside = |rows: &[[Ordering; 3]; 3], strictly: bool| {
        rows.iter()
            .any(|row| row.iter().all(|&o| o == Less || (!strictly && o == Equal)))
    };
    if outside(&sides[0], true) || outside(&sides[1], true) {
        return Some(Overlap {
            chart,
            points: SmallVec::new(),
            cuts: Default::default(),
            area: false,
        });
    }
    let area = !outside(&sides[0], false) && !outside(&sides[1], false);
    let tris = [t, s];
    let mut points: SmallVec<[InPlane; 6]> = SmallVec::new();
    // The points on each edge of either triangle: on[m][i] for edge i of triangle m.
    let mut on: [[SmallVec<[usize; 2]>; 3]; 2] = Default::default();
    let mut add = |x: InPlane, edges: &[(usize, usize)]| {
        let k = points.iter().position(|&y| y == x).unwrap_or_else(|| {
            points.push(x);
            points.len() - 1
        });
        for &(m, i) in edges {
            if !on[m][i].contains(&k) {
                on[m][i].push(k);
            }
        }
    };
    for m in 0..2 {
        let (rows, corners) = (&sides[1 - m], tris[m]);
        for j in 0..3 {
            // Corner j of triangle m in the closed other: on its two edges, and on each edge of
            // the other whose line passes through it.
            if rows.iter().all(|row| row[j] != Less) {
                let mut edges: SmallVec<[(usize, usize); 4]> = smallvec![(m, j), (m, (j + 2) % 3)];
                edges.extend((0..3).filter(|&i| rows[i][j] == Equal).map(|i| (1 - m, i)));
                add(InPlane::Corner(corners[j]), &edges);
            }
        }
    }
    // Edge k of a triangle strictly across a line, by its corners' sides `row` of it.
    let straddles = |row: &[Ordering; 3], k: usize| {
        let (a, b) = (row[k], row[(k + 1) % 3]);
        a != Equal && b != Equal && a != b
    };
    for i in 0..3 {
        for j in 0..3 {
            if straddles(&sides[0][i], j) && straddles(&sides[1][j], i) {
                let (e, f) = ((t[i], t[(i + 1) % 3]), (s[j], s[(j + 1) % 3]));
                add(
                    InPlane::Edges(key(e.0, e.1), key(f.0, f.1)),
                    &[(0, i), (1, j)],
                );
            }
        }
    }
    // Each triangle is cut along the other's edges; the points on an edge are the ends of its
    // part inside the other triangle (a segment of a line through a convex polygon).
    let mut cuts: [SmallVec<[(usize, usize); 3]>; 2] = Default::default();
    for m in 0..2 {
        for ends in &on[1 - m] {
            match ends[..] {
                [] | [_] => {}
                [a, b] => cuts[m].push((a, b)),
                _ => return None,
            }
        }
    }
    Some(Overlap {
        chart,
        points,
        cuts,
        area,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point3;
    use crate::num::{exact_orient, Num, Rational};
    use crate::yin3::corners::{F64Corners, RationalCorners};
    use crate::yin3::tri::intersect;
    use rand::{RngExt, SeedableRng};

    /// A point as an exact rational point.
    type P = Point3<Rational>;

    /// The contact `o` on the corners `p` (exact values `corners`) in exact points: the points
    /// sorted, and each triangle's cuts as sorted pairs, sorted.
    fn resolved(o: &Overlap, p: &impl Corners, corners: &[P]) -> (Vec<P>, [Vec<[P; 2]>; 2]) {
        let at = |x: &InPlane| match *x {
            InPlane::Corner(v) => corners[v].clone(),
            InPlane::Edges(e, f) => p.crossing(&o.chart, e, f),
        };
        let points: Vec<P> = o.points.iter().map(at).collect();
        normalized(points, [&o.cuts[0][..], &o.cuts[1][..]])
    }

    /// Points sorted and cuts (index pairs into `points`) as sorted pairs of points, sorted.
    fn normalized(points: Vec<P>, cuts: [&[(usize, usize)]; 2]) -> (Vec<P>, [Vec<[P; 2]>; 2]) {
        let cuts = cuts.map(|cuts| {
            let mut ends: Vec<[P; 2]> = (cuts.iter())
                .map(|&(a, b)| {
                    let mut e = [points[a].clone(), points[b].clone()];
                    e.sort();
                    e
                })
                .collect();
            ends.sort();
            ends
        });
        let mut points = points;
        points.sort();
        (points, cuts)
    }

    /// The lattice point (u, v) of one of three planes: z = 0 and z = u + 2v − 3 (whose
    /// points are `f64`s), and one with coordinates no `f64` holds.
    fn embed(plane: usize, u: i64, v: i64) -> P {
        let r = |n: i64, d: i64| Rational::from_i64(n) / Rational::from_i64(d);
        match plane {
            0 => Point3::int(u, v, 0),
            1 => Point3::int(u, v, u + 2 * v - 3),
            _ => Point3::new(r(u, 3), r(v, 5), r(u, 7) + r(v, 11) + r(1, 13)),
        }
    }

    /// Coplanar pairs of triangles on a small lattice of three planes, so that corners fall
    /// on the other's edges and edges overlap along a line often, some sharing corners (one in
    /// four of the second's is one of the first's): [`overlap`] finds the points,
    /// cuts and overlap in area that the constructed intersection ([`intersect`]) finds, on
    /// `f64` and on rational corners; every kind of contact occurs many times.
    #[test]
    fn coplanar_pairs_meet_as_constructed() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        // Pairs apart, overlapping in an area with crossing edges, touching in a point,
        // touching along a segment, and meeting with a shared corner.
        let mut seen = [0usize; 5];
        for round in 0..12_000 {
            let plane = round % 3;
            let corners: Vec<P> = (0..6)
                .map(|_| embed(plane, rng.random_range(-3..=3), rng.random_range(-3..=3)))
                .collect();
            // One corner in four of s is one of t's.
            let (t, mut s) = ([0, 1, 2], [3, 4, 5]);
            for v in &mut s {
                if rng.random_range(0..4) == 0 {
                    *v = rng.random_range(0..3);
                }
            }
            let used: Vec<usize> = (0..6).filter(|v| t.contains(v) || s.contains(v)).collect();
            let distinct =
                (used.iter()).all(|&i| used.iter().all(|&j| i == j || corners[i] != corners[j]));
            let at = |x: [usize; 3]| x.map(|v| &corners[v]);
            let flat = |x: [&P; 3]| Chart::checked_of_triangle(x[0], x[1], x[2]).is_none();
            if !distinct || flat(at(t)) || flat(at(s)) {
                continue;
            }
            let expected = intersect(at(t), at(s), &());
            let found = match plane {
                2 => overlap(&RationalCorners::new(corners.clone()), t, s).map(|o| {
                    (
                        resolved(&o, &RationalCorners::new(corners.clone()), &corners),
                        o,
                    )
                }),
                _ => {
                    let p = F64Corners(corners.iter().map(Point3::to_f64).collect());
                    overlap(&p, t, s).map(|o| (resolved(&o, &p, &corners), o))
                }
            };
            let (got, o) = found.expect("neither is degenerate");
            match expected {
                None => {
                    assert!(o.points.is_empty(), "round {round}: {o:?}");
                    seen[0] += 1;
                }
                Some(c) => {
                    assert!(c.coplanar);
                    let want = normalized(c.points.clone(), [&c.cuts_t, &c.cuts_s]);
                    assert_eq!(got, want, "round {round}: {o:?}");
                    assert_eq!(o.area, c.interiors_meet, "round {round}: {o:?}");
                    let edges = o.points.iter().any(|x| matches!(x, InPlane::Edges(..)));
                    seen[1] += usize::from(o.area && edges);
                    seen[2] += usize::from(!o.area && o.points.len() == 1);
                    seen[3] += usize::from(!o.area && o.points.len() == 2);
                    seen[4] += usize::from(t.iter().any(|v| s.contains(v)));
                }
            }
        }
        assert!(seen.iter().all(|&n| n >= 40), "{seen:?}");
    }

    /// Nearly collinear points in a tilted plane, a few units of the last place off the line
    /// in the image: the corners' in-plane orientation is the exact orientation of the images,
    /// on `f64` and on rational corners.
    #[test]
    fn in_plane_orientation_is_exact_near_a_line() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        for round in 0..2000 {
            let big = 1i64 << rng.random_range(20..52);
            let (u, v) = (rng.random_range(-big..big), rng.random_range(-big..big));
            let k = rng.random_range(-3..=3i64);
            let tilt = |x: i64, y: i64| Point3::int(x, y, x / 2 - y / 4);
            let points = vec![
                Point3::int(0, 0, 0),
                tilt(u, v),
                tilt(2 * u + k, 2 * v - k),
                Point3::int(1, 0, 0),
                Point3::int(0, 1, 0),
            ];
            let on_rationals = round % 2 == 1;
            let points: Vec<P> = match on_rationals {
                true => (points.iter())
                    .map(|p| {
                        let third = |x: &Rational| x.clone() / Rational::from_i64(3);
                        Point3::new(third(&p.x), third(&p.y), third(&p.z))
                    })
                    .collect(),
                false => points,
            };
            let chart = Chart::checked_of_triangle(&points[0], &points[3], &points[4])
                .expect("a chart of z = 0");
            let [a, b, c] = [0, 1, 2].map(|i| chart.image_of(&points[i]));
            let want = exact_orient(a, b, c);
            let got = match on_rationals {
                true => RationalCorners::new(points.clone()).orient2d(&chart, [0, 1, 2]),
                false => {
                    let f64s = points.iter().map(Point3::to_f64).collect();
                    F64Corners(f64s).orient2d(&chart, [0, 1, 2])
                }
            };
            assert_eq!(got, want, "round {round}");
        }
    }
}
