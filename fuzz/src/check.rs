//! The properties of the structured targets: building operands from grid shapes, and the
//! checks on the constructor and on the binary operations, exact and float.

use crate::input::{
    ConstructInput, GridPoint, OpsInput, Probe, Scale, Shape, COMPLEMENT, EPS, FILL_ONLY, NONZERO,
    SPECIAL_EPS,
};
use num_bigint::BigInt;
use std::fmt::Debug;
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::{FillRule, Location, YinError, YinSet2};
use yinset_testkit::membership::{self, Truth};

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
/// `from_rings_filled`; then the complement if [`COMPLEMENT`]. An error only from the fill.
fn build<N: Num>(
    curves: Vec<Vec<Point<N>>>,
    shape: &Shape,
    ctx: N::Ctx,
) -> Result<(YinSet2<N>, Path), YinError> {
    let (set, path) = match (shape.flags & FILL_ONLY == 0)
        .then(|| YinSet2::from_curves_with(curves.clone(), ctx).ok())
        .flatten()
    {
        Some(set) => (set, Path::Curves),
        None => (
            YinSet2::from_rings_filled_with(curves, rule(shape), ctx)?,
            Path::Fill,
        ),
    };
    Ok(if shape.flags & COMPLEMENT != 0 {
        (set.complement(), path)
    } else {
        (set, path)
    })
}

/// The exact operand of a shape.
pub fn build_exact<D: Debug>(shape: &Shape, input: &D) -> (YinSet2<Rational>, Path) {
    let curves = shape
        .curves
        .iter()
        .map(|c| c.iter().map(exact_point).collect())
        .collect();
    build(curves, shape, ())
        .unwrap_or_else(|e| fail!(input, "from_rings_filled rejected finite rings: {e}"))
}

/// The exact operand built from a float shape's very coordinates along the path the float
/// operand took (the float constructor validates exactly, so this path succeeds too).
fn build_exact_along<D: Debug>(
    curves: &[Vec<Point<Float>>],
    shape: &Shape,
    path: Path,
    input: &D,
) -> YinSet2<Rational> {
    let curves = exact_curves(curves);
    let set = match path {
        Path::Curves => YinSet2::from_curves(curves).unwrap_or_else(|e| {
            fail!(
                input,
                "float from_curves accepts what exact mode rejects: {e}"
            )
        }),
        Path::Fill => YinSet2::from_rings_filled(curves, rule(shape))
            .unwrap_or_else(|e| fail!(input, "exact from_rings_filled rejected finite rings: {e}")),
    };
    if shape.flags & COMPLEMENT != 0 {
        set.complement()
    } else {
        set
    }
}

/// Where float mode puts an input ([`Scale`]): grid coordinates (x, y) become
/// (s·x + offset.0, s·y + offset.1) in `f64`, with the tolerance and the jitter size δ (in
/// grid units) chosen with them.
#[derive(Clone, Copy, Debug)]
pub struct Placement {
    /// The tolerance asked for (ε = 0: the default).
    pub tol: Tolerance,
    /// The jitter size in grid units.
    pub delta: f64,
    /// The scale factor s.
    pub s: f64,
    /// The offset added after scaling.
    pub offset: (f64, f64),
}

impl Placement {
    /// The placement of the tol byte and the Scale bytes.
    pub fn of(tol: u8, scale: &Scale) -> Placement {
        let s = scale.factor();
        let eps = match usize::from(scale.eps) {
            0 => EPS[usize::from(tol & 7)] * s,
            e @ 1..=15 => SPECIAL_EPS[e - 1],
            e => s * 2f64.powi(e as i32 - 136),
        };
        // ε of a default tolerance on this grid is about 1e-10 × 7 grid units.
        let unit = if eps > 0.0 { eps / s } else { 1e-9 };
        let delta = match (tol >> 3) & 3 {
            0 => 0.0,
            1 => 2f64.powi(-30),
            2 => unit / 2.0,
            _ => unit * 2.0,
        };
        Placement {
            tol: Tolerance::new(eps),
            delta: delta.min(4.0),
            s,
            offset: scale.offset(),
        }
    }

    /// The float point of grid coordinates (x, y).
    fn at(&self, x: f64, y: f64) -> Point<Float> {
        Point::new(
            Float::new(x * self.s + self.offset.0),
            Float::new(y * self.s + self.offset.1),
        )
    }

    /// The float point of a grid point, jittered by δ if `jitter` and the point asks.
    fn point(&self, p: &GridPoint, jitter: bool) -> Point<Float> {
        let d = if jitter { self.delta } else { 0.0 };
        let (dx, dy) = match p.jitter {
            0 => (0.0, 0.0),
            1 => (d, 0.0),
            2 => (0.0, d),
            _ => (-d, -d),
        };
        self.at(f64::from(p.x) + dx, f64::from(p.y) + dy)
    }

    /// A shape's curves in float mode.
    fn curves(&self, shape: &Shape, jitter: bool) -> Vec<Vec<Point<Float>>> {
        shape
            .curves
            .iter()
            .map(|c| c.iter().map(|p| self.point(p, jitter)).collect())
            .collect()
    }

    /// A float point back in grid units (for the oracles' distances, which would overflow or
    /// underflow at the far ends of the range).
    fn unit(&self, p: [f64; 2]) -> [f64; 2] {
        [
            (p[0] - self.offset.0) / self.s,
            (p[1] - self.offset.1) / self.s,
        ]
    }

    /// Whether the grid coordinates are the `f64`s themselves (unit scale, no offset).
    fn is_identity(&self) -> bool {
        self.s == 1.0 && self.offset == (0.0, 0.0)
    }
}

/// The largest power of two not above `v > 0`, by doubling from the least subnormal (the
/// contract's grid, computed without the kernel's bit manipulation).
fn pow2_floor(v: f64) -> f64 {
    let mut g = f64::from_bits(1);
    while g * 2.0 <= v {
        g *= 2.0;
    }
    g
}

/// What the float-mode contract promises about one input, from its coordinates and ε alone.
struct Contract {
    /// The ε asked for (0: the default).
    eps: f64,
    /// The largest coordinate magnitude.
    magnitude: f64,
    /// The larger side of the bounding box.
    span: f64,
    /// The rings' total length in the L¹ norm (at least their Euclidean length), exact.
    length: Rational,
}

impl Contract {
    fn of(curves: &[Vec<Point<Float>>], tol: Tolerance) -> Contract {
        let all = || curves.iter().flatten().map(|p| p.to_f64());
        let magnitude = all().map(|[x, y]| x.abs().max(y.abs())).fold(0.0, f64::max);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for q in all() {
            for k in 0..2 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        let span = (hi[0] / 2.0 - lo[0] / 2.0).max(hi[1] / 2.0 - lo[1] / 2.0) * 2.0;
        Contract {
            eps: tol.eps(),
            magnitude,
            span: span.max(0.0),
            length: l1_length(&exact_curves(curves)),
        }
    }

    /// ε is too fine: some coordinate is more than 2⁵¹ steps of ε's grid from 0, so the
    /// contract asks for `ToleranceTooFine`.
    fn too_fine(&self) -> bool {
        self.eps > 0.0 && self.magnitude > pow2_floor(self.eps) * 2f64.powi(51)
    }

    /// A grid in force may be `g`: ε's own grid, or for the default ε at most 10⁻¹⁰ × the
    /// span or the finest representable grid (2⁻⁵⁰ × the magnitude, or the least subnormal).
    fn grid_ok(&self, g: f64) -> bool {
        if self.eps > 0.0 {
            g == pow2_floor(self.eps)
        } else {
            g > 0.0
                && g <= (self.span * 1e-10)
                    .max(self.magnitude * 2f64.powi(-50))
                    .max(f64::from_bits(1))
        }
    }
}

/// The rings' total L¹ length (closed rings), exact.
fn l1_length(rings: &[Vec<Point<Rational>>]) -> Rational {
    let abs = |v: Rational| if v < Rational::default() { -v } else { v };
    let mut sum = Rational::default();
    for ring in rings {
        for (k, a) in ring.iter().enumerate() {
            let b = &ring[(k + 1) % ring.len()];
            sum = sum + abs(b.x.clone() - a.x.clone()) + abs(b.y.clone() - a.y.clone());
        }
    }
    sum
}

/// The exact points of float curves.
fn exact_curves(curves: &[Vec<Point<Float>>]) -> Vec<Vec<Point<Rational>>> {
    curves
        .iter()
        .map(|c| c.iter().map(to_exact_point).collect())
        .collect()
}

/// Whether a set is bounded, and the area of the set or (unbounded) of its complement.
fn measure(set: &YinSet2<Rational>) -> (bool, Rational) {
    match set.area() {
        Some(a) => (true, a),
        None => (false, set.complement().area().unwrap_or_default()),
    }
}

/// The accuracy contract (area(F △ E) ≤ g·L, L the boundary length of the input, of E and
/// of F) in the form |area F − area E| ≤ g·(2·`length` + L_F), `length` the input rings' L¹
/// length (which bounds the input's and E's) and L_F F's: a float set may lose or gain only
/// what its grid allows, so a shape is never silently emptied (a feature smaller than the grid
/// may grow to a grid cell, whose boundary only F has); and F is bounded iff E is.
fn close_in_area<D: Debug>(
    what: &str,
    f: &YinSet2<Float>,
    e: &YinSet2<Rational>,
    g: f64,
    length: &Rational,
    input: &D,
) {
    let fx = exact_of(what, f, input);
    let (fb, fa) = measure(&fx);
    let (eb, ea) = measure(e);
    let l = Rational::from_integer(2.into()) * length.clone() + l1_length(&curves_of(&fx));
    let bound = grid_rational(g) * l;
    let diff = fa.clone() - ea.clone();
    if fb != eb || diff > bound || -diff > bound {
        fail!(
            input,
            "{what}: float area {fa} (bounded: {fb}) is not within g·(2·L + L_F) = {bound} of \
             the exact area {ea} (bounded: {eb}) on the same coordinates (g = {g:e})\n\
             float = {f:?}\nexact = {e:?}"
        );
    }
}

/// A grid spacing as an exact rational.
fn grid_rational(g: f64) -> Rational {
    Rational::from_f64(g).expect("a finite grid")
}

/// Judge float mode's own refusals (`ToleranceTooFine`, `CollapsedOnGrid`) against the
/// contract; `None` for any other error. `exact` is the exact set of the same coordinates
/// when there is one (a collapse is justified only if its area is within what the grid may
/// remove).
fn float_refusal_ok(e: &YinError, c: &Contract, exact: Option<&YinSet2<Rational>>) -> Option<bool> {
    Some(match e {
        YinError::ToleranceTooFine {
            requested,
            representable,
        } => c.too_fine() && requested.get() == c.eps && representable > requested,
        YinError::CollapsedOnGrid { grid } => {
            let g = grid.get();
            c.grid_ok(g)
                && exact.is_some_and(|x| {
                    measure(x).1
                        <= grid_rational(g) * Rational::from_integer(2.into()) * c.length.clone()
                })
        }
        _ => return None,
    })
}

/// A float set accepted under the contract: valid, on the grid it may use, and not accepted
/// where ε is too fine (never coarsened silently).
fn float_accepted<D: Debug>(what: &str, set: &YinSet2<Float>, c: &Contract, input: &D) {
    valid(what, set, input);
    if c.too_fine() {
        fail!(
            input,
            "{what}: ε = {:e} is too fine for coordinates up to {:e}, yet accepted on grid {:?}",
            c.eps,
            c.magnitude,
            set.grid()
        );
    }
    match set.grid() {
        Some(g) if c.grid_ok(g) => {}
        g => fail!(input, "{what}: grid {g:?} for ε = {:e}", c.eps),
    }
}

/// The float operand of a shape and the exact one of the same coordinates, or `None` when
/// float mode refuses it as the contract allows (ε too fine).
fn build_float<D: Debug>(
    shape: &Shape,
    place: &Placement,
    what: &str,
    input: &D,
) -> Option<(YinSet2<Float>, YinSet2<Rational>)> {
    let curves = place.curves(shape, true);
    let c = Contract::of(&curves, place.tol);
    match build(curves.clone(), shape, place.tol) {
        Ok((set, path)) => {
            let exact = build_exact_along(&curves, shape, path, input);
            float_accepted(what, &set, &c, input);
            if let Some(g) = set.grid() {
                close_in_area(what, &set, &exact, g, &c.length, input);
            }
            Some((set, exact))
        }
        Err(e) if float_refusal_ok(&e, &c, None) == Some(true) => None,
        Err(e) => fail!(input, "float from_rings_filled rejected finite rings: {e}"),
    }
}

/// Assert that `set` passes the exact validator.
fn valid<N: Num, D: Debug>(what: &str, set: &YinSet2<N>, input: &D) {
    if let Err(e) = set.validate() {
        fail!(input, "{what} fails the validator: {e}\n{what} = {set:?}");
    }
}

/// The Boolean operations checked: name, result, and the truth table it must follow off
/// boundaries.
const OPS: [(&str, Truth); 6] = [
    ("A∧B", membership::MEET),
    ("A∨B", membership::JOIN),
    ("A'", membership::COMPLEMENT_A),
    ("B'", membership::COMPLEMENT_B),
    ("A−B", membership::DIFFERENCE),
    ("A⊕B", membership::SYMMETRIC_DIFFERENCE),
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
        if let Some((k, got, want)) = membership::first_failure(&la, &lb, &set.locate(points), *f) {
            let p = &points[k];
            fail!(
                input,
                "membership oracle: {name} at ({}, {}) is {got:?}, expected {want:?} \
                 (A: {:?}, B: {:?})\nA = {a:?}\nB = {b:?}\n{name} = {set:?}",
                p.x,
                p.y,
                la[k],
                lb[k]
            );
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

/// Distance in grid units from `p` (grid units) to the boundary of `set` (infinite for 0̂
/// and 1̂).
fn distance_to_boundary(p: [f64; 2], set: &YinSet2<Float>, place: &Placement) -> f64 {
    set.curves()
        .iter()
        .flat_map(|c| c.edges())
        .map(|(a, b)| distance(p, place.unit(a.to_f64()), place.unit(b.to_f64())))
        .fold(f64::INFINITY, f64::min)
}

/// Largest ε for which the float oracles are applied, and their margin (grid units).
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
    place: &Placement,
    input: &D,
) {
    let far: Vec<Point<Float>> = points
        .iter()
        .filter(|p| distance_to_boundary(place.unit(p.to_f64()), set, place) >= FLOAT_ORACLE_MARGIN)
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

/// The binary operations in float mode, on shapes placed anywhere in the `f64` range with ε
/// from subnormal to huge ([`Placement`]): no panic; each operand valid, on its grid, within
/// the contract's area bound of the exact operand of the same coordinates, or refused with
/// `ToleranceTooFine` exactly when ε is too fine; every output valid (read exactly) and
/// convertible to exact mode; the area identities |A∧B| + |A∨B| = |A| + |B|,
/// |A∧B| + |A−B| = |A| and |A⊕B| + 2|A∧B| = |A| + |B| within the contract's bound (bounded
/// operands); and, for ε ≤ 10⁻³ grid units, two oracles at probes at least 0.1 grid units away
/// from both operands' boundaries, both on the sets read exactly (so that they test the
/// operations, not the ε-tolerant point location): the membership oracle, and float `locate`
/// agreeing with exact `locate` on every operand and result.
pub fn ops_float(input: &OpsInput) {
    let place = Placement::of(input.tol, &input.scale);
    let Some((a, _)) = build_float(&input.a, &place, "A", input) else {
        return;
    };
    let Some((b, _)) = build_float(&input.b, &place, "B", input) else {
        return;
    };
    let out = results(&a, &b);
    for ((name, _), set) in OPS.iter().zip(&out) {
        valid(name, set, input);
    }
    let exact: Vec<YinSet2<Rational>> = out
        .iter()
        .zip(OPS)
        .map(|(set, (name, _))| exact_of(name, set, input))
        .collect();
    let (ax, bx) = (exact_of("A", &a, input), exact_of("B", &b, input));
    area_identities(&ax, &bx, &exact, &out[0], input);
    let eps = a.ctx().eps().max(b.ctx().eps());
    if eps / place.s > FLOAT_ORACLE_EPS {
        return;
    }
    let points: Vec<Point<Float>> = input
        .probes
        .iter()
        .map(|p| {
            let (x, y) = p.doubled();
            place.at(x as f64 / 2.0, y as f64 / 2.0)
        })
        .filter(|p| {
            let q = place.unit(p.to_f64());
            distance_to_boundary(q, &a, &place).min(distance_to_boundary(q, &b, &place))
                >= FLOAT_ORACLE_MARGIN
        })
        .collect();
    if points.is_empty() {
        return;
    }
    let exact_points: Vec<Point<Rational>> = points.iter().map(to_exact_point).collect();
    let (la, lb) = (ax.locate(&exact_points), bx.locate(&exact_points));
    for (((name, f), set), x) in OPS.iter().zip(&out).zip(&exact) {
        let got = x.locate(&exact_points);
        if let Some((k, got, want)) = membership::first_failure(&la, &lb, &got, *f) {
            let p = &points[k];
            fail!(
                input,
                "membership oracle (float results read exactly): {name} at ({}, {}) is {got:?}, \
                 expected {want:?} (A: {:?}, B: {:?})\nA = {a:?}\nB = {b:?}\n{name} = {set:?}",
                p.x,
                p.y,
                la[k],
                lb[k]
            );
        }
    }
    float_locate_agrees("A", &a, &ax, &points, &place, input);
    float_locate_agrees("B", &b, &bx, &points, &place, input);
    for (((name, _), set), x) in OPS.iter().zip(&out).zip(&exact) {
        float_locate_agrees(name, set, x, &points, &place, input);
    }
}

/// The area identities of bounded operands on the float results read exactly: each result F
/// is within g·(L_A + L_B + L_E + L_F) ≤ g·(2·(L_A + L_B) + L_F) of the exact result E on the
/// same operands (the contract, lengths in L¹), so an identity Σ c·|F| = 0 holds within
/// Σ |c|·g·(2·(L_A + L_B) + L_F) over its terms.
fn area_identities<D: Debug>(
    a: &YinSet2<Rational>,
    b: &YinSet2<Rational>,
    out: &[YinSet2<Rational>],
    meet: &YinSet2<Float>,
    input: &D,
) {
    let (Some(x), Some(y), Some(g)) = (a.area(), b.area(), meet.grid()) else {
        return;
    };
    let int = |v: i64| Rational::from_integer(v.into());
    let g = grid_rational(g);
    let operands = int(2) * (l1_length(&curves_of(a)) + l1_length(&curves_of(b)));
    // Each result's area and its share of the bound, per unit coefficient.
    let term = |k: usize| {
        let area = out[k]
            .area()
            .expect("a result of bounded operands is bounded");
        let bound = g.clone() * (operands.clone() + l1_length(&curves_of(&out[k])));
        (area, bound)
    };
    let ((m, bm), (j, bj), (d, bd), (s, bs)) = (term(0), term(1), term(4), term(5));
    let checks = [
        (
            "|A∧B| + |A∨B| − |A| − |B|",
            m.clone() + j - x.clone() - y.clone(),
            bm.clone() + bj,
        ),
        (
            "|A∧B| + |A−B| − |A|",
            m.clone() + d - x.clone(),
            bm.clone() + bd,
        ),
        (
            "|A⊕B| + 2|A∧B| − |A| − |B|",
            s + int(2) * m - x - y,
            bs + int(2) * bm,
        ),
    ];
    for (what, v, bound) in checks {
        if v > bound || -v.clone() > bound {
            fail!(
                input,
                "area identity in float mode: {what} = {v}, beyond the contract's {bound} \
                 (g = {g})"
            );
        }
    }
}

/// The vertex cycles of an exact set.
fn curves_of(set: &YinSet2<Rational>) -> Vec<Vec<Point<Rational>>> {
    set.curves().iter().map(|c| c.vertices().to_vec()).collect()
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
        // Internal invariants; float mode's own refusals are judged by `float_refusal_ok`.
        YinError::NotFinite { .. }
        | YinError::NotCanonical
        | YinError::Unbalanced { .. }
        | YinError::SnapStalled { .. }
        | YinError::SweepCycle { .. }
        | YinError::CollapsedOnGrid { .. }
        | YinError::ToleranceTooFine { .. } => false,
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
    let place = Placement::of(input.tol, &input.scale);
    let float_curves = place.curves(shape, false);
    let c = Contract::of(&float_curves, place.tol);
    let exact_here = if place.is_identity() {
        exact
    } else {
        YinSet2::from_curves(exact_curves(&float_curves))
    };
    match (
        YinSet2::from_curves_with(float_curves, place.tol),
        &exact_here,
    ) {
        (Ok(set), Ok(x)) => {
            float_accepted("float from_curves", &set, &c, input);
            if let Some(g) = set.grid() {
                close_in_area("float from_curves", &set, x, g, &c.length, input);
            }
        }
        (Err(e), Err(_)) => {
            if float_refusal_ok(&e, &c, None) != Some(true) {
                check_error(&e, shape, input);
            }
        }
        (Ok(set), Err(e)) => fail!(
            input,
            "float mode accepts what exact mode rejects on the same coordinates ({e})\nfloat = {set:?}"
        ),
        (Err(e), Ok(x)) => {
            if float_refusal_ok(&e, &c, Some(x)) != Some(true) {
                fail!(
                    input,
                    "float mode rejects what exact mode accepts on the same coordinates: {e:?} ({e})"
                );
            }
        }
    }
    let jittered = place.curves(shape, true);
    let c = Contract::of(&jittered, place.tol);
    for rule in [FillRule::EvenOdd, FillRule::NonZero] {
        let what = format!("float fill {rule:?}");
        match YinSet2::from_rings_filled_with(jittered.clone(), rule, place.tol) {
            Ok(set) => {
                float_accepted(&what, &set, &c, input);
                let exact = YinSet2::from_rings_filled(exact_curves(&jittered), rule)
                    .unwrap_or_else(|e| {
                        fail!(input, "exact from_rings_filled rejected finite rings: {e}")
                    });
                if let Some(g) = set.grid() {
                    close_in_area(&what, &set, &exact, g, &c.length, input);
                }
            }
            Err(e) if float_refusal_ok(&e, &c, None) == Some(true) => {}
            Err(e) => fail!(input, "{what} rejected finite rings: {e:?} ({e})"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::panic::{catch_unwind, AssertUnwindSafe};

    /// The unit square as float curves.
    fn square(side: f64) -> Vec<Vec<Point<Float>>> {
        let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
        vec![vec![p(0.0, 0.0), p(side, 0.0), p(side, side), p(0.0, side)]]
    }

    #[test]
    fn pow2_floor_covers_subnormals_and_the_top() {
        assert_eq!(pow2_floor(5e-324), 5e-324);
        assert_eq!(pow2_floor(1.5e-323), 1e-323);
        assert_eq!(pow2_floor(3.0), 2.0);
        assert_eq!(pow2_floor(f64::MAX), 2f64.powi(1023));
    }

    #[test]
    fn tolerance_too_fine_is_judged_by_the_magnitude() {
        let fine = Contract::of(&square(1.0), Tolerance::new(1e-310));
        assert!(fine.too_fine());
        let e = YinSet2::from_curves_with(square(1.0), Tolerance::new(1e-310)).unwrap_err();
        assert_eq!(float_refusal_ok(&e, &fine, None), Some(true), "{e:?}");
        let edge = Contract::of(&square(1.0), Tolerance::new(2f64.powi(-51)));
        assert!(!edge.too_fine());
        assert_eq!(float_refusal_ok(&e, &edge, None), Some(false));
        let y = YinSet2::from_curves_with(square(1.0), Tolerance::new(2f64.powi(-51))).unwrap();
        float_accepted("square", &y, &edge, &"edge");
    }

    #[test]
    fn a_feature_grown_to_a_grid_cell_is_within_the_bound_by_its_own_length() {
        // A square of side 2⁻⁶ centred on the cell (0, 1)² of the grid g = 1: its vertices
        // round to the cell's corners, so it becomes the whole cell.
        let (lo, hi) = (0.5 - 2f64.powi(-7), 0.5 + 2f64.powi(-7));
        let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
        let tiny = vec![vec![p(lo, lo), p(hi, lo), p(hi, hi), p(lo, hi)]];
        let exact = YinSet2::from_curves(exact_curves(&tiny)).unwrap();
        let length = l1_length(&exact_curves(&tiny));
        let cell = YinSet2::from_curves_with(square(1.0), Tolerance::new(1.0)).unwrap();
        close_in_area("grown", &cell, &exact, 1.0, &length, &"g = 1");
        let finer = catch_unwind(AssertUnwindSafe(|| {
            close_in_area("grown", &cell, &exact, 0.1, &length, &"g = 0.1")
        }));
        assert!(finer.is_err(), "a cell grown on a grid of 0.1 passed");
    }

    #[test]
    fn an_emptied_set_fails_the_area_bound_unless_the_grid_allows_it() {
        let exact = YinSet2::from_curves(exact_curves(&square(1.0))).unwrap();
        let length = Rational::from_integer(4.into());
        let empty = YinSet2::<Float>::empty();
        let fine = catch_unwind(AssertUnwindSafe(|| {
            close_in_area("x", &empty, &exact, 2f64.powi(-10), &length, &"fine")
        }));
        assert!(
            fine.is_err(),
            "a unit square emptied on a 2^-10 grid passed"
        );
        close_in_area("x", &empty, &exact, 1.0, &length, &"coarse");
        let c = Contract::of(&square(1.0), Tolerance::new(1e300));
        let collapsed = YinError::CollapsedOnGrid {
            grid: Float::new(pow2_floor(1e300)),
        };
        assert_eq!(float_refusal_ok(&collapsed, &c, Some(&exact)), Some(true));
        let c = Contract::of(&square(1.0), Tolerance::new(0.01));
        let collapsed = YinError::CollapsedOnGrid {
            grid: Float::new(pow2_floor(0.01)),
        };
        assert_eq!(float_refusal_ok(&collapsed, &c, Some(&exact)), Some(false));
    }
}
