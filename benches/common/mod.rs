//! Workloads of the benches, as `f64` curves that every contender reads: yinset in
//! exact mode (each `f64` taken as the rational it is), yinset in float mode, and the peers.
//!
//! Curves follow yinset's convention (counterclockwise bounds a region, clockwise a hole), which
//! under the even-odd rule is also what the peers read, since every workload is bounded.

#![allow(dead_code)] // each bench target uses a part of this module

use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};
use std::f64::consts::TAU;
use std::path::PathBuf;
use yinset::io::{geojson, yin2_text};
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::{FillRule, YinSet2};

/// A set of closed curves (first point not repeated).
pub type Curves = Vec<Vec<[f64; 2]>>;

/// A random star-shaped polygon around the origin: `n` sorted random angles, radii uniform in
/// [0.5, 1], the whole turned by `turn` radians; counterclockwise.
pub fn star(n: usize, seed: u64, turn: f64) -> Vec<[f64; 2]> {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut angles: Vec<f64> = (0..n).map(|_| rng.random::<f64>() * TAU).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    angles
        .into_iter()
        .map(|a| {
            let r = rng.random_range(0.5..1.0);
            [r * (a + turn).cos(), r * (a + turn).sin()]
        })
        .collect()
}

/// W1: two random star-shaped polygons of `n` vertices each, about the same centre, the second
/// drawn independently and turned by 0.1 rad, so that they overlap in the whole disc of radius
/// 1/2 and their boundaries cross Θ(n) times. (Two stars about different centres would cross
/// Θ(n²) times: their spikes run in different directions.)
pub fn w1(n: usize) -> (Curves, Curves) {
    (vec![star(n, 1, 0.0)], vec![star(n, 2, 0.1)])
}

/// A k×k checkerboard of unit cells with the black cells (i + j even) as counterclockwise
/// squares, each vertex mapped by `f`. As one Yin set: k²/2 components touching at corners.
pub fn checkerboard(k: usize, f: impl Fn(f64, f64) -> [f64; 2]) -> Curves {
    let mut cells = Vec::with_capacity(k * k / 2 + 1);
    for i in 0..k {
        for j in 0..k {
            if (i + j) % 2 == 0 {
                let (x, y) = (i as f64, j as f64);
                cells.push(vec![
                    f(x, y),
                    f(x + 1.0, y),
                    f(x + 1.0, y + 1.0),
                    f(x, y + 1.0),
                ]);
            }
        }
    }
    cells
}

/// W2 (shift): the k×k checkerboard and a copy shifted by half a cell in x and y.
pub fn w2_shift(k: usize) -> (Curves, Curves) {
    (
        checkerboard(k, |x, y| [x, y]),
        checkerboard(k, |x, y| [x + 0.5, y + 0.5]),
    )
}

/// The angle of W2's rotated copy (about 0.57°).
pub const W2_TURN: f64 = 0.01;

/// W2 (rotate): the k×k checkerboard and a copy turned by [`W2_TURN`] about the board's centre
/// (a common corner of four cells when k is even: a shared vertex of both boards).
pub fn w2_rotate(k: usize) -> (Curves, Curves) {
    let c = k as f64 / 2.0;
    let (s, co) = W2_TURN.sin_cos();
    (
        checkerboard(k, |x, y| [x, y]),
        checkerboard(k, |x, y| {
            let (dx, dy) = (x - c, y - c);
            [c + co * dx - s * dy, c + s * dx + co * dy]
        }),
    )
}

/// `../shared/data/2d/<rel>` beside the repository; panics naming the path when it is missing.
pub fn data_path(rel: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/2d")
        .join(rel);
    if !p.exists() {
        panic!(
            "bench data missing: {} (the benches read ../shared/data beside the repository)",
            p.display()
        );
    }
    p
}

/// The text of a data file, panicking with its path when it cannot be read.
pub fn read_data(rel: &str) -> String {
    let p = data_path(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()))
}

/// The curves of the numbered files `dir/curveNN.txt` (panda, mickey), read in mode `N`
/// (exact mode: the decimal text without rounding).
pub fn figure<N: Num>(dir: &str) -> Vec<Vec<Point<N>>> {
    let root = data_path(dir);
    let mut curves = Vec::new();
    for k in 1.. {
        let file = root.join(format!("curve{k:02}.txt"));
        if k > 1 && !file.exists() {
            break;
        }
        let text = std::fs::read_to_string(&file)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", file.display()));
        curves.extend(
            yin2_text::read_curves::<N>(&text)
                .unwrap_or_else(|e| panic!("{}: {e}", file.display())),
        );
    }
    curves
}

/// The curves of a figure (see [`figure`]) as read in float mode.
pub fn yin2_dir(dir: &str) -> Curves {
    figure::<Float>(dir)
        .iter()
        .map(|c| c.iter().map(|p| [p.x.get(), p.y.get()]).collect())
        .collect()
}

/// W4: the panda and Mickey of seed 000 Fig. 13.
pub fn w4() -> (Curves, Curves) {
    (yin2_dir("panda"), yin2_dir("mickey"))
}

/// W3: the rings of the first two features of a GIS file (`asia`, `states_source`): the subject
/// multipolygon and the clip polygon of the overlay test they come from, as read in float mode.
/// Also the same rings read exactly from the decimal text (for exact mode).
pub fn w3(name: &str) -> ((Curves, Curves), (RationalRings, RationalRings)) {
    let rel = format!("gis/{name}.geojson");
    let text = read_data(&rel);
    let floats = geojson::read_features::<Float>(&text).unwrap_or_else(|e| panic!("{rel}: {e}"));
    let exact = geojson::read_features::<Rational>(&text).unwrap_or_else(|e| panic!("{rel}: {e}"));
    assert!(
        floats.len() >= 2,
        "{rel}: expected a subject and a clip feature"
    );
    let rings_f = |k: usize| -> Curves {
        floats[k]
            .polygons
            .iter()
            .flat_map(|p| p.rings())
            .map(|r| r.iter().map(|p| [p.x.get(), p.y.get()]).collect())
            .collect()
    };
    let rings_q = |k: usize| -> RationalRings {
        exact[k]
            .polygons
            .iter()
            .flat_map(|p| p.rings())
            .map(|r| r.to_vec())
            .collect()
    };
    ((rings_f(0), rings_f(1)), (rings_q(0), rings_q(1)))
}

/// Rings read exactly.
pub type RationalRings = Vec<Vec<Point<Rational>>>;

/// The bounding box `[xmin, ymin, xmax, ymax]` of some curves.
pub fn bbox(c: &Curves) -> [f64; 4] {
    c.iter().flatten().fold(
        [f64::MAX, f64::MAX, f64::MIN, f64::MIN],
        |[a, b, cc, d], p| [a.min(p[0]), b.min(p[1]), cc.max(p[0]), d.max(p[1])],
    )
}

/// W5's control volumes: the N×N grid of square cells of side h over a square slightly larger
/// than the bounding box `bb`.
pub fn grid_cells(bb: [f64; 4], n: usize) -> Vec<Vec<[f64; 2]>> {
    let side = (bb[2] - bb[0]).max(bb[3] - bb[1]) * 1.01;
    let (x0, y0) = (bb[0] - 0.005 * side, bb[1] - 0.005 * side);
    let h = side / n as f64;
    let mut cells = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let (xa, xb) = (x0 + i as f64 * h, x0 + (i + 1) as f64 * h);
            let (ya, yb) = (y0 + j as f64 * h, y0 + (j + 1) as f64 * h);
            cells.push(vec![[xa, ya], [xb, ya], [xb, yb], [xa, yb]]);
        }
    }
    cells
}

/// Points in number type `N`, each `f64` taken exactly.
pub fn points<N: Num>(c: &[[f64; 2]]) -> Vec<Point<N>> {
    c.iter()
        .map(|p| Point::new(N::from_f64(p[0]).unwrap(), N::from_f64(p[1]).unwrap()))
        .collect()
}

/// The Yin set bounded by `c` in exact mode (the curves must bound one as given).
pub fn exact(c: &Curves) -> YinSet2<Rational> {
    YinSet2::from_curves(c.iter().map(|v| points(v)).collect())
        .unwrap_or_else(|e| panic!("not a Yin set: {e}"))
}

/// The Yin set bounded by `c` in float mode, with ε from the input's extent.
pub fn float(c: &Curves) -> YinSet2<Float> {
    YinSet2::from_curves_with(c.iter().map(|v| points(v)).collect(), Tolerance::default())
        .unwrap_or_else(|e| panic!("not a Yin set: {e}"))
}

/// The Yin set filled by rings under the even-odd rule (GIS polygons), exact mode.
pub fn exact_filled(rings: &RationalRings) -> YinSet2<Rational> {
    YinSet2::from_rings_filled(rings.clone(), FillRule::EvenOdd)
        .unwrap_or_else(|e| panic!("rings: {e}"))
}

/// The Yin set filled by rings under the even-odd rule (GIS polygons), float mode.
pub fn float_filled(c: &Curves) -> YinSet2<Float> {
    YinSet2::from_rings_filled_with(
        c.iter().map(|v| points(v)).collect(),
        FillRule::EvenOdd,
        Tolerance::default(),
    )
    .unwrap_or_else(|e| panic!("rings: {e}"))
}

/// `q` random query points in the box `bb`, from a fixed seed.
pub fn queries(q: usize, bb: [f64; 4], seed: u64) -> Vec<[f64; 2]> {
    let mut rng = StdRng::seed_from_u64(seed);
    (0..q)
        .map(|_| {
            [
                rng.random_range(bb[0]..bb[2]),
                rng.random_range(bb[1]..bb[3]),
            ]
        })
        .collect()
}

/// Total vertex count.
pub fn vertices(c: &Curves) -> usize {
    c.iter().map(Vec::len).sum()
}

/// The number of copies in W6 at its largest.
pub const W6_COPIES: usize = 300;

/// W6's polygon: 16 vertices at equal angles about the origin, radii alternating between
/// 1/2 and 0.3–0.4 (a non-convex star of diameter 1), counterclockwise.
pub fn w6_polygon() -> Vec<[f64; 2]> {
    (0..16)
        .map(|j| {
            let r = if j % 2 == 0 {
                0.5
            } else {
                0.3 + 0.05 * (j % 3) as f64
            };
            let a = TAU * j as f64 / 16.0;
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// W6 ([`W6_COPIES`] copies at its largest): `copies` copies of [`w6_polygon`], copy k
/// turned by k·10⁻⁶ rad about its centre and shifted by k·10⁻⁶ (of its size, 1) along (1, 1/2):
/// rings to be filled under the non-zero rule, their union.
pub fn w6(copies: usize) -> Curves {
    let base = w6_polygon();
    (0..copies)
        .map(|k| {
            let t = k as f64 * 1e-6;
            let (s, c) = t.sin_cos();
            base.iter()
                .map(|p| [c * p[0] - s * p[1] + t, s * p[0] + c * p[1] + t / 2.0])
                .collect()
        })
        .collect()
}

/// Rings in exact mode, each `f64` taken as the rational it is.
pub fn rational_rings(c: &Curves) -> RationalRings {
    c.iter().map(|v| points(v)).collect()
}
