//! The built-in demonstration: example Yin sets with touching points, holes and unbounded parts,
//! run through every Boolean operation in exact mode, in 2D and in 3D.

use crate::kernel::{Point, Point3};
use crate::num::{Num, Rational};
use crate::yin2::{YinError, YinSet2};
use crate::yin3::shapes::{self, Mesh};
use crate::yin3::{Yin3Error, YinSet3};
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

/// One line describing a 3D Yin set: glued surfaces, Betti numbers, exact volume.
pub fn describe3<N: Num>(y: &YinSet3<N>) -> String {
    let b = y.betti();
    let volume = match y.volume() {
        Some(v) => format!("{v} (≈ {:.6})", v.to_f64()),
        None => "unbounded".to_string(),
    };
    format!(
        "{} surfaces, b0 = {}, b1 = {}, b2 = {}, volume {}",
        y.surfaces().len(),
        b.b0,
        b.b1,
        b.b2,
        volume
    )
}

/// The box [lo, hi] with integer corners.
fn cuboid(lo: [i64; 3], hi: [i64; 3]) -> Mesh<Rational> {
    let p = |c: [i64; 3]| Point3::int(c[0], c[1], c[2]);
    shapes::cuboid(&p(lo), &p(hi))
}

/// The Yin set bounded by the faces of several pieces together.
fn solid(pieces: Vec<Mesh<Rational>>) -> Result<YinSet3<Rational>, Yin3Error> {
    let (vertices, faces) = shapes::concat(pieces);
    YinSet3::from_triangles(vertices, faces)
}

/// The 3D example shapes: two unit cubes sharing an edge; a 4×4×4 cube with a tetrahedral
/// cavity whose apex touches the bottom face; a box across a face of that cube.
pub fn shapes3() -> Result<Vec<(&'static str, YinSet3<Rational>)>, Yin3Error> {
    let edge = solid(vec![
        cuboid([0, 0, 0], [1, 1, 1]),
        cuboid([1, 1, 0], [2, 2, 1]),
    ])?;
    // The cavity's faces turn their normals into it, out of the set.
    let cavity = (
        [(2, 2, 0), (1, 1, 2), (3, 1, 2), (2, 3, 2)]
            .iter()
            .map(|&(x, y, z)| Point3::int(x, y, z))
            .collect(),
        vec![vec![1, 3, 2], vec![0, 1, 2], vec![0, 2, 3], vec![0, 3, 1]],
    );
    let hollow = solid(vec![cuboid([0, 0, 0], [4, 4, 4]), cavity])?;
    let across = solid(vec![cuboid([3, 1, 1], [6, 3, 3])])?;
    Ok(vec![
        ("P (unit cubes sharing an edge)", edge),
        ("Q (4-cube, cavity touching its floor)", hollow),
        ("R (box across Q's face x = 4)", across),
    ])
}

/// Run the demonstration and return its report.
pub fn run() -> Result<String, Box<dyn std::error::Error + Send + Sync>> {
    let mut out = run2()?;
    out.push_str(&run3()?);
    Ok(out)
}

/// The 2D part of the demonstration.
fn run2() -> Result<String, YinError> {
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

/// The 3D part of the demonstration.
fn run3() -> Result<String, Yin3Error> {
    let s = shapes3()?;
    let mut out = String::from("\n3D (exact):\n");
    let mut line = |label: String, y: &YinSet3<Rational>| {
        let _ = writeln!(out, "{label:<40} {}", describe3(y));
    };
    for (name, y) in &s {
        line(name.to_string(), y);
    }
    let (p, q, r) = (&s[0].1, &s[1].1, &s[2].1);
    line("P ∧ Q".into(), &(p & q));
    line("P ∨ Q".into(), &(p | q));
    line("Q ∧ R".into(), &(q & r));
    line("Q ∨ R".into(), &(q | r));
    line("Q ∖ R".into(), &(q - r));
    line("Q △ R".into(), &(q ^ r));
    line("Q'".into(), &!q);
    let volume = |y: &YinSet3<Rational>| y.volume().unwrap_or_default();
    let lhs = volume(&(q & r)) + volume(&(q | r));
    let _ = writeln!(
        out,
        "check |Q∧R| + |Q∨R| = |Q| + |R| exactly: {}",
        lhs == volume(q) + volume(r)
    );
    let _ = writeln!(out, "check (Q')' == Q: {}", &!&!q == q);
    Ok(out)
}
