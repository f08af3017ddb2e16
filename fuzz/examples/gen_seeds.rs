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
//! * `ops3` (targets `ops3_exact`, `ops3_float`): the degenerate configurations of DESIGN-3D §3
//!   (tests/yin3_degenerate.rs) as operand pairs on the lattice, axis-aligned and rotated, and
//!   each once more with a float-mode placement in turn (B moved off the lattice, ε, scale).
//! * `construct3`: those solids' meshes alone and two in one face list, invalid meshes (an open
//!   box, a flipped face, crossing boxes, nested boxes of one orientation, bad faces), and the
//!   small shared meshes of `../shared/data/3d` rounded onto the lattice.
//! * `parse_obj`: the shared OBJ files of at most 8 KiB, the configurations written by
//!   `write_obj`, and hand-written samples (every index form, n-gons, exact fractions, errors).
//!
//! The data is read in place from `../shared/data/2d` and `../shared/data/3d` beside the
//! repository.
//! With `--check`, every seed is also run through its target's check (without libFuzzer), and
//! the generator exits non-zero if any check fails.

use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use yinset::io::{geojson, obj, wkt, yin2_text, NumberStyle, Polygon};
use yinset::kernel::{Point, Point3};
use yinset::num::{Float, Rational};
use yinset_fuzz::input::{
    ConstructInput, OpsInput, Probe, Scale, Shape, COMPLEMENT, FILL_ONLY, GRID, MAX_CURVES,
    MAX_POINTS, NONZERO,
};
use yinset_fuzz::input3::{
    Combine, Construct3Input, LatticePoint, Operand, Ops3Input, Place3, Probe3, Solid, LATTICE,
    MAX_FACES3, MAX_VERTICES3, MOVE_NONE, MOVE_SCALE, MOVE_SHIFT, MOVE_THIRDS, ROTATE,
};
use yinset_fuzz::text;
use yinset_fuzz::{check, check3, check3_float};

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

/// A Martinez case: its name, its file's text, and its subject and clipping polygons.
type MartinezCase = (String, String, [Vec<Polygon<Float>>; 2]);

/// The subject and clipping polygons of each Martinez case (its first two features).
fn martinez() -> Vec<MartinezCase> {
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

/// Float mode's far placements (input.rs, Scale): the ends of the `f64` range, offsets far
/// from the origin, and ε from subnormal to huge, each with what the contract expects.
fn far_scales() -> Vec<(&'static str, Scale)> {
    let scale = |mode, exp, shift, eps| Scale {
        mode,
        exp,
        shift,
        eps,
    };
    vec![
        // s = 2⁻⁹⁹⁷ (coordinates from 10⁻³⁰⁰), the tol byte's ε × s: valid results.
        ("tiny_pow2", scale(1, 0, 0, 0)),
        // s = 10⁻³⁰⁰, ε = 5·10⁻³²⁴: the least subnormal is still a representable grid there.
        ("tiny_dec_eps_subnormal", scale(2, 0, 0, 1)),
        // s = 1, ε = 10⁻³¹⁰: too fine (ToleranceTooFine).
        ("unit_eps_1e-310", scale(0, 0, 0, 3)),
        // s = 1, ε = 2⁻¹⁰²²: too fine.
        ("unit_eps_min_normal", scale(0, 0, 0, 4)),
        // s = 10²⁹⁹ and 2⁹⁹³ (coordinates up to 10³⁰⁰), ε × s.
        ("huge_dec", scale(2, 255, 0, 0)),
        ("huge_pow2", scale(1, 255, 0, 0)),
        // s = 2⁹⁹³ offset by s·2³ in x: ε × s relative to a shape far from the origin.
        ("huge_pow2_offset", scale(1 | 4, 255, 63, 0)),
        // s = 1 offset by 2⁴⁰ in y, ε × s: too fine for ε below 2⁻¹¹.
        ("unit_offset_2p40", scale(8, 0, 40, 0)),
        // s = 10⁻¹⁵⁰, ε = 10³⁰⁰: everything collapses onto one grid point (CollapsedOnGrid).
        ("mid_eps_1e300", scale(2, 64, 0, 14)),
        // s = 2⁻⁵⁰⁰, ε = s·2⁶⁴ (collapse) and s·2⁻³⁶ (fine, still representable).
        ("mid_eps_coarse", scale(1, 126, 0, 200)),
        ("mid_eps_fine", scale(1, 126, 0, 100)),
        // s = 10⁻²⁰, offset −s·2⁵⁰ in both, ε = f64::MAX.
        ("offset_eps_max", scale(2 | 12, 119, 50, 15)),
    ]
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
            ..Default::default()
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
                ..Default::default()
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
                ..Default::default()
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
            ..Default::default()
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
            ..Default::default()
        };
        seeds.add("construct", format!("pair_{name}"), input.encode());
    }
    // Float mode far from the unit grid: the figure pairs under the far placements in turn.
    let scales = far_scales();
    for (k, (name, a, b)) in figure_pairs().into_iter().enumerate() {
        let (scale_name, scale) = scales[k % scales.len()];
        let input = OpsInput {
            tol: next_tol(),
            a,
            b,
            probes: probes(),
            scale,
        };
        seeds.add("ops", format!("far_{scale_name}_{name}"), input.encode());
    }
    for (k, (name, rings)) in figures().into_iter().enumerate() {
        let (scale_name, scale) = scales[k % scales.len()];
        let input = ConstructInput {
            tol: next_tol(),
            shape: shape(0, &rings),
            probes: probes(),
            scale,
        };
        seeds.add(
            "construct",
            format!("far_{scale_name}_{name}"),
            input.encode(),
        );
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
    generate3(&mut seeds);
    found(&mut seeds);
    seeds
}

// ---------------------------------------------------------------------------------------------
// 3D: the degenerate configurations of DESIGN-3D §3 (tests/yin3_degenerate.rs) on the lattice,
// and the small shared meshes of ../shared/data/3d

fn lp(x: u8, y: u8, z: u8) -> LatticePoint {
    LatticePoint::new(x, y, z)
}

fn cuboid(lo: [u8; 3], hi: [u8; 3]) -> Solid {
    Solid::cuboid(lo, hi)
}

fn tetra(a: [u8; 3], b: [u8; 3], c: [u8; 3], d: [u8; 3]) -> Solid {
    Solid::Tetra([a, b, c, d].map(|[x, y, z]| lp(x, y, z)))
}

/// The 2×2×2 cells (bit i + 2j + 4k) of a list, at the lattice origin moved by `offset`.
fn cells(offset: [u8; 3], list: &[[u8; 3]]) -> Solid {
    let mask = list
        .iter()
        .fold(0u8, |m, c| m | 1 << (c[0] + 2 * c[1] + 4 * c[2]));
    Solid::Cells { offset, mask }
}

/// The box [0,4]³.
fn big() -> Solid {
    cuboid([0, 0, 0], [4, 4, 4])
}

/// Named 3D operand pairs: each degenerate configuration of DESIGN-3D §3.
fn figure_pairs3() -> Vec<(&'static str, Operand, Operand)> {
    let one = Operand::solid;
    let c = || cuboid([0, 0, 0], [2, 2, 2]);
    // A six-cell ring around the centre edge-free vertex (a solid torus), and four cubes meeting
    // at one vertex pairwise along edges (the star vertex).
    let ring = || {
        cells(
            [1, 1, 1],
            &[
                [0, 0, 0],
                [1, 0, 0],
                [1, 1, 0],
                [1, 1, 1],
                [0, 1, 1],
                [0, 0, 1],
            ],
        )
    };
    let star = || cells([1, 1, 1], &[[0, 0, 0], [1, 1, 0], [1, 0, 1], [0, 1, 1]]);
    vec![
        (
            "cubes_sharing_a_face",
            one(c()),
            one(cuboid([2, 0, 0], [4, 2, 2])),
        ),
        (
            "cubes_sharing_an_edge",
            one(c()),
            one(cuboid([2, 2, 0], [4, 4, 2])),
        ),
        (
            "cubes_sharing_a_vertex",
            one(c()),
            one(cuboid([2, 2, 2], [4, 4, 4])),
        ),
        (
            "coplanar_overlap_same_orientation",
            one(c()),
            one(cuboid([1, 1, 0], [3, 3, 2])),
        ),
        (
            "coplanar_overlap_opposite_orientation",
            one(c()),
            one(cuboid([1, 1, 2], [3, 3, 4])),
        ),
        (
            "tetrahedron_base_in_face_outside",
            one(cuboid([0, 0, 0], [4, 4, 2])),
            one(tetra([1, 1, 2], [3, 1, 2], [1, 3, 2], [2, 2, 4])),
        ),
        (
            "tetrahedron_base_in_face_inside",
            one(cuboid([0, 0, 0], [4, 4, 2])),
            one(tetra([1, 1, 2], [3, 1, 2], [1, 3, 2], [2, 2, 1])),
        ),
        (
            "cavity_touching_wall_at_a_point",
            Operand::two(
                Combine::Minus,
                big(),
                tetra([1, 1, 2], [3, 1, 2], [1, 3, 2], [2, 2, 0]),
            ),
            one(cuboid([1, 1, 0], [3, 3, 1])),
        ),
        (
            "cavity_edge_on_wall",
            Operand::two(
                Combine::Minus,
                big(),
                tetra([1, 0, 1], [3, 0, 1], [2, 2, 2], [2, 1, 3]),
            ),
            one(tetra([1, 0, 1], [3, 0, 1], [2, 2, 2], [2, 1, 0])),
        ),
        (
            "dent_from_box_on_floor",
            Operand::two(
                Combine::Minus,
                cuboid([0, 0, 0], [4, 4, 2]),
                cuboid([1, 1, 1], [3, 3, 2]),
            ),
            one(cuboid([1, 1, 1], [3, 3, 3])),
        ),
        (
            "ring_vs_centre_bar",
            one(ring()),
            one(cuboid([0, 2, 2], [4, 3, 3])),
        ),
        (
            "ring_vs_its_complement",
            one(ring()),
            one(ring()).complemented(),
        ),
        (
            "star_vertex_vs_box",
            one(star()),
            one(cuboid([2, 2, 2], [3, 3, 4])),
        ),
        ("star_vertex_vs_ring", one(star()), one(ring())),
        (
            "prism_edge_on_cube_face",
            one(c()),
            one(tetra([0, 1, 2], [2, 1, 2], [1, 0, 4], [1, 3, 4])),
        ),
        (
            "vertex_on_face",
            one(c()),
            one(tetra([1, 1, 2], [0, 0, 4], [4, 0, 4], [0, 4, 4])),
        ),
        (
            "unbounded_operands",
            one(c()).complemented(),
            one(cuboid([1, 1, 1], [3, 3, 3])).complemented(),
        ),
        ("identical", one(ring()), one(ring())),
        ("set_and_complement", one(c()), one(c()).complemented()),
        ("empty_vs_box", one(Solid::None), one(c())),
        ("full_vs_box", one(Solid::None).complemented(), one(c())),
        (
            "nested_boxes",
            Operand::two(Combine::Minus, big(), cuboid([1, 1, 1], [3, 3, 3])),
            one(cuboid([1, 1, 1], [3, 3, 3])),
        ),
        (
            "tetrahedra_sharing_an_edge",
            one(tetra([0, 0, 0], [4, 0, 0], [2, 4, 0], [2, 2, 4])),
            one(tetra([0, 0, 0], [4, 0, 0], [2, 0, 4], [2, 4, 2])),
        ),
    ]
}

/// Probes spread over the lattice.
fn probes3() -> Vec<Probe3> {
    [
        [1, 1, 1],
        [2, 2, 2],
        [2, 3, 1],
        [3, 3, 3],
        [4, 1, 2],
        [1, 4, 4],
        [0, 0, 0],
        [3, 2, 4],
    ]
    .into_iter()
    .map(Probe3)
    .collect()
}

/// A mesh on the lattice: points and faces.
type LatticeMesh = (Vec<[u8; 3]>, Vec<Vec<usize>>);

/// A solid's mesh on the lattice (its doubled coordinates halved).
fn lattice_mesh(s: &Solid) -> Option<LatticeMesh> {
    let (pts, faces) = check3::solid_mesh(s)?;
    let pts = pts.iter().map(|p| p.map(|c| (c / 2) as u8)).collect();
    Some((pts, faces))
}

/// Several meshes as one face list.
fn combine3(parts: &[LatticeMesh]) -> Construct3Input {
    let mut input = Construct3Input::default();
    for (pts, faces) in parts {
        let off = input.vertices.len();
        input
            .vertices
            .extend(pts.iter().map(|&[x, y, z]| lp(x, y, z)));
        input.faces.extend(
            faces
                .iter()
                .map(|f| f.iter().map(|&i| (i + off) as u8).collect()),
        );
    }
    input
}

/// The shared 3D meshes small enough for the parser's and the constructor's seeds.
fn small_meshes3() -> Vec<(String, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/3d");
    let mut names: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| {
            std::fs::metadata(p)
                .map(|m| m.len() <= 8192)
                .unwrap_or(false)
        })
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|p| {
            (
                p.file_stem().unwrap().to_string_lossy().into_owned(),
                read(&p),
            )
        })
        .collect()
}

/// A mesh read from OBJ, scaled into the lattice and rounded (the topology may change: any
/// lattice mesh is a good seed); `None` if too large for the input format.
fn to_lattice(text: &str) -> Option<Construct3Input> {
    let m = obj::read_obj::<Float>(text).expect("shared mesh reads");
    if m.vertices.len() > MAX_VERTICES3 || m.faces.len() > MAX_FACES3 {
        return None;
    }
    let f: Vec<[f64; 3]> = m.vertices.iter().map(|p| p.to_f64()).collect();
    let lo = [0, 1, 2].map(|k| f.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min));
    let hi = [0, 1, 2].map(|k| f.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max));
    let span = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    let top = f64::from(LATTICE - 1);
    let map = |p: &[f64; 3]| {
        let c = [0, 1, 2].map(|k| ((p[k] - lo[k]) * top / span).round().clamp(0.0, top) as u8);
        lp(c[0], c[1], c[2])
    };
    let faces: Vec<Vec<u8>> = m
        .faces
        .iter()
        .filter(|f| f.len() <= 6)
        .map(|f| f.iter().map(|&i| i as u8).collect())
        .collect();
    Some(Construct3Input {
        vertices: f.iter().map(map).collect(),
        faces,
    })
}

/// OBJ text of a solid: its faces fanned into triangles.
fn solid_obj(name: &str, s: &Solid, rotate: bool) -> Option<String> {
    let (pts, faces) = check3::solid_mesh(s)?;
    let v: Vec<Point3<Rational>> = pts
        .iter()
        .map(|p| {
            let h = |c: i64| Rational::new(c.into(), 2.into());
            let q = Point3::new(h(p[0]), h(p[1]), h(p[2]));
            if rotate {
                // A rational rotation about z by the Pythagorean angle cos = 3/5 (exact p/q
                // coordinates in the text).
                let f = |a: i64, b: i64| Rational::new(a.into(), b.into());
                Point3::new(
                    f(3, 5) * q.x.clone() - f(4, 5) * q.y.clone(),
                    f(4, 5) * q.x.clone() + f(3, 5) * q.y.clone(),
                    q.z.clone(),
                )
            } else {
                q
            }
        })
        .collect();
    let tris: Vec<[usize; 3]> = faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |k| [f[0], f[k], f[k + 1]]))
        .collect();
    Some(obj::write_obj(&v, &[(name.to_string(), tris)]))
}

/// 3D float mode's placements (input3.rs, Place3): B moved off the lattice (general position,
/// the transversal path) or by a coarse unit (still degenerate), ε from coarse to too fine,
/// and the ends of the `f64` range.
fn placements3() -> Vec<(&'static str, Place3)> {
    let place = |mode, k, exp, eps, scale| Place3 {
        mode,
        k,
        exp,
        eps,
        scale,
    };
    vec![
        // B shifted by (1, 2, 3)·2⁻²⁰: every contact becomes a proper crossing.
        ("shift_fine", place(MOVE_SHIFT, [1, 2, 3], 20, 0, 0)),
        // B shifted by (½, ½, ½): a coarse move (the Betti numbers are checked).
        ("shift_half", place(MOVE_SHIFT, [1, 1, 1], 1, 0, 0)),
        // B shifted by 2⁻⁴⁰ with ε = 2⁻³⁰: moved by less than ε.
        ("shift_below_eps", place(MOVE_SHIFT, [1, -1, 1], 40, 30, 0)),
        // B scaled about (2, 2, 2) by 1 + (1, −2, 3)·2⁻¹⁰: planes through the centre kept.
        ("scaled_axes", place(MOVE_SCALE, [1, -2, 3], 10, 0, 0)),
        // B shifted by the f64s nearest (5, 7, 11)/48: full mantissas.
        ("thirds", place(MOVE_THIRDS, [5, 7, 11], 4, 0, 0)),
        // Everything times 2⁻⁸⁹⁶ and 2⁸⁸⁹, B shifted finely.
        ("tiny", place(MOVE_SHIFT, [1, 2, 3], 20, 0, -128)),
        ("huge", place(MOVE_SHIFT, [1, 2, 3], 20, 0, 127)),
        // ε = 2⁻⁵⁵: too fine for coordinates up to 4 (ToleranceTooFine).
        ("eps_too_fine", place(MOVE_NONE, [0; 3], 0, 55, 0)),
        // ε = ½, B shifted by (3, 2, 1)/64.
        ("eps_half", place(MOVE_SHIFT, [3, 2, 1], 6, 1, 0)),
    ]
}

fn generate3(seeds: &mut Seeds) {
    let places = placements3();
    let mut k = 0;
    for (name, a, b) in figure_pairs3() {
        for flags in [0, ROTATE] {
            let input = Ops3Input {
                flags,
                a: a.clone(),
                b: b.clone(),
                probes: probes3(),
                place: Place3::default(),
            };
            let suffix = if flags == ROTATE { "_rotated" } else { "" };
            seeds.add("ops3", format!("fig_{name}{suffix}"), input.encode());
            // The same pair placed for float mode (ops3_float; ops3_exact ignores it).
            let (place_name, place) = places[k % places.len()];
            k += 1;
            seeds.add(
                "ops3",
                format!("float_{place_name}_{name}{suffix}"),
                Ops3Input { place, ..input }.encode(),
            );
        }
        // The constructor: each operand's solids, and both first solids as one face list.
        let meshes: Vec<_> = [&a.first, &a.second, &b.first]
            .into_iter()
            .filter_map(lattice_mesh)
            .collect();
        if let Some(m) = meshes.first() {
            seeds.add(
                "construct3",
                format!("fig_{name}_a"),
                combine3(std::slice::from_ref(m)).encode(),
            );
        }
        if meshes.len() >= 2 {
            let both = combine3(&meshes[..2]);
            if both.vertices.len() <= MAX_VERTICES3 && both.faces.len() <= MAX_FACES3 {
                seeds.add("construct3", format!("fig_{name}_together"), both.encode());
            }
        }
        if let Some(text) = solid_obj(name, &a.first, false) {
            seeds.add("parse_obj", format!("fig_{name}"), text);
        }
    }
    // Invalid meshes the constructor must reject (tests/yin3_degenerate.rs, errors).
    let cube = lattice_mesh(&cuboid([0, 0, 0], [2, 2, 2])).expect("a cube");
    let mut open = cube.clone();
    open.1.pop();
    let mut flipped = cube.clone();
    flipped.1[0].reverse();
    let inner = lattice_mesh(&cuboid([1, 1, 1], [3, 3, 3])).expect("a cube");
    let outer = lattice_mesh(&big()).expect("a cube");
    let mut bad_face = cube.clone();
    bad_face.1.push(vec![0, 1, 1]);
    for (name, input) in [
        ("open_box", combine3(&[open])),
        ("flipped_face", combine3(&[flipped])),
        ("crossing_boxes", combine3(&[cube.clone(), inner.clone()])),
        (
            "nested_same_orientation",
            combine3(&[outer, lattice_mesh(&cuboid([1, 1, 1], [2, 2, 2])).unwrap()]),
        ),
        ("repeated_vertex", combine3(&[bad_face])),
        (
            "out_of_range",
            Construct3Input {
                vertices: vec![lp(0, 0, 0), lp(1, 0, 0), lp(0, 1, 0)],
                faces: vec![vec![0, 1, 3]],
            },
        ),
        (
            "non_planar_quad",
            Construct3Input {
                vertices: vec![lp(0, 0, 0), lp(2, 0, 0), lp(2, 2, 0), lp(0, 2, 1)],
                faces: vec![vec![0, 1, 2, 3], vec![3, 2, 1, 0]],
            },
        ),
    ] {
        seeds.add("construct3", format!("err_{name}"), input.encode());
    }
    // The reversed cube (an unbounded set) and a hexagonal face.
    let mut reversed = cube;
    for f in &mut reversed.1 {
        f.reverse();
    }
    seeds.add(
        "construct3",
        "reversed_cube",
        combine3(&[reversed]).encode(),
    );
    // Shared meshes: read as text by the parser, and on the lattice for the constructor.
    for (name, text) in small_meshes3() {
        if let Some(input) = to_lattice(&text) {
            seeds.add("construct3", format!("data_{name}"), input.encode());
        }
        seeds.add("parse_obj", format!("data_{name}"), text);
    }
    seeds.add(
        "parse_obj",
        "sample",
        "# a tetrahedron with exact coordinates\r\nv 0 0 0\nv 1 0 0 1\nv 0 1 0\nv 0 0 1/3\n\
         vt 0 0\nvn 0 0 1\no tetrahedron\ng g\ns off\nf 1 3 2\nf 1/1 2/1 4/1\nf -3//1 -2//1 -1//1\n\
         f 3/1/1 1/1/1 4/1/1\nusemtl x\n",
    );
    seeds.add(
        "parse_obj",
        "rotated_box",
        solid_obj("rotated", &cuboid([0, 0, 0], [1, 2, 3]), true).expect("a box"),
    );
    seeds.add(
        "parse_obj",
        "quads_and_pentagon",
        "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 3 0\nv 0 2 0\nv 0 0 2\nv 2 0 2\nv 2 2 2\nv 1 3 2\nv 0 2 2\n\
         f 1 5 4 3 2\nf 6 7 8 9 10\nf 1 2 7 6\nf 2 3 8 7\nf 3 4 9 8\nf 4 5 10 9\nf 5 1 6 10\n",
    );
    seeds.add(
        "parse_obj",
        "errors",
        "v 0 0 0\nv 1 x 0\nv 1 2 3 4\nv 1 2 3 1 9\nf 1 2\nf 1 2 0\nf 1 2 7\nf 1/0 2 3\nf 1/2/3/4 2 3\nv 1e99999 0 0\n",
    );
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
        "ops3" => {
            let input: Ops3Input = yinset_fuzz::input::decode(bytes).expect("decodes");
            check3::ops3_exact(&input);
            check3_float::ops3_float(&input);
        }
        "construct3" => check3::construct3(&yinset_fuzz::input::decode(bytes).expect("decodes")),
        "parse_obj" => check3::obj(&text::text_of(bytes)),
        other => panic!("unknown corpus {other}"),
    }));
    result.map_err(|e| {
        e.downcast_ref::<String>()
            .cloned()
            .or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default()
    })
}

/// Inputs found by fuzzing, kept as seeds so that every run replays them first (each is also
/// a regression test: tests/fuzz_regressions.rs, tests/float_mode3.rs).
fn found(seeds: &mut Seeds) {
    // ops_float, 2026-11-27: a tiny hole around a point halfway between grid points of
    // 2.2·10¹² grows to the whole grid cell, within the accuracy bound only with the result's
    // own length.
    let tiny_hole: &[u8] = &[
        0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0x01, 0x02, 0x12, 0x10, 0x04, 0x2d, 0x2f,
        0x3f, 0x41, 0x00, 0x01, 0x04, 0x40, 0xf8, 0xc9, 0xce, 0xf9, 0xff, 0xff, 0xff, 0x00, 0x00,
        0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0x02, 0xaa, 0xaa, 0xaa, 0xaa, 0xaa, 0x5d, 0xab, 0xff,
        0x3d, 0xa0, 0x92, 0xfc, 0x49, 0x68, 0xb1, 0x00, 0x00, 0x00, 0x00, 0x02, 0x12,
    ];
    seeds.add("ops", "found_tiny_hole_grows_to_a_grid_cell", tiny_hole);
    // ops3_float, 2026-11-27: at a scale near 2⁻⁹²⁶, float locate missed a point lying on a
    // slanted face (its chart was taken from a normal whose f64 products underflowed).
    let slanted_face: &[u8] = &[
        0x00, 0x06, 0x01, 0x14, 0x14, 0x14, 0x02, 0x5d, 0x3a, 0x42, 0x0c, 0x00, 0x01, 0x10, 0x10,
        0x05, 0x00, 0x08, 0x2b, 0x52, 0x38, 0x81, 0x52, 0xa9, 0x00, 0x9f, 0x01, 0x01, 0x02, 0x03,
        0x14, 0x00, 0x80,
    ];
    seeds.add("ops3", "found_tiny_locate_on_a_slanted_face", slanted_face);
    // ops3_float, 2026-11-27: two pieces of A' ∧ B' apart by less than an ulp touched when
    // rounded; the float join kept the pieces' topology but not its own.
    let pieces_touch: &[u8] = &[
        0x47, 0x01, 0x29, 0x01, 0x00, 0x52, 0x00, 0x00, 0x02, 0x34, 0x0d, 0x69, 0x00, 0x00, 0x02,
        0x34, 0x0d, 0x69, 0x00, 0x00, 0x41, 0x87, 0x31, 0x06, 0x3a, 0x00,
    ];
    seeds.add("ops3", "found_pieces_rounded_to_touch", pieces_touch);
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
