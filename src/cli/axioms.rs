//! `axioms`: Boolean-algebra laws checked with `==` on random small exact Yin sets.

use super::encode::encode;
use super::error::CliError;
use super::format::Format;
use super::output::write_text;
use super::progress;
use crate::io::NumberStyle;
use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::{YinError, YinSet2};
use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Grid coordinates of the random shapes run over 0..=GRID.
const GRID: i64 = 6;

/// A law on three sets and its name.
type Law<N> = (
    &'static str,
    fn(&YinSet2<N>, &YinSet2<N>, &YinSet2<N>) -> bool,
);

/// The laws checked: De Morgan, absorption, distributivity, complements.
fn laws<N: Num>() -> [Law<N>; 9] {
    [
        ("De Morgan (A ∧ B)' = A' ∨ B'", |a, b, _| {
            !&(a & b) == &!a | &!b
        }),
        ("De Morgan (A ∨ B)' = A' ∧ B'", |a, b, _| {
            !&(a | b) == &!a & &!b
        }),
        ("absorption A ∧ (A ∨ B) = A", |a, b, _| {
            &(a | b) & a == *a
        }),
        ("absorption A ∨ (A ∧ B) = A", |a, b, _| {
            &(a & b) | a == *a
        }),
        (
            "distributivity A ∧ (B ∨ C) = (A ∧ B) ∨ (A ∧ C)",
            |a, b, c| a & &(b | c) == &(a & b) | &(a & c),
        ),
        (
            "distributivity A ∨ (B ∧ C) = (A ∨ B) ∧ (A ∨ C)",
            |a, b, c| a | &(b & c) == &(a | b) & &(a | c),
        ),
        ("complement A ∧ A' = 0", |a, _, _| (a & &!a).is_empty()),
        ("complement A ∨ A' = 1", |a, _, _| (a | &!a).is_full()),
        ("involution A'' = A", |a, _, _| !&!a == *a),
    ]
}

/// Check every law on `n` random triples from `seed`, with a progress bar; report on stdout,
/// failures (with their sets in yin2) on stderr.
pub fn run<N: Num>(n: u64, seed: u64) -> Result<(), CliError> {
    let mut rng = StdRng::seed_from_u64(seed);
    let laws = laws::<N>();
    let bar = progress::bar(n);
    let mut failed = 0u64;
    for trial in 0..n {
        let outcome = catch_unwind(AssertUnwindSafe(|| {
            let sets = [(); 3].map(|()| random_set::<N>(&mut rng));
            let [a, b, c] = sets;
            let sets = [a?, b?, c?];
            Ok::<_, YinError>((broken(&laws, &sets), sets))
        }));
        let report = match outcome {
            Ok(Ok((broken, _))) if broken.is_empty() => None,
            Ok(Ok((broken, sets))) => {
                failed += broken.len() as u64;
                Some(format!(
                    "trial {trial}: {} fail for\n{}",
                    broken.join("; "),
                    dump(&sets)
                ))
            }
            Ok(Err(e)) => {
                failed += laws.len() as u64;
                Some(format!("trial {trial}: a generated shape is invalid: {e}"))
            }
            Err(_) => {
                failed += laws.len() as u64;
                Some(format!(
                    "trial {trial}: the kernel panicked (message above)"
                ))
            }
        };
        if let Some(report) = report {
            bar.suspend(|| eprintln!("{report}"));
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let total = n * laws.len() as u64;
    write_text(
        None,
        &format!(
            "axioms: {n} random triples × {} laws, seed {seed}: {} passed, {failed} failed\n",
            laws.len(),
            total - failed
        ),
    )?;
    if failed > 0 {
        return Err(CliError::AxiomsFailed { failed, total });
    }
    Ok(())
}

/// The names of the laws that fail on `sets` (A, B, C).
fn broken<N: Num>(laws: &[Law<N>], sets: &[YinSet2<N>; 3]) -> Vec<&'static str> {
    let [a, b, c] = sets;
    laws.iter()
        .filter(|(_, holds)| !holds(a, b, c))
        .map(|(name, _)| *name)
        .collect()
}

/// The sets A, B, C in yin2 text.
fn dump<N: Num>(sets: &[YinSet2<N>; 3]) -> String {
    ["A", "B", "C"]
        .iter()
        .zip(sets)
        .map(|(name, s)| {
            let bytes = encode(s, Format::Yin2, NumberStyle::Exact).unwrap_or_default();
            let text = String::from_utf8_lossy(&bytes);
            format!("{name}:\n{text}")
        })
        .collect()
}

/// A random set: one to three shapes joined or cut out of each other, sometimes complemented.
fn random_set<N: Num>(rng: &mut StdRng) -> Result<YinSet2<N>, YinError> {
    let mut set = shape(rng)?;
    for _ in 0..rng.random_range(0..3) {
        let next = shape(rng)?;
        set = if rng.random_bool(0.7) {
            set.join(&next)
        } else {
            set.difference(&next)
        };
    }
    Ok(if rng.random_bool(0.2) {
        set.complement()
    } else {
        set
    })
}

/// A random shape on the grid: a rectangle, a triangle, or a square with a triangular hole
/// touching its bottom edge.
fn shape<N: Num>(rng: &mut StdRng) -> Result<YinSet2<N>, YinError> {
    let p = |x: i64, y: i64| Point::int(x, y);
    let curves = match rng.random_range(0..3) {
        0 => {
            let ([x0, x1], [y0, y1]) = (span(rng), span(rng));
            vec![vec![p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)]]
        }
        1 => vec![triangle(rng).map(|[x, y]| p(x, y)).to_vec()],
        _ => {
            let (x, y) = (
                rng.random_range(0..=GRID - 4),
                rng.random_range(0..=GRID - 4),
            );
            vec![
                vec![p(x, y), p(x + 4, y), p(x + 4, y + 4), p(x, y + 4)],
                vec![p(x + 2, y), p(x + 1, y + 2), p(x + 3, y + 2)],
            ]
        }
    };
    YinSet2::from_curves(curves)
}

/// Two distinct sorted grid coordinates.
fn span(rng: &mut StdRng) -> [i64; 2] {
    let a = rng.random_range(0..GRID);
    [a, rng.random_range(a + 1..=GRID)]
}

/// Three grid points, not collinear, counterclockwise.
fn triangle(rng: &mut StdRng) -> [[i64; 2]; 3] {
    let mut point = || [rng.random_range(0..=GRID), rng.random_range(0..=GRID)];
    loop {
        let (a, b, c) = (point(), point(), point());
        let cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        match cross.signum() {
            1 => return [a, b, c],
            -1 => return [a, c, b],
            _ => continue,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    #[test]
    fn shapes_are_valid_and_varied() {
        let mut rng = StdRng::seed_from_u64(7);
        let sets: Vec<YinSet2<Rational>> = (0..60)
            .map(|_| random_set(&mut rng).expect("valid shape"))
            .collect();
        assert!(sets.iter().any(|s| !s.is_bounded()), "some complements");
        assert!(sets.iter().any(|s| s.betti().total_holes > 0), "some holes");
        assert!(
            sets.iter().any(|s| s.betti().components > 1),
            "some disjoint parts"
        );
        for s in &sets {
            s.validate().expect("canonical");
        }
    }

    #[test]
    fn a_law_that_does_not_hold_is_reported() {
        let mut rng = StdRng::seed_from_u64(1);
        let sets = [(); 3].map(|()| shape::<Rational>(&mut rng).unwrap());
        let fake: [Law<Rational>; 2] = [
            ("always", |_, _, _| true),
            ("A = 0", |a, _, _| a.is_empty()),
        ];
        assert_eq!(broken(&fake, &sets), vec!["A = 0"]);
        assert_eq!(broken(&laws(), &sets), Vec::<&str>::new());
    }

    #[test]
    fn a_short_run_passes() {
        assert!(run::<Rational>(3, 11).is_ok());
    }

    #[test]
    fn same_seed_same_sets() {
        let draw = |seed| {
            let mut rng = StdRng::seed_from_u64(seed);
            random_set::<Rational>(&mut rng).unwrap()
        };
        assert_eq!(draw(3), draw(3));
    }
}
