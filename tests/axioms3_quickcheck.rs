//! The Boolean-algebra axioms in 3D, checked exactly with `==` on 3D Yin sets by quickcheck,
//! with `Arbitrary` + `shrink` on the shape programs of tests/common/gen3.rs and the law
//! definitions shared with the 2D suites (tests/kit/src/laws.rs). Every kernel output passes
//! the exact validator. Case counts: `AXIOM3_CASES` (default below).

mod common;
use common::gen3::{features3, probe_points3, shares3, Shape3, MINIMUM_SHARES3};
use common::laws::{self, Tally};
use common::runner::{cases3, verdict, QPair, QTriple, Shares};
use quickcheck::{Gen, QuickCheck, TestResult};
use std::sync::Mutex;

fn qc(n: u64) -> QuickCheck {
    QuickCheck::new()
        .tests(n)
        .max_tests(4 * n)
        .rng(Gen::new(16))
}

/// Run `n` cases of a property on two threads, each with its own generator (as
/// `runner::run_split` for proptest).
fn qc_split<A: quickcheck::Arbitrary + std::fmt::Debug>(n: u64, prop: fn(A) -> TestResult) {
    std::thread::scope(|scope| {
        for k in 0..2 {
            scope.spawn(move || qc(n / 2 + u64::from(k < n % 2)).quickcheck(prop));
        }
    });
}

static UNARY: Mutex<Tally> = Mutex::new(Tally::new());
static BINARY: Mutex<Tally> = Mutex::new(Tally::new());
static TERNARY: Mutex<Tally> = Mutex::new(Tally::new());
static SHARES: Mutex<Shares<12>> = Mutex::new(shares3());

fn unary_prop(s: Shape3) -> TestResult {
    verdict(&UNARY, |t| laws::unary(t, &s.build()))
}

fn binary_prop(p: QPair<Shape3>) -> TestResult {
    let pts = probe_points3();
    verdict(&BINARY, |t| {
        let (a, b) = (p.0.build(), p.1.build());
        SHARES.lock().unwrap().add(features3(&a, &b));
        let out = laws::binary(t, &a, &b)?;
        laws::membership(t, &a, &b, &out, &pts)
    })
}

fn ternary_prop(p: QTriple<Shape3>) -> TestResult {
    verdict(&TERNARY, |t| {
        laws::ternary(t, &p.0.build(), &p.1.build(), &p.2.build())
    })
}

fn report(tally: &Mutex<Tally>, what: &str, n: u64) {
    eprintln!(
        "{}",
        tally
            .lock()
            .unwrap()
            .report(&format!("quickcheck 3D {what} laws, {n} cases"))
    );
}

#[test]
fn unary_laws_3d() {
    let n = cases3(64) as u64;
    qc(n).quickcheck(unary_prop as fn(Shape3) -> TestResult);
    report(&UNARY, "unary", n);
}

/// The binary laws and the membership law on every generated pair, with the pairs' degenerate
/// features measured, printed and bounded from below.
#[test]
fn binary_laws_and_membership_3d() {
    let n = cases3(512) as u64;
    qc_split(n, binary_prop as fn(QPair<Shape3>) -> TestResult);
    report(&BINARY, "binary", n);
    let shares = SHARES.lock().unwrap();
    eprintln!("{}", shares.report("quickcheck 3D QPair3"));
    shares.assert_minimums(&MINIMUM_SHARES3);
}

#[test]
fn ternary_laws_3d() {
    let n = cases3(64) as u64;
    qc_split(n, ternary_prop as fn(QTriple<Shape3>) -> TestResult);
    report(&TERNARY, "ternary", n);
}
