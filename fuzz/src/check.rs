//! The properties of the structured targets: building operands from grid shapes, and the
//! checks on the constructor and on the binary operations, exact and float.

use crate::input::{
    ConstructInput, GridPoint, OpsInput, Probe, Shape, COMPLEMENT, EPS, FILL_ONLY, NONZERO,
};
use num_bigint::BigInt;
use std::fmt::Debug;
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::{FillRule, Location, YinError, YinSet2};

/// Fail with the input that made the property fail.
macro_rules! fail {
    ($input:expr, $($arg:tt)*) => {
        panic!("{}\ninput: {:?}", format!($($arg)*), $input)
    };
}
pub(crate) use fail;

/// The exact point of a grid point.
fn exact_point(p: &GridPoint) -> Point<Rational> {
    Point::int(i64::from(p.x), i64::from(p.y))
}

/// The exact point of a probe, (i − 1/2, j − 1/2).
pub fn probe_point(p: &Probe) -> Point<Rational> {
    let (x, y) = p.doubled();
    let half = |v: i64| Rational::new(BigInt::from(v), BigInt::from(2));
    Point::new(half(x), half(y))
}

/// The fill rule a shape asks for.
fn rule(shape: &Shape) -> FillRule {
    if shape.flags & NONZERO != 0 {
        FillRule::NonZero
    } else {
        FillRule::EvenOdd
    }
}

/// How an operand was made: by the validating constructor, or by filling polygon soup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Path {
    /// `from_curves` accepted the curves.
    Curves,
    /// `from_rings_filled` with the shape's rule.
    Fill,
}

/// Build an operand: `from_curves` first (unless [`FILL_ONLY`]), falling back to
/// `from_rings_filled`; then the complement if [`COMPLEMENT`].
fn build<N: Num, D: Debug>(
    curves: Vec<Vec<Point<N>>>,
    shape: &Shape,
    ctx: N::Ctx,
    input: &D,
) -> (YinSet2<N>, Path) {
    let (set, path) = match (shape.flags & FILL_ONLY == 0)
        .then(|| YinSet2::from_curves_with(curves.clone(), ctx).ok())
        .flatten()
    {
        Some(set) => (set, Path::Curves),
        None => match YinSet2::from_rings_filled_with(curves, rule(shape), ctx) {
            Ok(set) => (set, Path::Fill),
            Err(e) => fail!(input, "from_rings_filled rejected finite rings: {e}"),
        },
    };
    if shape.flags & COMPLEMENT != 0 {
        (set.complement(), path)
    } else {
        (set, path)
    }
}

/// The exact operand of a shape.
pub fn build_exact<D: Debug>(shape: &Shape, input: &D) -> (YinSet2<Rational>, Path) {
    let curves = shape
        .curves
        .iter()
        .map(|c| c.iter().map(exact_point).collect())
        .collect();
    build(curves, shape, (), input)
}

/// Float mode's ε and jitter size δ from the tol byte.
pub fn float_tolerance(tol: u8) -> (Tolerance, f64) {
    let eps = EPS[usize::from(tol & 7)];
    // ε of a default tolerance on this grid is about 1e-10 × 7.
    let scale = if eps == 0.0 { 1e-9 } else { eps };
    let delta = match (tol >> 3) & 3 {
        0 => 0.0,
        1 => 2f64.powi(-30),
        2 => scale / 2.0,
        _ => scale * 2.0,
    };
    (Tolerance::new(eps), delta)
}

/// The float point of a grid point, jittered by δ as it asks.
fn float_point(p: &GridPoint, delta: f64) -> Point<Float> {
    let (dx, dy) = match p.jitter {
        0 => (0.0, 0.0),
        1 => (delta, 0.0),
        2 => (0.0, delta),
        _ => (-delta, -delta),
    };
    Point::new(
        Float::new(f64::from(p.x) + dx),
        Float::new(f64::from(p.y) + dy),
    )
}

/// The float operand of a shape.
pub fn build_float<D: Debug>(
    shape: &Shape,
    tol: Tolerance,
    delta: f64,
    input: &D,
) -> (YinSet2<Float>, Path) {
    let curves = shape
        .curves
        .iter()
        .map(|c| c.iter().map(|p| float_point(p, delta)).collect())
        .collect();
    build(curves, shape, tol, input)
}

/// Assert that `set` passes the exact validator.
fn valid<N: Num, D: Debug>(what: &str, set: &YinSet2<N>, input: &D) {
    if let Err(e) = set.validate() {
        fail!(input, "{what} fails the validator: {e}\n{what} = {set:?}");
    }
}

/// The expected location in the result of a Boolean function of two operands, at a point off
/// both boundaries (`None` if on a boundary: no expectation).
fn expect(a: Location, b: Location, f: impl Fn(bool, bool) -> bool) -> Option<Location> {
    if a == Location::OnBoundary || b == Location::OnBoundary {
        return None;
    }
    Some(if f(a == Location::Inside, b == Location::Inside) {
        Location::Inside
    } else {
        Location::Outside
    })
}

/// The Boolean operations checked: name, result, and the truth table it must follow off
/// boundaries.
type Op = (&'static str, fn(bool, bool) -> bool);

const OPS: [Op; 6] = [
    ("A∧B", |a, b| a && b),
    ("A∨B", |a, b| a || b),
    ("A'", |a, _| !a),
    ("B'", |_, b| !b),
    ("A−B", |a, b| a && !b),
    ("A⊕B", |a, b| a != b),
];

/// The six results of [`OPS`] on `a` and `b`.
fn results<N: Num>(a: &YinSet2<N>, b: &YinSet2<N>) -> [YinSet2<N>; 6] {
    [
        a.meet(b),
        a.join(b),
        a.complement(),
        b.complement(),
        a.difference(b),
        a.symmetric_difference(b),
    ]
}

/// Check one membership probe set against the truth tables: `where_` gives the probes whose
/// location in each operand is trusted.
fn oracle<N: Num, D: Debug>(
    a: &YinSet2<N>,
    b: &YinSet2<N>,
    out: &[YinSet2<N>; 6],
    points: &[Point<N>],
    input: &D,
) {
    if points.is_empty() {
        return;
    }
    let (la, lb) = (a.locate(points), b.locate(points));
    for ((name, f), set) in OPS.iter().zip(out) {
        let got = set.locate(points);
        for (k, p) in points.iter().enumerate() {
            if let Some(want) = expect(la[k], lb[k], f) {
                if got[k] != want {
                    fail!(
                        input,
                        "membership oracle: {name} at ({}, {}) is {:?}, expected {want:?} \
                         (A: {:?}, B: {:?})\nA = {a:?}\nB = {b:?}\n{name} = {set:?}",
                        p.x,
                        p.y,
                        got[k],
                        la[k],
                        lb[k]
                    );
                }
            }
        }
    }
}

/// The binary operations in exact mode: every output valid, A∧B = B∧A, (A∨B)' = A'∧B',
/// (A∧B)∨(A−B) = A, A'' = A, the area identity, and the membership oracle.
pub fn ops_exact(input: &OpsInput) {
    let (a, _) = build_exact(&input.a, input);
    let (b, _) = build_exact(&input.b, input);
    valid("A", &a, input);
    valid("B", &b, input);
    let out = results(&a, &b);
    for ((name, _), set) in OPS.iter().zip(&out) {
        valid(name, set, input);
    }
    let [meet, join, ca, cb, diff, _] = &out;
    let ba = b.meet(&a);
    if *meet != ba {
        fail!(input, "A∧B ≠ B∧A\nA∧B = {meet:?}\nB∧A = {ba:?}");
    }
    let lhs = join.complement();
    let rhs = ca.meet(cb);
    if lhs != rhs {
        fail!(input, "(A∨B)' ≠ A'∧B'\n(A∨B)' = {lhs:?}\nA'∧B' = {rhs:?}");
    }
    if ca.complement() != a {
        fail!(input, "A'' ≠ A\nA'' = {:?}", ca.complement());
    }
    let parts = meet.join(diff);
    if parts != a {
        fail!(input, "(A∧B)∨(A−B) ≠ A\nresult = {parts:?}\nA = {a:?}");
    }
    if let (Some(x), Some(y), Some(m), Some(j)) = (a.area(), b.area(), meet.area(), join.area()) {
        if m.clone() + j.clone() != x.clone() + y.clone() {
            fail!(
                input,
                "area identity: |A∧B| + |A∨B| = {m} + {j} ≠ |A| + |B| = {x} + {y}"
            );
        }
    }
    let points: Vec<Point<Rational>> = input.probes.iter().map(probe_point).collect();
    oracle(&a, &b, &out, &points, input);
}

/// Distance from `p` to the segment `a b` (f64, for the float oracle's margin).
fn distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy)
}

/// Distance from `p` to the boundary of `set` (infinite for 0̂ and 1̂).
fn distance_to_boundary(p: [f64; 2], set: &YinSet2<Float>) -> f64 {
    set.curves()
        .iter()
        .flat_map(|c| c.edges())
        .map(|(a, b)| distance(p, a.to_f64(), b.to_f64()))
        .fold(f64::INFINITY, f64::min)
}

/// Largest ε for which the float oracles are applied, and their margin.
const FLOAT_ORACLE_EPS: f64 = 1e-3;
const FLOAT_ORACLE_MARGIN: f64 = 0.1;

/// The exact set of a float set's curves (the validator has passed, so this succeeds).
fn exact_of<D: Debug>(what: &str, set: &YinSet2<Float>, input: &D) -> YinSet2<Rational> {
    set.to_exact().unwrap_or_else(|e| {
        fail!(
            input,
            "{what} has no exact counterpart: {e}\n{what} = {set:?}"
        )
    })
}

/// Float `locate` must agree with exact `locate` on the same curves at points at least the
/// margin away from the set's boundary (ε-tolerant predicates may decide only near it).
fn float_locate_agrees<D: Debug>(
    what: &str,
    set: &YinSet2<Float>,
    exact: &YinSet2<Rational>,
    points: &[Point<Float>],
    input: &D,
) {
    let far: Vec<Point<Float>> = points
        .iter()
        .filter(|p| distance_to_boundary(p.to_f64(), set) >= FLOAT_ORACLE_MARGIN)
        .cloned()
        .collect();
    let got = set.locate(&far);
    let want = exact.locate(&far.iter().map(to_exact_point).collect::<Vec<_>>());
    for ((p, g), w) in far.iter().zip(got).zip(want) {
        if g != w {
            fail!(
                input,
                "float locate: ({}, {}) is {g:?} in {what} (float), {w:?} in the same curves read exactly, \
                 at least {FLOAT_ORACLE_MARGIN} from the boundary\n{what} = {set:?}",
                p.x,
                p.y
            );
        }
    }
}

/// The exact point of a float point.
fn to_exact_point(p: &Point<Float>) -> Point<Rational> {
    let q = |v: &Float| Rational::from_f64(v.get()).expect("finite");
    Point::new(q(&p.x), q(&p.y))
}

/// The binary operations in float mode: no panic, every output valid (read exactly) and
/// convertible to exact mode; and, for ε ≤ 10⁻³, two oracles at probes at least 0.1 away from
/// both operands' boundaries, both on the sets read exactly (so that they test the operations,
/// not the ε-tolerant point location): the membership oracle, and float `locate` agreeing
/// with exact `locate` on every operand and result.
pub fn ops_float(input: &OpsInput) {
    let (tol, delta) = float_tolerance(input.tol);
    let (a, _) = build_float(&input.a, tol, delta, input);
    let (b, _) = build_float(&input.b, tol, delta, input);
    valid("A", &a, input);
    valid("B", &b, input);
    let out = results(&a, &b);
    for ((name, _), set) in OPS.iter().zip(&out) {
        valid(name, set, input);
    }
    let exact: Vec<YinSet2<Rational>> = out
        .iter()
        .zip(OPS)
        .map(|(set, (name, _))| exact_of(name, set, input))
        .collect();
    let eps = a.ctx().eps().max(b.ctx().eps());
    if eps > FLOAT_ORACLE_EPS {
        return;
    }
    let points: Vec<Point<Float>> = input
        .probes
        .iter()
        .map(|p| {
            let (x, y) = p.doubled();
            Point::new(Float::new(x as f64 / 2.0), Float::new(y as f64 / 2.0))
        })
        .filter(|p| {
            let q = p.to_f64();
            distance_to_boundary(q, &a).min(distance_to_boundary(q, &b)) >= FLOAT_ORACLE_MARGIN
        })
        .collect();
    if points.is_empty() {
        return;
    }
    let (ax, bx) = (exact_of("A", &a, input), exact_of("B", &b, input));
    let exact_points: Vec<Point<Rational>> = points.iter().map(to_exact_point).collect();
    let (la, lb) = (ax.locate(&exact_points), bx.locate(&exact_points));
    for (((name, f), set), x) in OPS.iter().zip(&out).zip(&exact) {
        let got = x.locate(&exact_points);
        for (k, p) in points.iter().enumerate() {
            if let Some(want) = expect(la[k], lb[k], f) {
                if got[k] != want {
                    fail!(
                        input,
                        "membership oracle (float results read exactly): {name} at ({}, {}) is {:?}, \
                         expected {want:?} (A: {:?}, B: {:?})\nA = {a:?}\nB = {b:?}\n{name} = {set:?}",
                        p.x,
                        p.y,
                        got[k],
                        la[k],
                        lb[k]
                    );
                }
            }
        }
    }
    float_locate_agrees("A", &a, &ax, &points, input);
    float_locate_agrees("B", &b, &bx, &points, input);
    for (((name, _), set), x) in OPS.iter().zip(&out).zip(&exact) {
        float_locate_agrees(name, set, x, &points, input);
    }
}

/// Winding number of the closed rings around the probe (doubled coordinates), or `None` if the
/// probe lies on a ring. Integer arithmetic only: an oracle independent of the kernel.
pub fn winding(rings: &[Vec<GridPoint>], probe: &Probe) -> Option<i64> {
    let (px, py) = probe.doubled();
    let mut w = 0;
    for ring in rings {
        for (k, a) in ring.iter().enumerate() {
            let b = &ring[(k + 1) % ring.len()];
            let (ax, ay) = (2 * i64::from(a.x), 2 * i64::from(a.y));
            let (bx, by) = (2 * i64::from(b.x), 2 * i64::from(b.y));
            let cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
            if cross == 0
                && px >= ax.min(bx)
                && px <= ax.max(bx)
                && py >= ay.min(by)
                && py <= ay.max(by)
            {
                return None;
            }
            if ay <= py {
                if by > py && cross > 0 {
                    w += 1;
                }
            } else if by <= py && cross < 0 {
                w -= 1;
            }
        }
    }
    Some(w)
}

/// A constructor error must name curves and vertices that exist.
fn check_error<D: Debug>(e: &YinError, shape: &Shape, input: &D) {
    let n = shape.curves.len();
    let curve_ok = |c: usize| c < n;
    let vertex_ok = |c: usize, v: usize| c < n && v < shape.curves[c].len();
    let ok = match e {
        YinError::NoCurves => n == 0,
        // Internal invariants, and float-mode refusals that grid inputs (coordinates 0..7,
        // ε ≥ 10⁻⁹ or a grid point's own) never justify.
        YinError::NotFinite { .. }
        | YinError::NotCanonical
        | YinError::Unbalanced { .. }
        | YinError::SnapStalled { .. }
        | YinError::SweepCycle { .. }
        | YinError::CollapsedOnGrid { .. } => false,
        YinError::ToleranceTooFine {
            requested,
            representable,
        } => representable > requested,
        YinError::TooFewVertices { curve, count } => curve_ok(*curve) && *count < 3,
        YinError::RepeatedVertex { curve, vertex, .. }
        | YinError::NotSimple { curve, vertex, .. } => vertex_ok(*curve, *vertex),
        YinError::ProperCrossing {
            curve_a,
            vertex_a,
            curve_b,
            vertex_b,
            ..
        }
        | YinError::SharedEdge {
            curve_a,
            vertex_a,
            curve_b,
            vertex_b,
            ..
        } => vertex_ok(*curve_a, *vertex_a) && vertex_ok(*curve_b, *vertex_b),
        YinError::NestedSameOrientation { outer, inner, .. } => {
            curve_ok(*outer) && curve_ok(*inner) && outer != inner
        }
        YinError::MixedOutermost { positive, negative } => {
            curve_ok(*positive) && curve_ok(*negative) && positive != negative
        }
        YinError::DisconnectedAtom { curves, .. } => {
            curves.len() >= 2 && curves.iter().all(|&c| curve_ok(c))
        }
    };
    if !ok || e.to_string().is_empty() {
        fail!(input, "unclear constructor error: {e:?} ({e})");
    }
}

/// The constructor: `from_curves` returns a valid set or an error naming existing curves and
/// vertices; an accepted set equals the even-odd fill of its curves (complemented if
/// unbounded); both fills are valid and agree with an integer winding-number oracle at the
/// probes; float mode accepts exactly what exact mode accepts and returns valid sets.
pub fn construct(input: &ConstructInput) {
    let shape = &input.shape;
    let curves: Vec<Vec<Point<Rational>>> = shape
        .curves
        .iter()
        .map(|c| c.iter().map(exact_point).collect())
        .collect();
    let points: Vec<Point<Rational>> = input.probes.iter().map(probe_point).collect();
    let mut fills = Vec::new();
    for rule in [FillRule::EvenOdd, FillRule::NonZero] {
        let fill = match YinSet2::from_rings_filled(curves.clone(), rule) {
            Ok(fill) => fill,
            Err(e) => fail!(
                input,
                "from_rings_filled({rule:?}) rejected finite rings: {e}"
            ),
        };
        valid(&format!("fill {rule:?}"), &fill, input);
        let got = fill.locate(&points);
        for (probe, got) in input.probes.iter().zip(got) {
            let Some(w) = winding(&shape.curves, probe) else {
                continue;
            };
            let inside = match rule {
                FillRule::EvenOdd => w % 2 != 0,
                FillRule::NonZero => w != 0,
            };
            let want = if inside {
                Location::Inside
            } else {
                Location::Outside
            };
            if got != want {
                let p = probe_point(probe);
                fail!(
                    input,
                    "fill {rule:?} at ({}, {}) (winding number {w}) is {got:?}, expected {want:?}\nfill = {fill:?}",
                    p.x,
                    p.y
                );
            }
        }
        fills.push(fill);
    }
    let exact = YinSet2::from_curves(curves.clone());
    match &exact {
        Err(e) => check_error(e, shape, input),
        Ok(set) => {
            valid("from_curves", set, input);
            let want = if set.is_bounded() {
                fills[0].clone()
            } else {
                fills[0].complement()
            };
            if *set != want {
                fail!(
                    input,
                    "from_curves accepted curves that do not bound their even-odd fill\nfrom_curves = {set:?}\nfill = {want:?}"
                );
            }
            let _ = (set.betti(), set.area(), set.atoms(), set.parents());
        }
    }
    let (tol, delta) = float_tolerance(input.tol);
    let float_curves: Vec<Vec<Point<Float>>> = shape
        .curves
        .iter()
        .map(|c| c.iter().map(|p| float_point(p, 0.0)).collect())
        .collect();
    match (YinSet2::from_curves_with(float_curves, tol), &exact) {
        (Ok(set), Ok(_)) => valid("float from_curves", &set, input),
        (Err(e), Err(_)) => check_error(&e, shape, input),
        (Ok(set), Err(e)) => fail!(
            input,
            "float mode accepts what exact mode rejects ({e})\nfloat = {set:?}"
        ),
        (Err(e), Ok(_)) => fail!(input, "float mode rejects what exact mode accepts: {e}"),
    }
    for rule in [FillRule::EvenOdd, FillRule::NonZero] {
        let jittered = shape
            .curves
            .iter()
            .map(|c| c.iter().map(|p| float_point(p, delta)).collect())
            .collect();
        match YinSet2::from_rings_filled_with(jittered, rule, tol) {
            Ok(set) => valid(&format!("float fill {rule:?}"), &set, input),
            Err(e) => fail!(
                input,
                "float from_rings_filled({rule:?}) rejected finite rings: {e}"
            ),
        }
    }
}
