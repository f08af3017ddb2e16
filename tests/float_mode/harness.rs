//! The float-versus-exact comparison: build the same input in both modes, run an operation in
//! both, and check the float result against the exact one.
//!
//! For each float result F and exact result E of the same operation on the same input:
//! (a) F passes the exact validator, and `F.to_exact()` succeeds;
//! (b) the area of the symmetric difference of `F.to_exact()` and E is at most
//!     [`AREA_C`] · ε · L, with L as defined by [`scale_length`];
//! (c) the Betti numbers of F and E agree (asserted by the callers on well-separated inputs,
//!     counted on near-degenerate ones).

use super::gen::{exact_curves, Curves};
use std::fmt;
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational, Tolerance};
use yinset::yin2::{Betti, YinSet2};

pub type Exact = YinSet2<Rational>;
pub type Flt = YinSet2<Float>;

/// The accuracy constant C of float mode, as documented on `yinset::num::Tolerance`:
/// area(F △ E) ≤ C · ε · L.
pub const AREA_C: f64 = 1.0;

/// The operations compared.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Op {
    Meet,
    Join,
    Difference,
    Xor,
    Complement,
}

pub const OPS: [Op; 5] = [Op::Meet, Op::Join, Op::Difference, Op::Xor, Op::Complement];

impl Op {
    pub fn apply<N: Num>(self, a: &YinSet2<N>, b: &YinSet2<N>) -> YinSet2<N> {
        match self {
            Op::Meet => a.meet(b),
            Op::Join => a.join(b),
            Op::Difference => a.difference(b),
            Op::Xor => a.symmetric_difference(b),
            Op::Complement => a.complement(),
        }
    }

    /// Whether the operation reads its second operand.
    pub fn binary(self) -> bool {
        self != Op::Complement
    }
}

/// The float points of `f64` cycles.
pub fn float_curves(c: &Curves) -> Vec<Vec<Point<Float>>> {
    c.iter()
        .map(|v| {
            v.iter()
                .map(|p| Point::new(Float::new(p[0]), Float::new(p[1])))
                .collect()
        })
        .collect()
}

/// The exact set bounded by `c` (panics if invalid: generators only return valid cycles).
pub fn exact_set(c: &Curves) -> Exact {
    YinSet2::from_curves(exact_curves(c)).unwrap_or_else(|e| panic!("invalid input: {e}"))
}

/// The float set bounded by `c` with tolerance ε.
pub fn float_set(c: &Curves, eps: f64) -> Flt {
    YinSet2::from_curves_with(float_curves(c), Tolerance::new(eps))
        .unwrap_or_else(|e| panic!("float mode rejects a valid input: {e}"))
}

/// Total boundary length of a set's curves, in `f64`.
pub fn boundary_length<N: Num>(y: &YinSet2<N>) -> f64 {
    y.curves()
        .iter()
        .map(|c| {
            let v = c.vertices();
            (0..v.len())
                .map(|k| {
                    let (p, q) = (v[k].to_f64(), v[(k + 1) % v.len()].to_f64());
                    (q[0] - p[0]).hypot(q[1] - p[1])
                })
                .sum::<f64>()
        })
        .sum()
}

/// The length scale L of the accuracy bound, defined here once: the total boundary length of
/// the exact operands (one for the complement, two otherwise) plus those of the exact result
/// and of the float result (a feature smaller than the grid may grow to a grid cell, whose
/// boundary only F has).
pub fn scale_length(a: &Exact, b: Option<&Exact>, exact_result: &Exact, float: &Flt) -> f64 {
    boundary_length(a)
        + b.map_or(0.0, boundary_length)
        + boundary_length(exact_result)
        + boundary_length(float)
}

/// The exact area of the symmetric difference of `x` and `y`, by |x| + |y| − 2|x ∧ y| (for
/// two unbounded sets, on their complements, whose symmetric difference is the same set);
/// `None` if one is bounded and the other is not (infinite area).
pub fn sym_diff_area(x: &Exact, y: &Exact) -> Option<Rational> {
    let by_meet = |x: &Exact, y: &Exact| -> Rational {
        let m = x.meet(y);
        let two = Rational::from_i64(2);
        x.area().expect("bounded") + y.area().expect("bounded") - two * m.area().expect("bounded")
    };
    match (x.is_bounded(), y.is_bounded()) {
        (true, true) => Some(by_meet(x, y)),
        (false, false) => Some(by_meet(&x.complement(), &y.complement())),
        _ => None,
    }
}

/// Betti numbers with the holes per component sorted (the component order is canonical per
/// representation, not comparable across modes).
pub fn betti_key(b: &Betti) -> (usize, usize, Vec<usize>) {
    let mut holes = b.holes.clone();
    holes.sort_unstable();
    (b.components, b.total_holes, holes)
}

/// What one comparison found.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// area(F △ E) / (ε · L).
    pub ratio: f64,
    /// Betti numbers of F and E agree.
    pub betti_equal: bool,
    pub float_betti: Betti,
    pub exact_betti: Betti,
}

/// Run `op` in both modes on the exact operands (a, b) and float operands (fa, fb) at
/// tolerance ε and compare. `Err` for an invalid float result, a failed conversion or an
/// unbounded discrepancy.
pub fn compare(
    op: Op,
    (a, b): (&Exact, &Exact),
    (fa, fb): (&Flt, &Flt),
    eps: f64,
) -> Result<Outcome, String> {
    let exact = op.apply(a, b);
    let float = op.apply(fa, fb);
    float
        .validate()
        .map_err(|e| format!("{op:?}: float result fails the exact validator: {e}"))?;
    let fx = float
        .to_exact()
        .map_err(|e| format!("{op:?}: to_exact fails: {e}"))?;
    let d = sym_diff_area(&fx, &exact).ok_or_else(|| {
        format!(
            "{op:?}: float result is {}bounded, exact result is {}bounded",
            if fx.is_bounded() { "" } else { "un" },
            if exact.is_bounded() { "" } else { "un" }
        )
    })?;
    let l = scale_length(a, op.binary().then_some(b), &exact, &float);
    // In rationals: ε · L under- or overflows f64 at extreme magnitudes.
    let bound =
        Rational::from_f64(eps).expect("finite ε") * Rational::from_f64(l).expect("finite L");
    let ratio = (d / bound).to_f64();
    let (fb_, eb) = (float.betti(), exact.betti());
    Ok(Outcome {
        ratio,
        betti_equal: betti_key(&fb_) == betti_key(&eb),
        float_betti: fb_,
        exact_betti: eb,
    })
}

/// Statistics over many comparisons.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub cases: usize,
    pub comparisons: usize,
    pub max_ratio: f64,
    pub max_ratio_at: String,
    /// Largest ratio per operation.
    pub max_ratio_op: std::collections::BTreeMap<Op, f64>,
    pub betti_differ: usize,
    pub betti_differ_at: Vec<String>,
    /// Perturbed inputs that were not valid as given and were redrawn.
    pub redrawn: usize,
}

impl Stats {
    pub fn record(&mut self, op: Op, o: &Outcome, at: impl Fn() -> String) {
        self.comparisons += 1;
        let m = self.max_ratio_op.entry(op).or_default();
        *m = m.max(o.ratio);
        if o.ratio > self.max_ratio {
            self.max_ratio = o.ratio;
            self.max_ratio_at = at();
        }
        if !o.betti_equal {
            self.betti_differ += 1;
            if self.betti_differ_at.len() < 5 {
                self.betti_differ_at.push(format!(
                    "{}: float {:?} exact {:?}",
                    at(),
                    o.float_betti,
                    o.exact_betti
                ));
            }
        }
    }

    pub fn merge(&mut self, o: &Stats) {
        self.cases += o.cases;
        self.comparisons += o.comparisons;
        if o.max_ratio > self.max_ratio {
            self.max_ratio = o.max_ratio;
            self.max_ratio_at = o.max_ratio_at.clone();
        }
        for (&op, &r) in &o.max_ratio_op {
            let m = self.max_ratio_op.entry(op).or_default();
            *m = m.max(r);
        }
        self.betti_differ += o.betti_differ;
        for s in &o.betti_differ_at {
            if self.betti_differ_at.len() < 5 {
                self.betti_differ_at.push(s.clone());
            }
        }
        self.redrawn += o.redrawn;
    }
}

impl fmt::Display for Stats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} cases, {} comparisons, max area(F△E)/(ε·L) = {:.4} ({}), Betti differ in {} \
             ({:.2}%), {} perturbations redrawn",
            self.cases,
            self.comparisons,
            self.max_ratio,
            self.max_ratio_at,
            self.betti_differ,
            100.0 * self.betti_differ as f64 / self.comparisons.max(1) as f64,
            self.redrawn
        )?;
        for (op, r) in &self.max_ratio_op {
            write!(f, "\n    max ratio {op:?}: {r:.4}")?;
        }
        Ok(())
    }
}

/// Cycles as text (one `x y` line per vertex, `f64` in shortest round-trip form, curves
/// separated by blank lines), for reproducers.
pub fn dump(c: &Curves) -> String {
    c.iter()
        .map(|v| {
            v.iter()
                .map(|p| format!("{:?} {:?}", p[0], p[1]))
                .collect::<Vec<_>>()
                .join("\n")
        })
        .collect::<Vec<_>>()
        .join("\n\n")
}
