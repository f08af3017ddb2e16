//! Peers' overlay suites (JTS, Martinez) run against the kernel: loaders, the exact and float
//! checks, and the per-suite report (issue 7).
//!
//! Model: Yin sets are regular open sets, peers' results are OGC closed sets that may carry
//! points and lines. Every input and expected result is brought in as the regularized set its
//! polygons cover, by [`FillRule::EvenOdd`] (right for OGC polygons whatever their rings'
//! orientation, including rings that touch themselves; see `yinset::yin2::FillRule`), and the
//! lower-dimensional parts of expected results are dropped before comparing.
#![allow(dead_code)]

use crate::common::data_dir;
use std::cmp::Ordering;
use std::collections::BTreeSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use yinset::io::{geojson, wkt, Polygon};
use yinset::kernel::{BBox, Point};
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::{FillRule, Location, YinSet2};

/// Float mode's ε relative to the input's extent (largest coordinate magnitude).
pub const EPS_RELATIVE: f64 = 1e-9;

/// Float mode's area bound: |area_float − area_exact| ≤ C · ε · (boundary length of A and B).
pub const AREA_BOUND_C: f64 = 4.0;

/// Membership samples per side of the grid over the inputs' bounding box.
const GRID: i64 = 23;

/// The reason given for float-mode failures pinned in the suites.
pub const FLOAT_NOT_ROBUST: &str = "float mode not yet robust (issue 3)";

/// A Boolean operation of the suites.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    Intersection,
    Union,
    Difference,
    SymDifference,
}

impl Op {
    /// The operation named `name` in a suite (JTS names with or without `NG`, Martinez names).
    pub fn parse(name: &str) -> Option<Op> {
        match name.trim_end_matches("NG").to_ascii_lowercase().as_str() {
            "intersection" => Some(Op::Intersection),
            "union" => Some(Op::Union),
            "difference" | "diff" => Some(Op::Difference),
            "symdifference" | "symdiff" | "symmetricdifference" | "xor" => Some(Op::SymDifference),
            _ => None,
        }
    }

    /// The kernel's operation.
    pub fn apply<N: Num>(self, a: &YinSet2<N>, b: &YinSet2<N>) -> YinSet2<N> {
        match self {
            Op::Intersection => a & b,
            Op::Union => a | b,
            Op::Difference => a - b,
            Op::SymDifference => a ^ b,
        }
    }
}

/// One expected result: `op(A, B)`, or `op(B, A)` if `swapped`.
pub struct Expected<N> {
    pub op: Op,
    pub swapped: bool,
    pub result: Vec<Polygon<N>>,
}

impl<N> Expected<N> {
    /// `op(A,B)` or `op(B,A)`, the name used in reports and pinned lists.
    pub fn name(&self) -> String {
        let args = if self.swapped { "B,A" } else { "A,B" };
        format!("{:?}({args})", self.op)
    }
}

/// One case of a suite: two inputs and the expected results of some operations.
pub struct Case<N> {
    pub name: String,
    pub a: Vec<Polygon<N>>,
    pub b: Vec<Polygon<N>>,
    pub expected: Vec<Expected<N>>,
    /// Operations of the case that are not Boolean operations (not run).
    pub skipped: usize,
}

/// The files of a data set ending in `ext`, sorted, with their stems and texts.
fn files(name: &str, ext: &str) -> Vec<(String, String)> {
    let dir = data_dir(name);
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|p| {
            let text =
                std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            let stem = p.file_stem().expect("file name").to_string_lossy().into();
            (stem, text)
        })
        .collect()
}

/// The JTS overlay suites (`<case>` with `<a>`, `<b>`, `<test><op name arg1 arg2>WKT</op>`).
pub fn jts_cases<N: Num>() -> Vec<Case<N>> {
    let mut cases = Vec::new();
    for (stem, xml) in files("jts", "xml") {
        let doc = roxmltree::Document::parse(&xml).unwrap_or_else(|e| panic!("{stem}: {e}"));
        let elements = doc.root_element().children().filter(|n| n.is_element());
        for (k, case) in elements.filter(|n| n.has_tag_name("case")).enumerate() {
            let name = format!("{stem}#{}", k + 1);
            let child = |tag: &str| case.children().find(|n| n.has_tag_name(tag));
            let geometry = |tag: &str| {
                let text = child(tag).and_then(|n| n.text()).unwrap_or("");
                read_wkt::<N>(text).unwrap_or_else(|e| panic!("{name} <{tag}>: {e}"))
            };
            let (a, b) = (geometry("a"), geometry("b"));
            let (mut expected, mut skipped) = (Vec::new(), 0);
            for op in case.descendants().filter(|n| n.has_tag_name("op")) {
                let Some(kind) = op.attribute("name").and_then(Op::parse) else {
                    skipped += 1;
                    continue;
                };
                let swapped = op
                    .attribute("arg1")
                    .is_some_and(|s| s.eq_ignore_ascii_case("B"));
                let text = op.text().unwrap_or("");
                let result = read_wkt::<N>(text).unwrap_or_else(|e| panic!("{name} op: {e}"));
                expected.push(Expected {
                    op: kind,
                    swapped,
                    result,
                });
            }
            cases.push(Case {
                name,
                a,
                b,
                expected,
                skipped,
            });
        }
    }
    cases
}

/// The polygons of a WKT text, points and lines dropped (they have no area).
fn read_wkt<N: Num>(text: &str) -> Result<Vec<Polygon<N>>, yinset::io::ParseError> {
    wkt::read_polygonal_parts(text.trim())
}

/// The Martinez cases: a GeoJSON FeatureCollection with the two subjects first, then one
/// feature per operation (`properties.operation`) with the expected result.
pub fn martinez_cases<N: Num>() -> Vec<Case<N>> {
    files("martinez", "geojson")
        .into_iter()
        .map(|(name, text)| {
            let mut features = geojson::read_features::<N>(&text)
                .unwrap_or_else(|e| panic!("{name}: {e}"))
                .into_iter();
            let mut subject = || features.next().expect("two subject features").polygons;
            let (a, b) = (subject(), subject());
            let (mut expected, mut skipped) = (Vec::new(), 0);
            for f in features {
                let op = f.properties.get("operation").and_then(|v| v.as_str());
                match op.and_then(Op::parse) {
                    Some(op) => expected.push(Expected {
                        op,
                        swapped: false,
                        result: f.polygons,
                    }),
                    None => skipped += 1,
                }
            }
            Case {
                name,
                a,
                b,
                expected,
                skipped,
            }
        })
        .collect()
}

/// The regularized set covered by OGC polygons (even-odd fill of all their rings).
pub fn fill<N: Num>(polys: &[Polygon<N>], ctx: N::Ctx) -> Result<YinSet2<N>, String> {
    let rings: Vec<Vec<Point<N>>> = polys
        .iter()
        .flat_map(|p| p.rings().map(<[Point<N>]>::to_vec))
        .collect();
    YinSet2::from_rings_filled_with(rings, FillRule::EvenOdd, ctx).map_err(|e| e.to_string())
}

/// True if the polygons, exteriors turned counterclockwise and holes clockwise, are a realizable
/// spadjor as they stand (or there are none).
fn valid_as_given(polys: &[Polygon<Rational>]) -> bool {
    let oriented = |ring: &[Point<Rational>], ccw: bool| {
        let mut v = ring.to_vec();
        let n = v.len();
        let twice: Rational = (0..n)
            .map(|k| {
                v[k].x.clone() * v[(k + 1) % n].y.clone()
                    - v[(k + 1) % n].x.clone() * v[k].y.clone()
            })
            .sum();
        if (twice.sign() == Ordering::Greater) != ccw {
            v.reverse();
        }
        v
    };
    let curves: Vec<Vec<Point<Rational>>> = polys
        .iter()
        .flat_map(|p| {
            std::iter::once(oriented(&p.exterior, true))
                .chain(p.interiors.iter().map(|h| oriented(h, false)))
        })
        .collect();
    curves.is_empty() || YinSet2::from_curves(curves).is_ok()
}

/// `f()`, or the message of its panic.
fn guarded<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(p) => Err(format!(
            "panicked: {}",
            p.downcast_ref::<String>()
                .cloned()
                .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default()
        )),
    }
}

/// The inputs of a case in the order of the expected result's arguments.
fn operands<'a, N: Num>(
    a: &'a YinSet2<N>,
    b: &'a YinSet2<N>,
    e: &Expected<N>,
) -> (&'a YinSet2<N>, &'a YinSet2<N>) {
    if e.swapped {
        (b, a)
    } else {
        (a, b)
    }
}

/// Betti numbers as (components, holes per component sorted).
fn betti<N: Num>(y: &YinSet2<N>) -> (usize, Vec<usize>) {
    let b = y.betti();
    let mut holes = b.holes;
    holes.sort_unstable();
    (b.components, holes)
}

/// Exact check of one operation: our result is valid and has the regularized expected
/// result's area, Betti numbers, and membership at grid points off both boundaries (returns
/// how many points were compared).
fn check_exact(
    a: &YinSet2<Rational>,
    b: &YinSet2<Rational>,
    e: &Expected<Rational>,
    window: Option<&BBox<Rational>>,
) -> Result<usize, String> {
    let (x, y) = operands(a, b, e);
    let ours = e.op.apply(x, y);
    ours.validate()
        .map_err(|err| format!("invalid result: {err}"))?;
    let expected = fill(&e.result, ())?;
    if ours.area() != expected.area() {
        return Err(format!(
            "area {:?} ≠ expected {:?}",
            ours.area().map(|v| v.to_f64()),
            expected.area().map(|v| v.to_f64())
        ));
    }
    if betti(&ours) != betti(&expected) {
        return Err(format!(
            "Betti {:?} ≠ expected {:?}",
            betti(&ours),
            betti(&expected)
        ));
    }
    let Some(window) = window else {
        return Ok(0);
    };
    let samples = grid(window);
    let (got, want) = (ours.locate(&samples), expected.locate(&samples));
    let off = |l: &Location| *l != Location::OnBoundary;
    let mut compared = 0;
    for ((p, g), w) in samples.iter().zip(&got).zip(&want) {
        if off(g) && off(w) {
            if g != w {
                return Err(format!("at {p}: ours {g:?}, expected {w:?}"));
            }
            compared += 1;
        }
    }
    Ok(compared)
}

/// GRID² points strictly inside `window`, at offsets no data coordinate is likely to hit.
fn grid(window: &BBox<Rational>) -> Vec<Point<Rational>> {
    let frac = |k: i64, lo: &Rational, hi: &Rational| {
        let t = Rational::new((1000 * k + 371).into(), (1000 * GRID).into());
        lo.clone() + t * (hi.clone() - lo.clone())
    };
    (0..GRID)
        .flat_map(|i| (0..GRID).map(move |j| (i, j)))
        .map(|(i, j)| {
            Point::new(
                frac(i, &window.min.x, &window.max.x),
                frac(j, &window.min.y, &window.max.y),
            )
        })
        .collect()
}

/// The bounding box of both inputs (`None` if both are empty).
fn window<N: Num>(a: &YinSet2<N>, b: &YinSet2<N>) -> Option<BBox<N>> {
    match (a.bbox(), b.bbox()) {
        (Some(p), Some(q)) => Some(p.union(&q)),
        (p, q) => p.or(q),
    }
}

/// Outcome counts of one suite run, and the failures as (case, operation, reason).
#[derive(Default)]
pub struct Report {
    pub cases: usize,
    pub operations: usize,
    pub passed: usize,
    pub skipped: usize,
    /// Inputs and expected results whose rings, oriented as OGC means them, are not a realizable
    /// spadjor (rings touching themselves, …), so that only the fill brings them in.
    pub needs_fill: Vec<String>,
    /// Membership points compared (exact mode).
    pub samples: usize,
    pub failures: Vec<(String, String, String)>,
}

impl Report {
    /// Print the report, then assert that the failures are exactly the pinned (case, operation)
    /// pairs, naming the unexpected failures and the pinned pairs that now pass.
    pub fn print_and_check(&self, suite: &str, pinned: &[(&str, &str, &str)]) {
        println!(
            "{suite}: {} cases, {} operations, {} passed, {} pinned, {} skipped",
            self.cases,
            self.operations,
            self.passed,
            pinned.len(),
            self.skipped
        );
        if !self.needs_fill.is_empty() {
            println!(
                "  not valid Yin sets as given (filled): {:?}",
                self.needs_fill
            );
        }
        if self.samples > 0 {
            println!("  membership points compared: {}", self.samples);
        }
        for (case, op, reason) in &self.failures {
            println!("  failed {case} {op}: {reason}");
        }
        let failed: BTreeSet<(&str, &str)> = self
            .failures
            .iter()
            .map(|(c, o, _)| (c.as_str(), o.as_str()))
            .collect();
        let expected: BTreeSet<(&str, &str)> = pinned.iter().map(|&(c, o, _)| (c, o)).collect();
        let new: Vec<_> = failed.difference(&expected).collect();
        let fixed: Vec<_> = expected.difference(&failed).collect();
        assert!(
            new.is_empty() && fixed.is_empty(),
            "{suite}: unexpected failures {new:?}; pinned but passing (unpin them) {fixed:?}"
        );
    }
}

/// Run every case's Boolean operations in exact mode.
pub fn run_exact(cases: &[Case<Rational>]) -> Report {
    let mut report = Report {
        cases: cases.len(),
        ..Report::default()
    };
    for case in cases {
        report.skipped += case.skipped;
        let geometries = [("A".to_string(), &case.a), ("B".to_string(), &case.b)]
            .into_iter()
            .chain(case.expected.iter().map(|e| (e.name(), &e.result)));
        for (what, g) in geometries {
            if !valid_as_given(g) {
                report.needs_fill.push(format!("{} {what}", case.name));
            }
        }
        let inputs = guarded(|| Ok((fill(&case.a, ())?, fill(&case.b, ())?)));
        for e in &case.expected {
            report.operations += 1;
            let outcome = inputs
                .clone()
                .and_then(|(a, b)| guarded(|| check_exact(&a, &b, e, window(&a, &b).as_ref())));
            match outcome {
                Ok(samples) => {
                    report.passed += 1;
                    report.samples += samples;
                }
                Err(why) => report.failures.push((case.name.clone(), e.name(), why)),
            }
        }
    }
    report
}

/// Largest coordinate magnitude of some polygons.
fn extent<N: Num>(polys: &[Polygon<N>]) -> f64 {
    polys
        .iter()
        .flat_map(|p| p.rings().flatten())
        .map(|p| p.x.to_f64().abs().max(p.y.to_f64().abs()))
        .fold(0.0, f64::max)
}

/// Total length of the rings of some polygons (as f64).
fn boundary_length<N: Num>(polys: &[Polygon<N>]) -> f64 {
    polys
        .iter()
        .flat_map(|p| p.rings())
        .map(|ring| {
            let n = ring.len();
            (0..n)
                .map(|k| {
                    let ([x0, y0], [x1, y1]) = (ring[k].to_f64(), ring[(k + 1) % n].to_f64());
                    (x1 - x0).hypot(y1 - y0)
                })
                .sum::<f64>()
        })
        .sum()
}

/// Float check of one operation: the result is valid and its area is within
/// C · ε · (boundary length of the inputs) of the exact area.
fn check_float(
    a: &YinSet2<Float>,
    b: &YinSet2<Float>,
    e: &Expected<Float>,
    exact_area: f64,
    bound: f64,
) -> Result<(), String> {
    let (x, y) = operands(a, b, e);
    let ours = e.op.apply(x, y);
    ours.validate()
        .map_err(|err| format!("invalid result: {err}"))?;
    let area = ours.area().map(|v| v.to_f64()).ok_or("unbounded result")?;
    if (area - exact_area).abs() > bound {
        return Err(format!(
            "area {area} differs from exact {exact_area} by more than {bound}"
        ));
    }
    Ok(())
}

/// Run every case's Boolean operations in float mode (ε = EPS_RELATIVE × extent), against
/// the exact areas of the same operations; the filled inputs must be valid too.
pub fn run_float(exact: &[Case<Rational>], float: &[Case<Float>]) -> Report {
    let mut report = Report {
        cases: float.len(),
        ..Report::default()
    };
    for (ce, cf) in exact.iter().zip(float) {
        report.skipped += cf.skipped;
        let eps = EPS_RELATIVE * extent(&cf.a).max(extent(&cf.b));
        let ctx = Tolerance::new(eps);
        let bound = AREA_BOUND_C * eps * (boundary_length(&cf.a) + boundary_length(&cf.b));
        let exact_inputs = guarded(|| Ok((fill(&ce.a, ())?, fill(&ce.b, ())?)));
        let float_inputs = guarded(|| {
            let (a, b) = (fill(&cf.a, ctx)?, fill(&cf.b, ctx)?);
            for filled in [&a, &b] {
                filled
                    .validate()
                    .map_err(|err| format!("invalid filled input: {err}"))?;
            }
            Ok((a, b))
        });
        for (ee, ef) in ce.expected.iter().zip(&cf.expected) {
            report.operations += 1;
            let outcome = exact_inputs.clone().and_then(|(a, b)| {
                let (x, y) = operands(&a, &b, ee);
                let exact_area = guarded(|| {
                    ee.op
                        .apply(x, y)
                        .area()
                        .map(|v| v.to_f64())
                        .ok_or_else(|| "exact result unbounded".to_string())
                })?;
                let (fa, fb) = float_inputs.clone()?;
                guarded(|| check_float(&fa, &fb, ef, exact_area, bound))
            });
            match outcome {
                Ok(()) => report.passed += 1,
                Err(why) => report.failures.push((cf.name.clone(), ef.name(), why)),
            }
        }
    }
    report
}
