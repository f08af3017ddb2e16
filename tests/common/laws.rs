//! The Boolean-algebra laws, checked exactly with `==` on Yin sets (seed 000 Thm 4.11), with
//! every kernel output passed through the exact validator. Shared by the proptest and
//! quickcheck suites and by proofs/.
//!
//! Each check counts itself in a [`Tally`] under the law's name, so that suites can report how
//! many cases of each law they checked.

use super::cells::{Cells, Complex};
use super::Y;
use std::collections::BTreeMap;
use yinset::kernel::Point;
use yinset::num::Rational;
use yinset::yin2::{Location, YinSet2};

/// The first failure, described.
pub type Res = Result<(), String>;

/// Cases checked, per law.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    pub counts: BTreeMap<&'static str, u64>,
}

impl Tally {
    pub const fn new() -> Tally {
        Tally {
            counts: BTreeMap::new(),
        }
    }

    pub fn merge(&mut self, other: &Tally) {
        for (k, v) in &other.counts {
            *self.counts.entry(k).or_default() += v;
        }
    }

    pub fn total(&self) -> u64 {
        self.counts.values().sum()
    }

    pub fn report(&self, title: &str) -> String {
        let mut s = format!("{title}: {} checks\n", self.total());
        for (k, v) in &self.counts {
            s += &format!("  {v:>10}  {k}\n");
        }
        s
    }
}

/// Validate a kernel output (seed 000 Def. 3.17, Thm 3.21) and pass it on.
pub fn ok(y: Y, what: &str) -> Result<Y, String> {
    y.validate()
        .map_err(|e| format!("the validator rejects {what}: {e}\n{y:?}"))?;
    Ok(y)
}

/// Validate an input (e.g. a generated set, itself a kernel output).
pub fn valid_input(y: &Y, what: &str) -> Res {
    y.validate()
        .map_err(|e| format!("the validator rejects the input {what}: {e}\n{y:?}"))
}

/// Count one case of `name`; fail with `detail` if it does not hold.
pub fn law(t: &mut Tally, name: &'static str, holds: bool, detail: impl FnOnce() -> String) -> Res {
    *t.counts.entry(name).or_default() += 1;
    if holds {
        Ok(())
    } else {
        Err(format!("law '{name}' fails: {}", detail()))
    }
}

fn show(y: &Y) -> String {
    if y.is_empty() {
        return "0̂".into();
    }
    if y.is_full() {
        return "1̂".into();
    }
    let curves: Vec<String> = y
        .curves()
        .iter()
        .map(|c| {
            let v: Vec<String> = c.vertices().iter().map(|p| p.to_string()).collect();
            format!("[{}]", v.join(" "))
        })
        .collect();
    format!("{{{}}}", curves.join(", "))
}

fn neq(l: &Y, r: &Y) -> String {
    format!("\n  left  = {}\n  right = {}", show(l), show(r))
}

pub const UNARY_LAWS: [&str; 9] = [
    "idempotence: a∧a = a",
    "idempotence: a∨a = a",
    "identity: a∧1̂ = a",
    "identity: a∨0̂ = a",
    "annihilator: a∧0̂ = 0̂",
    "annihilator: a∨1̂ = 1̂",
    "complement: a∧a' = 0̂",
    "complement: a∨a' = 1̂",
    "involution: a'' = a",
];

/// Idempotence, identity, annihilator, complement and involution laws for one set.
pub fn unary(t: &mut Tally, a: &Y) -> Res {
    valid_input(a, "a")?;
    let (zero, one): (Y, Y) = (YinSet2::empty(), YinSet2::full());
    let na = ok(a.complement(), "a'")?;
    let cases: [(usize, Y, &Y); 9] = [
        (0, ok(a.meet(a), "a∧a")?, a),
        (1, ok(a.join(a), "a∨a")?, a),
        (2, ok(a.meet(&one), "a∧1̂")?, a),
        (3, ok(a.join(&zero), "a∨0̂")?, a),
        (4, ok(a.meet(&zero), "a∧0̂")?, &zero),
        (5, ok(a.join(&one), "a∨1̂")?, &one),
        (6, ok(a.meet(&na), "a∧a'")?, &zero),
        (7, ok(a.join(&na), "a∨a'")?, &one),
        (8, ok(na.complement(), "a''")?, a),
    ];
    for (k, l, r) in &cases {
        law(t, UNARY_LAWS[*k], l == *r, || {
            format!("a = {}{}", show(a), neq(l, r))
        })?;
    }
    Ok(())
}

pub const BINARY_LAWS: [&str; 9] = [
    "commutativity: a∧b = b∧a",
    "commutativity: a∨b = b∨a",
    "absorption: a∧(a∨b) = a",
    "absorption: a∨(a∧b) = a",
    "De Morgan: (a∧b)' = a'∨b'",
    "De Morgan: (a∨b)' = a'∧b'",
    "order: a∧b = a ⇔ a∨b = b",
    "area: |a∧b| + |a∨b| = |a| + |b|",
    "area: |a∖b| = |a| − |a∧b|",
];

/// The results of one binary case, for further oracles.
pub struct BinaryOut {
    pub meet: Y,
    pub join: Y,
    pub difference: Y,
    pub symmetric_difference: Y,
    pub complement_a: Y,
}

/// Commutativity, absorption, De Morgan, the order, and the exact area identities (for bounded
/// a and b) for one ordered pair.
pub fn binary(t: &mut Tally, a: &Y, b: &Y) -> Result<BinaryOut, String> {
    let ab = || format!("a = {}, b = {}", show(a), show(b));
    valid_input(a, "a")?;
    valid_input(b, "b")?;
    let m = ok(a.meet(b), "a∧b")?;
    let j = ok(a.join(b), "a∨b")?;
    let (na, nb) = (ok(a.complement(), "a'")?, ok(b.complement(), "b'")?);
    let cases: [(usize, Y, Y); 6] = [
        (0, m.clone(), ok(b.meet(a), "b∧a")?),
        (1, j.clone(), ok(b.join(a), "b∨a")?),
        (2, ok(a.meet(&j), "a∧(a∨b)")?, a.clone()),
        (3, ok(a.join(&m), "a∨(a∧b)")?, a.clone()),
        (4, ok(m.complement(), "(a∧b)'")?, ok(na.join(&nb), "a'∨b'")?),
        (5, ok(j.complement(), "(a∨b)'")?, ok(na.meet(&nb), "a'∧b'")?),
    ];
    for (k, l, r) in &cases {
        law(t, BINARY_LAWS[*k], l == r, || {
            format!("{}{}", ab(), neq(l, r))
        })?;
    }
    let le_meet = m == *a;
    law(
        t,
        BINARY_LAWS[6],
        le_meet == (j == *b) && le_meet == a.is_subset(b),
        || format!("{}: a∧b = a is {le_meet}, a∨b = b is {}", ab(), j == *b),
    )?;
    let d = ok(a.difference(b), "a∖b")?;
    if let (Some(x), Some(y)) = (a.area(), b.area()) {
        let (am, aj, ad) = (m.area(), j.area(), d.area());
        law(
            t,
            BINARY_LAWS[7],
            matches!((&am, &aj), (Some(p), Some(q)) if p.clone() + q.clone() == x.clone() + y),
            || format!("{}: |a∧b| = {am:?}, |a∨b| = {aj:?}", ab()),
        )?;
        law(
            t,
            BINARY_LAWS[8],
            matches!((&ad, &am), (Some(p), Some(q)) if p.clone() == x - q.clone()),
            || format!("{}: |a∖b| = {ad:?}, |a∧b| = {am:?}", ab()),
        )?;
    }
    let x = ok(a.symmetric_difference(b), "a⊕b")?;
    Ok(BinaryOut {
        meet: m,
        join: j,
        difference: d,
        symmetric_difference: x,
        complement_a: na,
    })
}

pub const TERNARY_LAWS: [&str; 4] = [
    "associativity: (a∧b)∧c = a∧(b∧c)",
    "associativity: (a∨b)∨c = a∨(b∨c)",
    "distributivity: a∧(b∨c) = (a∧b)∨(a∧c)",
    "distributivity: a∨(b∧c) = (a∨b)∧(a∨c)",
];

/// Associativity and both distributive laws for one ordered triple.
pub fn ternary(t: &mut Tally, a: &Y, b: &Y, c: &Y) -> Res {
    let abc = || format!("a = {}, b = {}, c = {}", show(a), show(b), show(c));
    for (y, what) in [(a, "a"), (b, "b"), (c, "c")] {
        valid_input(y, what)?;
    }
    let (ab_m, ab_j) = (ok(a.meet(b), "a∧b")?, ok(a.join(b), "a∨b")?);
    let (bc_m, bc_j) = (ok(b.meet(c), "b∧c")?, ok(b.join(c), "b∨c")?);
    let (ac_m, ac_j) = (ok(a.meet(c), "a∧c")?, ok(a.join(c), "a∨c")?);
    let cases: [(usize, Y, Y); 4] = [
        (
            0,
            ok(ab_m.meet(c), "(a∧b)∧c")?,
            ok(a.meet(&bc_m), "a∧(b∧c)")?,
        ),
        (
            1,
            ok(ab_j.join(c), "(a∨b)∨c")?,
            ok(a.join(&bc_j), "a∨(b∨c)")?,
        ),
        (
            2,
            ok(a.meet(&bc_j), "a∧(b∨c)")?,
            ok(ab_m.join(&ac_m), "(a∧b)∨(a∧c)")?,
        ),
        (
            3,
            ok(a.join(&bc_m), "a∨(b∧c)")?,
            ok(ab_j.meet(&ac_j), "(a∨b)∧(a∨c)")?,
        ),
    ];
    for (k, l, r) in &cases {
        law(t, TERNARY_LAWS[*k], l == r, || {
            format!("{}{}", abc(), neq(l, r))
        })?;
    }
    Ok(())
}

/// Points of a lattice offset so that they avoid the small-grid shapes' edges most of the time
/// (those that do not are skipped by [`membership`]).
pub fn probe_points() -> Vec<Point<Rational>> {
    let mut v = Vec::new();
    for i in -2..=14i64 {
        for j in -2..=14i64 {
            v.push(Point::new(
                Rational::new((7 * i + 2).into(), 14.into()),
                Rational::new((11 * j + 3).into(), 22.into()),
            ));
        }
    }
    v
}

pub const MEMBERSHIP: &str = "membership: locate(p, a op b) = locate(p, a) op locate(p, b)";

/// The point-membership oracle: for every point off ∂a and ∂b, the location in a∧b, a∨b,
/// a∖b, a⊕b and a' is the Boolean combination of the locations in a and b, and never on the
/// boundary. Counts one case per point and operation.
pub fn membership(t: &mut Tally, a: &Y, b: &Y, out: &BinaryOut, pts: &[Point<Rational>]) -> Res {
    let (la, lb) = (a.locate(pts), b.locate(pts));
    type Op = fn(bool, bool) -> bool;
    let ops: [(&str, &Y, Op); 5] = [
        ("∧", &out.meet, |p, q| p && q),
        ("∨", &out.join, |p, q| p || q),
        ("∖", &out.difference, |p, q| p && !q),
        ("⊕", &out.symmetric_difference, |p, q| p != q),
        ("'", &out.complement_a, |p, _| !p),
    ];
    for (name, r, f) in ops {
        let lr = r.locate(pts);
        for k in 0..pts.len() {
            if la[k] == Location::OnBoundary || lb[k] == Location::OnBoundary {
                continue;
            }
            let want = if f(la[k] == Location::Inside, lb[k] == Location::Inside) {
                Location::Inside
            } else {
                Location::Outside
            };
            law(t, MEMBERSHIP, lr[k] == want, || {
                format!(
                    "a {name} b at {}: {:?}, expected {want:?}\n  a = {}\n  b = {}",
                    pts[k],
                    lr[k],
                    show(a),
                    show(b)
                )
            })?;
        }
    }
    Ok(())
}

pub const CELL_ORACLE: [&str; 4] = [
    "cells: kernel result = set traced from the mask",
    "cells: Betti numbers = flood-fill counts",
    "cells: area = sum of the pieces",
    "cells: locate(piece centroid) = mask bit",
];

/// The grid-cell oracle for one kernel result `y` that should be the union of pieces `s`:
/// `y == expected` (the set traced from the mask independently of the kernel's operations),
/// its Betti numbers equal the flood-fill counts, its area the sum of the pieces, and each
/// piece centroid (and a point outside the window) is located as the mask says.
pub fn cells_check(t: &mut Tally, cx: &Complex, s: Cells, y: &Y, expected: &Y, what: &str) -> Res {
    law(t, CELL_ORACLE[0], y == expected, || {
        format!("{what} on {} ({s:?}){}", cx.name, neq(y, expected))
    })?;
    let want = cx.betti(s);
    let got = y.betti();
    let mut holes = got.holes.clone();
    holes.sort_unstable();
    law(
        t,
        CELL_ORACLE[1],
        got.components == want.components
            && holes == want.holes_sorted
            && got.total_holes == want.total_holes,
        || {
            format!(
                "{what} on {} ({s:?}): kernel {got:?}, expected {want:?}",
                cx.name
            )
        },
    )?;
    let (ga, wa) = (y.area(), cx.area(s));
    law(t, CELL_ORACLE[2], ga == wa, || {
        format!(
            "{what} on {} ({s:?}): area {ga:?}, expected {wa:?}",
            cx.name
        )
    })?;
    let pts: Vec<_> = cx.probes().into_iter().map(|(_, p)| p).collect();
    let (gl, wl) = (y.locate(&pts), cx.expected_locations(s));
    law(t, CELL_ORACLE[3], gl == wl, || {
        format!(
            "{what} on {} ({s:?}): located {gl:?}, expected {wl:?}",
            cx.name
        )
    })
}

/// The grid-cell oracle on all results of one binary case: a∧b, a∨b, a∖b, a⊕b and a' against
/// the bitwise operations on the masks.
pub fn cells_binary(
    t: &mut Tally,
    cx: &Complex,
    (a, b): (Cells, Cells),
    out: &BinaryOut,
    expected: &dyn Fn(Cells) -> Y,
) -> Res {
    let n = cx.len();
    let cases: [(&str, Cells, &Y); 5] = [
        ("a∧b", a.and(b), &out.meet),
        ("a∨b", a.or(b), &out.join),
        ("a∖b", a.minus(b, n), &out.difference),
        ("a⊕b", a.xor(b), &out.symmetric_difference),
        ("a'", a.not(n), &out.complement_a),
    ];
    for (what, s, y) in cases {
        cells_check(t, cx, s, y, &expected(s), what)?;
    }
    let order = out.meet == expected(a);
    law(
        t,
        "cells: a∧b = a ⇔ mask(a) ⊆ mask(b)",
        order == a.le(b),
        || format!("on {}: a = {a:?}, b = {b:?}", cx.name),
    )
}
