//! Running a checked property under proptest (or quickcheck) with a tally of the laws it
//! checked.

use super::laws::Tally;
use proptest::strategy::Strategy;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use quickcheck::TestResult;
use std::sync::Mutex;

/// Cases per property (override with the environment variable `AXIOM_CASES`).
pub fn cases(default: u32) -> u32 {
    env_cases("AXIOM_CASES", default)
}

/// Cases per 3D property (override with the environment variable `AXIOM3_CASES`; 3D cases
/// cost about a hundred times more than 2D ones, hence a separate knob).
pub fn cases3(default: u32) -> u32 {
    env_cases("AXIOM3_CASES", default)
}

fn env_cases(var: &str, default: u32) -> u32 {
    std::env::var(var)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Turn a law check into a quickcheck result, counting into `tally`.
pub fn verdict(
    tally: &Mutex<Tally>,
    check: impl FnOnce(&mut Tally) -> Result<(), String>,
) -> TestResult {
    let mut t = Tally::default();
    let r = check(&mut t);
    tally.lock().unwrap().merge(&t);
    match r {
        Ok(()) => TestResult::passed(),
        Err(e) => TestResult::error(e),
    }
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
    run_into(&tally, label, n, &strategy, &check);
    eprintln!(
        "{}",
        tally.lock().unwrap().report(&format!("{label}, {n} cases"))
    );
}

/// As [`run`], with the cases split over `threads` threads, each with its own runner (for
/// expensive properties: the test harness runs a file's tests on as many threads as there
/// are cores, and one long property would otherwise keep the others waiting).
pub fn run_split<S: Strategy + Sync>(
    label: &str,
    n: u32,
    threads: u32,
    strategy: S,
    check: impl Fn(&mut Tally, S::Value) -> Result<(), String> + Sync,
) where
    S::Value: Clone + std::fmt::Debug,
{
    let tally = Mutex::new(Tally::default());
    std::thread::scope(|scope| {
        for k in 0..threads {
            let part = n / threads + u32::from(k < n % threads);
            let (tally, strategy, check) = (&tally, &strategy, &check);
            scope.spawn(move || run_into(tally, label, part, strategy, check));
        }
    });
    eprintln!(
        "{}",
        tally.lock().unwrap().report(&format!("{label}, {n} cases"))
    );
}

/// Run `check` on `n` values of `strategy`, counting into `tally`; panic on failure.
fn run_into<S: Strategy>(
    tally: &Mutex<Tally>,
    label: &str,
    n: u32,
    strategy: &S,
    check: &impl Fn(&mut Tally, S::Value) -> Result<(), String>,
) where
    S::Value: Clone + std::fmt::Debug,
{
    let mut runner = TestRunner::new(Config {
        cases: n,
        failure_persistence: None,
        ..Config::default()
    });
    let result = runner.run(strategy, |v| {
        let mut t = Tally::default();
        let r = check(&mut t, v);
        tally.lock().unwrap().merge(&t);
        r.map_err(TestCaseError::fail)
    });
    if let Err(e) = result {
        panic!("{label}: {e}");
    }
}
