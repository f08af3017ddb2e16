//! Float meet against exact meet on non-degenerate inputs: the paper's
//! panda ∧ Mickey (read from `../shared/data/2d`), and two random star-shaped polygons of 10⁴
//! vertices each. Only the meet is timed; the operands are built beforehand, exactly
//! (`Rational`, decimal text read without rounding, random `f64` values read as rationals) and
//! in float mode (`Float` with `Tolerance::default()`, ε = 10⁻¹⁰ × the larger side of the bounding box, as a power of two).
//!
//! `cargo bench --bench float_vs_exact`; the ratio is the exact mean over the float mean.

#[path = "common/mod.rs"]
mod common;

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use std::hint::black_box;
use yinset::num::{Float, Rational, Tolerance};
use yinset::yin2::YinSet2;

/// SplitMix64, so that the random polygons are the same on every run.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A star-shaped polygon with `n` vertices around `centre`: radius 1 + 0.2 sin(5θ + φ) with
/// 10⁻⁵ noise (below the vertex spacing, so the boundary stays smooth and the two polygons
/// cross a few dozen times), at slightly jittered angles (general position with probability
/// one).
fn star(rng: &mut Rng, n: usize, centre: [f64; 2], phase: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = (k as f64 + 0.8 * rng.unit()) * std::f64::consts::TAU / n as f64;
            let r = 1.0 + 0.2 * (5.0 * t + phase).sin() + 1e-5 * rng.unit();
            [centre[0] + r * t.cos(), centre[1] + r * t.sin()]
        })
        .collect()
}

/// Exact and float operands of one benchmark.
struct Pair {
    exact: (YinSet2<Rational>, YinSet2<Rational>),
    float: (YinSet2<Float>, YinSet2<Float>),
}

fn panda_mickey() -> Pair {
    let exact = |name| YinSet2::<Rational>::from_curves(common::figure(name)).unwrap();
    let float = |name| {
        YinSet2::<Float>::from_curves_with(common::figure(name), Tolerance::default()).unwrap()
    };
    Pair {
        exact: (exact("panda"), exact("mickey")),
        float: (float("panda"), float("mickey")),
    }
}

fn stars(n: usize) -> Pair {
    let mut rng = Rng(0x5eed);
    let a = star(&mut rng, n, [0.0, 0.0], 0.0);
    let b = star(&mut rng, n, [0.13, 0.07], 1.0);
    let exact = |c: &[[f64; 2]]| YinSet2::<Rational>::from_curves(vec![common::points(c)]).unwrap();
    let float = |c: &[[f64; 2]]| {
        YinSet2::<Float>::from_curves_with(vec![common::points(c)], Tolerance::default()).unwrap()
    };
    Pair {
        exact: (exact(&a), exact(&b)),
        float: (float(&a), float(&b)),
    }
}

fn bench(c: &mut Criterion) {
    for (name, pair) in [
        ("panda ∧ Mickey", panda_mickey()),
        ("stars 10^4 ∧ stars 10^4", stars(10_000)),
    ] {
        let mut group = c.benchmark_group(name);
        group.sample_size(10).sampling_mode(SamplingMode::Flat);
        let (ea, eb) = &pair.exact;
        let (fa, fb) = &pair.float;
        group.bench_function("float meet", |b| b.iter(|| black_box(fa.meet(fb))));
        group.bench_function("exact meet", |b| b.iter(|| black_box(ea.meet(eb))));
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
