//! Random inputs for the float-versus-exact differential tests, as `f64` vertex cycles.
//!
//! * Well-separated sets ([`random_set`]): polygons with holes (and the odd island in a hole)
//!   whose vertices are points of a coarse integer grid, scaled by a power of two. Exact
//!   contacts on the grid (shared vertices, collinear overlaps, vertices on edges) occur, but
//!   no feature is smaller than the grid allows, which the callers choose ≫ ε.
//! * Near-degenerate perturbations ([`perturb`]): a vertex moved within ε/10 of another
//!   curve's edge or vertex, a copy offset by less than ε, a copy slid along one of its edges
//!   and offset across it by less than ε/10 (nearly collinear overlaps), every vertex jittered
//!   by less than ε/10.
//!
//! Every set returned passes the exact validator as given (its `f64` values read as
//! rationals): generators retry, and perturbations that break validity are dropped.

use yinset::kernel::Point;
use yinset::num::{Num, Rational};
use yinset::yin2::YinSet2;

/// Vertex cycles with `f64` coordinates.
pub type Curves = Vec<Vec<[f64; 2]>>;

/// SplitMix64: a small deterministic generator, so that every case is reproducible from its
/// seed on any platform.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x9E37_79B9_7F4A_7C15)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform integer in lo..=hi.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }

    /// True with probability p.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// A uniformly random element index of a non-empty slice of length `n`.
    pub fn index(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }

    /// A point uniform in the disc of radius r.
    pub fn in_disc(&mut self, r: f64) -> [f64; 2] {
        loop {
            let (x, y) = (self.range(-1.0, 1.0), self.range(-1.0, 1.0));
            if x * x + y * y < 1.0 {
                return [r * x, r * y];
            }
        }
    }
}

/// The exact points of `f64` cycles.
pub fn exact_curves(c: &Curves) -> Vec<Vec<Point<Rational>>> {
    c.iter()
        .map(|v| {
            v.iter()
                .map(|p| {
                    Point::new(
                        <Rational as Num>::from_f64(p[0]).expect("finite"),
                        <Rational as Num>::from_f64(p[1]).expect("finite"),
                    )
                })
                .collect()
        })
        .collect()
}

/// True if the cycles bound a Yin set exactly as given.
pub fn is_valid(c: &Curves) -> bool {
    !c.is_empty() && YinSet2::<Rational>::from_curves(exact_curves(c)).is_ok()
}

/// A star-shaped cycle around (cx, cy) with `k` vertices at random angles and radii in
/// [rmin, rmax], rounded to the integer grid, counterclockwise (consecutive repeats dropped).
fn star(rng: &mut Rng, cx: i64, cy: i64, rmin: f64, rmax: f64, k: usize) -> Vec<[f64; 2]> {
    let mut angles: Vec<f64> = (0..k)
        .map(|_| rng.range(0.0, std::f64::consts::TAU))
        .collect();
    angles.sort_by(f64::total_cmp);
    let mut v: Vec<[f64; 2]> = angles
        .iter()
        .map(|&t| {
            let r = rng.range(rmin, rmax);
            [
                (cx as f64 + r * t.cos()).round(),
                (cy as f64 + r * t.sin()).round(),
            ]
        })
        .collect();
    v.dedup();
    while v.len() > 1 && v.first() == v.last() {
        v.pop();
    }
    v
}

/// An axis-aligned rectangle, counterclockwise.
fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// A random primitive cycle (star or rectangle) centred near (cx, cy) of radius about r,
/// counterclockwise.
fn primitive(rng: &mut Rng, cx: i64, cy: i64, r: f64) -> Vec<[f64; 2]> {
    if rng.chance(0.25) {
        let (w, h) = (rng.int(1, r.max(1.0) as i64), rng.int(1, r.max(1.0) as i64));
        let (x, y) = ((cx - w) as f64, (cy - h) as f64);
        rect(x, y, x + 2.0 * w as f64, y + 2.0 * h as f64)
    } else {
        let k = rng.int(3, 12) as usize;
        star(rng, cx, cy, (r * 0.4).max(1.0), r.max(1.5), k)
    }
}

/// A random well-separated Yin set on the integer grid 0..=n: one to three components, each
/// with up to two holes, sometimes an island in a hole; then scaled by `scale` and shifted by
/// `offset` (both chosen by the caller so that the values stay exact in `f64`).
pub fn random_set(rng: &mut Rng, n: i64, scale: f64, offset: [f64; 2]) -> Curves {
    loop {
        let mut curves: Curves = Vec::new();
        let components = rng.int(1, 3);
        for _ in 0..components {
            let r = rng.range(n as f64 / 6.0, n as f64 / 2.5);
            let (cx, cy) = (
                rng.int((r as i64).min(n / 2), (n - r as i64).max(n / 2)),
                rng.int((r as i64).min(n / 2), (n - r as i64).max(n / 2)),
            );
            let outer = primitive(rng, cx, cy, r);
            if !try_push(&mut curves, outer) {
                continue;
            }
            for _ in 0..rng.int(0, 2) {
                let hr = rng.range(1.5, (r / 2.5).max(1.6));
                let (hx, hy) = (
                    cx + rng.int(-(r / 3.0) as i64, (r / 3.0) as i64),
                    cy + rng.int(-(r / 3.0) as i64, (r / 3.0) as i64),
                );
                let mut hole = primitive(rng, hx, hy, hr);
                hole.reverse();
                if try_push(&mut curves, hole) && hr > 3.0 && rng.chance(0.3) {
                    let island = primitive(rng, hx, hy, hr / 3.0);
                    try_push(&mut curves, island);
                }
            }
        }
        if curves.is_empty() {
            continue;
        }
        for c in curves.iter_mut() {
            for p in c.iter_mut() {
                *p = [p[0] * scale + offset[0], p[1] * scale + offset[1]];
            }
        }
        debug_assert!(is_valid(&curves));
        return curves;
    }
}

/// Add `c` to `curves` if the result is still a valid Yin set.
fn try_push(curves: &mut Curves, c: Vec<[f64; 2]>) -> bool {
    if c.len() < 3 {
        return false;
    }
    curves.push(c);
    if is_valid(curves) {
        true
    } else {
        curves.pop();
        false
    }
}

/// Move every vertex by `d`.
pub fn translate(c: &Curves, d: [f64; 2]) -> Curves {
    c.iter()
        .map(|v| v.iter().map(|p| [p[0] + d[0], p[1] + d[1]]).collect())
        .collect()
}

/// Reflect in the vertical line x = x0 and reverse every cycle (orientation kept).
pub fn mirror(c: &Curves, x0: f64) -> Curves {
    c.iter()
        .map(|v| v.iter().rev().map(|p| [2.0 * x0 - p[0], p[1]]).collect())
        .collect()
}

/// All edges of the cycles.
fn edges(c: &Curves) -> Vec<([f64; 2], [f64; 2])> {
    c.iter()
        .flat_map(|v| (0..v.len()).map(move |k| (v[k], v[(k + 1) % v.len()])))
        .collect()
}

/// The kinds of near-degenerate perturbation (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Perturbation {
    /// A vertex of b moved (with all of b) within ε/10 of a point inside an edge of a.
    VertexNearEdge,
    /// A vertex of b moved (with all of b) within ε/10 of a vertex of a.
    VertexNearVertex,
    /// b is a copy of a offset by less than ε.
    OffsetCopy,
    /// b is a copy of a slid along one of a's edges and offset across it by less than ε/10.
    CollinearSlide,
    /// Every vertex of a (or b) moved by less than ε/10.
    Jitter,
}

pub const PERTURBATIONS: [Perturbation; 5] = [
    Perturbation::VertexNearEdge,
    Perturbation::VertexNearVertex,
    Perturbation::OffsetCopy,
    Perturbation::CollinearSlide,
    Perturbation::Jitter,
];

/// Apply the perturbation `kind` at tolerance `eps` to the pair (a, b); `None` if the
/// perturbed sets are not valid as given (rounding of the moved coordinates, or a jitter that
/// made a curve cross another), so that the caller can count and redraw.
pub fn perturb(
    rng: &mut Rng,
    kind: Perturbation,
    a: &Curves,
    b: &Curves,
    eps: f64,
) -> Option<(Curves, Curves)> {
    // Strictly below ε/10 in Euclidean length.
    let small = 0.099 * eps;
    let (a, b) = match kind {
        Perturbation::VertexNearEdge => {
            let ea = edges(a);
            let (p, q) = ea[rng.index(ea.len())];
            let t = rng.range(0.05, 0.95);
            let target = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            let v = pick_vertex(rng, b);
            let o = rng.in_disc(small);
            let d = [target[0] + o[0] - v[0], target[1] + o[1] - v[1]];
            (a.clone(), translate(b, d))
        }
        Perturbation::VertexNearVertex => {
            let (u, v) = (pick_vertex(rng, a), pick_vertex(rng, b));
            let o = rng.in_disc(small);
            (
                a.clone(),
                translate(b, [u[0] + o[0] - v[0], u[1] + o[1] - v[1]]),
            )
        }
        Perturbation::OffsetCopy => {
            let o = rng.in_disc(0.99 * eps);
            (a.clone(), translate(a, o))
        }
        Perturbation::CollinearSlide => {
            let ea = edges(a);
            let (p, q) = ea[rng.index(ea.len())];
            let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
            let len = dx.hypot(dy);
            let t = rng.range(0.1, 0.9);
            let s = rng.range(-1.0, 1.0) * small;
            let d = [t * dx - s * dy / len, t * dy + s * dx / len];
            (a.clone(), translate(a, d))
        }
        Perturbation::Jitter => {
            let jitter = |rng: &mut Rng, c: &Curves| -> Curves {
                c.iter()
                    .map(|v| {
                        v.iter()
                            .map(|p| {
                                let o = rng.in_disc(small);
                                [p[0] + o[0], p[1] + o[1]]
                            })
                            .collect()
                    })
                    .collect()
            };
            let ja = jitter(rng, a);
            let jb = if rng.chance(0.5) {
                jitter(rng, b)
            } else {
                b.clone()
            };
            (ja, jb)
        }
    };
    (is_valid(&a) && is_valid(&b)).then_some((a, b))
}

fn pick_vertex(rng: &mut Rng, c: &Curves) -> [f64; 2] {
    let v = &c[rng.index(c.len())];
    v[rng.index(v.len())]
}

/// A star-shaped polygon with `n` vertices around `centre`: radius 1 + 0.2 sin(5θ + φ) with
/// 10⁻⁵ noise (below the vertex spacing, so the boundary stays smooth and the two polygons
/// cross a few dozen times), at slightly jittered angles (general position with probability
/// one).
pub fn random_star(rng: &mut Rng, n: usize, centre: [f64; 2], phase: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = (k as f64 + 0.8 * rng.unit()) * std::f64::consts::TAU / n as f64;
            let r = 1.0 + 0.2 * (5.0 * t + phase).sin() + 1e-5 * rng.unit();
            [centre[0] + r * t.cos(), centre[1] + r * t.sin()]
        })
        .collect()
}
