//! The complement of a 3D boundary representation from the set's own structure (seed 000
//! Def. 4.4 in 3D; yin3 docs: *Data model*): the same triangles reversed, with their fins,
//! glued surfaces, Hasse diagram and atoms derived combinatorially.

use super::fins::Pairing;
use super::glue::glued_surfaces;
use super::hasse::{atoms, hasse, Hasse};
use super::set::{genera, surfaces, Brep};
use super::values::exact_points;
use crate::num::Num;
use std::sync::OnceLock;

impl<N: Num> Brep<N> {
    /// The boundary of the complement (seed 000 Def. 4.4 in 3D): every triangle reversed, its
    /// structure derived from the set's in linear time, without a predicate where the glued
    /// surfaces stay the same.
    ///
    /// * Fins: the same rotation order about each edge, each fin turned ([`FinTable::reversed`](super::fins::FinTable::reversed)).
    /// * Glued surfaces: those of the turned table ([`glued_surfaces`] is combinatorial; on it
    ///   the pairing that bounds the complement is the one that bounded the set on the set's
    ///   table). Genera likewise ([`genera`]).
    /// * Where the surfaces are the set's (the same triangles in each, as whenever every edge
    ///   has two fins: both pairings of two fins are the same): the Hasse diagram is the same,
    ///   since a surface's parent depends on the surfaces as point sets alone (the absolute
    ///   values of their signed volumes, their boxes, and whether a winding number is zero,
    ///   all unchanged when every triangle is reversed); each orientation flips, since
    ///   reversing every triangle negates the signed volume (Def. 7.3), and the atoms follow
    ///   from the orientations and the diagram ([`atoms`]). Otherwise the new surfaces' Hasse
    ///   diagram is computed again by exact predicates ([`hasse`]).
    /// * Boundedness flips: the total signed volume is negated, whatever the grouping.
    pub(crate) fn complement(&self) -> Brep<N> {
        let tris: Vec<[usize; 3]> = self.tris.iter().map(|&[p, q, r]| [p, r, q]).collect();
        let table = self.table.reversed();
        let (label, count) = glued_surfaces(&table, tris.len(), Pairing::Inside);
        let genus = genera(&tris, &table, &label, count);
        // Labels are numbered in order of first triangle, as the set's surfaces are.
        let same = count == self.surfaces.len()
            && (self.surfaces.iter().enumerate())
                .all(|(s, surface)| surface.triangles.iter().all(|&t| label[t] == s));
        let (positive, parent, atoms) = if same {
            let positive: Vec<bool> = self.surfaces.iter().map(|s| !s.positive).collect();
            let atoms = atoms(&positive, &self.parent);
            (positive, self.parent.clone(), atoms)
        } else {
            let h = self.exact_hasse(&tris, &label, count);
            (h.positive, h.parent, h.atoms)
        };
        Brep {
            points: self.points.clone(),
            surfaces: surfaces(&label, count, &positive, &genus),
            tris,
            table,
            parent,
            atoms,
            bounded: !self.bounded,
            betti: OnceLock::new(),
            canon: OnceLock::new(),
        }
    }

    /// The Hasse diagram of the surfaces `label` of the triangles `tris` over this boundary's
    /// points, by exact predicates (of the `f64` values read as rationals in float mode).
    fn exact_hasse(&self, tris: &[[usize; 3]], label: &[usize], count: usize) -> Hasse {
        if N::EXACT {
            hasse(&self.points, tris, label, count, &N::exact_ctx())
        } else {
            hasse(&exact_points(&self.points), tris, label, count, &())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::fins::FinTable;
    use super::super::shapes::{concat, cuboid, Mesh};
    use super::*;
    use crate::kernel::Point3;
    use crate::num::{Float, Rational};
    use crate::yin3::YinSet3;
    use rand::rngs::StdRng;
    use rand::{RngExt, SeedableRng};
    use std::collections::BTreeMap;
    use yinset_testkit::cells::{full_mask, Cells};
    use yinset_testkit::cells3::Grid3;
    use yinset_testkit::rotation::{Rot, GENERAL};

    /// Each edge's fins as (triangle, apex, forward), keyed by the edge's endpoints.
    type Rotations = BTreeMap<(usize, usize), Vec<(usize, usize, bool)>>;

    /// Each edge's fins in counterclockwise order about the edge, starting at the smallest
    /// triangle, in the vertex numbering `to` (edge endpoints in increasing order, the rotation
    /// and directions turned where `to` swaps them).
    fn rotations(table: &FinTable, to: &[usize]) -> Rotations {
        (table.edges.iter().zip(table.fin_lists()))
            .map(|(&(a, b), fins)| {
                let (a, b) = (to[a], to[b]);
                let swap = a > b;
                let mut fins: Vec<(usize, usize, bool)> = fins
                    .iter()
                    .map(|f| (f.tri, to[f.apex], f.forward != swap))
                    .collect();
                if swap {
                    fins.reverse();
                }
                let first = (0..fins.len()).min_by_key(|&i| fins[i].0).unwrap_or(0);
                fins.rotate_left(first);
                ((a.min(b), a.max(b)), fins)
            })
            .collect()
    }

    /// The complement of `b` derived from its structure equals, field by field, the
    /// complement assembled from scratch from the reversed triangles (fins, surfaces with their
    /// orientations and genera, Hasse diagram, atoms, boundedness, Betti numbers); true if its
    /// glued surfaces are not the set's.
    fn check<N: Num>(b: &Brep<N>, what: &str) -> bool {
        let new = b.complement();
        let reversed = b.tris.iter().map(|&[p, q, r]| [p, r, q]).collect();
        let old = Brep::assemble(b.points.clone(), reversed)
            .unwrap_or_else(|e| panic!("{what}: the reversed boundary is refused: {e}"));
        // Assembly renumbers the vertices in order of first use: the same triangles, in order.
        let mut to = vec![usize::MAX; old.points.len()];
        assert_eq!(new.tris.len(), old.tris.len(), "{what}");
        for (t, u) in new.tris.iter().zip(&old.tris) {
            for (&v, &w) in t.iter().zip(u) {
                assert!(to[w] == usize::MAX || to[w] == v, "{what}: renumbering");
                to[w] = v;
                assert_eq!(new.points[v], old.points[w], "{what}: vertex {v}");
            }
        }
        let same: Vec<usize> = (0..new.points.len()).collect();
        assert_eq!(
            rotations(&new.table, &same),
            rotations(&old.table, &to),
            "{what}: fins"
        );
        assert_eq!(new.surfaces, old.surfaces, "{what}: surfaces");
        assert_eq!(new.parent, old.parent, "{what}: Hasse diagram");
        assert_eq!(new.atoms, old.atoms, "{what}: atoms");
        assert_eq!(new.bounded, old.bounded, "{what}: boundedness");
        assert_eq!(new.betti(), old.betti(), "{what}: Betti numbers");
        assert_eq!(new.bounded, !b.bounded, "{what}: boundedness flips");
        let partition = |b: &Brep<N>| -> Vec<Vec<usize>> {
            b.surfaces.iter().map(|s| s.triangles.clone()).collect()
        };
        partition(&new) != partition(b)
    }

    /// The boundary of the set that `mesh` bounds, exactly and in float mode (its coordinates
    /// rounded, its faces fans of triangles, which rounding keeps flat), each complemented by
    /// [`check`]; how many regrouped their surfaces.
    fn check_both(mesh: &Mesh<Rational>, what: &str) -> usize {
        let exact = YinSet3::from_triangles(mesh.0.clone(), mesh.1.clone())
            .unwrap_or_else(|e| panic!("{what}: refused: {e}"));
        let fans = (mesh.1.iter())
            .flat_map(|f| (1..f.len() - 1).map(|k| vec![f[0], f[k], f[k + 1]]))
            .collect();
        let near = |p: &Point3<Rational>| {
            Point3::new(
                Float::nearest(&p.x),
                Float::nearest(&p.y),
                Float::nearest(&p.z),
            )
        };
        let rounded = mesh.0.iter().map(near).collect();
        let float = YinSet3::<Float>::from_triangles(rounded, fans)
            .unwrap_or_else(|e| panic!("{what}: refused in float mode: {e}"));
        let exact = exact
            .brep()
            .map_or(0, |b| usize::from(check(b, &format!("{what}, exact"))));
        exact
            + float
                .brep()
                .map_or(0, |b| usize::from(check(b, &format!("{what}, float"))))
    }

    /// The integer box [lo, lo + size].
    fn cube(lo: [i64; 3], size: i64) -> Mesh<Rational> {
        let p = |k: i64| Point3::int(lo[0] + k, lo[1] + k, lo[2] + k);
        cuboid(&p(0), &p(size))
    }

    /// The faces of `mesh` turned inside out (the complement's boundary of a box: a cavity).
    fn inverted((points, faces): Mesh<Rational>) -> Mesh<Rational> {
        let faces = faces
            .into_iter()
            .map(|f| f.into_iter().rev().collect())
            .collect();
        (points, faces)
    }

    /// Boxes alone and touching, nested cavities and islands, a cavity touching its outer
    /// surface, and their complements (through the set's unbounded form).
    #[test]
    fn boxes_touching_and_nested() {
        let cases: Vec<(&str, Mesh<Rational>)> = vec![
            ("a box", cube([0, 0, 0], 1)),
            (
                "two boxes sharing an edge",
                concat(vec![cube([0, 0, 0], 1), cube([1, 1, 0], 1)]),
            ),
            (
                "two boxes sharing a vertex",
                concat(vec![cube([0, 0, 0], 1), cube([1, 1, 1], 1)]),
            ),
            (
                "two disjoint boxes",
                concat(vec![cube([0, 0, 0], 1), cube([3, 0, 0], 1)]),
            ),
            (
                "a cavity with an island with a cavity",
                concat(vec![
                    cube([0, 0, 0], 9),
                    inverted(cube([1, 1, 1], 7)),
                    cube([2, 2, 2], 5),
                    inverted(cube([3, 3, 3], 3)),
                ]),
            ),
            (
                "two cavities sharing an edge",
                concat(vec![
                    cube([0, 0, 0], 5),
                    inverted(cube([1, 1, 1], 1)),
                    inverted(cube([2, 2, 1], 1)),
                ]),
            ),
            (
                "the unbounded set outside two boxes sharing a vertex",
                inverted(concat(vec![cube([0, 0, 0], 1), cube([1, 1, 1], 1)])),
            ),
        ];
        for (what, mesh) in &cases {
            check_both(mesh, what);
        }
    }

    /// Every union of cells of a 2×2×2 grid, with the exterior or not, axis-aligned and turned
    /// into general position (cells sharing only an edge or a vertex, cavities, tori); unions
    /// of random cells of 3×3×3 and 4×4×2 grids (nested cavities, surfaces touching
    /// themselves). Some of them regroup their surfaces, so both paths run (one such set is
    /// named, in both modes).
    #[test]
    fn cell_sets_from_the_test_kit() {
        let mut rng = StdRng::seed_from_u64(54);
        let grids = [
            (Grid3::cube(2), None),
            (Grid3::cube(2).rotated(Rot::Quaternion(GENERAL)), None),
            (Grid3::cube(3), Some(0)),
            (Grid3::cube(3), Some(150)),
            (Grid3::grid(4, 4, 2), Some(150)),
        ];
        let (mut sets, mut regrouped) = (0, 0);
        for (grid, random) in grids {
            let masks: Vec<Cells> = match random {
                None => grid.all(true),
                // Found by the random masks: the exterior with 14 cells whose complement's
                // surfaces are two, as the set's, but other triangles in each.
                Some(0) => vec![Cells::new(20884388, true)],
                Some(n) => (0..n)
                    .map(|_| {
                        let bits = rng.random::<u64>() & full_mask(grid.len());
                        Cells::new(bits, rng.random::<bool>())
                    })
                    .collect(),
            };
            for s in masks {
                let (points, faces) = grid.mesh(s);
                if faces.is_empty() {
                    continue;
                }
                // The kit's points are of its own build of the crate: carried over as text.
                let points = (points.into_iter())
                    .map(|p| {
                        let q = grid.point(p.map(|c| 2 * c));
                        let c = |c: &dyn ToString| Rational::parse(&c.to_string()).expect("p/q");
                        Point3::new(c(&q.x), c(&q.y), c(&q.z))
                    })
                    .collect();
                regrouped += check_both(&(points, faces), &format!("{s:?} of {}", grid.name));
                sets += 2;
            }
        }
        eprintln!("{sets} sets complemented, {regrouped} with regrouped surfaces");
        assert!(regrouped >= 2, "the regrouping case is not regrouped");
    }
}
