//! The shared data sets read in place from `../shared/data/2d`: the paper's panda and Mickey,
//! and the GIS outlines, as `f64` cycles (decimal text parsed to the nearest `f64`; the exact
//! inputs are those `f64` values read as rationals).

use super::gen::{exact_curves, is_valid, Curves};
use crate::common::data_dir;
use yinset::io::{geojson, yin2_text, Polygon};
use yinset::num::{Float, Rational};
use yinset::yin2::{FillRule, YinSet2};

/// `f64` cycles of float points.
fn to_curves<'a>(rings: impl IntoIterator<Item = &'a [yinset::kernel::Point<Float>]>) -> Curves {
    rings
        .into_iter()
        .map(|r| r.iter().map(|p| [p.x.get(), p.y.get()]).collect())
        .collect()
}

/// All curves of one of the paper's figures (one file per curve).
pub fn figure(name: &str, count: usize) -> Curves {
    let dir = data_dir(name);
    let rings: Vec<Vec<_>> = (1..=count)
        .flat_map(|i| {
            let path = dir.join(format!("curve{i:02}.txt"));
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            yin2_text::read_curves::<Float>(&text)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        })
        .collect();
    to_curves(rings.iter().map(Vec::as_slice))
}

pub fn panda() -> Curves {
    figure("panda", 10)
}

pub fn mickey() -> Curves {
    figure("mickey", 6)
}

/// Twice the signed area of a cycle.
fn twice_area(r: &[[f64; 2]]) -> f64 {
    (0..r.len())
        .map(|k| {
            let (p, q) = (r[k], r[(k + 1) % r.len()]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum()
}

/// Rings oriented as a Yin set needs them: exteriors counterclockwise, holes clockwise.
fn oriented(polys: &[Polygon<Float>]) -> Curves {
    let mut out = Vec::new();
    for p in polys {
        for (k, ring) in p.rings().enumerate() {
            let mut r: Vec<[f64; 2]> = ring.iter().map(|q| [q.x.get(), q.y.get()]).collect();
            if (twice_area(&r) > 0.0) != (k == 0) {
                r.reverse();
            }
            out.push(r);
        }
    }
    out
}

/// How a GIS feature became a Yin set's cycles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Built {
    /// Its rings, oriented, are valid as given.
    AsGiven,
    /// Its parts overlap or touch improperly: filled by the non-zero rule exactly, and the
    /// filled set's vertices are all `f64` values.
    Filled,
}

/// The polygonal features of a GeoJSON file of `../shared/data/2d/gis`, each as its polygons'
/// rings (exteriors counterclockwise, holes clockwise), polygon by polygon.
pub fn gis(file: &str) -> Vec<Vec<Curves>> {
    let path = data_dir("gis").join(file);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let features = geojson::read_features::<Float>(&text)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    features
        .iter()
        .filter(|f| !f.polygons.is_empty())
        .map(|f| {
            f.polygons
                .iter()
                .map(|p| oriented(std::slice::from_ref(p)))
                .collect()
        })
        .collect()
}

/// Polygons of a feature, those whose bounding box meets `near` first (in input order), then
/// the others, as many as fit in `budget` vertices in all.
pub fn select(polygons: &[Curves], near: [f64; 4], budget: usize) -> Vec<Curves> {
    let meets = |c: &Curves| {
        let b = bbox(c);
        b[0] <= near[2] && near[0] <= b[2] && b[1] <= near[3] && near[1] <= b[3]
    };
    let mut out = Vec::new();
    let mut used = 0;
    for first in [true, false] {
        for p in polygons.iter().filter(|p| meets(p) == first) {
            let n: usize = p.iter().map(Vec::len).sum();
            if used + n <= budget {
                used += n;
                out.push(p.clone());
            }
        }
    }
    out
}

/// The Yin-set cycles of some polygons: as given if valid, else filled by the non-zero rule
/// exactly if the filled set's vertices are all `f64` values; `None` otherwise.
pub fn yin_cycles(polygons: &[Curves]) -> Option<(Curves, Built)> {
    let curves: Curves = polygons.iter().flatten().cloned().collect();
    if is_valid(&curves) {
        return Some((curves, Built::AsGiven));
    }
    let filled =
        YinSet2::<Rational>::from_rings_filled(exact_curves(&curves), FillRule::NonZero).ok()?;
    let back: Curves = filled
        .curves()
        .iter()
        .map(|c| c.vertices().iter().map(|p| p.to_f64()).collect())
        .collect();
    let exact_again = exact_curves(&back);
    let same = filled
        .curves()
        .iter()
        .zip(&exact_again)
        .all(|(c, e)| c.vertices() == e.as_slice());
    same.then_some((back, Built::Filled))
}

/// The bounding box (min x, min y, max x, max y) of cycles.
pub fn bbox(c: &Curves) -> [f64; 4] {
    c.iter().flatten().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        },
    )
}

/// The counterclockwise rectangle [x0, x1] × [y0, y1].
pub fn boxed(x0: f64, y0: f64, x1: f64, y1: f64) -> Curves {
    vec![vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]]
}
