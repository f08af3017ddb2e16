//! The faces of a vertex's link that lie in the set, r_p of the Betti numbers (DESIGN-3D
//! §2.12; [`super::betti`]): where the link of a vertex p has several components, each lies
//! in one face of each other, found by walking an arc of the link from one to the other.
//! Points of the link are directions from p, integer vectors with no point constructed: a
//! segment x → y not through p sweeps the directions λ(x − p) + μ(y − p), λ, μ ≥ 0, in the
//! order of the arc, and scaling a direction by a positive number changes nothing.

use crate::kernel::Point3;
use crate::num::Num;
use crate::union_find::UnionFind;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// An integer vector.
pub(super) type Vector = [BigInt; 3];

/// r_p where the link of `p` has several components (`groups` of corners): the number of
/// faces of the link lying in 𝒴, each a class of 𝒴-cycles bounding one face (Janiszewski);
/// `cycles` are the 𝒴-cycles (inside) and 𝒴'-cycles (outside) of the corners.
pub(super) fn local_components<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    p: usize,
    groups: &[Vec<usize>],
    cycles: [&mut UnionFind; 2],
    ycycles: &[usize],
) -> usize {
    let m = groups.len();
    let wedges: Vec<Vec<Wedge>> = groups
        .iter()
        .map(|g| g.iter().map(|&c| Wedge::at(points, tris, p, c)).collect())
        .collect();
    // face[i][j]: the face of component i that holds component j, as (in 𝒴?, its cycle).
    let mut face = vec![vec![(false, 0usize); m]; m];
    for i in 0..m {
        for j in 0..m {
            if i != j {
                let (k, above) = face_holding(&wedges[i], &wedges[j])
                    .unwrap_or_else(|| panic!("no generic arc between two link components at vertex {p} (a degenerate configuration the retries did not escape)"));
                let c = groups[i][k];
                face[i][j] = match above {
                    true => (false, cycles[1].find(c)),
                    false => (true, cycles[0].find(c)),
                };
            }
        }
    }
    let mut uf = UnionFind::new(ycycles.len());
    let pos = |c: usize| ycycles.binary_search(&c).expect("a 𝒴-cycle at p");
    for i in 0..m {
        for j in i + 1..m {
            let (fi, fj) = (face[i][j], face[j][i]);
            let apart = (0..m).any(|k| k != i && k != j && face[k][i] != face[k][j]);
            if fi.0 && fj.0 && !apart {
                uf.union(pos(fi.1), pos(fj.1));
            }
        }
    }
    uf.classes().1
}

/// A corner of a triangle at `p` seen from `p`: integer vectors `u`, `v` along its sides and
/// the normal n = u × v. Its wedge is the open cone of directions λu + μv, λ, μ > 0.
struct Wedge {
    u: Vector,
    v: Vector,
    n: Vector,
}

impl Wedge {
    /// The corner `c` (3 · triangle + k) of `tris`, at the vertex `p`.
    fn at<N: Num>(points: &[Point3<N>], tris: &[[usize; 3]], p: usize, c: usize) -> Wedge {
        let (t, k) = (tris[c / 3], c % 3);
        let o = &points[p];
        let (u, v) = (
            direction(o, &points[t[(k + 1) % 3]]),
            direction(o, &points[t[(k + 2) % 3]]),
        );
        let n = cross(&u, &v);
        Wedge { u, v, n }
    }

    /// The direction w₀u + w₁v inside the wedge.
    fn inside(&self, [w0, w1]: [i64; 2]) -> Vector {
        combine(&self.u, &BigInt::from(w0), &self.v, &BigInt::from(w1))
    }
}

/// The face of the link component with the wedges `ci` that holds the component with the
/// wedges `cj`: the first wedge of `ci` (its index) that the arc from a direction inside a
/// wedge of `cj` to one inside a wedge of `ci` crosses, and whether the arc comes from its +n
/// side; retried with other directions while the arc is degenerate ([`first_hit`]).
fn face_holding(ci: &[Wedge], cj: &[Wedge]) -> Option<(usize, bool)> {
    /// Weights of the two sides of a wedge for the directions tried, in order.
    const WEIGHTS: [[i64; 2]; 6] = [[1, 1], [2, 3], [1, 2], [3, 1], [5, 2], [1, 7]];
    cj.iter()
        .flat_map(|from| ci.iter().map(move |to| (from, to)))
        .flat_map(|(from, to)| {
            WEIGHTS.iter().flat_map(move |&wx| {
                WEIGHTS
                    .iter()
                    .map(move |&wy| (from.inside(wx), to.inside(wy)))
            })
        })
        .find_map(|(x, y)| first_hit(ci, &x, &y))
}

/// The first of the `wedges` crossed by the arc of directions from `x` to `y` and whether `x`
/// is on its +n side; `None` if the arc is degenerate (`x`, `y` parallel, the arc along a
/// wedge's plane, through a wedge's edge, or through two wedges at once). The arc meets the
/// plane of a wedge where α = n·x and β = n·y differ in sign, at s = |α| / (|α| + |β|) of the
/// way, in the direction z = |β|x + |α|y; z is inside the wedge iff z = λu + μv with
/// λ, μ > 0, the signs of (z × v)·n and (u × z)·n.
fn first_hit(wedges: &[Wedge], x: &Vector, y: &Vector) -> Option<(usize, bool)> {
    if cross(x, y).iter().all(Zero::is_zero) {
        return None;
    }
    // The nearest crossing so far: |α|, |β|, the wedge, and x's side.
    let mut best: Option<(BigInt, BigInt, usize, bool)> = None;
    for (k, w) in wedges.iter().enumerate() {
        let (alpha, beta) = (dot(&w.n, x), dot(&w.n, y));
        if alpha.is_zero() {
            // x lies in the wedge's plane but not in the wedge (the link components are
            // disjoint): the arc leaves the plane at once, unless it runs inside it.
            if beta.is_zero() {
                return None;
            }
            continue;
        }
        if beta.sign() == alpha.sign() {
            continue;
        }
        let (a, b) = (alpha.abs(), beta.abs());
        let z = combine(x, &b, y, &a);
        let (l, m) = (
            dot(&cross(&z, &w.v), &w.n).sign(),
            dot(&cross(&w.u, &z), &w.n).sign(),
        );
        use num_bigint::Sign::{NoSign, Plus};
        if l == NoSign || m == NoSign {
            return None;
        }
        if l != Plus || m != Plus {
            continue;
        }
        let above = alpha.is_positive();
        match &best {
            // s < s' iff a / (a + b) < a' / (a' + b') iff a b' < a' b.
            Some((a1, b1, _, _)) => match (&a * b1).cmp(&(a1 * &b)) {
                Ordering::Equal => return None,
                Ordering::Greater => {}
                Ordering::Less => best = Some((a, b, k, above)),
            },
            None => best = Some((a, b, k, above)),
        }
    }
    best.map(|(_, _, k, above)| (k, above))
}

/// An integer vector in the direction of `b − a` on the points' exact values ([`Num::fraction`],
/// so float points too): the coordinates n_b/d_b − n_a/d_a = (n_b d_a − n_a d_b)/(d_a d_b)
/// times the least common multiple of their denominators.
fn direction<N: Num>(a: &Point3<N>, b: &Point3<N>) -> Vector {
    let f = [0, 1, 2].map(|k| {
        let ((na, da), (nb, db)) = (a.coord(k).fraction(), b.coord(k).fraction());
        (nb * &da - na * &db, da * db)
    });
    let l = f.iter().fold(BigInt::one(), |l, (_, d)| l.lcm(d));
    f.map(|(n, d)| n * (&l / d))
}

/// x × y.
pub(super) fn cross(x: &Vector, y: &Vector) -> Vector {
    [0, 1, 2].map(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        &x[i] * &y[j] - &x[j] * &y[i]
    })
}

/// x · y.
pub(super) fn dot(x: &Vector, y: &Vector) -> BigInt {
    &x[0] * &y[0] + &x[1] * &y[1] + &x[2] * &y[2]
}

/// λx + μy.
fn combine(x: &Vector, l: &BigInt, y: &Vector, m: &BigInt) -> Vector {
    [0, 1, 2].map(|k| l * &x[k] + m * &y[k])
}
