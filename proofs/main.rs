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
//! (tests/kit/src/cells.rs) and only validated by `from_curves`; in 3D, the unions of the unit
//! cells of a small grid, whose expected sets are built from the masks' faces
//! (tests/kit/src/cells3.rs).

#[path = "../tests/common/mod.rs"]
mod common;

use common::cells::{full_mask, Affine, Cells, Complex};
use common::cells3::{Grid3, FEATURES3};
use common::laws::{self, CellOracle, Res, Tally};
use common::rotation::{Rot, GENERAL};
use common::Y;
use std::collections::HashSet;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use yinset::kernel::{Point, Point3};
use yinset::num::{Num, Rational};
use yinset::yin2::YinSet2;
use yinset_testkit::Y3;

/// True for the full run (`YINSET_PROOFS=full`).
fn full() -> bool {
    std::env::var("YINSET_PROOFS").is_ok_and(|v| v == "full")
}

/// A finite universe of Yin sets closed under the Boolean operations, indexed by [`Cells`]
/// masks (with the exterior bit for the unbounded sets), which carries out one case of each
/// theorem: the proofs below are generic over it, planar (2D) and spatial (3D) alike.
trait Universe: Sync {
    /// Its name in the tables.
    fn name(&self) -> &str;
    /// Every set: all masks, bounded only or also with the exterior.
    fn sets(&self, with_unbounded: bool) -> Vec<Cells>;
    /// Theorem U for the set `a`.
    fn unary(&self, t: &mut Tally, a: Cells) -> Res;
    /// Theorem B for the ordered pair (a, b).
    fn binary(&self, t: &mut Tally, a: Cells, b: Cells) -> Res;
    /// Theorem T for the ordered triple (a, b, c).
    fn ternary(&self, t: &mut Tally, a: Cells, b: Cells, c: Cells) -> Res;
}

/// A planar universe: every mask of a subdivision, with and without the exterior, and the
/// expected Yin set of each, traced from the mask.
struct Planar {
    cx: Complex,
    expected: Vec<Y>,
}

impl Planar {
    fn new(cx: Complex) -> Planar {
        let expected: Vec<Y> = cx.all(true).into_iter().map(|s| cx.yin(s)).collect();
        // The oracle is injective: distinct masks give distinct Yin sets (Thm 3.21).
        let distinct: HashSet<&Y> = expected.iter().collect();
        assert_eq!(
            distinct.len(),
            expected.len(),
            "oracle not injective on {}",
            cx.name
        );
        Planar { cx, expected }
    }

    fn index(&self, s: Cells) -> usize {
        (s.outside as usize) << self.cx.len() | s.mask as usize
    }

    fn get(&self, s: Cells) -> &Y {
        &self.expected[self.index(s)]
    }

    /// The set with piece centroids as probe points, for the membership oracle.
    fn probes(&self) -> Vec<yinset::kernel::Point<yinset::num::Rational>> {
        self.cx.probes().into_iter().map(|(_, p)| p).collect()
    }
}

impl Universe for Planar {
    fn name(&self) -> &str {
        &self.cx.name
    }

    fn sets(&self, with_unbounded: bool) -> Vec<Cells> {
        self.cx.all(with_unbounded)
    }

    fn unary(&self, t: &mut Tally, a: Cells) -> Res {
        let ya = self.get(a);
        self.cx.invariants(t, a, ya, "a (oracle input)")?;
        laws::unary(t, ya)?;
        let c = laws::ok(ya.complement(), "a'")?;
        let n = self.cx.len();
        laws::cells_check(t, &self.cx, a.not(n), &c, self.get(a.not(n)), "a'")
    }

    fn binary(&self, t: &mut Tally, a: Cells, b: Cells) -> Res {
        let (ya, yb) = (self.get(a), self.get(b));
        let out = laws::binary(t, ya, yb)?;
        laws::cells_binary(t, &self.cx, (a, b), &out, &|s| self.get(s).clone())?;
        laws::membership(t, ya, yb, &out, &self.probes())
    }

    fn ternary(&self, t: &mut Tally, a: Cells, b: Cells, c: Cells) -> Res {
        laws::ternary(t, self.get(a), self.get(b), self.get(c))
    }
}

/// A spatial universe: every union of the unit cells of a small grid (possibly rotated), with
/// and without the exterior, and the expected Yin set of each, built from the mask's faces.
struct Spatial {
    g: Grid3,
    expected: Vec<Y3>,
    /// Cube centres and a point outside (membership oracle).
    cube_probes: Vec<Point3<Rational>>,
}

impl Spatial {
    fn new(g: Grid3) -> Spatial {
        let expected: Vec<Y3> = par_map(&g.all(true), |&s| g.yin(s));
        // `Hash` and `==` are the canonical form's, which the interior `OnceLock` caches
        // only compute.
        #[allow(clippy::mutable_key_type)]
        let distinct: HashSet<&Y3> = expected.iter().collect();
        assert_eq!(
            distinct.len(),
            expected.len(),
            "oracle not injective on {}",
            g.name
        );
        let cube_probes = g.cube_probes();
        Spatial {
            g,
            expected,
            cube_probes,
        }
    }

    fn get(&self, s: Cells) -> &Y3 {
        &self.expected[(s.outside as usize) << self.g.len() | s.mask as usize]
    }

    /// A failure, with the operands' masks.
    fn at<T>(r: Result<T, String>, what: impl FnOnce() -> String) -> Result<T, String> {
        r.map_err(|e| format!("{}: {e}", what()))
    }
}

impl Universe for Spatial {
    fn name(&self) -> &str {
        &self.g.name
    }

    fn sets(&self, with_unbounded: bool) -> Vec<Cells> {
        self.g.all(with_unbounded)
    }

    fn unary(&self, t: &mut Tally, a: Cells) -> Res {
        let g = &self.g;
        let ya = self.get(a);
        let r = (|| {
            g.invariants(t, a, ya, "a (oracle input)")?;
            laws::unary(t, ya)?;
            let c = laws::ok(ya.complement(), "a'")?;
            let na = a.not(g.len());
            laws::cells_check(t, g, na, &c, self.get(na), "a'")
        })();
        Spatial::at(r, || format!("a = {a:?}"))
    }

    fn binary(&self, t: &mut Tally, a: Cells, b: Cells) -> Res {
        let (ya, yb) = (self.get(a), self.get(b));
        let r = (|| {
            let out = laws::binary(t, ya, yb)?;
            laws::cells_binary(t, &self.g, (a, b), &out, &|s| self.get(s).clone())?;
            laws::membership(t, ya, yb, &out, &self.cube_probes)
        })();
        Spatial::at(r, || format!("a = {a:?}, b = {b:?}"))
    }

    fn ternary(&self, t: &mut Tally, a: Cells, b: Cells, c: Cells) -> Res {
        let r = laws::ternary(t, self.get(a), self.get(b), self.get(c));
        Spatial::at(r, || format!("a = {a:?}, b = {b:?}, c = {c:?}"))
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

/// `f` of every item, in order, on all cores.
fn par_map<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let next = AtomicUsize::new(0);
    let out = Mutex::new(Vec::with_capacity(items.len()));
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                if k >= items.len() {
                    break;
                }
                let r = f(&items[k]);
                out.lock().unwrap().push((k, r));
            });
        }
    });
    let mut out = out.into_inner().unwrap();
    out.sort_by_key(|(k, _)| *k);
    out.into_iter().map(|(_, r)| r).collect()
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
fn theorem_unary(u: &impl Universe) {
    let start = Clock::start();
    let sets = u.sets(true);
    let result = par(&sets, |t, &a| u.unary(t, a));
    conclude(
        "U: unary laws, complement = ¬mask (Lemma 4.5, Thm 4.11)",
        &format!("{}, all {} sets", u.name(), sets.len()),
        sets.len(),
        start,
        result,
    );
}

/// **Theorem B (binary laws and the homomorphism; seed 000 Lemma 4.9, Def. 4.10, Thm 4.11).**
/// For every ordered pair (a, b) of the given sets: a∧b, a∨b, a∖b, a⊕b and a' equal the sets
/// built from the bitwise masks (ρ(a∧b) = ρ(a) ∩ ρ(b), Lemma 4.9; the join by De Morgan,
/// Def. 4.10), with the oracle's Betti numbers, exact areas (volumes) and located probes; the
/// order a∧b = a ⇔ a∨b = b ⇔ mask(a) ⊆ mask(b); commutativity, absorption and both De Morgan
/// laws; the exact measure identities |a∧b| + |a∨b| = |a| + |b| and |a∖b| = |a| − |a∧b|
/// (bounded a, b); and membership locate(p, a op b) = locate(p, a) op locate(p, b) at every
/// piece centroid (cube centre).
fn theorem_binary(u: &impl Universe, items: Vec<(Cells, Cells)>, universe: &str) {
    let start = Clock::start();
    let result = par(&items, |t, &(a, b)| u.binary(t, a, b));
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
fn theorem_ternary(u: &impl Universe, items: Vec<(Cells, Cells, Cells)>, universe: &str) {
    let start = Clock::start();
    let result = par(&items, |t, &(a, b, c)| u.ternary(t, a, b, c));
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
    theorem_unary(&Planar::new(Complex::grid(3, 3)));
}

#[test]
fn unary_on_pinwheel() {
    theorem_unary(&Planar::new(Complex::pinwheel()));
}

/// Theorem B on the bounded sets of a binary universe: every ordered pair in the full run
/// (with the unbounded sets too if `unbounded_in_full`), every bounded set against a fixed
/// spread of `quick` in the quick subset.
fn binary_on(u: &impl Universe, quick: usize, unbounded_in_full: bool) {
    if full() {
        let sets = u.sets(unbounded_in_full);
        let kind = if unbounded_in_full {
            "(bounded and unbounded)"
        } else {
            "of bounded sets"
        };
        let name = format!("{}, all {}² ordered pairs {kind}", u.name(), sets.len());
        theorem_binary(u, pairs(&sets), &name);
    } else {
        let bounded = u.sets(false);
        let few = sample(&bounded, quick);
        let items: Vec<_> = bounded
            .iter()
            .flat_map(|&a| few.iter().map(move |&b| (a, b)))
            .collect();
        let name = format!(
            "{}, all {} bounded sets × {} fixed ones",
            u.name(),
            bounded.len(),
            few.len()
        );
        theorem_binary(u, items, &name);
    }
}

/// Theorem B on every ordered pair of a small universe, bounded and unbounded sets alike.
fn binary_closed(u: &impl Universe) {
    let all = u.sets(true);
    let name = format!(
        "{}, all {}² ordered pairs (bounded and unbounded)",
        u.name(),
        all.len()
    );
    theorem_binary(u, pairs(&all), &name);
}

/// Theorem T on every ordered triple of a small universe: bounded and unbounded sets in the
/// full run, the bounded ones in the quick subset.
fn ternary_on(u: &impl Universe) {
    let unbounded = full();
    let sets = u.sets(unbounded);
    let kind = if unbounded {
        "bounded and unbounded"
    } else {
        "bounded"
    };
    let name = format!("{}, all {}³ ordered triples ({kind})", u.name(), sets.len());
    theorem_ternary(u, triples(&sets), &name);
}

#[test]
fn binary_on_3x3_grid() {
    binary_on(&Planar::new(Complex::grid(3, 3)), 6, false);
}

#[test]
fn binary_on_pinwheel() {
    binary_on(&Planar::new(Complex::pinwheel()), 6, false);
}

#[test]
fn binary_on_closed_small_universes() {
    for cx in [Complex::grid(2, 2), Complex::cross()] {
        binary_closed(&Planar::new(cx));
    }
}

#[test]
fn ternary_on_small_universes() {
    for cx in [Complex::grid(2, 2), Complex::cross()] {
        ternary_on(&Planar::new(cx));
    }
}

// ---------------------------------------------------------------------------------------------
// 2D in general position: the universes under rational affine maps, and arrangements of
// polygons whose sides cross at points with non-trivial denominators

/// The rotation by the Pythagorean angle with cos θ = 3/5, sin θ = 4/5, then a shift by
/// (1/3, 1/7): no edge of a grid stays axis-parallel; abscissae get denominators dividing 30,
/// ordinates dividing 70.
fn rotation() -> Affine {
    Affine::new([[(3, 5), (-4, 5)], [(4, 5), (3, 5)]], [(1, 3), (1, 7)])
}

/// The shear (x, y) ↦ (x + 3y/7, y): vertical edges become slanted, horizontal ones stay.
fn shear() -> Affine {
    Affine::new([[(1, 1), (3, 7)], [(0, 1), (1, 1)]], [(0, 1), (0, 1)])
}

/// The triangle and the quadrilateral of [`triangle_quad`].
const TRIANGLE: [(i64, i64); 3] = [(0, 1), (5, 2), (2, 5)];
const QUAD: [(i64, i64); 4] = [(1, 4), (3, 0), (6, 3), (4, 5)];

/// The faces of a triangle crossing a quadrilateral: 6 pieces, crossings with denominators
/// 2, 4, 5 and 11 (common denominator 220). The triangle and the quadrilateral themselves are
/// sets of the universe, so their meet and join cross in general position.
fn triangle_quad() -> Complex {
    Complex::arrangement(
        "triangle × quadrilateral (6 faces)",
        &[TRIANGLE.to_vec(), QUAD.to_vec()],
    )
}

/// The faces of two crossing triangles: 5 pieces, crossings with denominators 2, 3, 5, 9 and
/// 18 (common denominator 90).
fn two_triangles() -> Complex {
    Complex::arrangement(
        "two triangles (5 faces)",
        &[vec![(0, 0), (6, 1), (2, 5)], vec![(1, 3), (5, 4), (4, 6)]],
    )
}

/// Theorem U in general position: every set of the rotated pinwheel and of both arrangements
/// (and in the full run of the sheared 3×3 grid).
#[test]
fn unary_in_general_position() {
    let mut universes = vec![
        Complex::pinwheel().mapped("rotated", rotation()),
        triangle_quad(),
        two_triangles(),
    ];
    if full() {
        universes.push(Complex::grid(3, 3).mapped("sheared", shear()));
    }
    for cx in universes {
        theorem_unary(&Planar::new(cx));
    }
}

/// Theorem B in general position: the rotated pinwheel and both arrangements as
/// [`binary_on`] (every pair in the full run, the arrangements with their unbounded sets),
/// and every ordered pair of the closed rotated cross (and in the full run of the sheared 2×2
/// grid).
#[test]
fn binary_in_general_position() {
    binary_on(
        &Planar::new(Complex::pinwheel().mapped("rotated", rotation())),
        6,
        false,
    );
    binary_on(&Planar::new(triangle_quad()), 6, true);
    binary_on(&Planar::new(two_triangles()), 6, true);
    binary_closed(&Planar::new(Complex::cross().mapped("rotated", rotation())));
    if full() {
        binary_closed(&Planar::new(Complex::grid(2, 2).mapped("sheared", shear())));
    }
}

/// Theorem T in general position: every ordered triple of the two-triangle arrangement, the
/// sheared 2×2 grid and the rotated cross (bounded and unbounded sets) in the full run; in the
/// quick subset, the triples of a spread of 6 sets of each arrangement and of the rotated cross.
#[test]
fn ternary_in_general_position() {
    let universes = [
        Planar::new(two_triangles()),
        Planar::new(triangle_quad()),
        Planar::new(Complex::cross().mapped("rotated", rotation())),
        Planar::new(Complex::grid(2, 2).mapped("sheared", shear())),
    ];
    for u in &universes[..if full() { 4 } else { 3 }] {
        if full() && u.cx.len() <= 5 {
            ternary_on(u);
        } else if !full() {
            let few = sample(&u.sets(true), 6);
            let name = format!(
                "{}, all {}³ ordered triples of a spread",
                u.name(),
                few.len()
            );
            theorem_ternary(u, triples(&few), &name);
        }
    }
}

/// The general-position universes are what they claim: the triangle and the quadrilateral are
/// sets of the arrangement (built here from their corners alone), their meet has vertices with
/// denominator 11 (crossings, not lattice points), and no edge of the rotated pinwheel is
/// axis-parallel.
#[test]
fn general_position_universes_are_what_they_claim() {
    let u = Planar::new(triangle_quad());
    let corners = |c: &[(i64, i64)]| -> Vec<Point<Rational>> {
        c.iter().map(|&(x, y)| Point::int(x, y)).collect()
    };
    let t = YinSet2::from_curves(vec![corners(&TRIANGLE)]).expect("a triangle");
    let q = YinSet2::from_curves(vec![corners(&QUAD)]).expect("a quadrilateral");
    let find = |y: &common::Y| u.expected.iter().position(|e| e == y);
    let (it, iq) = (find(&t), find(&q));
    assert!(
        it.is_some() && iq.is_some(),
        "T and Q are sets of the universe"
    );
    let meet = u.expected[it.unwrap() & iq.unwrap()].clone();
    let zero = num_bigint::BigInt::from(0);
    assert!(
        meet.curves()
            .iter()
            .flat_map(|c| c.vertices())
            .any(|p| p.x.denom() % 11u32 == zero || p.y.denom() % 11u32 == zero),
        "T ∧ Q has a crossing with denominator 11: {meet:?}"
    );
    let pinwheel = Planar::new(Complex::pinwheel().mapped("rotated", rotation()));
    for y in &pinwheel.expected {
        for c in y.curves() {
            for (a, b) in c.edges() {
                assert!(a.x != b.x && a.y != b.y, "axis-parallel edge {a}–{b}");
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 3D: unions of unit cells (tests/kit/src/cells3.rs), axis-aligned and in general position

/// The rotation of the general-position universes: the unit quaternion [`GENERAL`], under
/// which no face, edge or normal of a rotated cell is parallel to a coordinate plane or axis.
const ROTATION: Rot = Rot::Quaternion(GENERAL);

// Test names contain `_3d_`: `cargo test --test proofs _3d_` runs the 3D proofs only.

#[test]
fn unary_3d_on_2x2x2() {
    theorem_unary(&Spatial::new(Grid3::grid(2, 2, 2)));
}

/// Theorem U in general position: every set of the rotated 2×2×2 universe in the full run, of
/// the rotated 2×2×1 universe in the quick subset.
#[test]
fn unary_3d_on_rotated() {
    let g = if full() {
        Grid3::grid(2, 2, 2)
    } else {
        Grid3::grid(2, 2, 1)
    };
    theorem_unary(&Spatial::new(g.rotated(ROTATION)));
}

/// Theorem B on the 2×2×2 universe: every ordered pair of its 256 bounded sets in the full run
/// (of all 512 sets with `YINSET_PROOFS_3D_UNBOUNDED=1`); in the quick subset, every bounded
/// set a against one partner b spread over the universe (a fixed permutation).
///
/// The full run takes hours: `YINSET_PROOFS_SLICE=k/n` runs only the pairs whose first
/// operand is in the k-th of n equal blocks of the sets (k = 0..n), so that it can be run, and
/// rerun, in pieces; the n slices together are every pair.
#[test]
fn binary_3d_on_2x2x2() {
    let u = Spatial::new(Grid3::grid(2, 2, 2));
    if full() {
        match slice() {
            None => binary_on(&u, 0, full_3d_unbounded()),
            Some((k, n)) => {
                let sets = u.sets(full_3d_unbounded());
                let m = sets.len();
                let firsts = &sets[k * m / n..(k + 1) * m / n];
                let items: Vec<_> = firsts
                    .iter()
                    .flat_map(|&a| sets.iter().map(move |&b| (a, b)))
                    .collect();
                let name = format!(
                    "{}, the ordered pairs of its {m} {} sets with a in slice {k} of {n} ({} × {m})",
                    u.name(),
                    if full_3d_unbounded() { "" } else { "bounded" },
                    firsts.len()
                );
                theorem_binary(&u, items, &name);
            }
        }
    } else {
        let bounded = u.sets(false);
        let n = bounded.len();
        let items: Vec<_> = (0..n)
            .map(|k| (bounded[k], bounded[(k * 167 + 89) % n]))
            .collect();
        let name = format!("{}, all {n} bounded sets × one partner each", u.name());
        theorem_binary(&u, items, &name);
    }
}

/// Theorem B on every ordered pair of a small universe with its unbounded sets: 2×2×1 cells
/// in the full run, 2×1×1 in the quick subset.
#[test]
fn binary_3d_on_small() {
    binary_closed(&Spatial::new(small_3d()));
}

/// Theorem B in general position: every ordered pair of the rotated small universe (2×2×1
/// in the full run, 2×1×1 in the quick subset), bounded and unbounded.
#[test]
fn binary_3d_on_rotated() {
    binary_closed(&Spatial::new(small_3d().rotated(ROTATION)));
}

/// Theorem T on every ordered triple of the 2×1×1 universe with its unbounded sets (the
/// bounded ones in the quick subset), and in the full run also of the 2×2×1 bounded sets.
#[test]
fn ternary_3d_on_small() {
    ternary_on(&Spatial::new(Grid3::grid(2, 1, 1)));
    if full() {
        let u = Spatial::new(Grid3::grid(2, 2, 1));
        let sets = u.sets(false);
        let name = format!(
            "{}, all {}³ ordered triples (bounded)",
            u.name(),
            sets.len()
        );
        theorem_ternary(&u, triples(&sets), &name);
    }
}

/// Theorem T in general position: every ordered triple of the rotated 2×1×1 universe with its
/// unbounded sets (the bounded ones in the quick subset).
#[test]
fn ternary_3d_on_rotated() {
    ternary_on(&Spatial::new(Grid3::grid(2, 1, 1).rotated(ROTATION)));
}

/// The small closed 3D universe: 2×2×1 cells in the full run, 2×1×1 in the quick subset.
fn small_3d() -> Grid3 {
    if full() {
        Grid3::grid(2, 2, 1)
    } else {
        Grid3::grid(2, 1, 1)
    }
}

/// `YINSET_PROOFS_SLICE=k/n` (k < n), if set.
fn slice() -> Option<(usize, usize)> {
    let v = std::env::var("YINSET_PROOFS_SLICE").ok()?;
    let (k, n) = v.split_once('/')?;
    let (k, n) = (k.parse().ok()?, n.parse().ok()?);
    assert!(k < n, "YINSET_PROOFS_SLICE={v}: need k < n");
    Some((k, n))
}

/// In the full run, whether the 2×2×2 binary proof takes the unbounded sets too (all 512²
/// pairs instead of 256²): `YINSET_PROOFS_3D_UNBOUNDED=1`.
fn full_3d_unbounded() -> bool {
    std::env::var("YINSET_PROOFS_3D_UNBOUNDED").is_ok_and(|v| v == "1")
}

/// How often the universes' pairs are degenerate (measured on every 37th ordered pair of the
/// full binary universes, exactly): shared vertices, collinear overlapping edges, touching
/// points, coincident curves with equal and opposite orientation, slanted edges.
#[test]
fn degenerate_cases_in_universes() {
    use common::gen::{feature_stats, Features};
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
        let u = Planar::new(cx);
        let all = pairs(&u.sets(false));
        let mut stats = feature_stats();
        for &(a, b) in all.iter().step_by(37) {
            stats.add(Features::of(u.get(a), u.get(b)).as_array());
        }
        eprintln!(
            "{}",
            stats.report(&format!("the bounded pairs of {}", u.cx.name))
        );
        stats.assert_minimums(&min);
    }
}

/// How often the 3D universe's bounded pairs are degenerate, counted from the masks over every
/// ordered pair of the 2×2×2 universe's bounded sets, both empty (the rotated universe has
/// the same combinatorics). See [`FEATURES3`].
#[test]
fn degenerate_cases_in_3d_universe() {
    let g = Grid3::grid(2, 2, 2);
    let sets: Vec<Cells> = g.all(false).into_iter().filter(|s| s.mask != 0).collect();
    let bettis: Vec<_> = g.all(false).into_iter().map(|s| g.betti(s)).collect();
    let betti = |s: Cells| bettis[s.mask as usize];
    let mut counts = [0usize; 8];
    let mut total = 0;
    for &a in &sets {
        for &b in &sets {
            total += 1;
            for (k, &x) in g.features(a, b, &betti).iter().enumerate() {
                counts[k] += usize::from(x);
            }
        }
    }
    let shares: Vec<f64> = counts.iter().map(|&c| c as f64 / total as f64).collect();
    eprintln!(
        "degenerate features in the {total} ordered pairs of non-empty bounded sets of {}:",
        g.name
    );
    for (k, name) in FEATURES3.iter().enumerate() {
        eprintln!("  {:5.1} %  {name}", 100.0 * shares[k]);
    }
    let min = [0.85, 0.6, 0.6, 0.05, 0.5, 0.02, 0.3, 0.03];
    for k in 0..8 {
        assert!(
            shares[k] >= min[k],
            "{}: {:.3} < {}",
            FEATURES3[k],
            shares[k],
            min[k]
        );
    }
}

#[test]
fn universes_are_what_they_claim() {
    // Sanity of the universes themselves: sizes, piece counts and the oracle's closure.
    assert_eq!(Complex::grid(3, 3).len(), 9);
    assert_eq!(Complex::pinwheel().len(), 8);
    assert_eq!(Complex::cross().len(), 4);
    let u = Planar::new(Complex::grid(2, 2));
    assert_eq!(u.expected.len(), 32);
    assert!(u.get(Cells::new(0, false)).is_empty());
    assert!(u.get(Cells::new(full_mask(4), true)).is_full());
}

#[test]
fn universes_3d_are_what_they_claim() {
    // Sizes, the extremes, and the cell oracle's Betti numbers on hand-computed sets of the
    // 2×2×2 grid (cell bit i + 2j + 4k for [i,i+1]×[j,j+1]×[k,k+1]).
    let g = Grid3::grid(2, 2, 2);
    assert_eq!((g.len(), g.all(true).len()), (8, 512));
    let bit = |c: [u64; 3]| 1u64 << (c[0] + 2 * c[1] + 4 * c[2]);
    let mask = |cs: &[[u64; 3]]| cs.iter().map(|&c| bit(c)).fold(0, |m, b| m | b);
    let b = |s: Cells| {
        let e = g.betti(s);
        (e.b0, e.b1, e.b2)
    };
    let bounded = |cs: &[[u64; 3]]| Cells::new(mask(cs), false);
    let unbounded = |cs: &[[u64; 3]]| Cells::new(mask(cs), true);
    assert_eq!(b(bounded(&[])), (0, 0, 0));
    assert_eq!(b(unbounded(&[])), (1, 0, 1), "ℝ³ minus a closed cube ≃ S²");
    assert_eq!(b(Cells::new(255, true)), (1, 0, 0), "ℝ³");
    assert_eq!(b(bounded(&[[0, 0, 0]])), (1, 0, 0));
    assert_eq!(b(Cells::new(255, false)), (1, 0, 0));
    assert_eq!(b(Cells::new(255 & !1, false)), (1, 0, 0), "7 cells");
    assert_eq!(
        b(bounded(&[[0, 0, 0], [1, 1, 0]])),
        (2, 0, 0),
        "sharing an edge"
    );
    assert_eq!(
        b(bounded(&[[0, 0, 0], [1, 1, 1]])),
        (2, 0, 0),
        "sharing a vertex"
    );
    // Six cells around the centre, face to face in a cycle, missing 010 and 101: a solid torus.
    let ring = [
        [0, 0, 0],
        [1, 0, 0],
        [1, 1, 0],
        [1, 1, 1],
        [0, 1, 1],
        [0, 0, 1],
    ];
    assert_eq!(b(bounded(&ring)), (1, 1, 0), "a ring of six cells");
    // Every closed cell of the 2×2×2 grid contains the centre, so a union of closed cells is
    // star-shaped about it, hence contractible: an unbounded set has b1 = 0 by Alexander
    // duality (the ring's complement and the exterior with two edge-sharing cells included),
    // and b2 = 1 unless it is ℝ³.
    assert_eq!(b(Cells::new(!mask(&ring) & 255, true)), (1, 0, 1));
    assert_eq!(b(unbounded(&[[0, 0, 0], [1, 1, 0]])), (1, 0, 1));
    assert_eq!(b(unbounded(&[[0, 0, 0]])), (1, 0, 1));
    // The expected sets of the extremes, and the rotation: orthogonal, determinant 1, no zero
    // entry (general position).
    let u = Spatial::new(Grid3::grid(2, 1, 1).rotated(ROTATION));
    assert!(u.get(Cells::new(0, false)).is_empty());
    assert!(u.get(Cells::new(3, true)).is_full());
    assert_eq!(
        u.get(Cells::new(3, false)).volume(),
        Some(Rational::from_i64(2))
    );
    let r = u.g.rot.entries();
    let zero = Rational::from_i64(0);
    for i in 0..3 {
        for j in 0..3 {
            let dot = (0..3).fold(zero.clone(), |s, k| s + r[i][k].clone() * r[j][k].clone());
            assert_eq!(dot, Rational::from_i64(i64::from(i == j)), "R Rᵀ = I");
            assert_ne!(r[i][j], zero, "no entry of the rotation is 0");
        }
    }
    let det = r[0][0].clone()
        * (r[1][1].clone() * r[2][2].clone() - r[1][2].clone() * r[2][1].clone())
        - r[0][1].clone() * (r[1][0].clone() * r[2][2].clone() - r[1][2].clone() * r[2][0].clone())
        + r[0][2].clone() * (r[1][0].clone() * r[2][1].clone() - r[1][1].clone() * r[2][0].clone());
    assert_eq!(det, Rational::from_i64(1));
}
