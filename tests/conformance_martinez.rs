//! Issue 7: the Martinez–Rueda cases (`../shared/data/2d/martinez`) in exact and float mode.
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
fn martinez_cases_exact() {
    if !common::data_available() {
        return;
    }
    let report = run_exact(&martinez_cases::<Rational>());
    report.print_and_check("Martinez exact", PINNED);
}

#[test]
fn martinez_cases_float() {
    if !common::data_available() {
        return;
    }
    let report = run_float(&martinez_cases::<Rational>(), &martinez_cases::<Float>());
    report.print_and_check("Martinez float", FLOAT_PINNED);
}
