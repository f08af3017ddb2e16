//! Seed corpus generator: writes `fuzz/seeds/<corpus>/<name>` (run it from anywhere):
//!
//! ```sh
//! cargo run --manifest-path fuzz/Cargo.toml --example gen_seeds            # write the seeds
//! cargo run --manifest-path fuzz/Cargo.toml --example gen_seeds -- --check # and replay them
//! ```
//!
//! * `ops` (targets `ops_exact`, `ops_float`): the degenerate configurations of seed 000's
//!   figures as operand pairs, and the Martinez and JTS overlay cases mapped onto the 8×8 grid.
//! * `construct`: each figure configuration as one curve list (valid and invalid ones).
//! * `parse_yin2`, `parse_wkt`, `parse_geojson`: small texts in each format, the figures
//!   written by the crate's writers, a panda curve, JTS WKT, small Martinez/GIS GeoJSON files.
//!
//! The data is read in place from `../shared/data/2d` beside the repository.
//! With `--check`, every seed is also run through its target's check (without libFuzzer), and
//! the generator exits non-zero if any check fails.

use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use yinset::io::{geojson, wkt, yin2_text, NumberStyle, Polygon};
use yinset::kernel::Point;
use yinset::num::{Float, Rational};
use yinset_fuzz::check;
use yinset_fuzz::input::{
    ConstructInput, OpsInput, Probe, Shape, COMPLEMENT, FILL_ONLY, GRID, MAX_CURVES, MAX_POINTS,
    NONZERO,
};
use yinset_fuzz::text;

type Ring = Vec<(u8, u8)>;

fn rect(x0: u8, y0: u8, x1: u8, y1: u8) -> Ring {
    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
}

fn rev(mut r: Ring) -> Ring {
    r.reverse();
    r
}

fn shape(flags: u8, rings: &[Ring]) -> Shape {
    let refs: Vec<&[(u8, u8)]> = rings.iter().map(Vec::as_slice).collect();
    Shape::of(flags, &refs)
}

/// Probes spread over the grid: (i − ½, j − ½).
fn probes() -> Vec<Probe> {
    [(1, 1), (2, 3), (3, 2), (4, 4), (6, 5), (8, 8)]
        .iter()
        .map(|&(i, j)| Probe { i, j })
        .collect()
}

/// The degenerate configurations of seed 000 (Figures 1, 3, 8, 11) and the classic overlay
/// degeneracies, as named curve lists.
fn figures() -> Vec<(&'static str, Vec<Ring>)> {
    vec![
        ("square", vec![rect(0, 0, 4, 4)]),
        (
            "squares_touching_at_corner",
            vec![rect(0, 0, 2, 2), rect(2, 2, 4, 4)],
        ),
        (
            "hole_touching_outer",
            vec![rect(0, 0, 4, 4), rev(vec![(2, 0), (3, 2), (1, 2)])],
        ),
        (
            "hole_touching_outer_twice",
            vec![rect(0, 0, 4, 4), rev(vec![(2, 0), (4, 2), (2, 4), (1, 2)])],
        ),
        (
            "holes_touching_each_other",
            vec![
                rect(0, 0, 4, 4),
                rev(vec![(1, 1), (2, 1), (2, 2)]),
                rev(vec![(2, 2), (3, 2), (3, 3)]),
            ],
        ),
        (
            "island_in_hole",
            vec![rect(0, 0, 7, 7), rev(rect(1, 1, 6, 6)), rect(2, 2, 5, 5)],
        ),
        (
            "island_touching_hole",
            vec![rect(0, 0, 7, 7), rev(rect(1, 1, 6, 6)), rect(1, 1, 3, 3)],
        ),
        ("hole_only_unbounded", vec![rev(rect(2, 2, 5, 5))]),
        ("bow_tie", vec![vec![(0, 0), (2, 2), (2, 0), (0, 2)]]),
        (
            "overlapping_squares",
            vec![rect(0, 0, 4, 4), rect(2, 2, 6, 6)],
        ),
        (
            "spike",
            vec![vec![(0, 0), (4, 0), (4, 4), (2, 4), (2, 6), (2, 4), (0, 4)]],
        ),
        (
            "triangle_fan",
            vec![vec![(0, 0), (6, 0), (3, 3)], vec![(3, 3), (6, 6), (0, 6)]],
        ),
    ]
}

/// Operand pairs: the figures against each other where the paper's degeneracies arise.
fn figure_pairs() -> Vec<(&'static str, Shape, Shape)> {
    let f: BTreeMap<&str, Vec<Ring>> = figures().into_iter().collect();
    let s = |name: &str| shape(0, &f[name]);
    vec![
        (
            "corner_touch",
            shape(0, &[rect(0, 0, 2, 2)]),
            shape(0, &[rect(2, 2, 4, 4)]),
        ),
        (
            "collinear_same_direction",
            shape(0, &[rect(0, 0, 4, 2)]),
            shape(0, &[rect(2, 0, 6, 3)]),
        ),
        (
            "collinear_opposite_direction",
            shape(0, &[rect(0, 0, 4, 2)]),
            shape(0, &[rect(1, 2, 3, 4)]),
        ),
        (
            "identical",
            s("hole_touching_outer"),
            s("hole_touching_outer"),
        ),
        (
            "set_and_complement",
            s("island_in_hole"),
            shape(COMPLEMENT, &f["island_in_hole"]),
        ),
        (
            "island_in_hole_vs_bar",
            s("island_in_hole"),
            shape(0, &[rect(0, 3, 7, 4)]),
        ),
        (
            "hole_touching_outer_vs_bar",
            s("hole_touching_outer"),
            shape(0, &[rect(1, 1, 5, 2)]),
        ),
        (
            "touching_holes_vs_diagonal",
            s("holes_touching_each_other"),
            shape(0, &[vec![(0, 0), (4, 4), (0, 4)]]),
        ),
        (
            "unbounded_vs_bounded",
            s("hole_only_unbounded"),
            shape(0, &[rect(3, 3, 7, 7)]),
        ),
        (
            "bow_tie_fill_vs_square",
            shape(FILL_ONLY | NONZERO, &f["bow_tie"]),
            shape(0, &[rect(1, 0, 3, 2)]),
        ),
        (
            "corner_squares_vs_complement",
            s("squares_touching_at_corner"),
            shape(COMPLEMENT, &[rect(1, 1, 3, 3)]),
        ),
        ("empty_vs_square", Shape::default(), s("square")),
        ("full_vs_square", shape(COMPLEMENT, &[]), s("square")),
    ]
}

/// The data directory beside the repository.
fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/2d")
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
}

/// Polygons mapped onto the grid: kept as they are if integral and within 8 units, else scaled
/// into [0, 7]² and rounded (the topology may change: any grid shape is a good seed). `None` if
/// too many rings or points for the input format.
fn to_grid(polys: &[&[Polygon<Float>]]) -> Option<Vec<Vec<Ring>>> {
    let all: Vec<[f64; 2]> = polys
        .iter()
        .flat_map(|ps| ps.iter())
        .flat_map(|p| p.rings())
        .flatten()
        .map(Point::to_f64)
        .collect();
    let min = |k: usize| all.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
    let max = |k: usize| all.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
    let (x0, y0) = (min(0), min(1));
    let span = (max(0) - x0).max(max(1) - y0);
    let integral = all
        .iter()
        .all(|p| p[0].fract() == 0.0 && p[1].fract() == 0.0);
    let top = f64::from(GRID - 1);
    let scale = if integral && span <= top {
        1.0
    } else {
        top / span
    };
    let map = |v: f64, o: f64| ((v - o) * scale).round().clamp(0.0, top) as u8;
    polys
        .iter()
        .map(|ps| {
            let rings: Vec<Ring> = ps
                .iter()
                .flat_map(|p| p.rings())
                .map(|r| {
                    let mut g: Ring = r
                        .iter()
                        .map(|p| (map(p.x.get(), x0), map(p.y.get(), y0)))
                        .collect();
                    g.dedup();
                    while g.len() > 1 && g.first() == g.last() {
                        g.pop();
                    }
                    g
                })
                .collect();
            (rings.len() <= MAX_CURVES && rings.iter().all(|r| r.len() <= MAX_POINTS))
                .then_some(rings)
        })
        .collect()
}

/// The subject and clipping polygons of each Martinez case (its first two features).
fn martinez() -> Vec<(String, String, [Vec<Polygon<Float>>; 2])> {
    let dir = data_dir().join("martinez");
    let mut names: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|path| {
            let text = read(&path);
            let mut features = geojson::read_features::<Float>(&text)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
                .into_iter();
            let mut next = || features.next().map(|f| f.polygons).unwrap_or_default();
            let pair = [next(), next()];
            let name = path.file_stem().unwrap().to_string_lossy().into_owned();
            (name, text, pair)
        })
        .collect()
}

/// The WKT texts of the `<a>` and `<b>` of each JTS case, in file order.
fn jts() -> Vec<(String, String, String)> {
    let dir = data_dir().join("jts");
    let mut out = Vec::new();
    for file in ["TestOverlayAA.xml", "TestNGOverlayA.xml"] {
        let xml = read(&dir.join(file));
        let element = |case: &str, tag: &str| {
            let open = format!("<{tag}>");
            let start = case.find(&open)? + open.len();
            let end = case[start..].find(&format!("</{tag}>"))?;
            Some(case[start..start + end].trim().to_string())
        };
        for (k, case) in xml.split("<case>").skip(1).enumerate() {
            if let (Some(a), Some(b)) = (element(case, "a"), element(case, "b")) {
                let stem = file.trim_end_matches(".xml");
                out.push((format!("{stem}_{k:02}"), a, b));
            }
        }
    }
    out
}

/// Rings of a figure as exact points (for the writers).
fn exact(rings: &[Ring]) -> Vec<Vec<Point<Rational>>> {
    rings
        .iter()
        .map(|r| {
            r.iter()
                .map(|&(x, y)| Point::int(i64::from(x), i64::from(y)))
                .collect()
        })
        .collect()
}

/// Seeds by corpus name.
#[derive(Default)]
struct Seeds(BTreeMap<&'static str, Vec<(String, Vec<u8>)>>);

impl Seeds {
    fn add(&mut self, corpus: &'static str, name: impl Into<String>, bytes: impl Into<Vec<u8>>) {
        self.0
            .entry(corpus)
            .or_default()
            .push((name.into(), bytes.into()));
    }
}

fn generate() -> Seeds {
    let mut seeds = Seeds::default();
    // Binary operations: figure pairs, then Martinez and JTS on the grid. The tol byte cycles
    // through the ε and jitter settings of float mode (exact mode ignores it).
    let mut tol = 0u8;
    let mut next_tol = || {
        tol = tol.wrapping_add(9) & 31;
        tol
    };
    for (name, a, b) in figure_pairs() {
        let input = OpsInput {
            tol: next_tol(),
            a,
            b,
            probes: probes(),
        };
        seeds.add("ops", format!("fig_{name}"), input.encode());
    }
    for (name, _, [a, b]) in martinez() {
        if let Some(g) = to_grid(&[&a, &b]) {
            let input = OpsInput {
                tol: next_tol(),
                a: shape(0, &g[0]),
                b: shape(0, &g[1]),
                probes: probes(),
            };
            seeds.add("ops", format!("martinez_{name}"), input.encode());
        }
    }
    for (name, a, b) in jts() {
        let (Ok(pa), Ok(pb)) = (
            wkt::read_polygons::<Float>(&a),
            wkt::read_polygons::<Float>(&b),
        ) else {
            continue;
        };
        if let Some(g) = to_grid(&[&pa, &pb]) {
            let input = OpsInput {
                tol: next_tol(),
                a: shape(FILL_ONLY, &g[0]),
                b: shape(FILL_ONLY, &g[1]),
                probes: probes(),
            };
            seeds.add("ops", format!("jts_{name}"), input.encode());
        }
    }
    // The constructor: every figure as one curve list, and the operand pairs' curves together.
    for (name, rings) in figures() {
        let input = ConstructInput {
            tol: next_tol(),
            shape: shape(0, &rings),
            probes: probes(),
        };
        seeds.add("construct", format!("fig_{name}"), input.encode());
    }
    for (name, a, b) in figure_pairs() {
        let mut both = a.clone();
        both.curves.extend(b.curves.iter().cloned());
        both.curves.truncate(MAX_CURVES);
        let input = ConstructInput {
            tol: next_tol(),
            shape: both,
            probes: probes(),
        };
        seeds.add("construct", format!("pair_{name}"), input.encode());
    }
    // Text formats: hand-written samples, the figures as written by the crate, data files.
    seeds.add(
        "parse_yin2",
        "sample",
        "# a unit square, then a triangle with exact fractions\n0 0\n1 0\n  1   1\n0 1\n0 0\n\n1/3 0.5\n4.5040114e+00 -2\n1 1\n",
    );
    seeds.add(
        "parse_yin2",
        "errors",
        "0 0\n1 x\n0 0 0\n  7\n1e99999999 0\n",
    );
    seeds.add(
        "parse_yin2",
        "panda_curve01",
        read(&data_dir().join("panda/curve01.txt")),
    );
    seeds.add(
        "parse_wkt",
        "sample",
        "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (2 0, 1 2, 3 2, 2 0))",
    );
    seeds.add(
        "parse_wkt",
        "collection",
        "GEOMETRYCOLLECTION (MULTIPOLYGON (((0 0, 1/3 0, 0 1, 0 0)), EMPTY), POLYGON EMPTY, \
         GEOMETRYCOLLECTION (POLYGON ((5 5, 6 5, 6 6, 5 5))), LINESTRING (0 0, 1 1), POINT (1 2))",
    );
    seeds.add("parse_wkt", "errors", "polygon ((0 0, 1 0, 1 1 1, 0 0)");
    for (name, a, b) in jts()
        .into_iter()
        .filter(|(_, a, b)| a.len() + b.len() < 600)
        .take(12)
    {
        seeds.add("parse_wkt", format!("jts_{name}_a"), a);
        seeds.add("parse_wkt", format!("jts_{name}_b"), b);
    }
    seeds.add(
        "parse_geojson",
        "sample",
        r#"{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"n": 1.5}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]], [[2, 0], [1, 2], [3, 2], [2, 0]]]}}, {"type": "Feature", "properties": null, "geometry": null}]}"#,
    );
    seeds.add(
        "parse_geojson",
        "collection",
        r#"{"type": "GeometryCollection", "geometries": [{"type": "MultiPolygon", "coordinates": [[[[0, 0], [1e-3, 0], [0, 1], [0, 0]]]]}, {"coordinates": [], "type": "Polygon"}]}"#,
    );
    for (name, text, _) in martinez().into_iter().filter(|(_, t, _)| t.len() <= 2500) {
        seeds.add("parse_geojson", format!("martinez_{name}"), text);
    }
    seeds.add(
        "parse_geojson",
        "gis_hole_hole",
        read(&data_dir().join("gis/hole_hole.geojson")),
    );
    for (name, rings) in figures() {
        let curves = exact(&rings);
        seeds.add(
            "parse_yin2",
            format!("fig_{name}"),
            yin2_text::write_curves(&curves),
        );
        let polys: Vec<Polygon<Rational>> = curves
            .into_iter()
            .map(|exterior| Polygon {
                exterior,
                interiors: vec![],
            })
            .collect();
        seeds.add(
            "parse_wkt",
            format!("fig_{name}"),
            wkt::write_multipolygon(&polys, NumberStyle::Exact).expect("decimal figures"),
        );
        seeds.add(
            "parse_geojson",
            format!("fig_{name}"),
            geojson::write_multipolygon(&polys, NumberStyle::Exact).expect("decimal figures"),
        );
    }
    seeds
}

/// Run one seed through its target's check; the panic message if it fails.
fn replay(corpus: &str, bytes: &[u8]) -> Result<(), String> {
    let result = catch_unwind(AssertUnwindSafe(|| match corpus {
        "ops" => {
            let input: OpsInput = yinset_fuzz::input::decode(bytes).expect("decodes");
            check::ops_exact(&input);
            check::ops_float(&input);
        }
        "construct" => {
            check::construct(&yinset_fuzz::input::decode(bytes).expect("decodes"));
        }
        "parse_yin2" => text::yin2(&text::text_of(bytes)),
        "parse_wkt" => text::wkt(&text::text_of(bytes)),
        "parse_geojson" => text::geojson(&text::text_of(bytes)),
        other => panic!("unknown corpus {other}"),
    }));
    result.map_err(|e| {
        e.downcast_ref::<String>()
            .cloned()
            .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default()
    })
}

fn main() {
    let check = std::env::args().any(|a| a == "--check");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("seeds");
    let seeds = generate();
    let mut failures = 0;
    for (corpus, list) in &seeds.0 {
        let dir = root.join(corpus);
        if dir.exists() {
            std::fs::remove_dir_all(&dir).expect("remove old seeds");
        }
        std::fs::create_dir_all(&dir).expect("create the seed directory");
        for (name, bytes) in list {
            std::fs::write(dir.join(name), bytes).expect("write a seed");
            if check {
                if let Err(message) = replay(corpus, bytes) {
                    failures += 1;
                    eprintln!("FAILED {corpus}/{name}: {message}\n");
                }
            }
        }
        println!("{corpus}: {} seeds in {}", list.len(), dir.display());
    }
    if check {
        println!("replayed every seed: {failures} failed");
        if failures > 0 {
            std::process::exit(1);
        }
    }
}
