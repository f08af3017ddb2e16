//! The 2D paper's own test data (seed 000 Figures 10 and 13), read exactly from
//! `../shared/data/2d`: the panda P and Mickey M.

mod common;
use common::*;
use yinset::io::yin2_text::read_curves;
use yinset::kernel::Point;
use yinset::num::{Num, Rational};
use yinset::yin2::{Location, YinSet2};

/// All curves of one figure, read exactly (one file per curve, as in the data set).
fn read_figure<N: Num>(name: &str, count: usize) -> Vec<Vec<Point<N>>> {
    let dir = data_dir(name);
    (1..=count)
        .flat_map(|i| {
            let path = dir.join(format!("curve{i:02}.txt"));
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            read_curves::<N>(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        })
        .collect()
}

fn panda() -> Y {
    YinSet2::from_curves(read_figure("panda", 10)).expect("panda is a realizable spadjor")
}

fn mickey() -> Y {
    YinSet2::from_curves(read_figure("mickey", 6)).expect("Mickey is a realizable spadjor")
}

#[test]
fn decimals_are_read_exactly() {
    if !common::data_available() {
        return;
    }
    let curves = read_figure::<Rational>("panda", 1);
    // The file starts with "4.0511876e+00   3.9586066e+00".
    assert_eq!(curves[0][0].x, q(40511876, 10_000_000));
    assert_eq!(curves[0][0].y, q(39586066, 10_000_000));
}

#[test]
fn panda_has_six_components_with_2_1_1_0_0_0_holes() {
    if !common::data_available() {
        return;
    }
    let p = panda();
    assert_eq!(p.curves().len(), 10);
    assert_eq!(p.curves().iter().filter(|c| c.is_positive()).count(), 6);
    let b = p.betti();
    assert_eq!(b.components, 6);
    let mut holes = b.holes.clone();
    holes.sort_unstable_by(|a, b| b.cmp(a));
    assert_eq!(holes, vec![2, 1, 1, 0, 0, 0]);
    assert_eq!(b.total_holes, 4);
    assert!(p.is_bounded());
}

#[test]
fn mickey_has_two_positive_and_four_negative_curves() {
    if !common::data_available() {
        return;
    }
    let m = mickey();
    assert_eq!(m.curves().len(), 6);
    assert_eq!(m.curves().iter().filter(|c| c.is_positive()).count(), 2);
}

#[test]
fn panda_and_mickey_exactly() {
    if !common::data_available() {
        return;
    }
    let (p, m) = (panda(), mickey());
    let t = std::time::Instant::now();
    let meet = p.meet(&m);
    eprintln!(
        "exact meet of panda and Mickey: {:?} (opt-level of this test profile)",
        t.elapsed()
    );
    let join = p.join(&m);
    let comp = p.complement();
    for y in [&meet, &join, &comp] {
        valid(y);
    }
    // |P∧M| + |P∨M| = |P| + |M|, exactly.
    assert_eq!(area(&meet) + area(&join), area(&p) + area(&m));
    assert_eq!(comp.complement(), p);
    assert!(!comp.is_bounded());
    assert_eq!(
        comp.betti().components,
        1 + 4,
        "the outside plus the four holes' insides"
    );
    // Membership oracle on a grid of points off all boundaries.
    let bb = p.bbox().unwrap().union(&m.bbox().unwrap());
    let n = 40;
    let pts: Vec<Point<Rational>> = (0..n * n)
        .map(|k| {
            let (i, j) = (
                Rational::from_i64(2 * (k % n) + 1),
                Rational::from_i64(2 * (k / n) + 1),
            );
            let two_n = Rational::from_i64(2 * n);
            Point::new(
                bb.min.x.clone() + (bb.max.x.clone() - bb.min.x.clone()) * i / two_n.clone(),
                bb.min.y.clone() + (bb.max.y.clone() - bb.min.y.clone()) * j / two_n,
            )
        })
        .collect();
    let (lp, lm, lmeet, ljoin) = (
        p.locate(&pts),
        m.locate(&pts),
        meet.locate(&pts),
        join.locate(&pts),
    );
    let mut checked = 0;
    for k in 0..pts.len() {
        if lp[k] == Location::OnBoundary || lm[k] == Location::OnBoundary {
            continue;
        }
        let (a, b) = (lp[k] == Location::Inside, lm[k] == Location::Inside);
        let expect = |v: bool| {
            if v {
                Location::Inside
            } else {
                Location::Outside
            }
        };
        assert_eq!(lmeet[k], expect(a && b), "meet at {}", pts[k]);
        assert_eq!(ljoin[k], expect(a || b), "join at {}", pts[k]);
        checked += 1;
    }
    assert!(checked > 1500, "only {checked} points checked");
    assert!(lmeet.contains(&Location::Inside) && lmeet.contains(&Location::Outside));
}
