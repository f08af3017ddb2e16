//! The 3D cell oracle's checks ([`Grid3`], proofs/cells3.rs) on kernel results, counted in
//! the same [`Tally`] as the laws (which tests/common/laws.rs states once for 2D and 3D).

use crate::cells3::{Grid3, Y3};
use crate::common::cells::Cells;
use crate::common::laws::{law, Algebra, BinaryOut, Res, Tally};
use yinset::kernel::Point3;
use yinset::num::Rational;

fn neq(l: &Y3, r: &Y3) -> String {
    format!("\n  left  = {}\n  right = {}", l.show(), r.show())
}

pub const CELL_ORACLE3: [&str; 4] = [
    "cells: kernel result = set built from the mask's faces",
    "cells: Betti numbers b0, b1, b2 = cell-complex counts",
    "cells: volume = number of cells",
    "cells: locate(centre of every open cell) = read off the mask",
];

/// The cell oracle for one kernel result `y` that should be the union `s`: `y == expected`
/// (built from the mask's faces by `from_triangles` only), and the invariants of
/// [`cells_invariants`].
pub fn cells_check(
    t: &mut Tally,
    g: &Grid3,
    probes: &[Point3<Rational>],
    s: Cells,
    y: &Y3,
    expected: &Y3,
    what: &str,
) -> Res {
    law(t, CELL_ORACLE3[0], y == expected, || {
        format!("{what} on {} ({s:?}){}", g.name, neq(y, expected))
    })?;
    cells_invariants(t, g, probes, s, y, what)
}

/// The invariants of a set `y` that should be the union `s`, read off the mask: its Betti
/// numbers equal the cell complex's, its volume the number of cells, and the centre of every
/// open cell of the grid (cube, face, edge, vertex) and a point outside are located as the
/// mask says.
pub fn cells_invariants(
    t: &mut Tally,
    g: &Grid3,
    probes: &[Point3<Rational>],
    s: Cells,
    y: &Y3,
    what: &str,
) -> Res {
    let want = g.betti(s);
    let got = y.betti();
    law(
        t,
        CELL_ORACLE3[1],
        (got.b0, got.b1, got.b2) == (want.b0, want.b1, want.b2),
        || {
            format!(
                "{what} on {} ({s:?}): kernel {got:?}, expected {want:?}",
                g.name
            )
        },
    )?;
    let (gv, wv) = (y.volume(), g.volume(s));
    law(t, CELL_ORACLE3[2], gv == wv, || {
        format!(
            "{what} on {} ({s:?}): volume {gv:?}, expected {wv:?}",
            g.name
        )
    })?;
    let (gl, wl) = (y.locate(probes), g.expected_locations(s));
    law(t, CELL_ORACLE3[3], gl == wl, || {
        let bad: Vec<String> = (0..gl.len())
            .filter(|&k| gl[k] != wl[k])
            .map(|k| format!("{}: {:?}, expected {:?}", probes[k], gl[k], wl[k]))
            .collect();
        format!("{what} on {} ({s:?}): {}", g.name, bad.join("; "))
    })
}

/// The cell oracle on all results of one binary case: a∧b, a∨b, a∖b, a⊕b and a' against the
/// bitwise operations on the masks, and the order against mask inclusion.
pub fn cells_binary(
    t: &mut Tally,
    g: &Grid3,
    probes: &[Point3<Rational>],
    (a, b): (Cells, Cells),
    out: &BinaryOut<Y3>,
    expected: &dyn Fn(Cells) -> Y3,
) -> Res {
    let n = g.len();
    let cases: [(&str, Cells, &Y3); 5] = [
        ("a∧b", a.and(b), &out.meet),
        ("a∨b", a.or(b), &out.join),
        ("a∖b", a.minus(b, n), &out.difference),
        ("a⊕b", a.xor(b), &out.symmetric_difference),
        ("a'", a.not(n), &out.complement_a),
    ];
    for (what, s, y) in cases {
        cells_check(t, g, probes, s, y, &expected(s), what)?;
    }
    let order = out.meet == expected(a);
    law(
        t,
        "cells: a∧b = a ⇔ mask(a) ⊆ mask(b)",
        order == a.le(b),
        || format!("on {}: a = {a:?}, b = {b:?}", g.name),
    )
}
