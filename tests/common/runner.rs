//! Running a checked property under proptest (or quickcheck) with a tally of the laws it
//! checked.

use super::laws::Tally;
use proptest::strategy::Strategy;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use quickcheck::{Arbitrary, Gen, TestResult};
use std::sync::Mutex;

/// Cases per property (override with the environment variable `AXIOM_CASES`; at most
/// `YINSET_CASES`).
pub fn cases(default: u32) -> u32 {
    env_cases("AXIOM_CASES", default)
}

/// Cases per 3D property (override with the environment variable `AXIOM3_CASES`; 3D cases
/// cost about a hundred times more than 2D ones, hence a separate knob).
pub fn cases3(default: u32) -> u32 {
    env_cases("AXIOM3_CASES", default)
}

/// `default`, or the value of `var` when set; at most `YINSET_CASES` either way.
fn env_cases(var: &str, default: u32) -> u32 {
    yinset_testkit::cases(
        std::env::var(var)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(default),
    )
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

/// A shape program that quickcheck generates, relates to another (the further operands of
/// [`QPair`] and [`QTriple`], often derived from the first) and shrinks.
pub trait Program: Arbitrary {
    /// A program related to `a`.
    fn related(g: &mut Gen, a: &Self) -> Self;
    /// Smaller variants, for shrinking.
    fn smaller(&self) -> Vec<Self>;
}

/// A pair of programs, the second related to the first.
#[derive(Clone, Debug)]
pub struct QPair<S>(pub S, pub S);

/// A triple of programs, the second and third related to the first.
#[derive(Clone, Debug)]
pub struct QTriple<S>(pub S, pub S, pub S);

impl<S: Program> Arbitrary for QPair<S> {
    fn arbitrary(g: &mut Gen) -> QPair<S> {
        let a = S::arbitrary(g);
        let b = S::related(g, &a);
        QPair(a, b)
    }

    /// The first shrunk, then the second.
    fn shrink(&self) -> Box<dyn Iterator<Item = QPair<S>>> {
        let (a, b) = (self.0.clone(), self.1.clone());
        let mut v: Vec<QPair<S>> = Vec::new();
        v.extend(a.smaller().into_iter().map(|x| QPair(x, b.clone())));
        v.extend(b.smaller().into_iter().map(|y| QPair(a.clone(), y)));
        Box::new(v.into_iter())
    }
}

impl<S: Program> Arbitrary for QTriple<S> {
    fn arbitrary(g: &mut Gen) -> QTriple<S> {
        let a = S::arbitrary(g);
        let b = S::related(g, &a);
        let c = S::related(g, &a);
        QTriple(a, b, c)
    }

    /// Each of the three shrunk in turn.
    fn shrink(&self) -> Box<dyn Iterator<Item = QTriple<S>>> {
        let (a, b, c) = (self.0.clone(), self.1.clone(), self.2.clone());
        let mut v: Vec<QTriple<S>> = Vec::new();
        v.extend(
            a.smaller()
                .into_iter()
                .map(|x| QTriple(x, b.clone(), c.clone())),
        );
        v.extend(
            b.smaller()
                .into_iter()
                .map(|y| QTriple(a.clone(), y, c.clone())),
        );
        v.extend(
            c.smaller()
                .into_iter()
                .map(|z| QTriple(a.clone(), b.clone(), z)),
        );
        Box::new(v.into_iter())
    }
}

/// Counts of a generator's degenerate features over a sample of pairs.
#[derive(Clone, Debug)]
pub struct Shares<const N: usize> {
    /// The features' names.
    names: &'static [&'static str; N],
    /// The fewest pairs on which [`Shares::assert_minimums`] asserts anything.
    min_pairs: usize,
    /// Pairs seen.
    pub pairs: usize,
    /// Pairs showing each feature.
    pub counts: [usize; N],
}

impl<const N: usize> Shares<N> {
    /// No pairs yet, of the features `names`, asserted on samples of at least `min_pairs`.
    pub const fn new(names: &'static [&'static str; N], min_pairs: usize) -> Shares<N> {
        Shares {
            names,
            min_pairs,
            pairs: 0,
            counts: [0; N],
        }
    }

    /// Count one pair showing the features `f`.
    pub fn add(&mut self, f: [bool; N]) {
        self.pairs += 1;
        for (c, on) in self.counts.iter_mut().zip(f) {
            *c += usize::from(on);
        }
    }

    /// The share of the pairs that show feature `k`.
    pub fn share(&self, k: usize) -> f64 {
        self.counts[k] as f64 / self.pairs.max(1) as f64
    }

    /// The shares as a table.
    pub fn report(&self, who: &str) -> String {
        let width = self
            .names
            .iter()
            .map(|n| n.chars().count())
            .max()
            .unwrap_or(0);
        let mut s = format!(
            "degenerate-case statistics of {who} over {} pairs:\n",
            self.pairs
        );
        for (k, name) in self.names.iter().enumerate() {
            s += &format!(
                "  {name:<width$} {:>5.1}%  ({})\n",
                100.0 * self.share(k),
                self.counts[k]
            );
        }
        s
    }

    /// Panic if any feature occurs in less than its minimum share (on samples of at least
    /// the minimum number of pairs).
    pub fn assert_minimums(&self, min: &[f64; N]) {
        if self.pairs < self.min_pairs {
            eprintln!("(only {} pairs: minimum shares not asserted)", self.pairs);
            return;
        }
        for (k, name) in self.names.iter().enumerate() {
            assert!(
                self.share(k) >= min[k],
                "generator no longer produces '{name}' often enough: {:.1}% < {:.1}%",
                100.0 * self.share(k),
                100.0 * min[k]
            );
        }
    }
}

/// A quickcheck draw in lo..=hi.
pub fn qc_range(g: &mut Gen, lo: i64, hi: i64) -> i64 {
    lo + i64::from(u32::arbitrary(g)).rem_euclid(hi - lo + 1)
}

/// A quickcheck coin that shows true with probability `p_true`.
pub fn qc_bool(g: &mut Gen, p_true: f64) -> bool {
    f64::from(u32::arbitrary(g)) < p_true * f64::from(u32::MAX)
}
