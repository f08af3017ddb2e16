//! Independent oracles for the 3D kernel's Boolean operations, exactly (the test kit's
//! cells3.rs and geom3.rs document the constructions):
//!
//! * unions of unit cells of a 2×2×2 and a 3×3×3 grid, with an exterior bit for unbounded sets,
//!   whose Boolean algebra is bitwise on masks: the expected set is built from the mask without
//!   the kernel's operations and compared with `==`; volume = number of cells; membership at
//!   cell centres, face and edge midpoints and vertices read off the mask; Betti numbers from
//!   the cell complex (b0 by face adjacency, b2 by 26-adjacency of the closed complement, b1
//!   from the Euler characteristic of the open cells); also with the grid turned by a rational
//!   rotation into general position;
//! * point membership against an independent ray-parity count (own exact segment–triangle
//!   test, rays re-drawn when they meet an edge) on random pairs of the generators, with the
//!   signed crossing count, the boundedness and the volume (sum of signed tetrahedra) as
//!   further checks;
//! * exact volume identities |A∧B| + |A∨B| = |A| + |B| and |A| = |A∧B| + |A∧B'| on random
//!   pairs, and for unbounded sets the same measured inside a window W.
//!
//! Case counts: `AXIOM3_CASES` (default below).

mod common;
use common::cells::{full_mask, Cells};
use common::cells3::{Grid3, Oracle3, CELL_ORACLE3};
use common::gen3::{features3, shares3, strategies, Shape3, CONTACT_MASKS};
use common::geom3::{common_den, ray_count, scale, IntGeom, Rng};
use common::laws::{self, law, ok, BinaryOut, Res, Tally};
use common::q;
use common::rotation::Rot;
use common::runner::{cases3, run, run_split};
use num_bigint::BigInt;
use proptest::prelude::*;
use std::sync::Mutex;
use yinset::kernel::Point3;
use yinset::num::{Num, Rational};
use yinset::yin2::Location;
use yinset::yin3::YinSet3;
use yinset_testkit::{P3, Y3};

/// A random union of cells, with a density drawn first so that sparse, dense and half-full
/// masks all occur, and the exterior bit set a fifth of the time.
fn cells_strategy(n: usize) -> impl Strategy<Value = Cells> {
    (
        proptest::collection::vec(0..100u8, n),
        0..=100u8,
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

/// A random set of the 2×2×2 grid: by density three times in four, else one of the masks
/// whose cells meet only along an edge or at a vertex (non-manifold edges and points).
fn cells_2x2x2() -> impl Strategy<Value = Cells> {
    prop_oneof![
        3 => cells_strategy(8),
        1 => (
            proptest::sample::select(CONTACT_MASKS.to_vec()),
            proptest::bool::weighted(0.2)
        )
            .prop_map(|(m, outside)| Cells::new(u64::from(m), outside)),
    ]
}

/// The five results of a pair, each validated.
fn operations(a: &Y3, b: &Y3) -> Result<BinaryOut<Y3>, String> {
    Ok(BinaryOut {
        meet: ok(a & b, "a∧b")?,
        join: ok(a | b, "a∨b")?,
        difference: ok(a - b, "a∖b")?,
        symmetric_difference: ok(a ^ b, "a⊕b")?,
        complement_a: ok(!a, "a'")?,
    })
}

/// Minimum shares of the degenerate features among the 2×2×2 cell pairs (order of
/// `gen3::FEATURES3`; cells are never turned and have no crossings).
const CELL_MINIMUM_SHARES: [f64; 12] = [
    0.50, 0.30, 0.25, 0.0, 0.0, 0.0, 0.30, 0.05, 0.17, 0.05, 0.0, 0.0,
];

/// The 2×2×2 grid: random pairs of its 512 sets (cached), the full binary laws on each pair,
/// and every result against the mask algebra.
#[test]
fn cell_oracle_2x2x2() {
    let o = Oracle3::new(Grid3::cube(2), true);
    let shares = Mutex::new(shares3());
    run_split(
        "cell oracle on the 2x2x2 grid (binary laws + oracle)",
        cases3(112),
        2,
        (cells_2x2x2(), cells_2x2x2()),
        |t, (a, b)| {
            let (ya, yb) = (o.expected(a), o.expected(b));
            shares.lock().unwrap().add(features3(&ya, &yb));
            o.check(t, a, &ya, "a")?;
            let out = laws::binary(t, &ya, &yb)?;
            o.check_binary(t, (a, b), &out)
        },
    );
    let shares = shares.into_inner().unwrap();
    eprintln!("{}", shares.report("the 2x2x2 cell pairs"));
    shares.assert_minimums(&CELL_MINIMUM_SHARES);
}

/// The 3×3×3 grid (2^28 sets, not cached): the five operations against the mask algebra.
#[test]
fn cell_oracle_3x3x3() {
    let o = Oracle3::new(Grid3::cube(3), false);
    run(
        "cell oracle on the 3x3x3 grid",
        cases3(12),
        (cells_strategy(27), cells_strategy(27)),
        |t, (a, b)| {
            let (ya, yb) = (o.expected(a), o.expected(b));
            o.check(t, a, &ya, "a")?;
            o.check_binary(t, (a, b), &operations(&ya, &yb)?)
        },
    );
}

/// The cut by control volumes (`meet_each`, parallel): a random set of the 3×3×3 grid met with
/// each of its 27 unit cells, against the mask algebra (cell k of 𝒴 is 𝒴's mask AND bit k).
#[test]
fn meet_each_cell_against_the_mask_algebra() {
    let o = Oracle3::new(Grid3::cube(3), false);
    let cells: Vec<Cells> = (0..27).map(|k| Cells::new(1 << k, false)).collect();
    let unit_cells: Vec<Y3> = cells.iter().map(|&c| o.expected(c)).collect();
    run(
        "meet_each on the 3x3x3 grid's cells",
        cases3(16),
        cells_strategy(27),
        |t, a| {
            let cut = o
                .expected(a)
                .meet_each(&unit_cells)
                .map_err(|e| e.to_string())?;
            for (k, (got, &c)) in cut.iter().zip(&cells).enumerate() {
                law(
                    t,
                    "meet_each = mask algebra",
                    *got == o.expected(a.and(c)),
                    || format!("{a:?}, cell {k}"),
                )?;
            }
            Ok(())
        },
    );
}

/// The 2×2×2 grid turned about an oblique axis (rational rotation, denominator 65): no vertex
/// on the lattice, every face slanted; the kernel must agree with the mask algebra exactly.
#[test]
fn cell_oracle_2x2x2_in_general_position() {
    let o = Oracle3::new(Grid3::cube(2).rotated(Rot::Oblique), true);
    run(
        "cell oracle on the 2x2x2 grid turned about an oblique axis",
        cases3(16),
        (cells_2x2x2(), cells_2x2x2()),
        |t, (a, b)| {
            let (ya, yb) = (o.expected(a), o.expected(b));
            o.check(t, a, &ya, "a")?;
            o.check_binary(t, (a, b), &operations(&ya, &yb)?)
        },
    );
}

const RAY: [&str; 4] = [
    "ray: locate(p) = on a closed triangle, else ray parity",
    "ray: signed crossings = [p ∈ Y] − [Y unbounded]",
    "bounded: is_bounded() = as the operands say",
    "volume: volume() = sum of the signed tetrahedra of the triangles",
];

/// One set against the ray oracle at the given points, with its expected boundedness.
fn ray_check(t: &mut Tally, z: &Y3, what: &str, bounded: bool, pts: &[P3], rng: &mut Rng) -> Res {
    law(t, RAY[2], z.is_bounded() == bounded, || {
        format!(
            "{what}: is_bounded() = {}, expected {bounded}",
            z.is_bounded()
        )
    })?;
    let den = common_den(z.vertices().iter().chain(pts));
    let g = IntGeom::new(z, &den);
    let got = z.locate(pts);
    for (k, p) in pts.iter().enumerate() {
        let ans = ray_count(&g, &scale(p, &den), rng);
        // p ∈ Y iff the parity is odd, or even for an unbounded Y.
        let inside = ans.odd == bounded;
        let want = if ans.on_boundary {
            Location::OnBoundary
        } else if inside {
            Location::Inside
        } else {
            Location::Outside
        };
        law(t, RAY[0], got[k] == want, || {
            format!("{what} at {p}: located {:?}, ray oracle {ans:?}", got[k])
        })?;
        if !ans.on_boundary {
            let w = i64::from(inside) - i64::from(!bounded);
            law(t, RAY[1], ans.winding == w, || {
                format!("{what} at {p}: {ans:?}, expected winding {w}")
            })?;
        }
    }
    if bounded {
        let d3 = &den * &den * &den * BigInt::from(6);
        let v = Rational::new(g.volume6(), d3);
        law(t, RAY[3], z.volume() == Some(v.clone()), || {
            format!("{what}: volume() = {:?}, triangles give {v}", z.volume())
        })?;
    }
    Ok(())
}

/// Random points (denominator 97: rarely on a boundary) and lattice points k/2 (often on one).
fn points() -> impl Strategy<Value = Vec<P3>> {
    (
        proptest::collection::vec([-97..=3 * 97i64, -97..=3 * 97i64, -97..=3 * 97i64], 12),
        proptest::collection::vec([-1..=5i64, -1..=5i64, -1..=5i64], 6),
    )
        .prop_map(|(r, l)| {
            r.into_iter()
                .map(|c| Point3::new(q(c[0], 97), q(c[1], 97), q(c[2], 97)))
                .chain(
                    l.into_iter()
                        .map(|c| Point3::new(q(c[0], 2), q(c[1], 2), q(c[2], 2))),
                )
                .collect()
        })
}

/// Membership of the operands and of every result against the ray oracle, and the membership
/// law at the points off both operands' boundaries.
#[test]
fn membership_against_ray_parity() {
    run_split(
        "membership against ray parity at random points",
        cases3(288),
        2,
        (strategies::pair(), points(), any::<u64>()),
        |t, ((sa, sb), pts, seed)| {
            let (a, b) = (sa.build(), sb.build());
            let out = laws::binary(t, &a, &b)?;
            laws::membership(t, &a, &b, &out, &pts)?;
            let (ba, bb) = (!sa.complement, !sb.complement);
            let mut rng = Rng(seed | 1);
            let sets: [(&str, &Y3, bool); 7] = [
                ("a", &a, ba),
                ("b", &b, bb),
                ("a∧b", &out.meet, ba || bb),
                ("a∨b", &out.join, ba && bb),
                ("a∖b", &out.difference, ba || !bb),
                ("a⊕b", &out.symmetric_difference, ba == bb),
                ("a'", &out.complement_a, !ba),
            ];
            for (what, z, bounded) in sets {
                ray_check(t, z, what, bounded, &pts, &mut rng)?;
            }
            Ok(())
        },
    );
}

/// Membership of cell sets (bounded and not) against the ray oracle at their probe points,
/// where rays from vertices and edge midpoints meet many edges and must be re-drawn.
#[test]
fn ray_oracle_on_cell_sets() {
    let g = Grid3::cube(2);
    let pts: Vec<P3> = g.probes();
    run(
        "ray oracle on 2x2x2 cell sets",
        cases3(32),
        (cells_2x2x2(), any::<u64>()),
        |t, (s, seed)| {
            let y = g.yin(s);
            ray_check(t, &y, "cells", !s.outside, &pts, &mut Rng(seed | 1))
        },
    );
}

const VOLUME: [&str; 6] = [
    "volume: |a∧b| + |a∨b| = |a| + |b|",
    "volume: |a| = |a∧b| + |a∧b'|",
    "volume in W: |(a∧b)∧W| + |(a∨b)∧W| = |a∧W| + |b∧W|",
    "volume in W: |a∧W| = |(a∧b)∧W| + |(a∧b')∧W|",
    "volume in W: |a'∧W| = |W| − |a∧W|",
    "volume in W: |(a⊕b)∧W| = |a∧W| + |b∧W| − 2|(a∧b)∧W|",
];

/// The box [lo, hi]³ (an operand, built by the library's own box helper).
fn cube(lo: i64, hi: i64) -> Y3 {
    YinSet3::cuboid(&Point3::int(lo, lo, lo), &Point3::int(hi, hi, hi)).unwrap()
}

/// The exact volume identities on random pairs: plainly for bounded operands, and inside a
/// window W containing every generated boundary for all operands.
#[test]
fn exact_volume_identities() {
    let w = cube(-3, 5);
    let vw = w.volume().unwrap();
    run(
        "exact volume identities",
        cases3(32),
        strategies::pair(),
        |t, (sa, sb): (Shape3, Shape3)| {
            let (a, b) = (sa.build(), sb.build());
            let vol = |y: &Y3, what: &str| -> Result<Rational, String> {
                Ok(ok(y & &w, what)?.volume().expect("bounded by W"))
            };
            let m = ok(&a & &b, "a∧b")?;
            let j = ok(&a | &b, "a∨b")?;
            let nb = ok(!&b, "b'")?;
            let anb = ok(&a & &nb, "a∧b'")?;
            let x = ok(&a ^ &b, "a⊕b")?;
            let na = ok(!&a, "a'")?;
            if let (Some(va), Some(vb)) = (a.volume(), b.volume()) {
                let (vm, vj, vd) = (m.volume(), j.volume(), anb.volume());
                law(
                    t,
                    VOLUME[0],
                    matches!((&vm, &vj), (Some(p), Some(r)) if p.clone() + r.clone() == va.clone() + vb.clone()),
                    || format!("|a∧b| = {vm:?}, |a∨b| = {vj:?}, |a| = {va}, |b| = {vb}"),
                )?;
                law(
                    t,
                    VOLUME[1],
                    matches!((&vm, &vd), (Some(p), Some(r)) if p.clone() + r.clone() == va),
                    || format!("|a∧b| = {vm:?}, |a∧b'| = {vd:?}, |a| = {va}"),
                )?;
            }
            let (wa, wb, wm, wj) = (
                vol(&a, "a∧W")?,
                vol(&b, "b∧W")?,
                vol(&m, "(a∧b)∧W")?,
                vol(&j, "(a∨b)∧W")?,
            );
            let (wd, wna, wx) = (
                vol(&anb, "(a∧b')∧W")?,
                vol(&na, "a'∧W")?,
                vol(&x, "(a⊕b)∧W")?,
            );
            let two = Rational::from_i64(2);
            law(
                t,
                VOLUME[2],
                wm.clone() + wj.clone() == wa.clone() + wb.clone(),
                || format!("{wm} + {wj} ≠ {wa} + {wb}"),
            )?;
            law(t, VOLUME[3], wa == wm.clone() + wd.clone(), || {
                format!("{wa} ≠ {wm} + {wd}")
            })?;
            law(t, VOLUME[4], wna == vw.clone() - wa.clone(), || {
                format!("{wna} ≠ |W| − {wa}")
            })?;
            law(
                t,
                VOLUME[5],
                wx == wa.clone() + wb.clone() - two * wm.clone(),
                || format!("{wx} ≠ {wa} + {wb} − 2·{wm}"),
            )
        },
    );
}

/// The cell checks can fail: on the 2×2×2 grid, a kernel result that is not the mask's set
/// fails `==`, and each invariant fails on its own for a result that agrees with the mask in
/// the invariants checked before it: Betti numbers (two cells sharing a vertex, for one cell),
/// volume (two face-adjacent cells: connected like one cell) and location (another single
/// cell: same topology and volume).
#[test]
fn cell_checks_reject_wrong_results() {
    let g = Grid3::cube(2);
    let cases = [
        (Cells::new(1 | 1 << 7, false), CELL_ORACLE3[1]),
        (Cells::new(1 | 1 << 1, false), CELL_ORACLE3[2]),
        (Cells::new(1 << 1, false), CELL_ORACLE3[3]),
    ];
    common::assert_cell_checks_fail(&g, |s| g.yin(s), Cells::new(1, false), &cases);
}

/// The cell oracle is not vacuous: hand-counted Betti numbers of configurations the kernel must
/// get right (edge and vertex contacts separate components; a ring is a solid torus; a cell
/// enclosed by the others is a cavity; the complement of a cavity), and the kernel agrees.
#[test]
fn cell_oracle_counts_by_hand() {
    let g3 = Grid3::cube(3);
    let bit = |i: u64, j: u64, k: u64| 1u64 << (i + 3 * j + 9 * k);
    let all = full_mask(27);
    let cases: [(&str, Cells, (usize, usize, usize)); 8] = [
        (
            "two cells sharing a face",
            Cells::new(bit(0, 0, 0) | bit(1, 0, 0), false),
            (1, 0, 0),
        ),
        (
            "two cells sharing an edge",
            Cells::new(bit(0, 0, 0) | bit(1, 1, 0), false),
            (2, 0, 0),
        ),
        (
            "two cells sharing a vertex",
            Cells::new(bit(0, 0, 0) | bit(1, 1, 1), false),
            (2, 0, 0),
        ),
        (
            "ring of 8 cells (solid torus)",
            Cells::new(
                (0..9)
                    .filter(|&b| b != 4)
                    .fold(0, |m, b| m | bit(b % 3, b / 3, 1)),
                false,
            ),
            (1, 1, 0),
        ),
        (
            "block with a cavity",
            Cells::new(all & !bit(1, 1, 1), false),
            (1, 0, 1),
        ),
        (
            "complement of the block with a cavity",
            Cells::new(bit(1, 1, 1), true),
            (2, 0, 1),
        ),
        (
            "complement of one cell",
            Cells::new(all & !bit(0, 0, 0), true),
            (1, 0, 1),
        ),
        ("1̂", Cells::new(all, true), (1, 0, 0)),
    ];
    for (what, s, want) in cases {
        let cb = g3.betti(s);
        assert_eq!((cb.b0, cb.b1, cb.b2), want, "oracle on {what}");
        let y = g3.yin(s);
        y.validate().unwrap();
        let b = y.betti();
        assert_eq!((b.b0, b.b1, b.b2), want, "kernel on {what}");
    }
    // The ray oracle on a unit cube and its complement: the centre, a face midpoint, a far point.
    let g1 = Grid3::cube(1);
    for outside in [false, true] {
        let s = Cells::new(u64::from(!outside), outside);
        let y = g1.yin(s);
        let pts = [[1, 1, 1], [2, 1, 1], [5, 1, 1]].map(|d| g1.point(d));
        let mut t = Tally::default();
        ray_check(&mut t, &y, "unit cell", !outside, &pts, &mut Rng(7)).unwrap();
        assert_eq!(t.total(), 1 + 3 + 2 + u64::from(!outside));
    }
}
