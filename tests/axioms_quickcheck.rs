//! The Boolean-algebra axioms of the Jordan space (seed 000 Thm 4.11), checked exactly with
//! `==` on Yin sets by quickcheck, with `Arbitrary` + `shrink` on the shape programs of
//! tests/common/gen.rs. Every kernel output passes the exact validator. Case counts:
//! `AXIOM_CASES` (default below).

mod common;
use common::gen::{feature_stats, Features, Shape};
use common::laws::{self, Tally};
use common::runner::{verdict, QPair, QTriple};
use quickcheck::{Arbitrary, Gen, QuickCheck, TestResult};
use std::sync::Mutex;

/// `AXIOM_CASES` or `default`, at most `YINSET_CASES` (as the proptest suites).
fn cases(default: u32) -> u64 {
    common::runner::cases(default).into()
}

fn qc(n: u64) -> QuickCheck {
    QuickCheck::new()
        .tests(n)
        .max_tests(4 * n)
        .rng(Gen::new(16))
}

static UNARY: Mutex<Tally> = Mutex::new(Tally::new());
static BINARY: Mutex<Tally> = Mutex::new(Tally::new());
static TERNARY: Mutex<Tally> = Mutex::new(Tally::new());

fn unary_prop(s: Shape) -> TestResult {
    verdict(&UNARY, |t| laws::unary(t, &s.build()))
}

fn binary_prop(p: QPair<Shape>) -> TestResult {
    let pts = laws::probe_points();
    verdict(&BINARY, |t| {
        let (a, b) = (p.0.build(), p.1.build());
        let out = laws::binary(t, &a, &b)?;
        laws::membership(t, &a, &b, &out, &pts)
    })
}

fn ternary_prop(p: QTriple<Shape>) -> TestResult {
    verdict(&TERNARY, |t| {
        laws::ternary(t, &p.0.build(), &p.1.build(), &p.2.build())
    })
}

#[test]
fn unary_laws() {
    let n = cases(512);
    qc(n).quickcheck(unary_prop as fn(Shape) -> TestResult);
    eprintln!(
        "{}",
        UNARY
            .lock()
            .unwrap()
            .report(&format!("quickcheck unary laws, {n} cases"))
    );
}

#[test]
fn binary_laws_and_membership() {
    let n = cases(512);
    qc(n).quickcheck(binary_prop as fn(QPair<Shape>) -> TestResult);
    eprintln!(
        "{}",
        BINARY
            .lock()
            .unwrap()
            .report(&format!("quickcheck binary laws, {n} cases"))
    );
}

#[test]
fn ternary_laws() {
    let n = cases(256);
    qc(n).quickcheck(ternary_prop as fn(QTriple<Shape>) -> TestResult);
    eprintln!(
        "{}",
        TERNARY
            .lock()
            .unwrap()
            .report(&format!("quickcheck ternary laws, {n} cases"))
    );
}

/// The share of generated pairs showing each degenerate feature, on a fixed seed, bounded
/// from below.
#[test]
fn generator_produces_degenerate_cases() {
    let mut g = Gen::from_size_and_seed(16, 0x5eed);
    let mut stats = feature_stats();
    for _ in 0..400 {
        let QPair(a, b) = QPair::<Shape>::arbitrary(&mut g);
        stats.add(Features::of(&a.build(), &b.build()).as_array());
    }
    eprintln!("{}", stats.report("quickcheck QPair"));
    stats.assert_minimums(&[
        0.35, 0.30, 0.15, 0.20, 0.05, 0.05, 0.25, 0.25, 0.05, 0.20, 0.04, 0.35,
    ]);
}

static LAST_FAILURE: Mutex<Option<QPair<Shape>>> = Mutex::new(None);

fn false_law(p: QPair<Shape>) -> TestResult {
    let (x, y) = (p.0.build(), p.1.build());
    let m = x.meet(&y);
    let holds = m == x || m == y;
    if !holds {
        *LAST_FAILURE.lock().unwrap() = Some(p);
    }
    TestResult::from_bool(holds)
}

/// Shrinking yields small counterexamples: quickcheck refutes a false "law" (a∧b is always a or
/// b) and shrinks the counterexample to at most one step per shape.
#[test]
fn shrinking_yields_small_counterexamples() {
    let r = QuickCheck::new()
        .tests(256)
        .rng(Gen::from_size_and_seed(16, 7))
        .quicktest(false_law as fn(QPair<Shape>) -> TestResult);
    assert!(r.is_err(), "the false law was not refuted");
    let QPair(a, b) = LAST_FAILURE.lock().unwrap().clone().unwrap();
    eprintln!("shrunk counterexample: a = {a:?}\n                       b = {b:?}");
    assert!(
        a.steps.len() <= 1 && b.steps.len() <= 1,
        "not shrunk: {a:?} {b:?}"
    );
}
