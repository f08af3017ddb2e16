//! The Boolean-algebra axioms in 3D (seed 000 Thm 4.11 for the 3D Yin space, seed 003), checked
//! exactly with `==` on 3D Yin sets by proptest, on generators biased to degeneracy
//! (tests/common/gen3.rs): the same law definitions as the 2D suites (tests/kit/src/laws.rs).
//! Every kernel output passes the exact validator. Case counts: `AXIOM3_CASES` (default below).

mod common;
use common::gen3::{features3, probe_points3, shares3, strategies, MINIMUM_SHARES3};
use common::laws;
use common::runner::{cases3, run, run_split};
use std::sync::Mutex;

#[test]
fn unary_laws_3d() {
    run(
        "proptest 3D unary laws",
        cases3(64),
        strategies::shape(),
        |t, s| laws::unary(t, &s.build()),
    );
}

/// The binary laws and the membership law on every generated pair, with the pairs' degenerate
/// features measured, printed and bounded from below.
#[test]
fn binary_laws_and_membership_3d() {
    let pts = probe_points3();
    let shares = Mutex::new(shares3());
    run_split(
        "proptest 3D binary laws",
        cases3(512),
        2,
        strategies::pair(),
        |t, (a, b)| {
            let (a, b) = (a.build(), b.build());
            shares.lock().unwrap().add(features3(&a, &b));
            let out = laws::binary(t, &a, &b)?;
            laws::membership(t, &a, &b, &out, &pts)
        },
    );
    let shares = shares.into_inner().unwrap();
    eprintln!("{}", shares.report("proptest 3D pair()"));
    shares.assert_minimums(&MINIMUM_SHARES3);
}

#[test]
fn ternary_laws_3d() {
    run_split(
        "proptest 3D ternary laws",
        cases3(64),
        2,
        strategies::triple(),
        |t, (a, b, c)| laws::ternary(t, &a.build(), &b.build(), &c.build()),
    );
}
