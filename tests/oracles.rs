//! Independent oracles for the kernel's Boolean operations, exactly:
//!
//! * unions of grid cells (and of triangles cutting the cells), whose Boolean algebra is bitwise
//!   on masks: the expected Yin set is traced from the mask without the kernel's operations, the
//!   expected Betti numbers are flood-fill counts (tests/kit/src/cells.rs documents why edge
//!   adjacency is the right connectivity for the set and for its complement);
//! * point membership: for random points off the boundaries,
//!   locate(p, A op B) = locate(p, A) op locate(p, B);
//! * exact area identities, also for unbounded sets (measured inside a window W).
//!
//! Case counts: `AXIOM_CASES` (default below).

mod common;
use common::cells::{full_mask, Cells, Complex, Split, CELL_ORACLE};
use common::gen::strategies;
use common::laws::{self, law, ok, CellOracle};
use common::runner::{cases, run};
use common::Y;
use proptest::prelude::*;
use yinset::kernel::Point;
use yinset::num::Rational;
use yinset::yin2::YinSet2;

/// The subdivisions of the random cell oracle: larger than the exhaustive universes of
/// proofs/, so that islands inside holes, nested holes and long pinched chains occur.
fn complexes() -> Vec<Complex> {
    vec![
        Complex::grid(5, 5),
        Complex::mixed(),
        Complex::new("3x3 cells, all cut by both diagonals", 3, 3, |_, _| {
            Split::Cross
        }),
        Complex::new("4x4 cells, alternating diagonals", 4, 4, |i, j| {
            if (i + j) % 2 == 0 {
                Split::Slash
            } else {
                Split::Backslash
            }
        }),
    ]
}

/// A random union of pieces, with a density drawn first so that sparse, dense and half-full
/// masks all occur.
fn cells_strategy(n: usize) -> impl Strategy<Value = Cells> {
    (
        proptest::collection::vec(0..100u8, n),
        0..100u8,
        proptest::bool::weighted(0.2),
    )
        .prop_map(|(coins, density, outside)| {
            let mask = coins
                .iter()
                .enumerate()
                .filter(|(_, &c)| c < density)
                .fold(0u64, |m, (k, _)| m | 1 << k);
            Cells::new(mask, outside)
        })
}

#[test]
fn grid_cell_oracle() {
    for cx in complexes() {
        let n = cx.len();
        let name = format!("cell oracle on {} ({n} pieces)", cx.name);
        run(
            &name,
            cases(128),
            (cells_strategy(n), cells_strategy(n)),
            |t, (a, b)| {
                let (ya, yb) = (cx.yin(a), cx.yin(b));
                cx.invariants(t, a, &ya, "a")?;
                let out = laws::binary(t, &ya, &yb)?;
                laws::cells_binary(t, &cx, (a, b), &out, &|s| cx.yin(s))
            },
        );
    }
}

/// The n-ary join and meet ([`YinSet2::join_all`], [`YinSet2::meet_all`]: divide and conquer
/// on rayon's threads) on 0 to 5 operands against the cell oracle (the set traced from the OR /
/// AND of the masks) and against the left fold of the binary operations (another association:
/// the laws' associativity on the kernel's own results).
#[test]
fn nary_cell_oracle() {
    for cx in [Complex::mixed(), Complex::grid(4, 4)] {
        let n = cx.len();
        let name = format!("n-ary join and meet on {} ({n} pieces)", cx.name);
        let none = Cells::new(0, false);
        let all = none.not(n);
        run(
            &name,
            cases(64),
            proptest::collection::vec(cells_strategy(n), 0..=5),
            |t, sets| {
                let ys: Vec<Y> = sets.iter().map(|&s| cx.yin(s)).collect();
                let join = ok(YinSet2::join_all(&ys), "join_all")?;
                let meet = ok(YinSet2::meet_all(&ys), "meet_all")?;
                let (or, and) = sets
                    .iter()
                    .fold((none, all), |(o, a), &s| (o.or(s), a.and(s)));
                law(t, "join_all = cell oracle", join == cx.yin(or), || {
                    format!("{sets:?}: got {join:?}")
                })?;
                law(t, "meet_all = cell oracle", meet == cx.yin(and), || {
                    format!("{sets:?}: got {meet:?}")
                })?;
                let fold_join = ys.iter().fold(Y::empty(), |a, b| a.join(b));
                let fold_meet = ys.iter().fold(Y::full(), |a, b| a.meet(b));
                law(
                    t,
                    "n-ary = fold of binary",
                    join == fold_join && meet == fold_meet,
                    || format!("{sets:?}"),
                )
            },
        );
    }
}

/// The cut by control volumes (`meet_each`, parallel): a random set met with each piece of the
/// complex, against the set traced from the mask AND that piece's bit.
#[test]
fn meet_each_piece_against_the_cell_oracle() {
    let cx = Complex::mixed();
    let n = cx.len();
    let pieces: Vec<Cells> = (0..n).map(|k| Cells::new(1 << k, false)).collect();
    let cells: Vec<Y> = pieces.iter().map(|&c| cx.yin(c)).collect();
    run(
        "meet_each on the pieces of the mixed complex",
        cases(32),
        cells_strategy(n),
        |t, a| {
            for (k, (got, &c)) in cx.yin(a).meet_each(&cells).iter().zip(&pieces).enumerate() {
                law(
                    t,
                    "meet_each = cell oracle",
                    *got == cx.yin(a.and(c)),
                    || format!("{a:?}, piece {k}"),
                )?;
            }
            Ok(())
        },
    );
}

/// The cell oracle after an affine map with non-integer rational coefficients: coordinates are
/// no longer small integers, and the kernel must still agree exactly.
#[test]
fn grid_cell_oracle_in_rational_coordinates() {
    let cx = Complex::mixed();
    let n = cx.len();
    let s = Rational::new(3.into(), 7.into());
    let (dx, dy) = (
        Rational::new((-5).into(), 3.into()),
        Rational::new(2.into(), 11.into()),
    );
    let map = move |p: Point<Rational>| {
        Point::new(p.x * s.clone() + dx.clone(), p.y * s.clone() + dy.clone())
    };
    let area_scale = Rational::new(9.into(), 49.into());
    run(
        "cell oracle in rational coordinates",
        cases(128),
        (cells_strategy(n), cells_strategy(n)),
        |t, (a, b)| {
            let (ya, yb) = (cx.yin_mapped(a, &map), cx.yin_mapped(b, &map));
            let cases: [(&str, Cells, Y); 5] = [
                ("a∧b", a.and(b), ok(ya.meet(&yb), "a∧b")?),
                ("a∨b", a.or(b), ok(ya.join(&yb), "a∨b")?),
                ("a∖b", a.minus(b, n), ok(ya.difference(&yb), "a∖b")?),
                ("a⊕b", a.xor(b), ok(ya.symmetric_difference(&yb), "a⊕b")?),
                ("a'", a.not(n), ok(ya.complement(), "a'")?),
            ];
            for (what, s, y) in cases {
                let want = cx.yin_mapped(s, &map);
                law(t, CELL_ORACLE[0], y == want, || format!("{what}: {s:?}"))?;
                let (got, exp) = (y.betti(), cx.betti(s));
                let mut holes = got.holes.clone();
                holes.sort_unstable();
                law(
                    t,
                    CELL_ORACLE[1],
                    got.components == exp.components && holes == exp.holes_sorted,
                    || format!("{what}: {got:?} vs {exp:?}"),
                )?;
                let want_area = cx.area(s).map(|x| x * area_scale.clone());
                law(t, CELL_ORACLE[2], y.area() == want_area, || {
                    format!("{what}: area {:?} vs {want_area:?}", y.area())
                })?;
            }
            Ok(())
        },
    );
}

/// Random points with rational coordinates (denominator 97, so rarely on a boundary).
fn points() -> impl Strategy<Value = Vec<Point<Rational>>> {
    proptest::collection::vec((-200..1000i64, -200..1000i64), 64).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| {
                Point::new(
                    Rational::new(x.into(), 97.into()),
                    Rational::new(y.into(), 97.into()),
                )
            })
            .collect()
    })
}

#[test]
fn membership_oracle() {
    run(
        "membership oracle at random points",
        cases(256),
        (strategies::pair(), points()),
        |t, ((a, b), pts)| {
            let (a, b) = (a.build(), b.build());
            let out = laws::binary(t, &a, &b)?;
            laws::membership(t, &a, &b, &out, &pts)
        },
    );
}

const AREA: [&str; 4] = [
    "area in W: |(a∧b)∧W| + |(a∨b)∧W| = |a∧W| + |b∧W|",
    "area in W: |(a∖b)∧W| = |a∧W| − |(a∧b)∧W|",
    "area in W: |a'∧W| = |W| − |a∧W|",
    "area in W: |(a⊕b)∧W| = |a∧W| + |b∧W| − 2|(a∧b)∧W|",
];

/// The exact area identities for every pair, bounded or not: areas are measured inside a window
/// W that contains every generated boundary (for bounded a and b the plain identities are
/// checked by the binary laws).
#[test]
fn exact_area_identities() {
    let w: Y = YinSet2::from_curves(vec![vec![
        Point::int(-3, -3),
        Point::int(11, -3),
        Point::int(11, 11),
        Point::int(-3, 11),
    ]])
    .unwrap();
    let aw = w.area().unwrap();
    run(
        "exact area identities",
        cases(256),
        strategies::pair(),
        |t, (a, b)| {
            let (a, b) = (a.build(), b.build());
            let area = |y: Y, what: &str| -> Result<Rational, String> {
                Ok(ok(y.meet(&w), what)?.area().expect("bounded by W"))
            };
            let m = ok(a.meet(&b), "a∧b")?;
            let (am, aa, ab) = (
                area(m, "(a∧b)∧W")?,
                area(a.clone(), "a∧W")?,
                area(b.clone(), "b∧W")?,
            );
            let aj = area(ok(a.join(&b), "a∨b")?, "(a∨b)∧W")?;
            let ad = area(ok(a.difference(&b), "a∖b")?, "(a∖b)∧W")?;
            let ac = area(ok(a.complement(), "a'")?, "a'∧W")?;
            let ax = area(ok(a.symmetric_difference(&b), "a⊕b")?, "(a⊕b)∧W")?;
            let two = Rational::from_integer(2.into());
            law(
                t,
                AREA[0],
                am.clone() + aj.clone() == aa.clone() + ab.clone(),
                || format!("{am} + {aj} ≠ {aa} + {ab}"),
            )?;
            law(t, AREA[1], ad == aa.clone() - am.clone(), || {
                format!("{ad} ≠ {aa} − {am}")
            })?;
            law(t, AREA[2], ac == aw.clone() - aa.clone(), || {
                format!("{ac} ≠ |W| − {aa}")
            })?;
            law(
                t,
                AREA[3],
                ax == aa.clone() + ab.clone() - two * am.clone(),
                || format!("{ax} ≠ {aa} + {ab} − 2·{am}"),
            )
        },
    );
}

/// The oracle is not vacuous: it distinguishes the cases the kernel must get right (a corner
/// contact splits components; a hole pinched against the outer curve counts as a hole).
#[test]
fn cell_oracle_counts_by_edge_adjacency() {
    let g = Complex::grid(3, 3);
    let bit = |i: u64, j: u64| 1u64 << (3 * j + i);
    // Two cells touching at a corner: two components.
    let diag = Cells::new(bit(0, 0) | bit(1, 1), false);
    assert_eq!(g.betti(diag).components, 2);
    assert_eq!(g.curves(diag).len(), 2);
    // The ring of 8 cells around the centre: one component with one hole.
    let ring = Cells::new(full_mask(9) & !bit(1, 1), false);
    assert_eq!(g.betti(ring).holes_sorted, vec![1]);
    // Remove a corner as well: the hole (the centre) touches the outside at a point, and is
    // still a hole (its own negatively oriented curve, seed 000 Cor. 3.14).
    let pinched = Cells::new(ring.mask & !bit(2, 2), false);
    assert_eq!(g.betti(pinched).holes_sorted, vec![1]);
    let y = g.yin(pinched);
    assert_eq!(y.betti().total_holes, 1);
    // Its complement: two components (the outside and the centre cell), touching at (2, 2).
    let c = g.betti(pinched.not(9));
    assert_eq!(c.components, 2);
    assert_eq!(y.complement(), g.yin(pinched.not(9)));
}

/// The cell checks can fail: on the 3×3 grid, a kernel result that is not the mask's set fails
/// `==`, and each invariant fails on its own for a result that agrees with the mask in the
/// invariants checked before it: Betti numbers (two cells touching at a corner, for one
/// cell), area (two edge-adjacent cells) and location (another single cell).
#[test]
fn cell_checks_reject_wrong_results() {
    let g = Complex::grid(3, 3);
    let cases = [
        (Cells::new(1 | 1 << 4, false), CELL_ORACLE[1]),
        (Cells::new(1 | 1 << 1, false), CELL_ORACLE[2]),
        (Cells::new(1 << 1, false), CELL_ORACLE[3]),
    ];
    common::assert_cell_checks_fail(&g, |s| g.yin(s), Cells::new(1, false), &cases);
}

/// Homological b₀ and b₁ of a union of pieces, from the cell complex alone: b₀ by
/// edge-adjacency of the pieces (and the exterior), b₁ = b₀ − χ, with χ(Y) = χ_c(Y) (Poincaré
/// duality for the open surface Y) = F − E + V over the open faces, edges and vertices of the
/// complex inside Y; the exterior of the window, an open annulus, adds 0. Nothing here is
/// shared with the kernel's complement-based count.
fn cell_homology(cx: &Complex, s: Cells) -> (usize, usize) {
    use std::collections::HashMap;
    let n = cx.len();
    let inside = |p: Option<usize>| p.map_or(s.outside, |p| s.mask >> p & 1 == 1);
    // Each undirected edge with the pieces on its sides (one piece: the other is the exterior),
    // and each vertex with the pieces around it.
    type V = (i64, i64);
    let mut sides: HashMap<(V, V), Vec<usize>> = HashMap::new();
    let mut around: HashMap<V, Vec<usize>> = HashMap::new();
    for (p, v) in cx.pieces.iter().enumerate() {
        for k in 0..v.len() {
            let (a, b) = (v[k], v[(k + 1) % v.len()]);
            sides.entry((a.min(b), a.max(b))).or_default().push(p);
            around.entry(a).or_default().push(p);
        }
    }
    let on_border: std::collections::HashSet<V> = sides
        .iter()
        .filter(|(_, ps)| ps.len() == 1)
        .flat_map(|(&(a, b), _)| [a, b])
        .collect();
    let mut comp = UnionFind((0..=n).collect());
    let faces = (0..n).filter(|&p| inside(Some(p))).count() as i64;
    let mut edges = 0i64;
    for ps in sides.values() {
        let other = if ps.len() == 1 { None } else { Some(ps[1]) };
        if inside(Some(ps[0])) && inside(other) {
            edges += 1;
            comp.union(ps[0], other.unwrap_or(n));
        }
    }
    let vertices = around
        .iter()
        .filter(|(v, ps)| {
            ps.iter().all(|&p| inside(Some(p))) && (!on_border.contains(v) || s.outside)
        })
        .count() as i64;
    let b0 = (0..=n)
        .filter(|&p| inside((p < n).then_some(p)) && comp.find(p) == p)
        .count();
    let chi = faces - edges + vertices;
    (b0, usize::try_from(b0 as i64 - chi).expect("b1 ≥ 0"))
}

/// Minimal union–find for [`cell_homology`].
struct UnionFind(Vec<usize>);

impl UnionFind {
    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            x = self.0[x];
        }
        x
    }
    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        self.0[a] = b;
    }
}

/// `YinSet2::homology` against the cell complex's b₀ and b₁ on every complex, where holes
/// pinched at a vertex and holes touching each other make it differ from the seed's count; the
/// share of such cases is printed and bounded from below.
#[test]
fn homology_oracle() {
    let differing = std::sync::atomic::AtomicUsize::new(0);
    let mut total = 0;
    for cx in complexes() {
        let n = cx.len();
        total += cases(128) as usize;
        run(
            &format!("homology on {}", cx.name),
            cases(128),
            cells_strategy(n),
            |t, s| {
                let y = cx.yin(s);
                let h = y.homology();
                let want = cell_homology(&cx, s);
                if y.betti().total_holes != h.b1 {
                    differing.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                }
                law(
                    t,
                    "homology: (b0, b1) = cell complex",
                    (h.b0, h.b1) == want,
                    || format!("{s:?} on {}: kernel {h:?}, cell complex {want:?}", cx.name),
                )
            },
        );
    }
    let d = differing.into_inner();
    eprintln!("homological b1 ≠ seed's hole count in {d} of {total} cases");
    assert!(
        d * 20 >= total,
        "only {d} of {total} cases tell the two counts apart"
    );
}

#[test]
fn cell_homology_by_hand() {
    let g = Complex::grid(3, 3);
    let bit = |i: u64, j: u64| 1u64 << (3 * j + i);
    let ring = Cells::new(full_mask(9) & !bit(1, 1), false);
    assert_eq!(cell_homology(&g, ring), (1, 1));
    let pinched = Cells::new(ring.mask & !bit(2, 2), false);
    assert_eq!(cell_homology(&g, pinched), (1, 0));
    assert_eq!(cell_homology(&g, pinched.not(9)), (2, 1));
    assert_eq!(cell_homology(&g, Cells::new(0, true)), (1, 1));
    assert_eq!(cell_homology(&g, Cells::new(full_mask(9), true)), (1, 0));
}
