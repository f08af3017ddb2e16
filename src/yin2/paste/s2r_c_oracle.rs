//! Property test of S2R-c (seed 000 Lemma 4.2): cutting a loop off at the first repeated vertex
//! gives the Jordan curves of the seed's "grow the loop γ₁, then divide it", on random piece
//! sets; the seed's version is written out here independently, as the oracle.

use super::Segmented;
use crate::kernel::Point;
use crate::num::Rational;
use crate::yin2::error::YinError;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;
use std::collections::HashMap;

/// A lattice vertex.
type V = (i64, i64);

/// A directed piece between two lattice vertices.
type Piece = (V, V);

/// Cell states, drawn uniformly below `STATES`: empty (0–5), the unit square (6–17), or the
/// half-square triangle at one of its corners (18–21). Mostly full cells with some empty ones
/// make holes pinched against each other or against the outer curve: the closed walks that
/// repeat a vertex.
const STATES: u8 = 22;

/// The counterclockwise boundary of a cell at (x, y) in state `s`.
fn cell_ring(x: i64, y: i64, s: u8) -> Vec<V> {
    let (sw, se, ne, nw) = ((x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1));
    match s {
        0..=5 => vec![],
        6..=17 => vec![sw, se, ne, nw],
        18 => vec![sw, se, nw],
        19 => vec![sw, se, ne],
        20 => vec![se, ne, nw],
        _ => vec![sw, ne, nw],
    }
}

/// The pieces bounding the union of the cells of a k × k grid, in the order given by `seed`:
/// every cell's counterclockwise boundary, minus the pairs of opposite pieces two cells share.
/// Cells meeting at a corner only make the repeated vertices S2R-c is about.
fn piece_set(k: usize, cells: &[u8], seed: u64) -> Vec<Piece> {
    let mut all = Vec::new();
    for (i, &s) in cells.iter().enumerate() {
        let ring = cell_ring((i % k) as i64, (i / k) as i64, s);
        for j in 0..ring.len() {
            all.push((ring[j], ring[(j + 1) % ring.len()]));
        }
    }
    let mut pieces: Vec<Piece> = all
        .iter()
        .filter(|&&(a, b)| !all.contains(&(b, a)))
        .copied()
        .collect();
    // Fisher–Yates with a splitmix64 stream.
    let mut state = seed;
    for i in (1..pieces.len()).rev() {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        pieces.swap(i, ((z ^ (z >> 31)) % (i as u64 + 1)) as usize);
    }
    pieces
}

/// The direction of a unit lattice step as a multiple of 45°, counterclockwise from east.
fn eighths(from: V, to: V) -> i64 {
    match (to.0 - from.0, to.1 - from.1) {
        (1, 0) => 0,
        (1, 1) => 1,
        (0, 1) => 2,
        (-1, 1) => 3,
        (-1, 0) => 4,
        (-1, -1) => 5,
        (0, -1) => 6,
        (1, -1) => 7,
        d => panic!("not a unit lattice step: {d:?}"),
    }
}

/// S2R-b's angle ∠β_out v β_in in eighths of a turn, in (0, 8]: from the ray v → w of β_out
/// counterclockwise to the ray v → u back along β_in = u → v.
fn ccw_angle(u: V, v: V, w: V) -> i64 {
    let a = (eighths(v, u) - eighths(v, w)).rem_euclid(8);
    if a == 0 {
        8
    } else {
        a
    }
}

/// The nesting property of a closed walk: between two visits of one vertex, the walk meets no
/// vertex it also meets outside them (no u … w … u … w).
fn nested(walk: &[V]) -> bool {
    (0..walk.len()).all(|i| {
        (i + 1..walk.len())
            .filter(|&j| walk[j] == walk[i])
            .all(|j| {
                let outside: Vec<&V> = walk[j + 1..].iter().chain(&walk[..i]).collect();
                walk[i + 1..j].iter().all(|v| !outside.contains(&v))
            })
    })
}

/// S2R-c as the seed states it: divide a closed walk into Jordan curves, here by cutting off the
/// shortest stretch between two visits of one vertex until no vertex repeats.
fn divide(mut walk: Vec<V>) -> Vec<Vec<V>> {
    let mut curves = Vec::new();
    loop {
        let shortest = (0..walk.len())
            .flat_map(|i| (i + 1..walk.len()).map(move |j| (i, j)))
            .filter(|&(i, j)| walk[i] == walk[j])
            .min_by_key(|&(i, j)| j - i);
        match shortest {
            Some((i, j)) => curves.push(walk.drain(i..j).collect()),
            None => {
                curves.push(walk);
                return curves;
            }
        }
    }
}

/// What the seed's S2R-b..d make of a piece set.
struct SeedLoops {
    /// The Jordan curves, as vertex cycles.
    curves: Vec<Vec<V>>,
    /// Whether every grown loop γ₁ had the nesting property.
    nested: bool,
    /// Whether some γ₁ was not a Jordan curve (a vertex repeated on it).
    repeated: bool,
}

/// Seed 000 Lemma 4.2, S2R-b..d: from the first unused piece, grow the path by the clockwise
/// rule until it closes at its start into γ₁, then divide γ₁ (S2R-c); repeat until no piece
/// is left.
fn seed_loops(pieces: &[Piece]) -> SeedLoops {
    let mut used = vec![false; pieces.len()];
    let mut out = SeedLoops {
        curves: Vec::new(),
        nested: true,
        repeated: false,
    };
    for first in 0..pieces.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let mut grown = vec![first];
        loop {
            let (u, v) = pieces[grown[grown.len() - 1]];
            if v == pieces[first].0 {
                break;
            }
            let next = (0..pieces.len())
                .filter(|&e| !used[e] && pieces[e].0 == v)
                .min_by_key(|&e| ccw_angle(u, v, pieces[e].1))
                .expect("a balanced piece set: the path can only stop at its start");
            used[next] = true;
            grown.push(next);
        }
        let walk: Vec<V> = grown.iter().map(|&e| pieces[e].0).collect();
        out.nested &= nested(&walk);
        out.repeated |= (1..walk.len()).any(|j| walk[..j].contains(&walk[j]));
        out.curves.extend(divide(walk));
    }
    out
}

/// Vertex cycles up to rotation and order: each started at its least vertex, then sorted.
fn canonical(mut curves: Vec<Vec<V>>) -> Vec<Vec<V>> {
    for c in &mut curves {
        let least = (0..c.len()).min_by_key(|&i| c[i]).unwrap_or(0);
        c.rotate_left(least);
    }
    curves.sort();
    curves
}

fn point(v: V) -> Point<Rational> {
    Point::int(v.0, v.1)
}

/// The pieces as a segmented spadjor, in their order.
fn segmented(pieces: &[Piece]) -> Segmented<Rational> {
    let mut g = Segmented::new();
    for &(a, b) in pieces {
        let (i, j) = (g.id(&point(a)), g.id(&point(b)));
        g.push(i, j);
    }
    g
}

/// Random piece sets: a k × k grid of cells (k = 4, 5) and an order of the pieces.
fn piece_sets() -> impl Strategy<Value = Vec<Piece>> {
    (4usize..=5)
        .prop_flat_map(|k| {
            (
                Just(k),
                proptest::collection::vec(0..STATES, k * k),
                any::<u64>(),
            )
        })
        .prop_map(|(k, cells, seed)| piece_set(k, &cells, seed))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]

    /// S2R-c by first repetition ([`Segmented::loops`]) equals the seed's grow-then-divide,
    /// and every grown loop has the nesting property the equality rests on.
    #[test]
    fn first_repetition_equals_grow_then_divide(pieces in piece_sets()) {
        let seed = seed_loops(&pieces);
        prop_assert!(seed.nested, "a grown loop is not nested: {:?}", pieces);
        let (loops, _, _) = segmented(&pieces)
            .loops(&())
            .map_err(|e| TestCaseError::fail(format!("{e} on {pieces:?}")))?;
        let by_point: HashMap<Point<Rational>, V> =
            pieces.iter().flat_map(|&(a, b)| [(point(a), a), (point(b), b)]).collect();
        let got = loops
            .into_iter()
            .map(|c| c.iter().map(|p| by_point[p]).collect())
            .collect();
        prop_assert_eq!(canonical(got), canonical(seed.curves));
    }

    /// Without one piece the set is unbalanced at that piece's start, and pasting says so.
    #[test]
    fn a_missing_piece_is_an_unbalanced_error(pieces in piece_sets(), which in any::<usize>()) {
        prop_assume!(!pieces.is_empty());
        let mut pieces = pieces;
        let (a, _) = pieces.remove(which % pieces.len());
        prop_assert_eq!(
            segmented(&pieces).paste_exact(()).err(),
            Some(YinError::Unbalanced { point: point(a).to_string() })
        );
    }
}

/// The generator reaches the cases S2R-c is about: γ₁ with a repeated vertex, in at least a
/// fifth of a deterministic sample (56 of 256 when this was written).
#[test]
fn piece_sets_repeat_vertices_often() {
    let mut runner = TestRunner::deterministic();
    let strategy = piece_sets();
    let sample = 256;
    let repeated = (0..sample)
        .filter(|_| {
            let pieces = strategy.new_tree(&mut runner).unwrap().current();
            seed_loops(&pieces).repeated
        })
        .count();
    eprintln!("{repeated} of {sample} piece sets grow a loop with a repeated vertex");
    assert!(
        repeated * 5 >= sample,
        "only {repeated} of {sample} piece sets grow a loop with a repeated vertex"
    );
}
