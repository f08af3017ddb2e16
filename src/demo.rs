//! The built-in demonstration: example Yin sets with touching points, holes and unbounded parts,
//! run through every Boolean operation in exact mode.

use crate::kernel::Point;
use crate::num::{Num, Rational};
use crate::yin2::{YinError, YinSet2};
use std::fmt::Write;

/// A counterclockwise axis-aligned rectangle.
fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Vec<Point<Rational>> {
    [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        .iter()
        .map(|&(x, y)| Point::int(x, y))
        .collect()
}

/// The example shapes: a frame with a hole touching its outer curve, two squares touching at a
/// corner, and a slanted diamond.
pub fn shapes() -> Result<Vec<(&'static str, YinSet2<Rational>)>, YinError> {
    // A hole touching the outer curve at (3,0), and a second hole touching the first at (1,3).
    let mut hole = vec![
        Point::int(3, 0),
        Point::int(5, 3),
        Point::int(3, 5),
        Point::int(1, 3),
    ];
    hole.reverse();
    let mut notch = vec![Point::int(1, 3), Point::int(2, 5), Point::int(1, 5)];
    notch.reverse();
    let frame = YinSet2::from_curves(vec![rect(0, 0, 6, 6), hole, notch])?;
    let touching = YinSet2::from_curves(vec![rect(4, 4, 8, 8), rect(8, 8, 10, 10)])?;
    let half = |n: i64| Rational::new(n.into(), 2.into());
    let diamond = YinSet2::from_curves(vec![vec![
        Point::new(half(7), half(-1)),
        Point::new(half(19), half(11)),
        Point::new(half(7), half(23)),
        Point::new(half(-5), half(11)),
    ]])?;
    Ok(vec![
        ("A (square, two touching holes)", frame),
        ("B (squares touching at a corner)", touching),
        ("C (diamond)", diamond),
    ])
}

/// One line describing a Yin set: curves, Betti numbers, exact area.
pub fn describe<N: Num>(y: &YinSet2<N>) -> String {
    let b = y.betti();
    let area = match y.area() {
        Some(a) => format!("{a} (≈ {:.6})", a.to_f64()),
        None => "unbounded".to_string(),
    };
    format!(
        "{} curves, b0 = {}, holes per component {:?}, area {}",
        y.curves().len(),
        b.components,
        b.holes,
        area
    )
}

/// Run the demonstration and return its report.
pub fn run() -> Result<String, YinError> {
    let s = shapes()?;
    let mut out = String::new();
    let mut line = |label: String, y: &YinSet2<Rational>| {
        let _ = writeln!(out, "{label:<36} {}", describe(y));
    };
    for (name, y) in &s {
        line(name.to_string(), y);
    }
    let (a, b, c) = (&s[0].1, &s[1].1, &s[2].1);
    line("A ∧ B".into(), &(a & b));
    line("A ∨ B".into(), &(a | b));
    line("A'".into(), &!a);
    line("B' (Fig. 11(b): re-pasted)".into(), &!b);
    line("A ∖ C".into(), &(a - c));
    line("A △ C".into(), &(a ^ c));
    line("(A ∨ B) ∧ C".into(), &(&(a | b) & c));
    let lhs = (a & b).area().unwrap_or_default() + (a | b).area().unwrap_or_default();
    let rhs = a.area().unwrap_or_default() + b.area().unwrap_or_default();
    let _ = writeln!(
        out,
        "check |A∧B| + |A∨B| = |A| + |B| exactly: {}",
        lhs == rhs
    );
    let _ = writeln!(out, "check (A')' == A: {}", &!&!a == a);
    Ok(out)
}
