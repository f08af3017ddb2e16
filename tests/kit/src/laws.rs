//! The Boolean-algebra laws, checked exactly with `==` on Yin sets (seed 000 Thm 4.11), with
//! every kernel output passed through the exact validator. Shared by the proptest and
//! quickcheck suites (2D and 3D) and by proofs/: the laws are written once, generically over
//! [`Algebra`], which both `YinSet2` and `YinSet3` implement; so are the checks of a kernel
//! result against a cell oracle ([`CellOracle`], [`cells_check`], [`cells_binary`]).
//!
//! Each check counts itself in a [`Tally`] under the law's name, so that suites can report how
//! many cases of each law they checked.

use crate::cells::Cells;
use crate::membership::{self, Truth};
use crate::shapes::show3;
use crate::{Y, Y3};
use std::collections::BTreeMap;
use std::fmt::{Debug, Display};
use yinset::kernel::{Point, Point3};
use yinset::num::Rational;
use yinset::yin2::{Location, YinSet2};
use yinset::yin3::YinSet3;

/// What the laws need of a Yin space: the Boolean operations, the exact validator, the measure
/// (area or volume) and point location.
pub trait Algebra: Clone + PartialEq + Debug {
    /// A point of the space.
    type Pt: Clone + Display;
    /// The names of the two measure identities checked by [`binary`].
    const MEASURE_LAWS: [&'static str; 2];
    /// 0̂, the empty set.
    fn zero() -> Self;
    /// 1̂, the whole space.
    fn one() -> Self;
    /// The meet a∧b.
    fn meet(&self, o: &Self) -> Self;
    /// The join a∨b.
    fn join(&self, o: &Self) -> Self;
    /// The complement a'.
    fn complement(&self) -> Self;
    /// The difference a∖b.
    fn difference(&self, o: &Self) -> Self;
    /// The symmetric difference a⊕b.
    fn symmetric_difference(&self, o: &Self) -> Self;
    /// The order, decided otherwise than by `a∧b == a` where the space allows it;
    /// `difference` is `self ∖ o`, already computed and validated.
    fn is_subset(&self, o: &Self, difference: &Self) -> bool;
    /// The public exact validator.
    fn check(&self) -> Result<(), String>;
    /// Area or volume; `None` if unbounded.
    fn measure(&self) -> Option<Rational>;
    /// The location of each point.
    fn locate(&self, pts: &[Self::Pt]) -> Vec<Location>;
    /// A readable description for failure messages.
    fn show(&self) -> String;
}

impl Algebra for Y {
    type Pt = Point<Rational>;
    const MEASURE_LAWS: [&'static str; 2] = [
        "area: |a∧b| + |a∨b| = |a| + |b|",
        "area: |a∖b| = |a| − |a∧b|",
    ];
    fn zero() -> Y {
        YinSet2::empty()
    }
    fn one() -> Y {
        YinSet2::full()
    }
    fn meet(&self, o: &Y) -> Y {
        YinSet2::meet(self, o)
    }
    fn join(&self, o: &Y) -> Y {
        YinSet2::join(self, o)
    }
    fn complement(&self) -> Y {
        YinSet2::complement(self)
    }
    fn difference(&self, o: &Y) -> Y {
        YinSet2::difference(self, o)
    }
    fn symmetric_difference(&self, o: &Y) -> Y {
        YinSet2::symmetric_difference(self, o)
    }
    fn is_subset(&self, o: &Y, _difference: &Y) -> bool {
        YinSet2::is_subset(self, o)
    }
    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
    fn measure(&self) -> Option<Rational> {
        self.area()
    }
    fn locate(&self, pts: &[Point<Rational>]) -> Vec<Location> {
        YinSet2::locate(self, pts)
    }
    fn show(&self) -> String {
        if self.is_empty() {
            return "0̂".into();
        }
        if self.is_full() {
            return "1̂".into();
        }
        let curves: Vec<String> = self
            .curves()
            .iter()
            .map(|c| {
                let v: Vec<String> = c.vertices().iter().map(|p| p.to_string()).collect();
                format!("[{}]", v.join(" "))
            })
            .collect();
        format!("{{{}}}", curves.join(", "))
    }
}

impl Algebra for Y3 {
    type Pt = Point3<Rational>;
    const MEASURE_LAWS: [&'static str; 2] = [
        "volume: |a∧b| + |a∨b| = |a| + |b|",
        "volume: |a∖b| = |a| − |a∧b|",
    ];
    fn zero() -> Y3 {
        YinSet3::empty()
    }
    fn one() -> Y3 {
        YinSet3::full()
    }
    fn meet(&self, o: &Y3) -> Y3 {
        YinSet3::meet(self, o)
    }
    fn join(&self, o: &Y3) -> Y3 {
        YinSet3::join(self, o)
    }
    fn complement(&self) -> Y3 {
        YinSet3::complement(self)
    }
    fn difference(&self, o: &Y3) -> Y3 {
        YinSet3::difference(self, o)
    }
    fn symmetric_difference(&self, o: &Y3) -> Y3 {
        YinSet3::symmetric_difference(self, o)
    }
    /// a ≤ b iff a∖b = a∧b' = 0̂ (the kernel's `is_subset` is `a∧b == a`, which the order
    /// law compares against already).
    fn is_subset(&self, _o: &Y3, difference: &Y3) -> bool {
        difference.is_empty()
    }
    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
    fn measure(&self) -> Option<Rational> {
        self.volume()
    }
    fn locate(&self, pts: &[Point3<Rational>]) -> Vec<Location> {
        YinSet3::locate(self, pts)
    }
    /// 0̂, 1̂, or the boundary's triangles (outward normals) and whether it is bounded.
    fn show(&self) -> String {
        show3(self)
    }
}

/// The first failure, described.
pub type Res = Result<(), String>;

/// Cases checked, per law.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// Cases checked, by the law's name.
    pub counts: BTreeMap<&'static str, u64>,
}

impl Tally {
    /// No cases yet.
    pub const fn new() -> Tally {
        Tally {
            counts: BTreeMap::new(),
        }
    }

    /// Add another tally's counts.
    pub fn merge(&mut self, other: &Tally) {
        for (k, v) in &other.counts {
            *self.counts.entry(k).or_default() += v;
        }
    }

    /// Cases checked, all laws together.
    pub fn total(&self) -> u64 {
        self.counts.values().sum()
    }

    /// The counts as a table under `title`.
    pub fn report(&self, title: &str) -> String {
        let mut s = format!("{title}: {} checks\n", self.total());
        for (k, v) in &self.counts {
            s += &format!("  {v:>10}  {k}\n");
        }
        s
    }
}

/// Validate a kernel output (seed 000 Def. 3.17, Thm 3.21) and pass it on.
pub fn ok<A: Algebra>(y: A, what: &str) -> Result<A, String> {
    y.check()
        .map_err(|e| format!("the validator rejects {what}: {e}\n{y:?}"))?;
    Ok(y)
}

/// Validate an input (e.g. a generated set, itself a kernel output).
pub fn valid_input<A: Algebra>(y: &A, what: &str) -> Res {
    y.check()
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

fn show<A: Algebra>(y: &A) -> String {
    y.show()
}

fn neq<A: Algebra>(l: &A, r: &A) -> String {
    format!("\n  left  = {}\n  right = {}", show(l), show(r))
}

/// The laws [`unary`] checks.
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
pub fn unary<A: Algebra>(t: &mut Tally, a: &A) -> Res {
    valid_input(a, "a")?;
    let (zero, one) = (A::zero(), A::one());
    let na = ok(a.complement(), "a'")?;
    let cases: [(usize, A, &A); 9] = [
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

/// The binary laws; [`binary`] also checks the two measure identities
/// [`Algebra::MEASURE_LAWS`].
pub const BINARY_LAWS: [&str; 7] = [
    "commutativity: a∧b = b∧a",
    "commutativity: a∨b = b∨a",
    "absorption: a∧(a∨b) = a",
    "absorption: a∨(a∧b) = a",
    "De Morgan: (a∧b)' = a'∨b'",
    "De Morgan: (a∨b)' = a'∧b'",
    "order: a∧b = a ⇔ a∨b = b",
];

/// The results of one binary case, for further oracles.
pub struct BinaryOut<A> {
    /// a∧b.
    pub meet: A,
    /// a∨b.
    pub join: A,
    /// a∖b.
    pub difference: A,
    /// a⊕b.
    pub symmetric_difference: A,
    /// a'.
    pub complement_a: A,
}

/// Commutativity, absorption, De Morgan, the order, and the exact measure identities (for
/// bounded a and b) for one ordered pair.
pub fn binary<A: Algebra>(t: &mut Tally, a: &A, b: &A) -> Result<BinaryOut<A>, String> {
    let ab = || format!("a = {}, b = {}", show(a), show(b));
    valid_input(a, "a")?;
    valid_input(b, "b")?;
    let m = ok(a.meet(b), "a∧b")?;
    let j = ok(a.join(b), "a∨b")?;
    let (na, nb) = (ok(a.complement(), "a'")?, ok(b.complement(), "b'")?);
    let cases: [(usize, A, A); 6] = [
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
    let d = ok(a.difference(b), "a∖b")?;
    let le_meet = m == *a;
    law(
        t,
        BINARY_LAWS[6],
        le_meet == (j == *b) && le_meet == a.is_subset(b, &d),
        || format!("{}: a∧b = a is {le_meet}, a∨b = b is {}", ab(), j == *b),
    )?;
    if let (Some(x), Some(y)) = (a.measure(), b.measure()) {
        let (am, aj, ad) = (m.measure(), j.measure(), d.measure());
        law(
            t,
            A::MEASURE_LAWS[0],
            matches!((&am, &aj), (Some(p), Some(q)) if p.clone() + q.clone() == x.clone() + y),
            || format!("{}: |a∧b| = {am:?}, |a∨b| = {aj:?}", ab()),
        )?;
        law(
            t,
            A::MEASURE_LAWS[1],
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

/// The laws [`ternary`] checks.
pub const TERNARY_LAWS: [&str; 4] = [
    "associativity: (a∧b)∧c = a∧(b∧c)",
    "associativity: (a∨b)∨c = a∨(b∨c)",
    "distributivity: a∧(b∨c) = (a∧b)∨(a∧c)",
    "distributivity: a∨(b∧c) = (a∨b)∧(a∨c)",
];

/// Associativity and both distributive laws for one ordered triple.
pub fn ternary<A: Algebra>(t: &mut Tally, a: &A, b: &A, c: &A) -> Res {
    let abc = || format!("a = {}, b = {}, c = {}", show(a), show(b), show(c));
    for (y, what) in [(a, "a"), (b, "b"), (c, "c")] {
        valid_input(y, what)?;
    }
    let (ab_m, ab_j) = (ok(a.meet(b), "a∧b")?, ok(a.join(b), "a∨b")?);
    let (bc_m, bc_j) = (ok(b.meet(c), "b∧c")?, ok(b.join(c), "b∨c")?);
    let (ac_m, ac_j) = (ok(a.meet(c), "a∧c")?, ok(a.join(c), "a∨c")?);
    let cases: [(usize, A, A); 4] = [
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

/// The name of the membership law.
pub const MEMBERSHIP: &str = "membership: locate(p, a op b) = locate(p, a) op locate(p, b)";

/// The point-membership oracle: for every point off ∂a and ∂b, the location in a∧b, a∨b,
/// a∖b, a⊕b and a' is the Boolean combination of the locations in a and b, and never on the
/// boundary. Counts one case per point and operation.
pub fn membership<A: Algebra>(
    t: &mut Tally,
    a: &A,
    b: &A,
    out: &BinaryOut<A>,
    pts: &[A::Pt],
) -> Res {
    let (la, lb) = (a.locate(pts), b.locate(pts));
    let ops: [(&str, &A, Truth); 5] = [
        ("∧", &out.meet, membership::MEET),
        ("∨", &out.join, membership::JOIN),
        ("∖", &out.difference, membership::DIFFERENCE),
        (
            "⊕",
            &out.symmetric_difference,
            membership::SYMMETRIC_DIFFERENCE,
        ),
        ("'", &out.complement_a, membership::COMPLEMENT_A),
    ];
    for (name, r, f) in ops {
        let lr = r.locate(pts);
        for (k, got, want) in membership::judged(&la, &lb, &lr, f) {
            law(t, MEMBERSHIP, got == want, || {
                format!(
                    "a {name} b at {}: {got:?}, expected {want:?}\n  a = {}\n  b = {}",
                    pts[k],
                    show(a),
                    show(b)
                )
            })?;
        }
    }
    Ok(())
}

/// A cell oracle: a universe of sets indexed by [`Cells`] masks, whose Boolean algebra is
/// bitwise on the masks, and which reads the invariants of each set off its mask.
pub trait CellOracle {
    /// The sets of the universe.
    type Set: Algebra;
    /// The name of the law `kernel result = expected set`.
    const SAME: &'static str;
    /// The universe's name, for failure messages.
    fn name(&self) -> &str;
    /// The number of cells (bits of a mask).
    fn cells(&self) -> usize;
    /// The invariants of a set `y` that should be the union `s`, read off the mask (Betti
    /// numbers, measure, locations), each counted as a law.
    fn invariants(&self, t: &mut Tally, s: Cells, y: &Self::Set, what: &str) -> Res;
}

/// The cell oracle for one kernel result `y` that should be the union `s`: `y == expected`
/// (the set built from the mask independently of the kernel's operations), and the invariants
/// of [`CellOracle::invariants`].
pub fn cells_check<O: CellOracle>(
    t: &mut Tally,
    o: &O,
    s: Cells,
    y: &O::Set,
    expected: &O::Set,
    what: &str,
) -> Res {
    law(t, O::SAME, y == expected, || {
        format!("{what} on {} ({s:?}){}", o.name(), neq(y, expected))
    })?;
    o.invariants(t, s, y, what)
}

/// The name of the order law against mask inclusion.
pub const CELL_ORDER: &str = "cells: a∧b = a ⇔ mask(a) ⊆ mask(b)";

/// The cell oracle on all results of one binary case: a∧b, a∨b, a∖b, a⊕b and a' against the
/// bitwise operations on the masks (`expected` gives the set of a mask), and the order against
/// mask inclusion.
pub fn cells_binary<O: CellOracle>(
    t: &mut Tally,
    o: &O,
    (a, b): (Cells, Cells),
    out: &BinaryOut<O::Set>,
    expected: &dyn Fn(Cells) -> O::Set,
) -> Res {
    let n = o.cells();
    let cases: [(&str, Cells, &O::Set); 5] = [
        ("a∧b", a.and(b), &out.meet),
        ("a∨b", a.or(b), &out.join),
        ("a∖b", a.minus(b, n), &out.difference),
        ("a⊕b", a.xor(b), &out.symmetric_difference),
        ("a'", a.not(n), &out.complement_a),
    ];
    for (what, s, y) in cases {
        cells_check(t, o, s, y, &expected(s), what)?;
    }
    let order = out.meet == expected(a);
    law(t, CELL_ORDER, order == a.le(b), || {
        format!("on {}: a = {a:?}, b = {b:?}", o.name())
    })
}
