//! MRS-a of seed 000 Def. 4.8 by a Bentley–Ottmann sweep in O((n + I) log n) (seed 002 §1.3),
//! and the arrangement of the edges with its faces' winding numbers from the same sweep.

// The sweep line is tilted infinitesimally, so events come in the lexicographic order of points
// and a vertical edge runs from its lower to its upper end. At each event `p` the edges through
// `p` (starting there, ending there, or containing it) are taken out of the status, every pair
// of them that first meets at `p` is reported, and the ones that go on are put back in the order
// of their directions after `p`; only the two new neighbour pairs are tested for a crossing
// ahead. Every decision is `orient`, `classify` or the order of points.

use super::arrangement::{Arrangement, Recorder};
use super::status::{Status, NIL};
use super::vertex::{Crossing, Vertex};
use crate::kernel::{classify, crosses, Contact, Point};
use crate::num::{Num, Rational};
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// A closed straight edge `a → b` of positive length.
pub type Edge<N> = (Point<N>, Point<N>);

/// MRS-a (seed 002 §1.3): meeting pairs `i < j` with `wanted`, by `(i, j)`, with their contact.
///
/// Exact mode: Bentley–Ottmann, O((n + I) log n). It keeps its status ordered through the crossing
/// points (held implicitly, decided by filtered predicates, exact where the filter cannot decide:
/// the private `vertex` module), so it needs them exact; with rounded ones (float mode) it can miss
/// a pair, so float mode takes the pairs of edges whose boxes meet, or, when finding them would
/// scan more than [`BOX_SCANS_PER_EDGE`] pairs per edge, the meeting pairs of the edges' exact
/// images by Bentley–Ottmann. That fallback finds every pair that meets exactly but not the pairs
/// that only come within ε, which float mode's snap rounding then resolves on the ε-grid.
pub fn intersections<N: Num>(
    edges: &[Edge<N>],
    ctx: &N::Ctx,
    wanted: impl Fn(usize, usize) -> bool,
) -> Vec<(usize, usize, Contact<N>)> {
    let mut pairs = if N::EXACT {
        Sweep::new(edges, ctx).run()
    } else {
        float_candidates(edges)
    };
    pairs.sort_unstable();
    pairs.dedup();
    pairs
        .into_iter()
        .filter(|&(i, j)| wanted(i, j))
        .filter_map(|(i, j)| {
            let c = classify(&edges[i].0, &edges[i].1, &edges[j].0, &edges[j].1, ctx);
            (c != Contact::Disjoint).then_some((i, j, c))
        })
        .collect()
}

/// Float mode's candidate pairs of edges: the pairs whose boxes meet ([`by_extents`]), or,
/// where finding them would scan more than [`BOX_SCANS_PER_EDGE`] pairs per edge (long slanted
/// edges side by side: their number grows like n²), the meeting pairs of the edges' exact
/// images by Bentley–Ottmann ([`exact_image_pairs`]), O((n + I) log n).
fn float_candidates<N: Num>(edges: &[Edge<N>]) -> Vec<(usize, usize)> {
    by_extents(edges, BOX_SCANS_PER_EDGE * edges.len() + 4096)
        .unwrap_or_else(|| exact_image_pairs(edges))
}

/// Float mode's budget of box pairs scanned per edge before it falls back to the sweep of the
/// edges' exact images (the GIS outlines of the benches scan 13–17): also the bound on the
/// pair list's memory, 16 bytes a pair (at 256 a pair it was 12 GB of the W1 n = 10⁶ float
/// meet's 15 GB peak).
pub const BOX_SCANS_PER_EDGE: usize = 32;

/// The pairs of edges whose bounding boxes meet, by sweep and prune: the boxes sorted by their
/// left side, each paired with the boxes still open at it whose y-ranges meet its own. Complete
/// whatever the arithmetic (each box is widened by an ulp around its `f64` image, exact for
/// floats); O(n log n + X) for X pairs of boxes whose x-ranges overlap, and `None` once X
/// passes `budget` (long slanted edges side by side, where X grows like n²).
fn by_extents<N: Num>(edges: &[Edge<N>], budget: usize) -> Option<Vec<(usize, usize)>> {
    let mut boxes: Vec<([f64; 4], usize)> = edges
        .iter()
        .enumerate()
        .map(|(i, (a, b))| {
            let (x, y) = ([a.x.to_f64(), b.x.to_f64()], [a.y.to_f64(), b.y.to_f64()]);
            let lo_hi = |v: [f64; 2]| [v[0].min(v[1]).next_down(), v[0].max(v[1]).next_up()];
            let ([x0, x1], [y0, y1]) = (lo_hi(x), lo_hi(y));
            ([x0, x1, y0, y1], i)
        })
        .collect();
    boxes.sort_unstable_by(|a, b| a.0[0].total_cmp(&b.0[0]));
    let (mut open, mut out, mut work) = (Vec::<([f64; 4], usize)>::new(), Vec::new(), 0usize);
    for &(b, i) in &boxes {
        open.retain(|(c, _)| c[1] >= b[0]);
        work += open.len();
        if work > budget {
            return None;
        }
        out.extend(
            open.iter()
                .filter(|(c, _)| c[2] <= b[3] && b[2] <= c[3])
                .map(|&(_, j)| (i.min(j), i.max(j))),
        );
        open.push((b, i));
    }
    Some(out)
}

/// The meeting pairs of the edges' exact images (their `f64` coordinates read as the rationals
/// they are), by Bentley–Ottmann in O((n + I) log n).
pub(crate) fn exact_image_pairs<N: Num>(edges: &[Edge<N>]) -> Vec<(usize, usize)> {
    let q = |v: &N| Rational::from_f64(v.to_f64()).unwrap_or_else(|_| Rational::zero());
    let image: Vec<Edge<Rational>> = edges
        .iter()
        .map(|(a, b)| (Point::new(q(&a.x), q(&a.y)), Point::new(q(&b.x), q(&b.y))))
        .collect();
    Sweep::new(&image, &()).run()
}

/// The arrangement of `edges`: one Bentley–Ottmann sweep (seed 002 §1.3) that cuts every
/// edge at every point where it meets another and records, for each piece, the piece directly
/// below it, so that the winding numbers of all faces follow in one pass
/// ([`Arrangement::windings`]) — no crossing pair is classified twice, no piece needs a
/// midpoint to be located, and points are numbered by their event instead of hashed.
///
/// The sweep order needs exact crossing points: exact mode (float mode's snapped fragments
/// have a sweep of their own on grid integers, [`super::grid_arrange::arrange_grid`]).
pub(crate) fn arrange<'a, N: Num>(
    edges: &'a [Edge<N>],
    ctx: &'a N::Ctx,
) -> Arrangement<Vertex<'a, N>> {
    let mut sweep = Sweep::new(edges, ctx);
    sweep.record = Some(Recorder::new(edges.len()));
    sweep.drive();
    sweep.record.expect("set above").finish()
}

/// Merge sort for the orders around an event (seed 002 §1.3), safe if `cmp` is not total (ε).
fn sort_robust(v: &mut [usize], cmp: &mut impl FnMut(usize, usize) -> Ordering) {
    if v.len() <= 12 {
        for i in 1..v.len() {
            let mut j = i;
            while j > 0 && cmp(v[j - 1], v[j]) == Ordering::Greater {
                v.swap(j - 1, j);
                j -= 1;
            }
        }
        return;
    }
    let mid = v.len() / 2;
    sort_robust(&mut v[..mid], cmp);
    sort_robust(&mut v[mid..], cmp);
    let mut merged = Vec::with_capacity(v.len());
    let (mut i, mut j) = (0, mid);
    while i < mid && j < v.len() {
        if cmp(v[j], v[i]) == Ordering::Less {
            merged.push(v[j]);
            j += 1;
        } else {
            merged.push(v[i]);
            i += 1;
        }
    }
    merged.extend_from_slice(&v[i..mid]);
    merged.extend_from_slice(&v[j..]);
    v.copy_from_slice(&merged);
}

/// The pairs of edges through event `p` that first meet there (seed 002 §1.3): all pairs with an
/// edge starting here (`starting`), and the pairs of edges of `old` (arriving at `p`) that come
/// from different directions (collinear ones met before `p`).
fn report_pairs<N: Num>(
    seg: &[(&Point<N>, &Point<N>)],
    ctx: &N::Ctx,
    p: &Vertex<'_, N>,
    old: &mut [usize],
    starting: &[usize],
    pairs: &mut Vec<(usize, usize)>,
) {
    let back = |a: usize, b: usize| p.orient_along(seg[a].1, seg[a].0, seg[b].0, ctx);
    sort_robust(old, &mut |a, b| back(a, b).reverse().then(a.cmp(&b)));
    let pair = |a: usize, b: usize| (a.min(b), a.max(b));
    let mut group_end = 0;
    for k in 0..old.len() {
        if k == group_end {
            group_end = k + 1;
            while group_end < old.len()
                && back(old[group_end - 1], old[group_end]) == Ordering::Equal
            {
                group_end += 1;
            }
        }
        pairs.extend(old[group_end..].iter().map(|&b| pair(old[k], b)));
    }
    for (k, &s) in starting.iter().enumerate() {
        pairs.extend(
            starting[k + 1..]
                .iter()
                .chain(old.iter())
                .map(|&b| pair(s, b)),
        );
    }
}

/// The state of the Bentley–Ottmann sweep of seed 002 §1.3 over one edge set.
struct Sweep<'a, N: Num> {
    /// Each edge as `(lo, hi)`, its ends in sweep order.
    seg: Vec<(&'a Point<N>, &'a Point<N>)>,
    ctx: &'a N::Ctx,
    status: Status,
    /// Crossings ahead of the sweep, with the edges found crossing there.
    crossings: BTreeMap<Crossing<'a, N>, Vec<usize>>,
    /// Event stamp of the last time each edge was taken out of the status.
    mark: Vec<usize>,
    /// Candidate pairs `(i, j)`, `i < j`.
    pairs: Vec<(usize, usize)>,
    /// The arrangement's faces and pieces, when the sweep records them ([`arrange`]).
    record: Option<Recorder<Vertex<'a, N>>>,
}

impl<'a, N: Num> Sweep<'a, N> {
    /// Set up the sweep of seed 002 §1.3 over `edges`.
    fn new(edges: &'a [Edge<N>], ctx: &'a N::Ctx) -> Self {
        let seg = edges
            .iter()
            .map(|(a, b)| if a <= b { (a, b) } else { (b, a) })
            .collect();
        Sweep {
            seg,
            ctx,
            status: Status::new(edges.len()),
            crossings: BTreeMap::new(),
            mark: vec![usize::MAX; edges.len()],
            pairs: Vec::new(),
            record: None,
        }
    }

    /// Run the sweep of seed 002 §1.3: every pair of edges that meet, once, in exact mode.
    fn run(mut self) -> Vec<(usize, usize)> {
        self.drive();
        self.pairs
    }

    /// Process every event in sweep order.
    fn drive(&mut self) {
        let mut ends: Vec<(&'a Point<N>, usize, bool)> = Vec::with_capacity(2 * self.seg.len());
        for (i, &(lo, hi)) in self.seg.iter().enumerate() {
            ends.push((lo, i, false));
            ends.push((hi, i, true));
        }
        ends.sort_by(|a, b| a.0.cmp(b.0));
        let (mut k, mut stamp) = (0, 0);
        let (mut starting, mut ending) = (Vec::new(), Vec::new());
        loop {
            let next_end = ends.get(k).map(|e| e.0);
            let take_crossing = match (self.crossings.first_key_value(), next_end) {
                (None, None) => break,
                (Some((q, _)), Some(e)) => q.cmp_point(e) != Ordering::Greater,
                (Some(_), None) => true,
                (None, Some(_)) => false,
            };
            let (p, through) = match (take_crossing, next_end) {
                (false, Some(e)) => (Vertex::Given(e), Vec::new()),
                _ => match self.crossings.pop_first() {
                    Some((q, through)) => (Vertex::Crossing(q), through),
                    None => break,
                },
            };
            starting.clear();
            ending.clear();
            while let Some(&(q, i, is_end)) = ends.get(k) {
                if p.cmp_point(q) != Ordering::Equal {
                    break;
                }
                if is_end {
                    ending.push(i);
                } else {
                    starting.push(i);
                }
                k += 1;
            }
            self.event(p, &starting, &ending, &through, stamp);
            stamp += 1;
        }
    }

    /// Event `p` (seed 002 §1.3): report pairs first meeting at `p`, reorder the edges through it.
    fn event(
        &mut self,
        p: Vertex<'a, N>,
        starting: &[usize],
        ending: &[usize],
        through: &[usize],
        stamp: usize,
    ) {
        let (seg, ctx) = (&self.seg, self.ctx);
        let status = &mut self.status;
        // Edges known to pass through p (ending here, or found crossing here): out by handle.
        let mut old = Vec::new();
        for &s in ending.iter().chain(through) {
            if status.live[s] && self.mark[s] != stamp {
                self.mark[s] = stamp;
                status.remove(s);
                old.push(s);
            }
        }
        // The rest of the edges through p form the middle of the status.
        let side = |t: usize| p.side(t, seg[t].0, seg[t].1, ctx);
        let (below, rest) = status.split(status.root, |t| side(t) != Ordering::Greater);
        let (on, above) = status.split(rest, |t| side(t) == Ordering::Less);
        status.collect(on, &mut old);
        for &s in &old {
            status.reset(s);
            status.live[s] = false;
        }
        if let Some(r) = &mut self.record {
            r.close(&old, stamp);
        }
        // The arrangement needs no pairs: its pieces come from the status itself.
        if self.record.is_none() {
            report_pairs(seg, ctx, &p, &mut old, starting, &mut self.pairs);
        }
        // Back into the status: the edges going on past p, by their direction after p.
        let mut next: Vec<usize> = old
            .iter()
            .chain(starting)
            .copied()
            .filter(|&s| p.cmp_point(seg[s].1) == Ordering::Less)
            .collect();
        let ahead = |a: usize, b: usize| p.orient_along(seg[a].0, seg[a].1, seg[b].1, ctx);
        sort_robust(&mut next, &mut |a, b| ahead(a, b).reverse().then(a.cmp(&b)));
        // For the arrangement: which neighbours leave p in the same direction (one group).
        let same: Vec<bool> = match self.record {
            Some(_) => next
                .windows(2)
                .map(|w| ahead(w[0], w[1]) == Ordering::Equal)
                .collect(),
            None => Vec::new(),
        };
        let (lower, upper) = status.rejoin(below, &next, above);
        match (next.first(), next.last()) {
            (Some(&f), Some(&l)) => {
                self.check(lower, f, &p);
                self.check(l, upper, &p);
            }
            _ => self.check(lower, upper, &p),
        }
        if let Some(r) = &mut self.record {
            r.open(p, &next, lower, |k| same[k - 1]);
        }
    }

    /// Schedule the crossing of neighbours `s` and `t` if it lies ahead of `p` (seed 002 §1.3).
    fn check(&mut self, s: usize, t: usize, p: &Vertex<'a, N>) {
        if s == NIL || t == NIL {
            return;
        }
        let (i, j) = (s.min(t), s.max(t));
        let (a, b) = (self.seg[i], self.seg[j]);
        // A crossing needs overlapping y-extents (the x-extents overlap at the sweep line).
        let (ya, yb) = ((&a.0.y).min(&a.1.y), (&b.0.y).min(&b.1.y));
        if (&a.0.y).max(&a.1.y) < yb || (&b.0.y).max(&b.1.y) < ya {
            return;
        }
        if crosses(a.0, a.1, b.0, b.1, self.ctx) {
            let q = Crossing::new((i, j), a, b);
            if p.cmp_crossing(&q) == Ordering::Less {
                self.crossings.entry(q).or_default().extend([i, j]);
            } else {
                // Only with rounded crossing points (float mode): keep the pair anyway.
                self.pairs.push((i, j));
            }
        }
    }
}

/// Segments on the lattice 0..=n × 0..=n (n even), many of them sharing ends, lines and
/// directions: any, horizontal, vertical, diagonal, antidiagonal, through the centre, and along
/// the line y = x/2 (the sweeps' property tests).
#[cfg(test)]
pub(crate) fn lattice_segment(
    n: i64,
) -> impl proptest::strategy::Strategy<Value = ((i64, i64), (i64, i64))> {
    use proptest::prelude::*;
    let c = move || 0..=n;
    prop_oneof![
        3 => ((c(), c()), (c(), c())),
        2 => (c(), c(), c()).prop_map(|(y, a, b)| ((a, y), (b, y))),
        2 => (c(), c(), c()).prop_map(|(x, a, b)| ((x, a), (x, b))),
        2 => (c(), c()).prop_map(|(a, b)| ((a, a), (b, b))),
        1 => (c(), c()).prop_map(move |(a, b)| ((a, n - a), (b, n - b))),
        2 => (c(), c()).prop_map(move |q| ((n / 2, n / 2), q)),
        1 => (0..=n / 2, 0..=n / 2).prop_map(|(a, b)| ((2 * a, a), (2 * b, b))),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::orient;
    use crate::num::{Float, Rational, Tolerance};
    use crate::yin2::arrangement::Group;
    use proptest::prelude::*;

    type Seg = ((i64, i64), (i64, i64));

    fn edges_of<N: Num>(segs: &[Seg]) -> Vec<Edge<N>> {
        segs.iter()
            .map(|&((a, b), (c, d))| (Point::int(a, b), Point::int(c, d)))
            .collect()
    }

    /// The O(n²) oracle: every pair, classified.
    fn brute<N: Num>(
        edges: &[Edge<N>],
        ctx: &N::Ctx,
        wanted: impl Fn(usize, usize) -> bool,
    ) -> Vec<(usize, usize, Contact<N>)> {
        let mut out = Vec::new();
        for i in 0..edges.len() {
            for j in i + 1..edges.len() {
                if wanted(i, j) {
                    let c = classify(&edges[i].0, &edges[i].1, &edges[j].0, &edges[j].1, ctx);
                    if c != Contact::Disjoint {
                        out.push((i, j, c));
                    }
                }
            }
        }
        out
    }

    fn check_exact(segs: &[Seg], wanted: impl Fn(usize, usize) -> bool + Copy) -> usize {
        let edges = edges_of::<Rational>(segs);
        let got = intersections(&edges, &(), wanted);
        let want = brute(&edges, &(), wanted);
        assert_eq!(got, want, "segments: {segs:?}");
        got.len()
    }

    /// Float mode: equal to the oracle here, as the rounding of crossing points stays far below ε.
    fn check_float(segs: &[Seg]) -> usize {
        let edges = edges_of::<Float>(segs);
        let ctx = Tolerance::new(8.0 * Tolerance::RELATIVE_DEFAULT);
        let got = intersections(&edges, &ctx, |_, _| true);
        let want = brute(&edges, &ctx, |_, _| true);
        assert!(got.windows(2).all(|w| (w[0].0, w[0].1) < (w[1].0, w[1].1)));
        assert!(got.iter().all(|x| want.contains(x)), "segments: {segs:?}");
        assert_eq!(got.len(), want.len(), "segments: {segs:?}");
        got.len()
    }

    /// The arrangement of a closed edge set against brute force: every edge is the chain of its
    /// groups' pieces from its lower to its upper end, no two pieces cross or overlap, and the
    /// windings of the faces beside each non-vertical piece equal the count, signed by
    /// direction, of the edges that a downward ray from the piece's midpoint crosses (half-open
    /// in x, so vertices count once).
    fn check_arrangement(segs: &[Seg]) {
        let edges = edges_of::<Rational>(segs);
        let arr = arrange(&edges, &());
        let up = |e: usize| if edges[e].0 < edges[e].1 { 1i64 } else { -1 };
        let windings: Vec<(i64, i64)> = arr.windings(up).collect();
        let end = |g: &Group| (arr.points[g.from].point(), arr.points[g.to].point());
        for (e, (a, b)) in edges.iter().enumerate() {
            let mut chain: Vec<_> = arr
                .groups
                .iter()
                .filter(|g| arr.members[g.members.clone()].contains(&e))
                .map(end)
                .collect();
            chain.sort();
            let (lo, hi) = if a < b { (a, b) } else { (b, a) };
            assert_eq!(chain.first().map(|c| c.0), Some(lo), "edge {e} of {segs:?}");
            assert_eq!(chain.last().map(|c| c.1), Some(hi), "edge {e} of {segs:?}");
            assert!(
                chain.windows(2).all(|w| w[0].1 == w[1].0),
                "edge {e} of {segs:?}"
            );
        }
        for (k, g) in arr.groups.iter().enumerate() {
            let (p, q) = end(g);
            assert!(p < q, "{segs:?}");
            for h in &arr.groups[k + 1..] {
                let (r, t) = end(h);
                let c = classify(p, q, r, t, &());
                assert!(
                    matches!(c, Contact::Disjoint | Contact::Touching(_)),
                    "pieces {p:?}–{q:?} and {r:?}–{t:?} meet as {c:?} in {segs:?}"
                );
            }
            if p.x == q.x {
                continue;
            }
            let m = p.midpoint(q);
            let mut below = 0;
            for (e, (a, b)) in edges.iter().enumerate() {
                let (lo, hi) = if a < b { (a, b) } else { (b, a) };
                if !(lo.x <= m.x && m.x < hi.x) {
                    continue;
                }
                match orient(lo, hi, &m, &()) {
                    Ordering::Greater => below += up(e),
                    Ordering::Equal => assert!(
                        arr.members[g.members.clone()].contains(&e),
                        "edge {e} passes through the inside of piece {p:?}–{q:?}: {segs:?}"
                    ),
                    Ordering::Less => {}
                }
            }
            let through: i64 = arr.members[g.members.clone()].iter().map(|&e| up(e)).sum();
            assert_eq!(
                windings[k],
                (below, below + through),
                "piece {p:?}–{q:?} of {segs:?}"
            );
        }
    }

    fn segs(zero_length: bool) -> impl Strategy<Value = Vec<Seg>> {
        proptest::collection::vec(lattice_segment(4), 0..40).prop_map(move |v| {
            v.into_iter()
                .filter(|s| zero_length || s.0 != s.1)
                .collect()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: yinset_testkit::cases(600), failure_persistence: None, ..ProptestConfig::default() })]

        #[test]
        fn sweep_equals_brute_force(s in segs(false)) {
            check_exact(&s, |_, _| true);
        }

        /// Windings beside a piece are constant only for closed edge sets (at every vertex as
        /// many edges enter as leave), as in every fill and Boolean operation: rings on the
        /// 5×5 grid, which repeat, overlap, touch and retrace one another.
        #[test]
        fn arrangement_equals_brute_force(rings in proptest::collection::vec(
            proptest::collection::vec((0..=4i64, 0..=4i64), 2..7), 1..5)
        ) {
            let segs: Vec<Seg> = rings
                .iter()
                .flat_map(|r| (0..r.len()).map(move |k| (r[k], r[(k + 1) % r.len()])))
                .filter(|s| s.0 != s.1)
                .collect();
            check_arrangement(&segs);
        }

        #[test]
        fn sweep_respects_wanted(s in segs(false), m in 1usize..5, na in 0usize..40) {
            check_exact(&s, |i, j| (i * 7 + j * 3) % (m + 1) != 0);
            check_exact(&s, |i, j| (i < na) != (j < na));
        }

        #[test]
        fn zero_length_edges_do_not_break_it(s in segs(true)) {
            // `classify` is not meant for points, so only the other pairs are compared.
            let proper = |i: usize, j: usize| s[i].0 != s[i].1 && s[j].0 != s[j].1;
            check_exact(&s, proper);
        }

        #[test]
        fn float_mode_equals_brute_force(s in segs(false)) {
            check_float(&s);
        }

        /// Float mode's fallback for too many box pairs finds every pair that meets exactly,
        /// jittered by half a unit in the last place or not.
        #[test]
        fn float_fallback_finds_every_exact_contact(s in segs(false), jitter in 0u8..3) {
            let d = [0.0, 2f64.powi(-50), 0.25][usize::from(jitter)];
            let edges: Vec<Edge<Float>> = s
                .iter()
                .enumerate()
                .map(|(k, &((a, b), (c, e)))| {
                    let f = |v: i64, i: usize| Float::new(v as f64 + if (k + i) % 3 == 0 { d } else { 0.0 });
                    (Point::new(f(a, 0), f(b, 1)), Point::new(f(c, 2), f(e, 3)))
                })
                .filter(|(a, b)| a != b)
                .collect();
            let exact = Tolerance::default();
            let classified = |pairs: Vec<(usize, usize)>| -> Vec<_> {
                let mut v: Vec<_> = pairs
                    .into_iter()
                    .map(|(i, j)| (i, j, classify(&edges[i].0, &edges[i].1, &edges[j].0, &edges[j].1, &exact)))
                    .filter(|(_, _, c)| *c != Contact::Disjoint)
                    .collect();
                v.sort_by_key(|&(i, j, _)| (i, j));
                v.dedup_by_key(|&mut (i, j, _)| (i, j));
                v
            };
            let pairs = by_extents(&edges, usize::MAX).unwrap();
            prop_assert!(pairs.is_empty() || by_extents(&edges, 0).is_none());
            prop_assert_eq!(
                classified(exact_image_pairs(&edges)),
                classified(pairs)
            );
        }
    }

    #[test]
    fn star_through_one_point() {
        // 16 edges through (0, 0): 12 crossing it, 4 ending there, with two duplicates.
        let mut s: Vec<Seg> = vec![];
        for (a, b) in [
            (1, 0),
            (0, 1),
            (1, 1),
            (1, -1),
            (2, 1),
            (1, 2),
            (2, -1),
            (1, -2),
            (3, 1),
            (1, 3),
        ] {
            s.push(((-a, -b), (a, b)));
        }
        s.extend([((5, 0), (-5, 0)), ((0, 5), (0, -5))]);
        s.extend([
            ((0, 0), (4, 1)),
            ((-4, 1), (0, 0)),
            ((0, 0), (0, 7)),
            ((0, 0), (-3, -3)),
        ]);
        let n = s.len();
        assert_eq!(check_exact(&s, |_, _| true), n * (n - 1) / 2);
    }

    #[test]
    fn overlapping_collinear_chain() {
        // Edges [i, i + 3] on the x-axis, alternating directions, plus the same on a diagonal
        // and a vertical line, and a transversal through all of them.
        let mut s: Vec<Seg> = vec![];
        for i in 0..10 {
            let (a, b) = if i % 2 == 0 { (i, i + 3) } else { (i + 3, i) };
            s.push(((a, 0), (b, 0)));
            s.push(((a, a), (b, b)));
            s.push(((5, a), (5, b)));
        }
        s.push(((0, 13), (13, 0)));
        check_exact(&s, |_, _| true);
    }

    #[test]
    fn crossing_grid() {
        let mut s: Vec<Seg> = vec![];
        for i in 0..12 {
            s.push(((-1, i), (12, i)));
            s.push(((i, 12), (i, -1)));
        }
        let got = check_exact(&s, |_, _| true);
        assert_eq!(got, 144);
        // Closing the grid's frame adds touching and overlapping contacts.
        s.extend([
            ((-1, -1), (12, -1)),
            ((12, -1), (12, 12)),
            ((-1, 12), (12, 12)),
            ((-1, -1), (-1, 12)),
        ]);
        s.extend([
            ((3, 3), (3, 8)),
            ((3, 5), (9, 5)),
            ((0, 0), (11, 11)),
            ((11, 0), (0, 11)),
        ]);
        check_exact(&s, |_, _| true);
    }

    #[test]
    fn duplicates_and_reversals() {
        let mut s: Vec<Seg> = vec![];
        for _ in 0..4 {
            s.extend([
                ((0, 0), (3, 3)),
                ((3, 3), (0, 0)),
                ((1, 0), (1, 4)),
                ((1, 4), (1, 0)),
            ]);
        }
        let n = s.len();
        assert_eq!(check_exact(&s, |_, _| true), n * (n - 1) / 2);
    }

    #[test]
    fn float_mode_on_axis_parallel_grids() {
        let mut s: Vec<Seg> = vec![];
        for i in 0..6 {
            s.push(((-1, i), (6, i)));
            s.push(((i, 6), (i, -1)));
            s.push(((i, i), (i + 2, i)));
        }
        // 36 crossings, 6 overlaps, 15 T-junctions and crossings of the short edges.
        assert_eq!(check_float(&s), 57);
    }

    /// `n` short segments in a large square, a quarter axis-parallel on a coarse grid (overlaps).
    fn random_segments(n: usize, seed: u64) -> Vec<Seg> {
        let mut state = seed;
        let mut next = move |m: i64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % m as u64) as i64
        };
        (0..n)
            .map(|_| {
                if next(4) == 0 {
                    let (x, y, l) = (next(500) * 64, next(500) * 64, (1 + next(4)) * 64);
                    if next(2) == 0 {
                        ((x, y), (x + l, y))
                    } else {
                        ((x, y + l), (x, y))
                    }
                } else {
                    let (x, y) = (next(32_000), next(32_000));
                    ((x, y), (x + next(401) - 200, y + next(401) - 200))
                }
            })
            .filter(|s| s.0 != s.1)
            .collect()
    }

    /// The oracle for many edges: integer bounding boxes first, then `classify`.
    fn brute_boxed(segs: &[Seg]) -> Vec<(usize, usize, Contact<Rational>)> {
        let boxes: Vec<[i64; 4]> = segs
            .iter()
            .map(|&((a, b), (c, d))| [a.min(c), b.min(d), a.max(c), b.max(d)])
            .collect();
        let edges = edges_of::<Rational>(segs);
        let mut out = Vec::new();
        for i in 0..segs.len() {
            let bi = boxes[i];
            for j in i + 1..segs.len() {
                let bj = boxes[j];
                if bi[0] <= bj[2] && bj[0] <= bi[2] && bi[1] <= bj[3] && bj[1] <= bi[3] {
                    let c = classify(&edges[i].0, &edges[i].1, &edges[j].0, &edges[j].1, &());
                    if c != Contact::Disjoint {
                        out.push((i, j, c));
                    }
                }
            }
        }
        out
    }

    #[test]
    fn twenty_thousand_random_segments() {
        let segs = random_segments(20_000, 0x2545_f491_4f6c_dd1d);
        let edges = edges_of::<Rational>(&segs);
        let got = intersections(&edges, &(), |_, _| true);
        let want = brute_boxed(&segs);
        assert!(want.len() > 1000);
        assert_eq!(got, want);
    }
}
