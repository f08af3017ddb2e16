//! Bounded-exhaustive proofs that the kernel's Jordan space is a Boolean algebra isomorphic to
//! the Yin space (seed 000 Thm 4.11), on finite universes of Yin sets: for every set, every
//! pair, and (for the ternary laws) every triple of a universe, every law is checked exactly
//! with `==` and every kernel output passes the exact validator. See proofs/README.md for the
//! theorems, universes, counts and the commands.
//!
//! `cargo test --test proofs` runs the quick subset; the full run is
//! `YINSET_PROOFS=full cargo test --release --test proofs -- --nocapture --test-threads 1`
//! (each proof then uses every core itself).
//!
//! A universe is the set of all unions of the pieces of a small planar subdivision (unit
//! squares, or squares cut into triangles by their diagonals), optionally with the exterior of
//! the window: closed under complement, meet and join, where those are bitwise on masks. The
//! expected set of every mask is traced from the mask independently of the kernel's operations
//! (tests/common/cells.rs) and only validated by `from_curves`.

#[path = "../tests/common/mod.rs"]
mod common;

use common::cells::{full_mask, Cells, Complex};
use common::laws::{self, Res, Tally};
use common::Y;
use std::collections::HashSet;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// True for the full run (`YINSET_PROOFS=full`).
fn full() -> bool {
    std::env::var("YINSET_PROOFS").is_ok_and(|v| v == "full")
}

/// A closed universe: every mask of a subdivision, with and without the exterior, and the
/// expected Yin set of each, traced from the mask.
struct Universe {
    cx: Complex,
    expected: Vec<Y>,
}

impl Universe {
    fn new(cx: Complex) -> Universe {
        let expected: Vec<Y> = cx.all(true).into_iter().map(|s| cx.yin(s)).collect();
        // The oracle is injective: distinct masks give distinct Yin sets (Thm 3.21).
        let distinct: HashSet<&Y> = expected.iter().collect();
        assert_eq!(
            distinct.len(),
            expected.len(),
            "oracle not injective on {}",
            cx.name
        );
        Universe { cx, expected }
    }

    fn index(&self, s: Cells) -> usize {
        (s.outside as usize) << self.cx.len() | s.mask as usize
    }

    fn get(&self, s: Cells) -> &Y {
        &self.expected[self.index(s)]
    }

    fn sets(&self, with_unbounded: bool) -> Vec<Cells> {
        self.cx.all(with_unbounded)
    }

    /// The set with piece centroids as probe points, for the membership oracle.
    fn probes(&self) -> Vec<yinset::kernel::Point<yinset::num::Rational>> {
        self.cx.probes().into_iter().map(|(_, p)| p).collect()
    }
}

/// Run `check` on every item, on all cores; stop at the first failure.
fn par<T: Sync>(
    items: &[T],
    check: impl Fn(&mut Tally, &T) -> Res + Sync,
) -> (Tally, Result<(), String>) {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let tally = Mutex::new(Tally::default());
    let error = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                let mut t = Tally::default();
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    if k >= items.len() || failed.load(Ordering::Relaxed) {
                        break;
                    }
                    if full() && k > 0 && k % (items.len() / 10).max(1) == 0 {
                        eprintln!("  … {k} of {} cases", items.len());
                    }
                    if let Err(e) = check(&mut t, &items[k]) {
                        failed.store(true, Ordering::Relaxed);
                        error.lock().unwrap().get_or_insert(e);
                        break;
                    }
                }
                tally.lock().unwrap().merge(&t);
            });
        }
    });
    let e = error.into_inner().unwrap();
    (tally.into_inner().unwrap(), e.map_or(Ok(()), Err))
}

/// CPU time of this process so far, in seconds (Linux: /proc/self/stat, USER_HZ = 100;
/// elsewhere 0).
fn cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let fields: Vec<&str> = stat
        .rsplit_once(')')
        .map_or(vec![], |(_, rest)| rest.split_whitespace().collect());
    // After the command name: state is field 3, utime field 14, stime field 15.
    let tick = |k: usize| {
        fields
            .get(k - 3)
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(0.0)
    };
    (tick(14) + tick(15)) / 100.0
}

/// Wall-clock and CPU time since a start.
struct Clock {
    wall: Instant,
    cpu: f64,
}

impl Clock {
    fn start() -> Clock {
        Clock {
            wall: Instant::now(),
            cpu: cpu_seconds(),
        }
    }
}

/// Print the proof's table row and its per-law counts; panic on failure.
fn conclude(
    theorem: &str,
    universe: &str,
    cases: usize,
    start: Clock,
    (tally, result): (Tally, Result<(), String>),
) {
    let secs = start.wall.elapsed().as_secs_f64();
    let cpu = cpu_seconds() - start.cpu;
    let verdict = if result.is_ok() { "holds" } else { "FAILS" };
    eprintln!(
        "\n| {theorem} | {universe} | {cases} | {} | {verdict} | {secs:.1} s | {cpu:.1} s |\n{}",
        tally.total(),
        tally.report("  checks per law")
    );
    if let Err(e) = result {
        panic!("{theorem} on {universe}: {e}");
    }
}

/// Every ordered pair of `sets`.
fn pairs(sets: &[Cells]) -> Vec<(Cells, Cells)> {
    sets.iter()
        .flat_map(|&a| sets.iter().map(move |&b| (a, b)))
        .collect()
}

/// Every ordered triple of `sets`.
fn triples(sets: &[Cells]) -> Vec<(Cells, Cells, Cells)> {
    let mut v = Vec::with_capacity(sets.len().pow(3));
    for &a in sets {
        for &b in sets {
            for &c in sets {
                v.push((a, b, c));
            }
        }
    }
    v
}

/// A fixed spread of `k` masks (for the quick subset): the extremes and a deterministic sample.
fn sample(sets: &[Cells], k: usize) -> Vec<Cells> {
    let mut v: Vec<Cells> = (0..k)
        .map(|i| sets[(i * 2654435761) % sets.len()])
        .collect();
    v.push(sets[0]);
    v.push(*sets.last().unwrap());
    v.sort();
    v.dedup();
    v
}

// ---------------------------------------------------------------------------------------------
// The theorems

/// **Theorem U (unary laws and the complement; seed 000 Lemma 4.5, Thm 4.11).** For every set a
/// of the universe (bounded or not): the validator accepts a and a'; a' equals the set traced
/// from the complemented mask, with the flood-fill Betti numbers, exact area and located
/// centroids (ρ(a') = ρ(a)^⊥, Lemma 4.5); and idempotence a∧a = a∨a = a, identity a∧1̂ = a∨0̂ =
/// a, annihilator a∧0̂ = 0̂, a∨1̂ = 1̂, complement a∧a' = 0̂, a∨a' = 1̂ and involution a'' = a hold.
fn theorem_unary(u: &Universe) {
    let start = Clock::start();
    let sets = u.sets(true);
    let n = u.cx.len();
    let result = par(&sets, |t, &a| {
        let ya = u.get(a);
        laws::cells_check(t, &u.cx, a, ya, ya, "a (oracle input)")?;
        laws::unary(t, ya)?;
        let c = laws::ok(ya.complement(), "a'")?;
        laws::cells_check(t, &u.cx, a.not(n), &c, u.get(a.not(n)), "a'")
    });
    conclude(
        "U: unary laws, complement = ¬mask (Lemma 4.5, Thm 4.11)",
        &format!("{}, all {} sets", u.cx.name, sets.len()),
        sets.len(),
        start,
        result,
    );
}

/// **Theorem B (binary laws and the homomorphism; seed 000 Lemma 4.9, Def. 4.10, Thm 4.11).**
/// For every ordered pair (a, b) of the given sets: a∧b, a∨b, a∖b, a⊕b and a' equal the sets
/// traced from the bitwise masks (ρ(a∧b) = ρ(a) ∩ ρ(b), Lemma 4.9; the join by De Morgan,
/// Def. 4.10), with flood-fill Betti numbers, exact areas and located centroids; the order
/// a∧b = a ⇔ a∨b = b ⇔ mask(a) ⊆ mask(b); commutativity, absorption and both De Morgan laws;
/// the exact area identities |a∧b| + |a∨b| = |a| + |b| and |a∖b| = |a| − |a∧b| (bounded a, b);
/// and membership locate(p, a op b) = locate(p, a) op locate(p, b) at every piece centroid.
fn theorem_binary(u: &Universe, items: Vec<(Cells, Cells)>, universe: &str) {
    let start = Clock::start();
    let pts = u.probes();
    let result = par(&items, |t, &(a, b)| {
        let (ya, yb) = (u.get(a), u.get(b));
        let out = laws::binary(t, ya, yb)?;
        laws::cells_binary(t, &u.cx, (a, b), &out, &|s| u.get(s).clone())?;
        laws::membership(t, ya, yb, &out, &pts)
    });
    conclude(
        "B: binary laws, ∧ ∨ ∖ ⊕ ' = bitwise (Lemma 4.9, Def. 4.10, Thm 4.11)",
        universe,
        items.len(),
        start,
        result,
    );
}

/// **Theorem T (ternary laws; seed 000 Thm 4.11).** For every ordered triple (a, b, c) of the
/// universe: (a∧b)∧c = a∧(b∧c), (a∨b)∨c = a∨(b∨c), a∧(b∨c) = (a∧b)∨(a∧c) and
/// a∨(b∧c) = (a∨b)∧(a∨c), every side computed by the kernel and validated.
fn theorem_ternary(u: &Universe, items: Vec<(Cells, Cells, Cells)>, universe: &str) {
    let start = Clock::start();
    let result = par(&items, |t, &(a, b, c)| {
        laws::ternary(t, u.get(a), u.get(b), u.get(c))
    });
    conclude(
        "T: associativity, distributivity (Thm 4.11)",
        universe,
        items.len(),
        start,
        result,
    );
}

// ---------------------------------------------------------------------------------------------
// The runs: quick subset by default, everything with YINSET_PROOFS=full

#[test]
fn unary_on_3x3_grid() {
    theorem_unary(&Universe::new(Complex::grid(3, 3)));
}

#[test]
fn unary_on_pinwheel() {
    theorem_unary(&Universe::new(Complex::pinwheel()));
}

/// Theorem B on the bounded sets of a binary universe: every ordered pair in the full run, every
/// set against a fixed spread of 7 in the quick subset.
fn binary_on(cx: Complex) {
    let u = Universe::new(cx);
    let bounded = u.sets(false);
    if full() {
        let name = format!(
            "{}, all {}² ordered pairs of bounded sets",
            u.cx.name,
            bounded.len()
        );
        theorem_binary(&u, pairs(&bounded), &name);
    } else {
        let few = sample(&bounded, 6);
        let items: Vec<_> = bounded
            .iter()
            .flat_map(|&a| few.iter().map(move |&b| (a, b)))
            .collect();
        let name = format!(
            "{}, all {} bounded sets × {} fixed ones",
            u.cx.name,
            bounded.len(),
            few.len()
        );
        theorem_binary(&u, items, &name);
    }
}

#[test]
fn binary_on_3x3_grid() {
    binary_on(Complex::grid(3, 3));
}

#[test]
fn binary_on_pinwheel() {
    binary_on(Complex::pinwheel());
}

#[test]
fn binary_on_closed_small_universes() {
    for cx in [Complex::grid(2, 2), Complex::cross()] {
        let u = Universe::new(cx);
        let all = u.sets(true);
        let name = format!(
            "{}, all {}² ordered pairs (bounded and unbounded)",
            u.cx.name,
            all.len()
        );
        theorem_binary(&u, pairs(&all), &name);
    }
}

#[test]
fn ternary_on_small_universes() {
    for cx in [Complex::grid(2, 2), Complex::cross()] {
        let u = Universe::new(cx);
        let sets = if full() { u.sets(true) } else { u.sets(false) };
        let kind = if full() {
            "bounded and unbounded"
        } else {
            "bounded"
        };
        let name = format!(
            "{}, all {}³ ordered triples ({kind})",
            u.cx.name,
            sets.len()
        );
        theorem_ternary(&u, triples(&sets), &name);
    }
}

/// How often the universes' pairs are degenerate (measured on every 37th ordered pair of the
/// full binary universes, exactly): shared vertices, collinear overlapping edges, touching
/// points, coincident curves with equal and opposite orientation, slanted edges.
#[test]
fn degenerate_cases_in_universes() {
    use common::gen::{FeatureStats, Features};
    for (cx, min) in [
        (
            Complex::grid(3, 3),
            [
                0.9, 0.9, 0.15, 0.4, 0.05, 0.0, 0.01, 0.5, 0.0, 0.0, 0.0, 0.0,
            ],
        ),
        (
            Complex::pinwheel(),
            [0.9, 0.9, 0.05, 0.8, 0.1, 0.0, 0.0, 0.8, 0.0, 0.0, 0.0, 0.9],
        ),
    ] {
        let u = Universe::new(cx);
        let all = pairs(&u.sets(false));
        let mut stats = FeatureStats::default();
        for &(a, b) in all.iter().step_by(37) {
            stats.add(&Features::of(u.get(a), u.get(b)));
        }
        eprintln!(
            "{}",
            stats.report(&format!("the bounded pairs of {}", u.cx.name))
        );
        stats.assert_minimums(&min);
    }
}

#[test]
fn universes_are_what_they_claim() {
    // Sanity of the universes themselves: sizes, piece counts and the oracle's closure.
    assert_eq!(Complex::grid(3, 3).len(), 9);
    assert_eq!(Complex::pinwheel().len(), 8);
    assert_eq!(Complex::cross().len(), 4);
    let u = Universe::new(Complex::grid(2, 2));
    assert_eq!(u.expected.len(), 32);
    assert!(u.get(Cells::new(0, false)).is_empty());
    assert!(u.get(Cells::new(full_mask(4), true)).is_full());
}
