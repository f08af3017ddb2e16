//! Issue 7: the JTS overlay suites (`../shared/data/2d/jts`) in exact and float mode.
//! Run with `--nocapture` to see the per-suite report.

mod common;
mod conformance;
use conformance::*;
use yinset::num::{Float, Rational};

/// Failures in exact mode: (case, operation, reason), each a difference of model.
const PINNED: &[(&str, &str, &str)] = &[];

/// Failures in float mode: (case, operation, reason).
const FLOAT_PINNED: &[(&str, &str, &str)] = &[];

#[test]
fn jts_overlay_suites_exact() {
    if !common::data_available() {
        return;
    }
    let report = run_exact(&jts_cases::<Rational>());
    report.print_and_check("JTS exact", PINNED);
}

#[test]
fn jts_overlay_suites_float() {
    if !common::data_available() {
        return;
    }
    let report = run_float(&jts_cases::<Rational>(), &jts_cases::<Float>());
    report.print_and_check("JTS float", FLOAT_PINNED);
}
