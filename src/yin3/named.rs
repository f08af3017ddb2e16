//! The contacts of a meet's arrangement that the transversal meet's classification settles
//! ([`super::contact`]; yin3 docs: *Meet*), those with an edge in the other's plane or an end
//! on the other's edge ([`Contact::Along`], [`Contact::OnEdge`], which the transversal meet
//! declines), and coplanar pairs, classified in their plane ([`super::in_plane`]): decided from
//! exact orientations of the input vertices alone (`f64` filters and stack integers where every
//! vertex is an `f64`, filtered rational orientations otherwise), each end named by what
//! defines it ([`Site`]) and constructed once however many pairs find it. A pair neither
//! settles (a degenerate triangle, which valid operands do not have) is left to the
//! arrangement's constructed contacts ([`super::tri`]); both give exact points, interned by
//! value into one table.

use super::contact::{contact, Contact, Edge, End, Site};
use super::corners::Corners;
use super::in_plane::{overlap, InPlane, Overlap};
use super::parallel::{map_all, PARALLEL_FROM};
use super::soup::Soup;
use crate::kernel::Point3;
use crate::num::{Num, Rational};
use foldhash::{HashMap, HashMapExt};
use smallvec::SmallVec;
use std::cmp::Ordering;

/// What the classification settled about a pair of triangles, in the soup's points.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Settled {
    /// Disjoint.
    Apart,
    /// Meeting only in these shared corners (one twice for a corner).
    Touch([usize; 2]),
    /// Crossing between these two points (one twice where they meet in one point).
    Cross([usize; 2]),
    /// Coplanar, meeting in the convex polygon of these points, the first triangle of the pair
    /// cut along the segments `cuts[0]` and the second along `cuts[1]`, overlapping in an area
    /// where `area`.
    InPlane {
        points: SmallVec<[usize; 6]>,
        cuts: [SmallVec<[(usize, usize); 3]>; 2],
        area: bool,
    },
    /// Not settled: the arrangement's constructed contacts decide.
    Open,
}

/// How a pair was classified: as the transversal meet does, or in their common plane.
enum Class {
    Of(Contact),
    InPlane(Option<Box<Overlap>>),
}

/// The meeting pairs' contacts as the transversal meet's classification finds them, or
/// [`overlap`] where they are coplanar, with each constructed end's index in the soup once
/// made.
pub(super) struct Named<C: Corners> {
    corners: C,
    contacts: Vec<Class>,
    made: HashMap<Site, usize>,
}

impl<C: Corners> Named<C> {
    /// The contacts of the pairs `meeting` of the soup's triangles (of different operands),
    /// on `corners`, the soup's points so far (its input vertices) with their exact tests, and
    /// `values`, the same points as numbers whose exact predicates are as cheap (their `f64`s
    /// where they are `f64`s). Coplanar pairs are classified in their plane ([`overlap`]).
    pub(super) fn new<N: Num, M: Num>(
        corners: C,
        values: &[Point3<M>],
        soup: &Soup<N>,
        meeting: &[(usize, usize)],
    ) -> Self {
        let points: Vec<&Point3<M>> = values.iter().collect();
        let tris = &soup.tris;
        let parallel = tris.len() >= PARALLEL_FROM;
        let planes: Vec<C::Plane> = map_all(tris, parallel, |&t| corners.plane(t));
        let classify = |&(i, j): &(usize, usize)| {
            // Operand 0's triangle first, so that ends are named alike by every pair.
            let (t, s) = match soup.operand[i] {
                0 => (i, j),
                _ => (j, i),
            };
            if tris[s]
                .iter()
                .all(|&v| corners.side(&planes[t], v) == Ordering::Equal)
            {
                return Class::InPlane(overlap(&corners, tris[t], tris[s]).map(Box::new));
            }
            let both = [&planes[t], &planes[s]];
            Class::Of(contact(&corners, both, &points, (t, tris[t]), (s, tris[s])))
        };
        Named {
            made: HashMap::with_capacity(meeting.len()),
            contacts: map_all(meeting, parallel, classify),
            corners,
        }
    }

    /// What the classification settled about the `k`th meeting pair, the triangles `pair`,
    /// its constructed ends made and interned into `soup` on first sight.
    pub(super) fn settled<N: Num>(
        &mut self,
        k: usize,
        pair: (usize, usize),
        soup: &mut Soup<N>,
    ) -> Settled {
        let contact = match self.contacts.get_mut(k) {
            Some(Class::Of(contact)) => *contact,
            Some(Class::InPlane(o)) => match o.take() {
                // Each pair is settled once: its overlap is not kept.
                Some(o) => return self.in_plane(*o, soup.operand[pair.0] != 0, soup),
                None => return Settled::Open,
            },
            None => return Settled::Open,
        };
        match contact {
            Contact::Apart => Settled::Apart,
            Contact::Touch([x, y]) => Settled::Touch([x[0], y[0]]),
            Contact::Cross(ends) | Contact::Along(ends) | Contact::OnEdge(ends) => {
                Settled::Cross(ends.map(|end| self.point(end, soup)))
            }
            Contact::Degenerate => Settled::Open,
        }
    }

    /// A coplanar pair's [`Overlap`] (operand 0's triangle first) in the soup's points, its
    /// cuts in the pair's order (operand 1's triangle first where `swap`).
    fn in_plane<N: Num>(&mut self, o: Overlap, swap: bool, soup: &mut Soup<N>) -> Settled {
        if o.points.is_empty() {
            return Settled::Apart;
        }
        let mut points: SmallVec<[usize; 6]> = SmallVec::new();
        for &x in &o.points {
            points.push(match x {
                InPlane::Corner(v) => v,
                InPlane::Edges(e, f) => self.constructed(Site::Edges(e, f), soup, |corners| {
                    corners.crossing(&o.chart, e, f)
                }),
            });
        }
        let mut cuts = o
            .cuts
            .map(|cuts| cuts.iter().map(|&(a, b)| (points[a], points[b])).collect());
        if swap {
            cuts.swap(0, 1);
        }
        Settled::InPlane {
            points,
            cuts,
            area: o.area,
        }
    }

    /// The edges (each by its ends, the smaller first) inside whose open segment each
    /// constructed point lies by its names: a pierce point inside its edge, two edges'
    /// crossing inside both.
    pub(super) fn edges_through(&self) -> HashMap<usize, SmallVec<[Edge; 2]>> {
        let mut through: HashMap<usize, SmallVec<[Edge; 2]>> =
            HashMap::with_capacity(self.made.len());
        for (site, &v) in &self.made {
            let edges: SmallVec<[Edge; 2]> = match *site {
                Site::Pierce(e, _) => SmallVec::from_slice(&[e]),
                Site::Edges(e, f) => SmallVec::from_slice(&[e, f]),
                // An input point: inside no edge, and not to be taken for a named one.
                Site::Vertex(..) => continue,
            };
            through.entry(v).or_default().extend(edges);
        }
        through
    }

    /// The soup's index of the point `end`: an input vertex's own, a constructed point's
    /// made on first sight.
    fn point<N: Num>(&mut self, end: End, soup: &mut Soup<N>) -> usize {
        let (site, edge, tri) = match end {
            End::Corner(x, _) | End::Vertex(x, _) => return x,
            End::Pierce(edge, tri) => (Site::Pierce(edge, tri), edge, tri),
            // The edge that passes through the triangle's plane: the other's if the triangle
            // is the first edge's own (Contact::Along).
            End::Edges(e, f, tri) => {
                match soup.tris[tri].contains(&e.0) && soup.tris[tri].contains(&e.1) {
                    true => (Site::Edges(e, f), f, tri),
                    false => (Site::Edges(e, f), e, tri),
                }
            }
        };
        let tri = soup.tris[tri];
        self.constructed(site, soup, |corners| corners.pierce(edge, tri))
    }

    /// The soup's index of the constructed point `site`, made by `make` from the corners and
    /// interned on first sight.
    fn constructed<N: Num>(
        &mut self,
        site: Site,
        soup: &mut Soup<N>,
        make: impl FnOnce(&C) -> Point3<Rational>,
    ) -> usize {
        if let Some(&v) = self.made.get(&site) {
            return v;
        }
        let p = make(&self.corners);
        let v = soup.intern(&Point3::new(
            N::nearest(&p.x),
            N::nearest(&p.y),
            N::nearest(&p.z),
        ));
        self.made.insert(site, v);
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use crate::yin3::arrange::{arrange_named, f64_values};
    use crate::yin3::corners::{F64Corners, RationalCorners};
    use crate::yin3::geom::in_triangle3;
    use crate::yin3::grid::tests::{point, tetrahedron_over};
    use crate::yin3::meet::{constructed_meet, general_meet};
    use crate::yin3::values::exact_points;
    use crate::yin3::YinSet3;
    use rand::{RngExt, SeedableRng};

    /// A box with corners on the grid of halves in [0, 2]³ joined with a tetrahedron on it where
    /// that is not flat: coplanar faces, edges in the other's planes and crossings in one operand.
    fn operand(rng: &mut rand::rngs::StdRng) -> Option<YinSet3<Rational>> {
        let [x, y] = [0; 2].map(|_| [0; 3].map(|_| rng.random_range(0..=4)));
        let lo = point(x[0].min(y[0]), x[1].min(y[1]), x[2].min(y[2]), 2);
        let hi = point(x[0].max(y[0]), x[1].max(y[1]), x[2].max(y[2]), 2);
        let cuboid = YinSet3::cuboid(&lo, &hi);
        let tetra = tetrahedron_over(rng, &[2])?;
        Some(cuboid.ok()?.join(&tetra))
    }

    /// The set turned by the rotation with cosine 3/5 about the z axis: its coordinates are
    /// no `f64`s, so that its pairs are classified on their rationals.
    fn turned(s: &YinSet3<Rational>) -> YinSet3<Rational> {
        let q = |n: i64| Rational::from_i64(n) / Rational::from_i64(5);
        let points = (s.vertices().iter())
            .map(|p| {
                let x = q(3) * p.x.clone() - q(4) * p.y.clone();
                let y = q(4) * p.x.clone() + q(3) * p.y.clone();
                Point3::new(x, y, p.z.clone())
            })
            .collect();
        let faces = s.triangles().iter().map(|t| t.to_vec()).collect();
        YinSet3::from_triangles(points, faces).expect("a turned set is valid")
    }

    /// Two operands ([`operand`]), [`turned`] where `on_rationals`.
    fn operands(
        rng: &mut rand::rngs::StdRng,
        on_rationals: bool,
    ) -> Option<(YinSet3<Rational>, YinSet3<Rational>)> {
        // Both drawn, so that every round takes the same draws.
        let (a, b) = (operand(rng), operand(rng));
        let (a, b) = (a?, b?);
        Some(match on_rationals {
            true => (turned(&a), turned(&b)),
            false => (a, b),
        })
    }

    /// `f64s` or `rationals` applied to the classification of the soup's `pairs`: on the
    /// points' `f64`s where each is one (as [`arrange_named`] does), on rationals otherwise.
    fn with_named<R>(
        soup: &Soup<Rational>,
        pairs: &[(usize, usize)],
        f64s: impl FnOnce(Named<F64Corners>) -> R,
        rationals: impl FnOnce(Named<RationalCorners>) -> R,
    ) -> R {
        let exact = exact_points(&soup.points);
        match exact.iter().all(Point3::is_f64) {
            true => {
                let (values, floats) = f64_values(&exact);
                f64s(Named::new(F64Corners(values), &floats, soup, pairs))
            }
            false => {
                let corners = RationalCorners::new(exact.clone());
                rationals(Named::new(corners, &exact, soup, pairs))
            }
        }
    }

    /// How the classification takes the pairs of triangles of `a` and `b` (all of them):
    /// counts of crossing pairs, pairs with an edge on the other's plane, pairs with an end on
    /// the other's edge, coplanar pairs overlapping in an area, coplanar pairs whose edges
    /// cross, and open pairs.
    fn contact_counts(a: &YinSet3<Rational>, b: &YinSet3<Rational>) -> [usize; 6] {
        let [a_brep, b_brep] = [a, b].map(|s| s.brep().expect("a boundary"));
        let soup = Soup::of_operands(a_brep, b_brep);
        let pairs = named_pairs(&soup);
        let contacts = with_named(&soup, &pairs, |n| n.contacts, |n| n.contacts);
        let mut counts = [0; 6];
        for c in &contacts {
            match c {
                Class::Of(Contact::Cross(_)) => counts[0] += 1,
                Class::Of(Contact::Along(_)) => counts[1] += 1,
                Class::Of(Contact::OnEdge(_)) => counts[2] += 1,
                Class::InPlane(Some(o)) if o.area => counts[3] += 1,
                Class::Of(Contact::Degenerate) | Class::InPlane(None) => counts[5] += 1,
                _ => {}
            }
            if let Class::InPlane(Some(o)) = c {
                if o.points.iter().any(|x| matches!(x, InPlane::Edges(..))) {
                    counts[4] += 1;
                }
            }
        }
        counts
    }

    /// Every point constructed by name lies inside each edge that [`Named::edges_through`]
    /// gives it, by exact rational arithmetic on the constructed point (collinear with the
    /// edge's ends and strictly between them), on operands with coplanar faces, edges in each
    /// other's planes and crossings, on `f64`s and on rationals; many points lie inside two
    /// edges.
    #[test]
    fn named_points_lie_inside_their_edges() {
        /// The number of (point, edge) facts checked, and of points inside two edges.
        fn check<C: Corners>(mut named: Named<C>, mut soup: Soup<Rational>) -> [usize; 2] {
            for (k, &pair) in named_pairs(&soup).iter().enumerate() {
                named.settled(k, pair, &mut soup);
            }
            let mut counts = [0; 2];
            for (v, edges) in named.edges_through() {
                let x = &soup.points[v];
                for &(p, q) in &edges {
                    let (p, q) = (&soup.points[p], &soup.points[q]);
                    let d = |a: &Point3<Rational>, b: &Point3<Rational>| {
                        [
                            b.x.clone() - a.x.clone(),
                            b.y.clone() - a.y.clone(),
                            b.z.clone() - a.z.clone(),
                        ]
                    };
                    let (u, w) = (d(p, q), d(p, x));
                    let cross = [0, 1, 2].map(|k| {
                        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                        u[i].clone() * w[j].clone() - u[j].clone() * w[i].clone()
                    });
                    let along =
                        (0..3).fold(Rational::zero(), |s, k| s + u[k].clone() * w[k].clone());
                    let length =
                        (0..3).fold(Rational::zero(), |s, k| s + u[k].clone() * u[k].clone());
                    assert!(
                        cross.iter().all(|c| *c == Rational::zero()),
                        "off the edge's line"
                    );
                    assert!(
                        along > Rational::zero() && along < length,
                        "not inside the edge"
                    );
                    counts[0] += 1;
                }
                counts[1] += usize::from(edges.len() == 2);
            }
            counts
        }
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let mut seen = [[0; 2]; 2];
        for round in 0..200 {
            let on_rationals = round % 2;
            let Some((a, b)) = operands(&mut rng, on_rationals == 1) else {
                continue;
            };
            let [a, b] = [&a, &b].map(|s| s.brep().expect("a boundary"));
            let soup = Soup::of_operands(a, b);
            let pairs = named_pairs(&soup);
            let counts = with_named(
                &soup,
                &pairs,
                |n| check(n, soup.clone()),
                |n| check(n, soup.clone()),
            );
            for k in 0..2 {
                seen[k][on_rationals] += counts[k];
            }
        }
        assert!(seen.iter().flatten().all(|&n| n >= 100), "{seen:?}");
    }

    /// The arrangement of a meet's operands with pairs settled by name gives every contact
    /// point to every triangle holding it (it is a corner of one of the triangle's pieces),
    /// by exact tests of every point against every triangle: on operands with coplanar faces,
    /// edges in each other's planes and crossings, on `f64`s and on rationals, with many
    /// constructed points (those named inside edges the arrangement does not distribute).
    #[test]
    fn every_contact_point_is_a_corner_of_the_triangles_holding_it() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let mut constructed = [0; 2];
        for round in 0..200 {
            let on_rationals = round % 2;
            let Some((a, b)) = operands(&mut rng, on_rationals == 1) else {
                continue;
            };
            let [a, b] = [&a, &b].map(|s| s.brep().expect("a boundary"));
            let mut soup = Soup::of_operands(a, b);
            let inputs = soup.points.len();
            let arrangement = arrange_named(&mut soup, &()).expect("an arrangement");
            let mut corners: Vec<Vec<usize>> = vec![Vec::new(); soup.tris.len()];
            for (piece, parent) in &arrangement.pieces {
                corners[*parent].extend(piece);
            }
            for v in (0..soup.points.len()).filter(|&v| arrangement.contact[v]) {
                for (t, pieces) in corners.iter().enumerate() {
                    if in_triangle3(soup.corners(t), &soup.points[v], &()) {
                        assert!(pieces.contains(&v), "round {round}: {v} not in {t}");
                    }
                }
                constructed[on_rationals] += usize::from(v >= inputs);
            }
        }
        assert!(constructed.iter().all(|&n| n >= 200), "{constructed:?}");
    }

    /// Every pair of a soup's triangles of different operands, the smaller index first.
    fn named_pairs(soup: &Soup<Rational>) -> Vec<(usize, usize)> {
        let first_b = soup
            .operand
            .iter()
            .position(|&o| o == 1)
            .unwrap_or(soup.tris.len());
        (0..first_b)
            .flat_map(|i| (first_b..soup.tris.len()).map(move |j| (i, j)))
            .collect()
    }

    /// Operands with coplanar faces, edges in each other's planes and crossings, on the grid
    /// of halves (classified on `f64`s) and turned by a rational rotation (on rationals), and
    /// their complements: the meet with pairs settled by name equals the meet with every
    /// contact constructed; the classification leaves no pair open, and crossing pairs, pairs
    /// with an edge on the other's plane, pairs with an end on the other's edge, coplanar pairs
    /// overlapping in an area and coplanar pairs whose edges cross each occur in many meets.
    #[test]
    fn named_contacts_meet_as_constructed_ones() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(53);
        // Meets with crossing pairs, with pairs along a plane, with ends on edges, with coplanar
        // overlaps and with coplanar edges crossing, on f64s and on rationals.
        let mut seen = [[0; 2]; 5];
        for round in 0..600 {
            let on_rationals = round % 2;
            let Some((a, b)) = operands(&mut rng, on_rationals == 1) else {
                continue;
            };
            for (x, y) in [(&a, b.clone()), (&a, b.complement())] {
                if x.is_empty() || y.is_empty() {
                    continue;
                }
                assert_eq!(
                    general_meet(x, &y),
                    constructed_meet(x, &y),
                    "round {round}"
                );
                let [cross, along, on_edge, area, edges, open] = contact_counts(x, &y);
                assert_eq!(open, 0, "round {round}");
                let kinds = [cross, along, on_edge, area, edges].map(|n| n > 0);
                for (k, _) in kinds.iter().enumerate().filter(|(_, &on)| on) {
                    seen[k][on_rationals] += 1;
                }
            }
        }
        assert!(seen.iter().flatten().all(|&n| n >= 40), "{seen:?}");
    }
}
