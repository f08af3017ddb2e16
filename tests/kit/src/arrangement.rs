//! The faces of the arrangement of a few polygons' sides, for the proof universes whose curves
//! cross in general position (proofs/README.md): every crossing of two sides is computed here,
//! exactly on `Ratio<i64>` (overflow panics), without the kernel.

use num_integer::Integer;
use num_rational::Ratio;
use std::collections::{BTreeMap, BTreeSet};

type Q = Ratio<i64>;
type P = (Q, Q);

fn sub(p: P, q: P) -> P {
    (p.0 - q.0, p.1 - q.1)
}

fn cross(u: P, v: P) -> Q {
    u.0 * v.1 - u.1 * v.0
}

/// Counterclockwise order of directions from the positive x-axis, angles in [0, 2π).
fn angle_cmp(a: P, b: P) -> std::cmp::Ordering {
    let zero = Q::from_integer(0);
    let upper = |d: P| d.1 > zero || (d.1 == zero && d.0 > zero);
    upper(b).cmp(&upper(a)).then_with(|| zero.cmp(&cross(a, b)))
}

/// The bounded faces of the arrangement of the sides of `polygons` (integer vertices), each as a
/// counterclockwise cycle of its arrangement vertices, in integer coordinates scaled by the
/// returned common denominator of all vertices. No two sides may be collinear, and the sides
/// must form a connected drawing (one unbounded face).
pub fn faces(polygons: &[Vec<(i64, i64)>]) -> (Vec<Vec<(i64, i64)>>, i64) {
    let q = |p: (i64, i64)| (Q::from_integer(p.0), Q::from_integer(p.1));
    let sides: BTreeSet<(P, P)> = polygons
        .iter()
        .flat_map(|v| (0..v.len()).map(move |k| (v[k], v[(k + 1) % v.len()])))
        .map(|(a, b)| (q(a.min(b)), q(a.max(b))))
        .collect();
    // Split every side at its crossings with the others.
    let mut edges: BTreeSet<(P, P)> = BTreeSet::new();
    for &(a, b) in &sides {
        let r = sub(b, a);
        let mut on: Vec<P> = vec![a, b];
        for &(c, d) in &sides {
            if (c, d) == (a, b) {
                continue;
            }
            let s = sub(d, c);
            let den = cross(r, s);
            if den == Q::from_integer(0) {
                assert!(
                    cross(r, sub(c, a)) != Q::from_integer(0),
                    "collinear sides {a:?}–{b:?} and {c:?}–{d:?}"
                );
                continue;
            }
            let (t, u) = (cross(sub(c, a), s) / den, cross(sub(c, a), r) / den);
            let unit = |x: Q| x >= Q::from_integer(0) && x <= Q::from_integer(1);
            if unit(t) && unit(u) {
                on.push((a.0 + t * r.0, a.1 + t * r.1));
            }
        }
        on.sort();
        on.dedup();
        edges.extend(on.windows(2).map(|w| (w[0], w[1])));
    }
    // Neighbours of each vertex in counterclockwise order.
    let mut around: BTreeMap<P, Vec<P>> = BTreeMap::new();
    for &(p, r) in &edges {
        around.entry(p).or_default().push(r);
        around.entry(r).or_default().push(p);
    }
    for (&v, ns) in around.iter_mut() {
        ns.sort_by(|&a, &b| angle_cmp(sub(a, v), sub(b, v)));
    }
    // Trace the faces, each on the left of its half-edges: after u → v, turn to the neighbour of
    // v just clockwise of u.
    let mut seen: BTreeSet<(P, P)> = BTreeSet::new();
    let mut bounded = Vec::new();
    let mut unbounded = 0;
    for &(p, r) in &edges {
        for start in [(p, r), (r, p)] {
            if seen.contains(&start) {
                continue;
            }
            let (mut u, mut v) = start;
            let mut face = Vec::new();
            while seen.insert((u, v)) {
                face.push(u);
                let ns = &around[&v];
                let k = ns.iter().position(|&w| w == u).expect("a neighbour");
                (u, v) = (v, ns[(k + ns.len() - 1) % ns.len()]);
            }
            let area2 = (0..face.len()).fold(Q::from_integer(0), |s, k| {
                s + cross(face[k], face[(k + 1) % face.len()])
            });
            if area2 > Q::from_integer(0) {
                bounded.push(face);
            } else {
                unbounded += 1;
            }
        }
    }
    assert_eq!(unbounded, 1, "the drawing is not connected");
    let den = around
        .keys()
        .flat_map(|p| [*p.0.denom(), *p.1.denom()])
        .fold(1, |l, d| l.lcm(&d));
    let scaled = |p: &P| ((p.0 * den).to_integer(), (p.1 * den).to_integer());
    let faces = bounded
        .iter()
        .map(|f| f.iter().map(scaled).collect())
        .collect();
    (faces, den)
}
