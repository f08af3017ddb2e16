//! The 3D operations on the workloads V1–V4 (benches/yin3_work): meet, join, complement,
//! locate (1 000 points) and Betti numbers, exact and float, on V1–V4 at small sizes (V3
//! without torusbig, which the table covers); V4 also on rayon's threads (`YinSet3::meet_each`)
//! beside the single-thread figure. Operands are built (and their files written to
//! target/yin3_workloads) before timing. Times are the process's CPU time
//! (all threads), except V4's parallel case (wall time, printed). The table against the peers at larger
//! sizes is benches/yin3_table.rs (run by benches/yin3_peers.sh).
//!
//! ```sh
//! cargo bench --bench yin3_ops              # everything
//! cargo bench --bench yin3_ops -- V1/meet   # ids containing "V1/meet"
//! ```

#[path = "peers/cpu_time.rs"]
mod cpu_time;
#[path = "yin3_work/mod.rs"]
mod work;

use cpu_time::CpuTime;
use criterion::{BatchSize, Criterion};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;
use yinset::kernel::Point3;
use yinset::num::{Float, Num, Rational};
use yinset::yin3::YinSet3;

/// The workload pairs at bench sizes, as files.
fn pairs() -> Vec<(String, PathBuf, PathBuf)> {
    let (a, b) = work::v1(1000);
    let (g, shifted, turned) = work::v2(4);
    let mut v = vec![
        (
            "V1/n=968".to_string(),
            work::write("v1_a_968", &a),
            work::write("v1_b_968", &b),
        ),
        (
            "V2-shift/k=4".into(),
            work::write("v2_grid_4", &g),
            work::write("v2_shifted_4", &shifted),
        ),
        (
            "V2-turn/k=4".into(),
            work::write("v2_grid_4", &g),
            work::write("v2_turned_4", &turned),
        ),
    ];
    // torusbig (16 384 triangles a side) is left to the table: seconds per exact call.
    v.extend(
        work::v3_files()
            .into_iter()
            .filter(|(l, _, _)| !l.starts_with("torusbig"))
            .map(|(l, a, b)| (format!("V3/{l}"), a, b)),
    );
    v
}

/// 1 000 points on a 10×10×10 lattice spanning the box of `s` (a little beyond it).
fn probes<N: Num>(s: &YinSet3<N>) -> Vec<Point3<N>> {
    let b = s.bbox().expect("a bounded boundary");
    let (lo, hi) = (b.min.to_f64(), b.max.to_f64());
    let mut out = Vec::with_capacity(1000);
    for i in 0..10 {
        for j in 0..10 {
            for k in 0..10 {
                let c = [i, j, k]
                    .iter()
                    .enumerate()
                    .map(|(a, &t)| lo[a] + (hi[a] - lo[a]) * (t as f64 * 0.113 - 0.01))
                    .map(|x| N::from_f64(x).expect("finite"))
                    .collect::<Vec<N>>();
                let Ok([x, y, z]) = <[N; 3]>::try_from(c) else {
                    unreachable!("three coordinates")
                };
                out.push(Point3::new(x, y, z));
            }
        }
    }
    out
}

/// Every operation on every pair in backend `N`.
fn ops<N: Num>(c: &mut Criterion<CpuTime>, mode: &str) {
    for (label, pa, pb) in pairs() {
        let (a, b) = (work::load::<N>(&pa), work::load::<N>(&pb));
        let meet = a.meet(&b);
        let mut g = c.benchmark_group(format!("{label}/{mode}"));
        g.sample_size(10);
        g.bench_function("meet", |t| t.iter(|| black_box(a.meet(&b))));
        g.bench_function("join", |t| t.iter(|| black_box(a.join(&b))));
        g.bench_function("complement", |t| t.iter(|| black_box(a.complement())));
        let q = probes(&a);
        g.bench_function("locate", |t| t.iter(|| black_box(a.locate(&q))));
        // Betti numbers are cached in the set: each iteration gets a fresh clone of the meet.
        g.bench_function("betti(meet)", |t| {
            t.iter_batched(
                || meet.clone(),
                |m| black_box(m.betti()),
                BatchSize::SmallInput,
            )
        });
        g.finish();
    }
}

/// V4: the sphere met with each of the N³ cells, one thread and rayon's pool.
fn v4<N: Num>(c: &mut Criterion<CpuTime>, mode: &str) {
    let n = 4;
    let sphere: YinSet3<N> = work::load(&work::write("v4_sphere_968", &work::v4_sphere(1000)));
    let cells: Vec<YinSet3<N>> = work::v4_cells(n)
        .iter()
        .enumerate()
        .map(|(i, m)| work::load(&work::write(&format!("v4_cell_{n}_{i}"), m)))
        .collect();
    let mut g = c.benchmark_group(format!("V4/N={n}/{mode}"));
    g.sample_size(10);
    g.bench_function("cells (1 thread)", |t| {
        t.iter(|| cells.iter().map(|x| sphere.meet(x)).collect::<Vec<_>>())
    });
    g.finish();
    // rayon: wall time, as the process's CPU time adds up the pool's threads.
    let best = (0..5)
        .map(|_| {
            let t0 = Instant::now();
            black_box(sphere.meet_each(&cells).expect("representable"));
            t0.elapsed().as_secs_f64() * 1e3
        })
        .fold(f64::INFINITY, f64::min);
    println!(
        "V4/N={n}/{mode}/cells (rayon, {} threads): {best:.1} ms wall, best of 5",
        rayon::current_num_threads()
    );
}

fn main() {
    let mut c = Criterion::default()
        .with_measurement(CpuTime)
        .configure_from_args();
    ops::<Rational>(&mut c, "exact");
    ops::<Float>(&mut c, "float");
    v4::<Rational>(&mut c, "exact");
    v4::<Float>(&mut c, "float");
    c.final_summary();
}
