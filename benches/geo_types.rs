//! The meet of two polygons given as `geo_types` values, by geo's own
//! `BooleanOps` and by yinset through the `geo-types` conversions (exact and float mode),
//! conversions included. Run: `cargo bench --features geo-types --bench geo_types`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use geo::BooleanOps;
use geo_types::{Coord, LineString, MultiPolygon, Polygon};
use std::hint::black_box;
use yinset::num::{Float, Num, Rational};
use yinset::yin2::YinSet2;

/// A star of `n` spikes around (cx, 0): radii alternating 1 and 0.6, turned by `phase`.
fn star(n: usize, cx: f64, phase: f64) -> Polygon<f64> {
    let coords: Vec<Coord<f64>> = (0..2 * n)
        .map(|k| {
            let t = phase + std::f64::consts::PI * k as f64 / n as f64;
            let r = if k % 2 == 0 { 1.0 } else { 0.6 };
            Coord {
                x: cx + r * t.cos(),
                y: r * t.sin(),
            }
        })
        .collect();
    Polygon::new(LineString(coords), vec![])
}

/// The meet by yinset in number type `N`, from and back to `geo_types`.
fn ours<N: Num>(a: &Polygon<f64>, b: &Polygon<f64>) -> MultiPolygon<f64> {
    let (a, b) = (
        YinSet2::<N>::try_from(a).unwrap(),
        YinSet2::<N>::try_from(b).unwrap(),
    );
    MultiPolygon::try_from(&(&a & &b)).unwrap()
}

fn meet(c: &mut Criterion) {
    let mut group = c.benchmark_group("geo_types_meet");
    for n in [100, 300] {
        let (a, b) = (star(n, 0.0, 0.0), star(n, 0.5, 0.001));
        group.bench_with_input(BenchmarkId::new("geo", n), &n, |bench, _| {
            bench.iter(|| black_box(a.intersection(&b)))
        });
        group.bench_with_input(BenchmarkId::new("yinset_float", n), &n, |bench, _| {
            bench.iter(|| black_box(ours::<Float>(&a, &b)))
        });
        group.bench_with_input(BenchmarkId::new("yinset_exact", n), &n, |bench, _| {
            bench.iter(|| black_box(ours::<Rational>(&a, &b)))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = meet
}
criterion_main!(benches);
