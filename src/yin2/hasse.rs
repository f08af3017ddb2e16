//! The Hasse diagram of a realizable spadjor (seed 002 Alg. 3), its atoms (seed 000 Lemma 3.18,
//! R2A-a/b) and Betti numbers (seed 000 Cor. 3.14).

use super::curve::Curve;
use super::locate::{locate_by_crossings, locate_in_edges, Location};
use crate::kernel::{BBox, Point};
use crate::num::Num;

/// An atom spadjor (seed 000 Def. 3.16): at most one positive curve and the negative curves
/// directly inside it, as indices into the spadjor's curves.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Atom {
    /// The positively oriented curve γ⁺ (`None` for the unbounded atom 𝒥⁻).
    pub outer: Option<usize>,
    /// The negatively oriented curves γ⁻ (the holes).
    pub holes: Vec<usize>,
}

/// Betti numbers of a Yin set as seed 000 Cor. 3.14 counts them: connected components and the
/// negatively oriented curves (holes) of each. A hole pinched to its outer curve at a point
/// counts, unlike in homology: [`super::YinSet2::homology`] gives the homological b₀, b₁.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Betti {
    /// b₀: the number of connected components.
    pub components: usize,
    /// The holes of each component (seed b₁), in the order of [`super::YinSet2::atoms`].
    pub holes: Vec<usize>,
    /// The total number of holes (seed b₁; not homological where holes touch).
    pub total_holes: usize,
}

impl Betti {
    /// The Betti numbers of a set whose atoms are `atoms`.
    pub(crate) fn of_atoms(atoms: &[Atom]) -> Betti {
        let holes: Vec<usize> = atoms.iter().map(|a| a.holes.len()).collect();
        Betti {
            components: atoms.len(),
            total_holes: holes.iter().sum(),
            holes,
        }
    }
}

/// Up to this many curves to locate inside one curve, each is located by one pass over its
/// edges rather than by a sweep of them.
const FEW_QUERIES: usize = 16;

/// Parent of each curve in the Hasse diagram of inclusion (seed 002 Alg. 3): the smallest curve
/// whose bounded region contains it. Curves must be pairwise almost disjoint with every touching
/// point a vertex of each curve through it. The curves containing a curve form a chain, so the
/// smallest of them is the one that lies inside the most curves (no areas are compared: exact
/// areas of curves through many crossing points are numbers of ever-growing size).
pub(crate) fn parents<N: Num>(curves: &[Curve<N>], ctx: &N::Ctx) -> Vec<Option<usize>> {
    let m = curves.len();
    let boxes: Vec<BBox<N>> = curves.iter().map(|c| c.bbox()).collect();
    let samples: Vec<Point<N>> = curves.iter().map(|c| c.sample()).collect();
    // Curves by the left side of their boxes: a curve inside curve i has its left side in
    // [left(i), right(i)].
    let mut by_left: Vec<usize> = (0..m).collect();
    by_left.sort_by(|&a, &b| boxes[a].min.x.cmp(&boxes[b].min.x));
    let mut containing: Vec<Vec<usize>> = vec![Vec::new(); m];
    for i in 0..m {
        let from = by_left.partition_point(|&j| boxes[j].min.x < boxes[i].min.x);
        let to = by_left.partition_point(|&j| boxes[j].min.x <= boxes[i].max.x);
        let candidates: Vec<usize> = by_left[from..to]
            .iter()
            .copied()
            .filter(|&j| j != i && boxes[i].contains_box(&boxes[j]))
            .collect();
        if candidates.is_empty() {
            continue;
        }
        let queries: Vec<Point<N>> = candidates.iter().map(|&j| samples[j].clone()).collect();
        let ccw = curves[i].is_positive();
        let edges: Vec<(&Point<N>, &Point<N>)> = curves[i]
            .edges()
            .map(|(a, b)| if ccw { (a, b) } else { (b, a) })
            .collect();
        let located = if queries.len() <= FEW_QUERIES {
            (queries.iter())
                .map(|q| locate_by_crossings(&edges, q, ctx))
                .collect()
        } else {
            locate_in_edges(&edges, false, &queries, ctx)
        };
        for (&j, loc) in candidates.iter().zip(located) {
            if loc == Location::Inside {
                containing[j].push(i);
            }
        }
    }
    containing
        .iter()
        .map(|c| c.iter().copied().max_by_key(|&i| containing[i].len()))
        .collect()
}

/// Parent of each loop in the Hasse diagram (seed 002 Alg. 3) from the plane sweep that made
/// its pieces, with no point located: pieces `0..` in the order the sweep opened them,
/// `loop_of[e]` the loop of piece `e`, `below[e]` the piece directly below the lower end of `e`
/// as it leaves (`None` for the far face), `ascending(e)` if `e` runs from its lower end to its
/// upper one in sweep order (the set's interior above it). Loops must be Jordan curves,
/// pairwise almost disjoint, bounding a Yin set.
///
/// The first piece f of a loop leaves the loop's first vertex in sweep order, below the other
/// piece that does; the loop's bounded region is the wedge above f, so the loop is positive iff
/// f ascends, and the face below f lies outside it. That face lies on the upper side of
/// k = `below[f]`, on a loop D opened earlier. The curves containing the loop are those
/// containing that face: D and the curves containing D if D's bounded region lies above k (D
/// positive iff k ascends), else the curves containing D. Cost: O(pieces).
pub(crate) fn swept_parents(
    loop_of: &[usize],
    below: &[Option<usize>],
    ascending: impl Fn(usize) -> bool,
    loops: usize,
) -> Vec<Option<usize>> {
    let mut first = vec![usize::MAX; loops];
    let mut parent = vec![None; loops];
    for (f, &l) in loop_of.iter().enumerate() {
        if first[l] != usize::MAX {
            continue;
        }
        first[l] = f;
        parent[l] = below[f].and_then(|k| {
            let d = loop_of[k];
            if ascending(first[d]) == ascending(k) {
                Some(d)
            } else {
                parent[d]
            }
        });
    }
    parent
}

/// The atoms of a realizable spadjor (seed 000 Lemma 3.18): R2A-a, each positive curve with the
/// negative curves it covers; R2A-b, the remaining negative curves as one atom 𝒥⁻.
pub(crate) fn atoms(positive: &[bool], parent: &[Option<usize>]) -> Vec<Atom> {
    let mut atoms: Vec<Atom> = Vec::new();
    let mut atom_of = vec![usize::MAX; positive.len()];
    for (i, &pos) in positive.iter().enumerate() {
        if pos {
            atom_of[i] = atoms.len();
            atoms.push(Atom {
                outer: Some(i),
                holes: Vec::new(),
            });
        }
    }
    let mut unbounded = Atom {
        outer: None,
        holes: Vec::new(),
    };
    for (j, &pos) in positive.iter().enumerate() {
        if pos {
            continue;
        }
        match parent[j] {
            Some(p) if positive[p] => atoms[atom_of[p]].holes.push(j),
            _ => unbounded.holes.push(j),
        }
    }
    if !unbounded.holes.is_empty() {
        atoms.push(unbounded);
    }
    atoms
}

#[cfg(test)]
mod tests {
    use super::parents;
    use crate::kernel::Point;
    use crate::num::{Float, Num, Rational, Tolerance};
    use crate::yin2::set::Repr;
    use crate::yin2::{FillRule, YinSet2};
    use proptest::prelude::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    fn ring(c: &[(i64, i64)]) -> Vec<Point<Rational>> {
        c.iter().map(|&(x, y)| Point::int(x, y)).collect()
    }

    #[test]
    fn a_hole_and_an_island_hang_below_their_curves() {
        // A square with a square hole holding a square island, and a separate square.
        let y = YinSet2::<Rational>::from_curves(vec![
            ring(&[(0, 0), (9, 0), (9, 9), (0, 9)]),
            ring(&[(1, 1), (1, 8), (8, 8), (8, 1)]),
            ring(&[(3, 3), (6, 3), (6, 6), (3, 6)]),
            ring(&[(20, 0), (21, 0), (21, 1), (20, 1)]),
        ])
        .expect("a valid set");
        let (curves, parents) = (y.curves(), y.parents());
        assert_eq!(parents.len(), 4);
        let index = |x: i64| {
            curves
                .iter()
                .position(|c| c.vertices().iter().any(|p| p.x == Rational::from_i64(x)))
                .expect("a curve")
        };
        let (outer, hole, island, apart) = (index(0), index(1), index(3), index(20));
        assert_eq!(parents[outer], None);
        assert_eq!(parents[apart], None);
        assert_eq!(parents[hole], Some(outer));
        assert_eq!(parents[island], Some(hole));
        assert!(YinSet2::<Rational>::empty().parents().is_empty());
    }

    /// Up to six rings on an 18 × 12 lattice, each a square about one of two centres (squares
    /// about one centre nest into holes and islands) or a polygon of 3 to 6 points (which
    /// cross the squares, touch them and each other), in either orientation.
    fn nesting_rings() -> impl Strategy<Value = Vec<Vec<Point<Rational>>>> {
        let square = (0i64..2, 1i64..5, any::<bool>()).prop_map(|(i, r, turn)| {
            let (x, y) = (4 + 9 * i, 6);
            let mut s = ring(&[
                (x - r, y - r),
                (x + r, y - r),
                (x + r, y + r),
                (x - r, y + r),
            ]);
            if turn {
                s.reverse();
            }
            s
        });
        let point = (0i64..18, 0i64..13).prop_map(|(x, y)| Point::int(x, y));
        let polygon = proptest::collection::vec(point, 3..7);
        proptest::collection::vec(prop_oneof![4 => square, 1 => polygon], 1..7)
    }

    /// The parents stored with `y`, checked against [`parents`] (which locates a point of each
    /// curve in the curves around it); the depth of the deepest curve, and whether two curves
    /// touch.
    fn check_parents<N: Num>(y: &YinSet2<N>) -> (usize, bool) {
        let ctx = N::Ctx::default();
        let Repr::Spadjor(s) = &y.repr else {
            return (0, false);
        };
        assert_eq!(s.parent, parents(&s.curves, &ctx), "{:?}", s.curves);
        let depth = |mut i: usize| {
            let mut d = 0;
            while let Some(p) = s.parent[i] {
                (i, d) = (p, d + 1);
            }
            d
        };
        let mut vertices: Vec<&Point<N>> = s.curves.iter().flat_map(|c| c.vertices()).collect();
        vertices.sort();
        let touch = vertices.windows(2).any(|w| w[0] == w[1]);
        ((0..s.curves.len()).map(depth).max().unwrap_or(0), touch)
    }

    /// Every fill (exact and float, non-zero and even-odd) comes out of the plane sweep with
    /// its Hasse diagram ([`super::swept_parents`]): it equals the located one, on inputs whose
    /// curves nest two deep and touch.
    #[test]
    fn the_swept_hasse_diagram_is_the_located_one() {
        let mut runner = TestRunner::deterministic();
        let strategy = nesting_rings();
        let (mut deep, mut touching) = (0, 0);
        for _ in 0..600 {
            let rings = strategy.new_tree(&mut runner).expect("a case").current();
            let float: Vec<Vec<Point<Float>>> = (rings.iter())
                .map(|r| {
                    r.iter()
                        .map(|p| p.to_f64())
                        .map(|[x, y]| Point::new(Float::new(x), Float::new(y)))
                        .collect()
                })
                .collect();
            for rule in [FillRule::NonZero, FillRule::EvenOdd] {
                let exact = YinSet2::from_rings_filled(rings.clone(), rule).expect("finite");
                let (depth, touch) = check_parents(&exact);
                deep += usize::from(depth >= 2);
                touching += usize::from(touch);
                let eps = Tolerance::new(0.25);
                check_parents(
                    &YinSet2::from_rings_filled_with(float.clone(), rule, eps).expect("finite"),
                );
            }
        }
        assert!(
            deep >= 40 && touching >= 40,
            "{deep} nested two deep, {touching} touching"
        );
    }
}
