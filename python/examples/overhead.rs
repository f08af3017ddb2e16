//! The Rust side of the Python overhead benchmark (python/bench/overhead.py): the kernel's
//! exact meet alone on the same inputs, the median of repeated runs in milliseconds.
//!
//! `cargo run --release --example overhead -- PANDA_DIR MICKEY_DIR SPHERE_A.obj SPHERE_B.obj RUNS`

use std::path::Path;
use std::time::Instant;
use yinset::io::{obj, yin2_text};
use yinset::num::Rational;
use yinset::yin2::YinSet2;
use yinset::yin3::YinSet3;

/// The exact 2D set of the `curveNN.txt` files of `dir`, in name order.
fn curves_of(dir: &Path) -> YinSet2<Rational> {
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("curve directory")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "txt"))
        .collect();
    files.sort();
    let text: String = files
        .iter()
        .map(|f| std::fs::read_to_string(f).expect("curve file") + "\n\n")
        .collect();
    match yin2_text::read(&text).expect("yin2 text") {
        yin2_text::Yin2Text::Curves(c) => YinSet2::from_curves(c).expect("valid curves"),
        yin2_text::Yin2Text::Plane => YinSet2::full(),
    }
}

/// The exact 3D set of an OBJ file.
fn solid_of(path: &str) -> YinSet3<Rational> {
    let mesh = obj::read_obj(&std::fs::read_to_string(path).expect("OBJ file")).expect("OBJ");
    YinSet3::from_triangles(mesh.vertices, mesh.faces).expect("valid mesh")
}

/// The median time of `runs` calls of `f`, in milliseconds.
fn median_ms<T>(runs: usize, mut f: impl FnMut() -> T) -> f64 {
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let t = Instant::now();
            std::hint::black_box(f());
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[runs / 2]
}

/// Print the median times of panda ∧ Mickey and of the spheres' meet.
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let runs: usize = args[5].parse().expect("number of runs");
    let (panda, mickey) = (
        curves_of(Path::new(&args[1])),
        curves_of(Path::new(&args[2])),
    );
    let (a, b) = (solid_of(&args[3]), solid_of(&args[4]));
    println!(
        "panda_mickey_ms {:.3}",
        median_ms(runs, || panda.meet(&mickey))
    );
    println!("spheres_ms {:.3}", median_ms(runs, || a.meet(&b)));
}
