//! Construction from point arrays with no inclusion relations given (seed 000 §5.1): checks
//! that the curves form a realizable spadjor (Def. 3.15–3.17) and builds its Hasse diagram.

use super::error::YinError;
use super::intersect::{intersections, Edge};
use super::set::{Spadjor, YinSet2};
use super::stage::{bounded_by, resolve_for};
use crate::kernel::{cmp_clockwise_from, Contact, Point};
use crate::num::{Num, Rational};
use crate::union_find::UnionFind;
use foldhash::{HashMap, HashMapExt, HashSet, HashSetExt};
use std::cmp::Ordering;

impl<N: Num> YinSet2<N> {
    /// The Yin set bounded by `curves` (each a vertex cycle; a repeated closing vertex is
    /// dropped), with the default context (float mode: ε from the input's extent).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::Rational, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| vec![Point::int(x, y), Point::int(x + s, y), Point::int(x + s, y + s), Point::int(x, y + s)];
    /// let a = YinSet2::<Rational>::from_curves(vec![sq(0, 0, 2)]).unwrap();
    /// let b = YinSet2::<Rational>::from_curves(vec![sq(1, 1, 2)]).unwrap();
    /// assert_eq!((&a & &b).area(), Some(Rational::from_integer(1.into())));
    /// assert_eq!((&a | &b).betti().components, 1);
    /// ```
    pub fn from_curves(curves: Vec<Vec<Point<N>>>) -> Result<YinSet2<N>, YinError> {
        YinSet2::from_curves_with(curves, N::Ctx::default())
    }

    /// As [`YinSet2::from_curves`], with the given context (float mode: the tolerance ε).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Float, Tolerance}, yin2::YinSet2};
    /// let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
    /// let tol = Tolerance::new(0.25);
    /// // A vertex off the grid of ε = 0.25 is snapped to it.
    /// let a = YinSet2::from_curves_with(vec![vec![p(0.0, 0.0), p(2.1, 0.0), p(2.1, 2.0), p(0.0, 2.0)]], tol)?;
    /// assert_eq!(a.area().unwrap().get(), 4.0);
    /// a.validate()?;
    /// # Ok::<(), yinset::yin2::YinError>(())
    /// ```
    pub fn from_curves_with(
        curves: Vec<Vec<Point<N>>>,
        ctx: N::Ctx,
    ) -> Result<YinSet2<N>, YinError> {
        let curves = basic_checks(curves)?;
        let ctx = resolve_for(&curves, ctx)?;
        // The input must bound a Yin set exactly as given; float mode's ε applies to results.
        let spadjor = realize(curves, &N::Ctx::default())?;
        bounded_by(spadjor, ctx)
    }

    /// Check the representation invariant exactly (seed 000 Def. 3.17, Thm 3.21): rebuilding the
    /// set from its own curves with exact predicates succeeds and gives the same canonical form.
    /// In float mode the coordinates are read as the exact rationals they are.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let (a, b) = (sq(0, 0, 2), sq(1, 1, 2));
    /// for r in [&a & &b, &a | &b, &a - &b, &a ^ &b, !&a] {
    ///     r.validate()?; // every operation's output is a realizable spadjor
    /// }
    /// # Ok::<(), yinset::yin2::YinError>(())
    /// ```
    pub fn validate(&self) -> Result<(), YinError> {
        if self.curves().is_empty() {
            return Ok(());
        }
        if !N::EXACT {
            let raw = self.exact_curves()?;
            let rebuilt = YinSet2::<Rational>::from_curves(raw.clone())?;
            let same = rebuilt.curves().len() == raw.len()
                && rebuilt
                    .curves()
                    .iter()
                    .zip(&raw)
                    .all(|(c, r)| c.vertices() == r.as_slice());
            return if same {
                Ok(())
            } else {
                Err(YinError::NotCanonical)
            };
        }
        let raw: Vec<Vec<Point<N>>> = self
            .curves()
            .iter()
            .map(|c| c.vertices().to_vec())
            .collect();
        let rebuilt = YinSet2::from_curves_with(raw, self.ctx)?;
        if rebuilt == *self {
            Ok(())
        } else {
            Err(YinError::NotCanonical)
        }
    }
}

impl<N: Num> YinSet2<N> {
    /// The curves with every coordinate read as the exact rational it is (float mode).
    fn exact_curves(&self) -> Result<Vec<Vec<Point<Rational>>>, YinError> {
        let exact = |v: &N| Rational::from_f64(v.to_f64()).map_err(|_| YinError::NotCanonical);
        self.curves()
            .iter()
            .map(|c| {
                c.vertices()
                    .iter()
                    .map(|p| Ok(Point::new(exact(&p.x)?, exact(&p.y)?)))
                    .collect()
            })
            .collect()
    }
}

/// Per-curve checks: finite coordinates, at least 3 vertices, no repeated consecutive vertex.
fn basic_checks<N: Num>(curves: Vec<Vec<Point<N>>>) -> Result<Vec<Vec<Point<N>>>, YinError> {
    if curves.is_empty() {
        return Err(YinError::NoCurves);
    }
    curves
        .into_iter()
        .enumerate()
        .map(|(c, mut v)| {
            if let Some(k) = v.iter().position(|p| !p.x.is_finite() || !p.y.is_finite()) {
                return Err(YinError::NotFinite {
                    curve: c,
                    vertex: k,
                });
            }
            if v.len() > 1 && v.first() == v.last() {
                v.pop();
            }
            if v.len() < 3 {
                return Err(YinError::TooFewVertices {
                    curve: c,
                    count: v.len(),
                });
            }
            let n = v.len();
            if let Some(k) = (0..n).find(|&k| v[k] == v[(k + 1) % n]) {
                return Err(YinError::RepeatedVertex {
                    curve: c,
                    vertex: (k + 1) % n,
                    point: v[k].to_string(),
                });
            }
            Ok(v)
        })
        .collect()
}

/// The curves through one touching point: (curve, original edge index, previous, next vertex).
type Passage<N> = (usize, usize, Point<N>, Point<N>);

/// Curves with touching points inserted, and the passages through each touching point.
type Inserted<N> = (Vec<Vec<Point<N>>>, HashMap<Point<N>, Vec<Passage<N>>>);

/// Check simplicity, almost-disjointness and the orientation structure; build the spadjor.
fn realize<N: Num>(curves: Vec<Vec<Point<N>>>, ctx: &N::Ctx) -> Result<Spadjor<N>, YinError> {
    let mut owner: Vec<(usize, usize)> = Vec::new();
    let mut edges: Vec<Edge<N>> = Vec::new();
    for (c, v) in curves.iter().enumerate() {
        for k in 0..v.len() {
            owner.push((c, k));
            edges.push((v[k].clone(), v[(k + 1) % v.len()].clone()));
        }
    }
    let mut splits: Vec<Vec<Point<N>>> = vec![Vec::new(); edges.len()];
    let mut touching: HashSet<Point<N>> = HashSet::new();
    for (i, j, contact) in intersections(&edges, ctx, |_, _| true) {
        let ((ci, ki), (cj, kj)) = (owner[i], owner[j]);
        if ci == cj {
            let len = curves[ci].len();
            let shared = if kj == ki + 1 {
                Some(&curves[ci][kj])
            } else if ki == 0 && kj == len - 1 {
                Some(&curves[ci][0])
            } else {
                None
            };
            match (&contact, shared) {
                (Contact::Touching(p), Some(s)) if p == s => continue,
                (Contact::Touching(p) | Contact::Crossing(p) | Contact::Overlap(p, _), _) => {
                    return Err(YinError::NotSimple {
                        curve: ci,
                        vertex: ki,
                        point: p.to_string(),
                    })
                }
                (Contact::Disjoint, _) => continue,
            }
        }
        match contact {
            Contact::Crossing(p) => {
                return Err(YinError::ProperCrossing {
                    curve_a: ci,
                    vertex_a: ki,
                    curve_b: cj,
                    vertex_b: kj,
                    point: p.to_string(),
                })
            }
            Contact::Overlap(p, q) => {
                return Err(YinError::SharedEdge {
                    curve_a: ci,
                    vertex_a: ki,
                    curve_b: cj,
                    vertex_b: kj,
                    from: p.to_string(),
                    to: q.to_string(),
                })
            }
            Contact::Touching(p) => {
                splits[i].push(p.clone());
                splits[j].push(p.clone());
                touching.insert(p);
            }
            Contact::Disjoint => {}
        }
    }
    let (curves, passages) = insert_touching_points(curves, &edges, splits, &touching);
    check_touches_do_not_cross(&passages, ctx)?;
    let (spadjor, origin) = Spadjor::assemble(curves, &touching, ctx);
    check_structure(&spadjor, &origin, &passages)?;
    Ok(spadjor)
}

/// Make every touching point a vertex of each curve through it (so that S_V cuts there), and
/// list, per touching point, the curves passing through it.
fn insert_touching_points<N: Num>(
    curves: Vec<Vec<Point<N>>>,
    edges: &[Edge<N>],
    mut splits: Vec<Vec<Point<N>>>,
    touching: &HashSet<Point<N>>,
) -> Inserted<N> {
    let mut out = Vec::with_capacity(curves.len());
    let mut passages: HashMap<Point<N>, Vec<Passage<N>>> = HashMap::new();
    let mut e = 0;
    for (c, v) in curves.into_iter().enumerate() {
        let mut w: Vec<(Point<N>, usize)> = Vec::with_capacity(v.len());
        for (k, vertex) in v.iter().enumerate() {
            w.push((vertex.clone(), k));
            let (a, b) = (&edges[e].0, &edges[e].1);
            let s = &mut splits[e];
            s.retain(|p| p != a && p != b);
            s.sort();
            s.dedup();
            if a > b {
                s.reverse();
            }
            w.extend(s.drain(..).map(|p| (p, k)));
            e += 1;
        }
        let n = w.len();
        for t in 0..n {
            if touching.contains(&w[t].0) {
                let (prev, next) = (w[(t + n - 1) % n].0.clone(), w[(t + 1) % n].0.clone());
                passages
                    .entry(w[t].0.clone())
                    .or_default()
                    .push((c, w[t].1, prev, next));
            }
        }
        out.push(w.into_iter().map(|(p, _)| p).collect());
    }
    (out, passages)
}

/// At a touching point, two curves must not cross: the rays of one lie in one sector of the other.
fn check_touches_do_not_cross<N: Num>(
    passages: &HashMap<Point<N>, Vec<Passage<N>>>,
    ctx: &N::Ctx,
) -> Result<(), YinError> {
    for (p, list) in passages {
        for (x, (c1, k1, prev1, next1)) in list.iter().enumerate() {
            for (c2, k2, prev2, next2) in &list[x + 1..] {
                let before =
                    |q: &Point<N>| cmp_clockwise_from(p, prev1, q, next1, ctx) == Ordering::Less;
                if before(prev2) != before(next2) {
                    return Err(YinError::ProperCrossing {
                        curve_a: *c1,
                        vertex_a: *k1,
                        curve_b: *c2,
                        vertex_b: *k2,
                        point: p.to_string(),
                    });
                }
            }
        }
    }
    Ok(())
}

/// Orientations alternate with nesting, outermost curves agree, atoms are connected
/// (seed 000 Def. 3.16–3.17).
fn check_structure<N: Num>(
    s: &Spadjor<N>,
    origin: &[usize],
    passages: &HashMap<Point<N>, Vec<Passage<N>>>,
) -> Result<(), YinError> {
    let name = |o: bool| if o { "positively" } else { "negatively" };
    for (j, p) in s.parent.iter().enumerate() {
        if let Some(i) = *p {
            if s.positive[i] == s.positive[j] {
                return Err(YinError::NestedSameOrientation {
                    outer: origin[i],
                    inner: origin[j],
                    orientation: name(s.positive[j]),
                });
            }
        }
    }
    let root =
        |pos: bool| (0..s.curves.len()).find(|&i| s.parent[i].is_none() && s.positive[i] == pos);
    if let (Some(a), Some(b)) = (root(true), root(false)) {
        return Err(YinError::MixedOutermost {
            positive: origin[a],
            negative: origin[b],
        });
    }
    // Atoms connected: curves and touching points of one atom form a forest.
    let mut canonical = vec![0; origin.len()];
    for (i, &o) in origin.iter().enumerate() {
        canonical[o] = i;
    }
    let mut atom_of = vec![0; origin.len()];
    for (a, atom) in s.atoms.iter().enumerate() {
        for &i in atom.outer.iter().chain(&atom.holes) {
            atom_of[i] = a;
        }
    }
    let mut uf = UnionFind::new(origin.len());
    for (p, list) in passages {
        let mut by_atom: HashMap<usize, Vec<usize>> = HashMap::new();
        for (c, ..) in list {
            let i = canonical[*c];
            by_atom.entry(atom_of[i]).or_default().push(i);
        }
        for (a, group) in by_atom {
            if group.len() < 2 {
                continue;
            }
            let node = uf.add();
            for &i in &group {
                if !uf.union(node, i) {
                    let atom = &s.atoms[a];
                    let curves = atom
                        .outer
                        .iter()
                        .chain(&atom.holes)
                        .map(|&i| origin[i])
                        .collect();
                    return Err(YinError::DisconnectedAtom {
                        curves,
                        point: p.to_string(),
                    });
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use crate::kernel::Point;
    use crate::num::Rational;
    use crate::yin2::{YinError, YinSet2};

    /// The vertex cycle of the integer points `c`.
    fn ring(c: &[(i64, i64)]) -> Vec<Point<Rational>> {
        c.iter().map(|&(x, y)| Point::int(x, y)).collect()
    }

    /// A curve that passes through its first vertex again, along an edge next to neither its
    /// first nor its last edge (which meet that edge there), is not simple: the figure eight
    /// (1, 0), (2, 1), (2, −1), (0, 1), (0, −1), whose third edge, from (2, −1) to (0, 1),
    /// has (1, 0) as its midpoint.
    #[test]
    fn a_curve_through_its_first_vertex_twice_is_not_simple() {
        let eight = ring(&[(1, 0), (2, 1), (2, -1), (0, 1), (0, -1)]);
        let got = YinSet2::<Rational>::from_curves(vec![eight]);
        assert!(
            matches!(got, Err(YinError::NotSimple { curve: 0, .. })),
            "{got:?}"
        );
    }

    #[test]
    fn a_repeated_vertex_is_named_by_its_second_occurrence() {
        let square = ring(&[(5, 5), (6, 5), (6, 6), (5, 6)]);
        let doubled = ring(&[(0, 0), (2, 0), (2, 0), (2, 2), (0, 2)]);
        assert_eq!(
            YinSet2::<Rational>::from_curves(vec![square, doubled]).err(),
            Some(YinError::RepeatedVertex {
                curve: 1,
                vertex: 2,
                point: "(2, 0)".to_string(),
            })
        );
    }
}
