//! Float meet against exact meet (issue 3, item 6) on non-degenerate inputs: the paper's
//! panda ∧ Mickey (read from `../shared/data/2d`), and two random star-shaped polygons of 10⁴
//! vertices each. Only the meet is timed; the operands are built beforehand, exactly
//! (`Rational`, decimal text read without rounding, random `f64` values read as rationals) and
//! in float mode (`Float` with `Tolerance::default()`, ε = 10⁻¹⁰ × extent).
//!
//! `cargo bench --bench float_vs_exact`; the ratio is the exact mean over the float mean.

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use std::hint::black_box;
use std::path::PathBuf;
use yinset::io::yin2_text::read_curves;
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::YinSet2;

/// All curves of one of the paper's figures (one file per curve).
fn figure<N: Num>(name: &str, count: usize) -> Vec<Vec<Point<N>>> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/2d")
        .join(name);
    (1..=count)
        .flat_map(|i| {
            let path = dir.join(format!("curve{i:02}.txt"));
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            read_curves::<N>(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        })
        .collect()
}

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

fn points<N: Num>(c: &[[f64; 2]]) -> Vec<Point<N>> {
    c.iter()
        .map(|p| Point::new(N::from_f64(p[0]).unwrap(), N::from_f64(p[1]).unwrap()))
        .collect()
}

/// Exact and float operands of one benchmark.
struct Pair {
    exact: (YinSet2<Rational>, YinSet2<Rational>),
    float: (YinSet2<Float>, YinSet2<Float>),
}

fn panda_mickey() -> Pair {
    let exact = |name, count| YinSet2::<Rational>::from_curves(figure(name, count)).unwrap();
    let float = |name, count| {
        YinSet2::<Float>::from_curves_with(figure(name, count), Tolerance::default()).unwrap()
    };
    Pair {
        exact: (exact("panda", 10), exact("mickey", 6)),
        float: (float("panda", 10), float("mickey", 6)),
    }
}

fn stars(n: usize) -> Pair {
    let mut rng = Rng(0x5eed);
    let a = star(&mut rng, n, [0.0, 0.0], 0.0);
    let b = star(&mut rng, n, [0.13, 0.07], 1.0);
    let exact = |c: &[[f64; 2]]| YinSet2::<Rational>::from_curves(vec![points(c)]).unwrap();
    let float = |c: &[[f64; 2]]| {
        YinSet2::<Float>::from_curves_with(vec![points(c)], Tolerance::default()).unwrap()
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
