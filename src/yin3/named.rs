//! The contacts of a meet's arrangement that the transversal meet's classification settles
//! ([`super::contact`]; yin3 docs: *Meet*), and those with an edge in the other's plane
//! ([`Contact::Along`], which the transversal meet declines): decided from exact orientations
//! of the input vertices alone (`f64` filters and stack integers where every vertex is an
//! `f64`, filtered rational orientations otherwise), each end named by what defines it
//! ([`Site`]) and constructed once however many pairs find it. The other pairs — coplanar, a
//! vertex on an edge or on an edge's line, a shared corner with a coplanar edge — are left to
//! the arrangement's constructed contacts ([`super::tri`]); both give exact points, interned
//! by value into one table.

use super::arrange::Soup;
use super::contact::{contact, Contact, End, Site};
use super::corners::Corners;
use super::transversal::{map_all, PARALLEL_FROM};
use crate::kernel::Point3;
use crate::num::Num;
use foldhash::{HashMap, HashMapExt};
use std::cmp::Ordering;

/// What the classification settled about a pair of triangles, in the soup's points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Settled {
    /// Disjoint.
    Apart,
    /// Meeting only in these shared corners (one twice for a corner).
    Touch([usize; 2]),
    /// Crossing between these two points (one twice where they meet in one point).
    Cross([usize; 2]),
    /// Not settled: the arrangement's constructed contacts decide.
    Open,
}

/// Pairs classified at a time; classification stops once the open pairs of the chunks so far
/// outnumber a chunk plus sixteen times the pairs settled as crossing (operands that share faces
/// throughout, where it would only add work), and the remaining pairs are left open.
const CHUNK: usize = 2048;

/// The meeting pairs' contacts as the transversal meet's classification finds them, with
/// each constructed end's index in the soup once made.
pub(super) struct Named<C: Corners> {
    corners: C,
    contacts: Vec<Contact>,
    made: HashMap<Site, usize>,
}

impl<C: Corners> Named<C> {
    /// The contacts of the pairs `meeting` of the soup's triangles (of different operands),
    /// on `corners`, the soup's points so far (its input vertices) with their exact tests, and
    /// `values`, the same points as numbers whose exact predicates are as cheap (their `f64`s
    /// where they are `f64`s). Coplanar pairs are left open at once: the classification never
    /// settles them. Pairs past the classified ones ([`CHUNK`]) are open.
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
                return Contact::Degenerate;
            }
            let both = [&planes[t], &planes[s]];
            contact(&corners, both, &points, (t, tris[t]), (s, tris[s]))
        };
        // Chunk by chunk, until open pairs outnumber the settled crossings by far.
        let mut contacts: Vec<Contact> = Vec::with_capacity(meeting.len());
        let (mut open, mut crossed) = (0, 0);
        for chunk in meeting.chunks(CHUNK) {
            if open > CHUNK + 16 * crossed {
                break;
            }
            for c in map_all(chunk, parallel, classify) {
                match c {
                    Contact::Degenerate => open += 1,
                    Contact::Cross(_) | Contact::Along(_) => crossed += 1,
                    _ => {}
                }
                contacts.push(c);
            }
        }
        Named {
            corners,
            made: HashMap::with_capacity(meeting.len()),
            contacts,
        }
    }

    /// What the classification settled about the `k`th meeting pair, its constructed ends
    /// made and interned into `soup` on first sight.
    pub(super) fn settled<N: Num>(&mut self, k: usize, soup: &mut Soup<N>) -> Settled {
        let Some(&contact) = self.contacts.get(k) else {
            return Settled::Open;
        };
        match contact {
            Contact::Apart => Settled::Apart,
            Contact::Touch([x, y]) => Settled::Touch([x[0], y[0]]),
            Contact::Cross(ends) | Contact::Along(ends) => {
                Settled::Cross(ends.map(|end| self.point(end, soup)))
            }
            Contact::Degenerate => Settled::Open,
        }
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
        if let Some(&v) = self.made.get(&site) {
            return v;
        }
        let p = self.corners.pierce(edge, soup.tris[tri]);
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
    use crate::yin3::arrange::f64_values;
    use crate::yin3::corners::{F64Corners, RationalCorners};
    use crate::yin3::grid::tests::{point, tetrahedron_over};
    use crate::yin3::meet::{constructed_meet, general_meet};
    use crate::yin3::values::exact_points;
    use crate::yin3::YinSet3;
    use rand::{RngExt, SeedableRng};

    /// A box with corners on the grid of halves in [0, 2]³ joined with a tetrahedron on it where that is
    /// not flat: coplanar faces, edges in the other's planes and crossings in one operand.
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

    /// How the classification takes the pairs of triangles of `a` and `b` (all of them):
    /// counts of crossing pairs, pairs with an edge on the other's plane, and open pairs.
    fn contact_counts(a: &YinSet3<Rational>, b: &YinSet3<Rational>) -> [usize; 3] {
        let [a_brep, b_brep] = [a, b].map(|s| s.brep().expect("a boundary"));
        let soup = Soup::of_operands(a_brep, b_brep);
        let first_b = a.triangles().len();
        let pairs: Vec<(usize, usize)> = (0..first_b)
            .flat_map(|i| (first_b..soup.tris.len()).map(move |j| (i, j)))
            .collect();
        let exact = exact_points(&soup.points);
        let contacts = match exact.iter().all(Point3::is_f64) {
            true => {
                let (f64s, floats) = f64_values(&exact);
                Named::new(F64Corners(f64s), &floats, &soup, &pairs).contacts
            }
            false => {
                let corners = RationalCorners::new(exact.clone());
                Named::new(corners, &exact, &soup, &pairs).contacts
            }
        };
        let mut counts = [0; 3];
        for c in contacts {
            match c {
                Contact::Cross(_) => counts[0] += 1,
                Contact::Along(_) => counts[1] += 1,
                Contact::Degenerate => counts[2] += 1,
                _ => {}
            }
        }
        counts
    }

    /// A soup of two fans of 100 triangles about the origin, operand 1's in the plane z = 0
    /// with operand 0's (`flat`) or tilted through it, and every pair of them.
    fn fans(flat: bool) -> (Soup<Rational>, Vec<(usize, usize)>) {
        let mut soup = Soup::new();
        for operand in 0..2u8 {
            let lift = i64::from(operand == 1 && !flat);
            for k in 0..100 {
                let rim = |k: i64| point(100 + k, 1 + k * k, lift * (k - 50), 1);
                let (a, b) = (rim(k), rim(k + 1));
                soup.push([&point(0, 0, 0, 1), &a, &b], operand);
            }
        }
        let pairs = (0..100).flat_map(|i| (100..200).map(move |j| (i, j)));
        (soup, pairs.collect())
    }

    /// Classification stops where open pairs outnumber the crossings by far (two coplanar
    /// fans: all open, two chunks classified of 10⁴ pairs), and goes on where they cross.
    #[test]
    fn classification_stops_where_it_settles_nothing() {
        for (flat, classified) in [(true, 2 * CHUNK), (false, 10_000)] {
            let (soup, pairs) = fans(flat);
            let (f64s, floats) = f64_values(&soup.points);
            let named = Named::new(F64Corners(f64s), &floats, &soup, &pairs);
            assert_eq!(named.contacts.len(), classified, "flat {flat}");
        }
    }

    /// Operands with coplanar faces, edges in each other's planes and crossings, on the grid
    /// of halves (classified on `f64`s) and turned by a rational rotation (on rationals), and
    /// their complements: the meet with pairs settled by name equals the meet with every
    /// contact constructed, and crossing pairs and open pairs occur together in many of the
    /// meets, pairs with an edge on the other's plane in many too.
    #[test]
    fn named_contacts_meet_as_constructed_ones() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(53);
        // Meets with crossing and open pairs, and with pairs along a plane, on f64s and on
        // rationals.
        let (mut mixed, mut alongs) = ([0; 2], [0; 2]);
        for round in 0..600 {
            let (Some(a), Some(b)) = (operand(&mut rng), operand(&mut rng)) else {
                continue;
            };
            let on_rationals = round % 2;
            let (a, b) = match on_rationals {
                1 => (turned(&a), turned(&b)),
                _ => (a, b),
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
                let [cross, along, open] = contact_counts(x, &y);
                if cross > 0 && open > 0 {
                    mixed[on_rationals] += 1;
                }
                if along > 0 {
                    alongs[on_rationals] += 1;
                }
            }
        }
        let many = |n: &[usize; 2]| n.iter().all(|&n| n >= 40);
        assert!(many(&mixed) && many(&alongs), "{mixed:?} {alongs:?}");
    }
}
