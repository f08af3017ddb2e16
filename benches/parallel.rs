//! rayon's share: the exact meet of W1 (the per-edge cuts of S_V run in
//! parallel) and batch locate of 10⁵ random points in W1's first star, exact and in float mode
//! (chunks of queries swept in parallel; float mode's ε test per point in parallel), and the cut
//! of the panda by the cells of a 16×16 grid (`meet_each`, cells in parallel).
//!
//! Run it twice and compare: `RAYON_NUM_THREADS=1 cargo bench --bench parallel` and
//! `RAYON_NUM_THREADS=2 cargo bench --bench parallel` (benches/BENCHMARKS.md).

#[path = "common/mod.rs"]
mod common;

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use std::hint::black_box;
use yinset::num::{Float, Rational};

fn parallel(c: &mut Criterion) {
    let mut group = c.benchmark_group("parallel");
    group.sampling_mode(SamplingMode::Flat).sample_size(10);
    let (a, b) = common::w1(2_000);
    let (ea, eb) = (common::exact(&a), common::exact(&b));
    group.bench_function("W1 n=2000 exact meet", |bench| {
        bench.iter(|| black_box(&ea & &eb))
    });
    let queries = common::queries(100_000, common::bbox(&a), 7);
    let exact_q = common::points::<Rational>(&queries);
    group.bench_function("locate 1e5 points, W1 star n=2000, exact", |bench| {
        bench.iter(|| black_box(ea.locate(&exact_q)))
    });
    let fa = common::float(&a);
    let float_q = common::points::<Float>(&queries);
    group.bench_function("locate 1e5 points, W1 star n=2000, float", |bench| {
        bench.iter(|| black_box(fa.locate(&float_q)))
    });
    // The cut by control volumes (seed 000 §5.5): the panda met with each cell of a 16×16 grid
    // over its box, `meet_each` (cells in parallel).
    let (panda, _) = common::w4();
    let cells: Vec<common::Curves> = common::grid_cells(common::bbox(&panda), 16)
        .into_iter()
        .map(|c| vec![c])
        .collect();
    let (ep, fp) = (common::exact(&panda), common::float(&panda));
    let exact_cells: Vec<_> = cells.iter().map(common::exact).collect();
    let float_cells: Vec<_> = cells.iter().map(common::float).collect();
    group.bench_function("cut panda by 16x16 cells, exact", |bench| {
        bench.iter(|| black_box(ep.meet_each(&exact_cells)))
    });
    group.bench_function("cut panda by 16x16 cells, float", |bench| {
        bench.iter(|| black_box(fp.meet_each(&float_cells)))
    });
    group.finish();
}

criterion_group!(benches, parallel);
criterion_main!(benches);
