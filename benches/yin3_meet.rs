//! The exact and float 3D meet on the shared meshes, and their ratio: ballmid ∧ ballright (no
//! contact, a ball 10⁻⁶ inside another) and torus ∧ innerball (touching along a closed polygon of
//! shared edges), operands built beforehand. Where ../shared/tools/cgal3d is built at
//! target/cgal3d/cgal3d, its exact Nef-polyhedron and corefinement CPU times on the same files are
//! printed beside ours, as a peer column.
//!
//! `cargo bench --bench yin3_meet`

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::PathBuf;
use yinset::io::obj::read_obj;
use yinset::num::{Float, Num, Rational};
use yinset::yin3::YinSet3;

/// A mesh of ../shared/data/3d.
fn data(name: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/3d")
        .join(name);
    assert!(p.is_file(), "bench data missing: {}", p.display());
    p
}

fn load<N: Num>(name: &str) -> YinSet3<N> {
    let mesh = read_obj::<N>(&std::fs::read_to_string(data(name)).unwrap()).unwrap();
    YinSet3::from_triangles(mesh.vertices, mesh.faces).unwrap()
}

/// CGAL's best CPU milliseconds of the meet with `engine`, if the harness is built.
fn cgal_ms(a: &str, b: &str, engine: &str) -> Option<f64> {
    let bin = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/cgal3d/cgal3d");
    let out = std::process::Command::new(bin)
        .args([
            "meet",
            data(a).to_str()?,
            data(b).to_str()?,
            "--engine",
            engine,
            "--reps",
            "5",
        ])
        .output()
        .ok()?;
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).ok()?;
    json["time_ms"].as_f64()
}

fn meets(c: &mut Criterion) {
    let mut g = c.benchmark_group("yin3 meet");
    g.sample_size(20);
    for (a, b) in [
        ("ballmid.obj", "ballright.obj"),
        ("torus.obj", "innerball.obj"),
    ] {
        let (x, y) = (load::<Rational>(a), load::<Rational>(b));
        g.bench_function(format!("{a} ∧ {b}"), |bench| {
            bench.iter(|| black_box(&x & &y))
        });
        // 3D float mode (yin3 docs): exact on the f64 values, the result rounded.
        let (x, y) = (load::<Float>(a), load::<Float>(b));
        g.bench_function(format!("float {a} ∧ {b}"), |bench| {
            bench.iter(|| black_box(x.try_meet(&y).unwrap()))
        });
        for engine in ["nef", "corefine"] {
            if let Some(ms) = cgal_ms(a, b, engine) {
                println!("peer: CGAL {engine} {a} ∧ {b}: {ms:.2} ms CPU (best of 5)");
            }
        }
    }
    g.finish();
}

criterion_group!(benches, meets);
criterion_main!(benches);
