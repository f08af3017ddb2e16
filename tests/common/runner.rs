//! Running a checked property under proptest with a tally of the laws it checked.

use super::laws::Tally;
use proptest::strategy::Strategy;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::sync::Mutex;

/// Cases per property (override with the environment variable `AXIOM_CASES`).
pub fn cases(default: u32) -> u32 {
    std::env::var("AXIOM_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Run `check` on `n` values of `strategy` (with shrinking on failure), then print the tally
/// of checks per law under `label`.
pub fn run<S: Strategy>(
    label: &str,
    n: u32,
    strategy: S,
    check: impl Fn(&mut Tally, S::Value) -> Result<(), String>,
) where
    S::Value: Clone + std::fmt::Debug,
{
    let tally = Mutex::new(Tally::default());
    let mut runner = TestRunner::new(Config {
        cases: n,
        failure_persistence: None,
        ..Config::default()
    });
    let result = runner.run(&strategy, |v| {
        let mut t = Tally::default();
        let r = check(&mut t, v);
        tally.lock().unwrap().merge(&t);
        r.map_err(TestCaseError::fail)
    });
    if let Err(e) = result {
        panic!("{label}: {e}");
    }
    eprintln!(
        "{}",
        tally.lock().unwrap().report(&format!("{label}, {n} cases"))
    );
}
