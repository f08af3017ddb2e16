//! Float mode's normalization (seed 000 §5.2 made consistent): iterated snap rounding of the
//! boundary pieces to the ε-grid, then regularization by winding numbers. Every float result is
//! thereby exactly a valid Yin set whose vertices are grid points, decided with exact predicates.

use super::buckets::Buckets;
use super::error::YinError;
use super::faces::fill_arranged;
use super::grid_arrange::{arrange_grid, crossing_pixel, G};
use super::grid_pairs::grid_crossing_pairs;
use super::hot_pixels::HotPixels;
use super::set::YinSet2;
use super::winding::Winding;
use crate::kernel::Point;
use crate::num::Num;
use std::collections::{BTreeMap, BTreeSet};

/// A closed ring of points (the last one joined to the first) with its label.
pub(crate) type Ring<'a, N> = (&'a [Point<N>], usize);

/// A fragment of a rerouted segment: the indices of its ends among the hot pixels, with its
/// segment's label.
type Fragment = ((usize, usize), usize);

/// The Yin set of the faces where `inside` holds, given the operands' boundaries as closed
/// rings labelled by operand (`0` or `1`), after snapping them to the grid of `ctx` (float mode,
/// [`crate::num::Tolerance`]). The whole computation runs on grid integers relative to a local
/// origin ([`Frame`]), with exact integer-valued predicates; only the result's vertices are
/// mapped back to coordinates. Closed rings make every winding number defined. If `valid`, the
/// rings of each label bound a Yin set, so that they do not cross each other where snapping
/// moves none of their vertices, and snap rounding is tried lazily first ([`Snap`]: that pays
/// where it rarely fails, and fails often among arbitrary rings nearly on top of each other).
pub(crate) fn regularize<'a, N: Num>(
    rings: impl Iterator<Item = Ring<'a, N>> + Clone,
    valid: bool,
    ctx: N::Ctx,
    inside: impl Fn(Winding) -> bool,
) -> Result<YinSet2<N>, YinError> {
    regularize_as(rings, valid, valid, ctx, inside)
}

/// [`regularize`], with the snap rounding `lazy` first or not.
fn regularize_as<'a, N: Num>(
    rings: impl Iterator<Item = Ring<'a, N>> + Clone,
    valid: bool,
    lazy: bool,
    ctx: N::Ctx,
    inside: impl Fn(Winding) -> bool,
) -> Result<YinSet2<N>, YinError> {
    let frame = Frame::of(rings.clone().flat_map(|(ring, _)| ring), ctx);
    let ctx = frame.ctx;
    let count = rings.clone().map(|(ring, _)| ring.len()).sum();
    let (mut segments, mut labels) = (Vec::with_capacity(count), Vec::with_capacity(count));
    let mut grid: Vec<G> = Vec::new();
    let mut moved = [!valid; 2];
    for (ring, label) in rings {
        grid.clear();
        grid.extend(ring.iter().map(|p| frame.to_grid(p)));
        moved[label] |= ring.iter().zip(&grid).any(|(p, &k)| frame.at(k) != *p);
        let next = grid.iter().skip(1).chain(grid.first());
        let sides = grid.iter().zip(next).filter(|(a, b)| a != b);
        segments.extend(sides.map(|(&a, &b)| (a, b)));
        labels.resize(segments.len(), label);
    }
    // Snapped fragments should not cross: their arrangement is swept on the grid integers with
    // exact integer orientations. Where two still cross (the arrangement reports them), the
    // segments are rerouted through more pixels ([`Snap::force`]).
    let mut snap = Snap::new(segments, labels, |label| !moved[label], lazy);
    loop {
        let (fragments, owner) = snap.fragments();
        let arr = arrange_grid(&snap.hot, fragments.iter().map(|f| f.0));
        if !arr.crossed.is_empty() {
            snap.force(&fragments, &owner, &arr.crossed)?;
            continue;
        }
        let label = |e: usize| fragments[e].1;
        let ascending = |e: usize| {
            let (a, b) = fragments[e].0;
            a < b
        };
        // The grid points are exact numbers and the map from the grid is a translation and a
        // scaling by a power of two: the exact predicates decide the same on either side.
        let point = |k: G| frame.at(k);
        let set = fill_arranged(arr, point, label, ascending, N::Ctx::default(), &inside)?;
        return Ok(set.with_ctx(ctx));
    }
}

/// The grid of one snap rounding: spacing `g` (a power of two) and a local origin on the grid
/// near the centre of the input, so that grid coordinates are integers below 2⁵² and results
/// do not depend on where the input sits (up to multiples of g).
struct Frame<N: Num> {
    g: f64,
    origin: G,
    /// The context of the result: the requested one, or the finest representable grid if the
    /// requested one is finer (only for a set whose ε was replaced by `with_ctx`).
    ctx: N::Ctx,
}

impl<N: Num> Frame<N> {
    /// The frame for `points` under the grid of `ctx`, from their box: snapping is monotone,
    /// so the snapped box's corners are the box's corners snapped.
    fn of<'a>(points: impl Iterator<Item = &'a Point<N>>, ctx: N::Ctx) -> Frame<N> {
        let (lo, hi) = points.fold(
            ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]),
            |(lo, hi), p| {
                let (x, y) = (p.x.to_f64(), p.y.to_f64());
                ([lo[0].min(x), lo[1].min(y)], [hi[0].max(x), hi[1].max(y)])
            },
        );
        let empty = lo[0] > hi[0];
        let magnitude = if empty {
            0.0
        } else {
            lo.iter().chain(&hi).fold(0.0, |m: f64, v| m.max(v.abs()))
        };
        let ctx = match N::resolve_ctx(N::Ctx::default(), 0.0, magnitude) {
            Ok(finest) => N::combine_ctx(ctx, finest),
            Err(_) => ctx,
        };
        let g = N::grid(&ctx).unwrap_or(1.0);
        let mut frame = Frame {
            g,
            origin: (0, 0),
            ctx,
        };
        if !empty {
            let centre = |lo: f64, hi: f64| frame.snap(lo) / 2 + frame.snap(hi) / 2;
            frame.origin = (centre(lo[0], hi[0]), centre(lo[1], hi[1]));
        }
        frame
    }

    /// The grid step nearest `v` (ties up), as a multiple of `g` from 0.
    fn snap(&self, v: f64) -> i64 {
        floor_i64(v / self.g + 0.5)
    }

    /// The grid point nearest `p` (ties up, as [`crossing_pixel`] rounds, so that snapping
    /// commutes with translations by the grid), relative to the origin: exact, as every
    /// coordinate is at most 2⁵¹ grid steps from 0 and g is a power of two.
    fn to_grid(&self, p: &Point<N>) -> G {
        let k = |v: &N| self.snap(v.to_f64());
        (k(&p.x) - self.origin.0, k(&p.y) - self.origin.1)
    }

    /// The point of grid point `k` (exact).
    fn at(&self, k: G) -> Point<N> {
        let c = |k: i64, o: i64| N::from_f64((k + o) as f64 * self.g).unwrap_or_else(|_| N::zero());
        Point::new(c(k.0, self.origin.0), c(k.1, self.origin.1))
    }
}

/// `t.floor() as i64` (saturating, 0 for NaN) without a call to libm's `floor`: truncation,
/// one less where that rounded a negative fraction up.
fn floor_i64(t: f64) -> i64 {
    let i = t as i64;
    i.saturating_sub(i64::from(i as f64 > t))
}

/// Snap rounding (Hobby 1999; Guibas and Marimont 1998) of grid segments, tried lazily first:
/// each segment is rerouted, in order along it, through the centres of the pixels of its own
/// crossings ([`grid_crossing_pairs`]), and, if that leaves two fragments crossing (a rerouted
/// fragment across a segment whose end's or crossing's pixel it passes), through the centres of
/// all the hot pixels it meets, as Hobby's — the pixels of the segments' ends and of their
/// crossings — which leaves none crossing. Every fragment's ends are thus within half a pixel
/// of its segment. Where two fragments still cross (half-open pixels, see
/// [`super::hot_pixels`]), [`Snap::force`] adds the pixel of their crossing and forces it into
/// both paths where their segments do not meet it; paths stay monotone along their segments
/// and every such round adds a new (segment, centre) stop, so the iteration ends.
struct Snap {
    segments: Vec<(G, G)>,
    /// The operand (`0` or `1`) each segment came from.
    labels: Vec<usize>,
    /// The segments' ends and the pixels of crossings: the points of the arrangement, sorted,
    /// without repeats.
    hot: Vec<G>,
    /// The indices in `hot` of each segment's ends.
    ends: Vec<(usize, usize)>,
    /// The indices in `hot` of the pixels of each segment's crossings that project strictly
    /// inside it, while rerouting is lazy; `None` once it is through every hot pixel met.
    lazy: Option<Buckets>,
    /// The pixels forced into the paths of segments, by segment (few segments have any).
    forced: BTreeMap<usize, BTreeSet<G>>,
}

impl Snap {
    /// The hot pixels of `segments`, segment k from operand `labels[k]`: endpoints and the
    /// pixels of crossings (none between two segments of a label that is `apart`, whose
    /// segments do not cross each other); rerouting `lazy` first, or as Hobby's at once.
    fn new(
        segments: Vec<(G, G)>,
        labels: Vec<usize>,
        apart: impl Fn(usize) -> bool,
        lazy: bool,
    ) -> Snap {
        let (vertices, mut ends) = rank_ends(&segments);
        // The segments by their left side: by their lower end in the order of the vertices.
        let lower_ends = ends.iter().enumerate().map(|(k, &(i, j))| (i.min(j), k));
        let by_left = Buckets::new(vertices.len(), lower_ends);
        let family = |k: usize| Some(labels[k]).filter(|&label| apart(label));
        let pairs = grid_crossing_pairs(&segments, by_left.all(), family);
        // The pixel of each crossing pair, with the pair's index, sorted; while rerouting is
        // lazy, whether it projects strictly inside each segment of the pair.
        let mut inside = Vec::with_capacity(if lazy { pairs.len() } else { 0 });
        let mut crossings: Vec<(G, usize)> = pairs
            .iter()
            .enumerate()
            .map(|(k, &(i, j))| {
                let (s, t) = (segments[i], segments[j]);
                let c = crossing_pixel(s, t);
                if lazy {
                    inside.push([inside_projection(s, c), inside_projection(t, c)]);
                }
                (c, k)
            })
            .collect();
        sort_by_grid(&mut crossings, |c| c.0);
        // The vertices and the crossings merged, each pixel once; where each vertex went, and
        // where the pixel of each crossing pair is.
        let mut hot: Vec<G> = Vec::with_capacity(vertices.len() + crossings.len());
        let mut at_hot = Vec::with_capacity(vertices.len());
        let mut at = vec![0; crossings.len()];
        let mut next = crossings.iter().peekable();
        for &v in &vertices {
            while let Some(&(c, k)) = next.next_if(|c| c.0 < v) {
                at[k] = push_new(&mut hot, c);
            }
            at_hot.push(hot.len());
            hot.push(v);
            while let Some(&(_, k)) = next.next_if(|c| c.0 == v) {
                at[k] = hot.len() - 1;
            }
        }
        for &(c, k) in next {
            at[k] = push_new(&mut hot, c);
        }
        for end in &mut ends {
            *end = (at_hot[end.0], at_hot[end.1]);
        }
        let lazy = lazy.then(|| {
            let own = pairs
                .iter()
                .zip(&at)
                .zip(&inside)
                .flat_map(|((&(i, j), &h), &on)| {
                    [(on[0], i), (on[1], j)]
                        .into_iter()
                        .filter(|s| s.0)
                        .map(move |s| (s.1, h))
                });
            Buckets::new(segments.len(), own)
        });
        Snap {
            segments,
            labels,
            hot,
            ends,
            lazy,
            forced: BTreeMap::new(),
        }
    }

    /// Finds the indices in `hot` of every segment's ends again (after pixels were added).
    fn locate_ends(&mut self) {
        let hot = &self.hot;
        let index = |g: G| {
            hot.binary_search(&g)
                .expect("the ends of the segments are hot pixels")
        };
        self.ends = self
            .segments
            .iter()
            .map(|&(a, b)| (index(a), index(b)))
            .collect();
    }

    /// The fragments of all segments and the segment each comes from.
    fn fragments(&self) -> (Vec<Fragment>, Vec<usize>) {
        let pixels = HotPixels::new(&self.hot);
        // Most segments are one fragment.
        let most = self.segments.len() + self.segments.len() / 4;
        let (mut fragments, mut owner) = (Vec::with_capacity(most), Vec::with_capacity(most));
        let mut path = Vec::new();
        for (k, (&s, &label)) in self.segments.iter().zip(&self.labels).enumerate() {
            path.clear();
            match &self.lazy {
                Some(own) => path.extend_from_slice(own.get(k)),
                None => {
                    pixels.met_by(s, self.ends[k], &mut path);
                    path.retain(|&h| inside_projection(s, self.hot[h]));
                }
            }
            let forced = self.forced.get(&k);
            if path.is_empty() && forced.is_none() {
                // A segment with no pixel to pass through is one fragment.
                owner.push(k);
                fragments.push((self.ends[k], label));
                continue;
            }
            let route = Route {
                s,
                ends: self.ends[k],
                sorted: &self.hot,
            };
            route.through(forced, &mut path);
            for w in path.windows(2) {
                owner.push(k);
                fragments.push(((w[0], w[1]), label));
            }
        }
        (fragments, owner)
    }

    /// The pairs `crossed` of `fragments` (from segments `owner`) cross: rerouting that was
    /// lazy becomes Hobby's; else their pixels become hot and are forced into both segments'
    /// paths.
    fn force(
        &mut self,
        fragments: &[Fragment],
        owner: &[usize],
        crossed: &[(usize, usize)],
    ) -> Result<(), YinError> {
        // Lazy rerouting left a crossing: reroute through every hot pixel met, as Hobby's.
        if self.lazy.take().is_some() {
            return Ok(());
        }
        let hot = &self.hot;
        let grid = |f: &Fragment| (hot[f.0 .0], hot[f.0 .1]);
        let pixels: Vec<(G, [usize; 2])> = crossed
            .iter()
            .map(|&(i, j)| {
                let c = crossing_pixel(grid(&fragments[i]), grid(&fragments[j]));
                (c, [owner[i], owner[j]])
            })
            .collect();
        let mut progress = false;
        for &(c, owners) in &pixels {
            if let Err(at) = self.hot.binary_search(&c) {
                self.hot.insert(at, c);
                progress = true;
            }
            for k in owners {
                progress |= inside_projection(self.segments[k], c)
                    && self.forced.entry(k).or_default().insert(c);
            }
        }
        if progress {
            self.locate_ends();
            return Ok(());
        }
        // Cannot happen for a crossing strictly inside two fragments; never loop forever.
        Err(YinError::SnapStalled {
            point: format!("{:?}", pixels[0].0),
        })
    }
}

/// The fewest ends sorted by radix (fewer mispredicted branches than comparisons: W4's 3 700
/// ends −5 %); below, the passes over the digits cost more than they save (W6's joins +16 %).
/// 8 in unit tests, so that both ways are taken.
const RADIX_FROM: usize = if cfg!(test) { 8 } else { 1024 };

/// Pushes `p` onto the sorted `hot` unless it is the last one there; its index in `hot`.
fn push_new(hot: &mut Vec<G>, p: G) -> usize {
    if hot.last() != Some(&p) {
        hot.push(p);
    }
    hot.len() - 1
}

/// Sorts `items` by their grid point `key`: from [`RADIX_FROM`] items by radix, on one word
/// holding both coordinates where they fit ([`Packing`]), else on x alone (counting one digit
/// of every key costs a pass over them, and x mostly decides) and then by y within each run of
/// one x.
fn sort_by_grid<T>(items: &mut [T], key: impl Fn(&T) -> G) {
    if items.len() < RADIX_FROM {
        items.sort_unstable_by_key(key);
        return;
    }
    let packing = Packing::of(key(&items[0]), items.iter().map(&key));
    match packing.bits() {
        0..=32 => radsort::sort_by_key(items, |t| packing.pack(key(t)) as u32),
        33..=64 => radsort::sort_by_key(items, |t| packing.pack(key(t))),
        _ => {
            let least = packing.least.0;
            radsort::sort_by_key(items, |t| (key(t).0 - least) as u64);
            for run in items.chunk_by_mut(|a, b| key(a).0 == key(b).0) {
                if run.len() > 1 {
                    run.sort_unstable_by_key(|t| key(t).1);
                }
            }
        }
    }
}

/// Grid points as one ordered word: each coordinate counted from its least value and divided
/// by the power of two that divides all of them (points on a coarser lattice than the grid),
/// x above y.
struct Packing {
    least: G,
    shift: (u32, u32),
    /// The bits of y's field.
    low: u32,
    /// The bits of x's field.
    high: u32,
}

impl Packing {
    /// The packing of `points`, of which `first` is one.
    fn of(first: G, points: impl Iterator<Item = G>) -> Packing {
        // Differences from the first point share their low zero bits with those from the least.
        let (least, most, spread) = points.fold((first, first, (0u64, 0u64)), |(l, m, d), k| {
            let step = |v: i64, f: i64| v.wrapping_sub(f) as u64;
            (
                (l.0.min(k.0), l.1.min(k.1)),
                (m.0.max(k.0), m.1.max(k.1)),
                (d.0 | step(k.0, first.0), d.1 | step(k.1, first.1)),
            )
        });
        let shift = (
            spread.0.trailing_zeros() % 64,
            spread.1.trailing_zeros() % 64,
        );
        // Coordinates are below 2⁵²: spans are below 2⁵³.
        let width = |span: i64, shift: u32| 64 - ((span as u64) >> shift).leading_zeros();
        Packing {
            least,
            shift,
            low: width(most.1 - least.1, shift.1),
            high: width(most.0 - least.0, shift.0),
        }
    }

    /// The bits a packed point takes.
    fn bits(&self) -> u32 {
        self.low + self.high
    }

    /// Point `k`, one of those packed, as a word ordered as the points (if it has at most 64
    /// bits).
    fn pack(&self, k: G) -> u64 {
        let field = |v: i64, least: i64, shift: u32| ((v - least) as u64) >> shift;
        let y = field(k.1, self.least.1, self.shift.1);
        // y may take all 64 bits, x then none.
        let x = field(k.0, self.least.0, self.shift.0).checked_shl(self.low);
        x.unwrap_or(0) | y
    }
}

/// The distinct ends of the grid `segments`, sorted, and the indices in them of every
/// segment's ends. A segment's end that is the next one's start (along a curve) is not sorted
/// again.
fn rank_ends(segments: &[(G, G)]) -> (Vec<G>, Vec<(usize, usize)>) {
    let shared = |k: usize| segments.get(k + 1).is_some_and(|s| s.0 == segments[k].1);
    // Every start, coded 2k for segment k, and every end not shared, coded 2k + 1.
    let mut coded: Vec<(G, usize)> = Vec::with_capacity(segments.len() + segments.len() / 4);
    for (k, &(a, b)) in segments.iter().enumerate() {
        coded.push((a, 2 * k));
        if !shared(k) {
            coded.push((b, 2 * k + 1));
        }
    }
    sort_by_grid(&mut coded, |e| e.0);
    let mut vertices: Vec<G> = Vec::with_capacity(coded.len());
    let mut ends = vec![(0, 0); segments.len()];
    for (g, code) in coded {
        if vertices.last() != Some(&g) {
            vertices.push(g);
        }
        let end = &mut ends[code / 2];
        *(if code % 2 == 0 {
            &mut end.0
        } else {
            &mut end.1
        }) = vertices.len() - 1;
    }
    for k in (0..segments.len()).rev() {
        if shared(k) {
            ends[k].1 = ends[k + 1].0;
        }
    }
    (vertices, ends)
}

/// True if `c` projects strictly inside the segment `s`.
fn inside_projection(s: (G, G), c: G) -> bool {
    let (a, b) = s;
    let d = ((b.0 - a.0) as i128, (b.1 - a.1) as i128);
    let t = (c.0 - a.0) as i128 * d.0 + (c.1 - a.1) as i128 * d.1;
    t > 0 && t < d.0 * d.0 + d.1 * d.1
}

/// A segment `s` to reroute, with the indices of its ends in the `sorted` hot pixels.
struct Route<'a> {
    s: (G, G),
    ends: (usize, usize),
    sorted: &'a [G],
}

impl Route<'_> {
    /// The path of the segment `s = ab` rerouted through the centres of the hot pixels in
    /// `path` (indices of ones it meets, on entry) and through the `forced` centres, all
    /// projecting strictly inside `s`, in order along `s`, into `path` as indices of the hot
    /// pixels (from `a` to `b`, no point repeated in a row).
    fn through(&self, forced: Option<&BTreeSet<G>>, path: &mut Vec<usize>) {
        let (s, sorted, ends) = (self.s, self.sorted, self.ends);
        let (a, b) = s;
        path.extend(forced.into_iter().flatten().map(|c| {
            sorted
                .binary_search(c)
                .expect("forced pixels are hot pixels")
        }));
        if path.len() > 1 {
            let d = ((b.0 - a.0) as i128, (b.1 - a.1) as i128);
            let along = |c: G| (c.0 - a.0) as i128 * d.0 + (c.1 - a.1) as i128 * d.1;
            path.sort_unstable_by_key(|&k| (along(sorted[k]), k));
            path.dedup();
        }
        path.insert(0, ends.0);
        path.push(ends.1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational, Tolerance};
    use crate::yin2::faces::inside_set;
    use crate::yin2::grid_arrange::cross_properly;
    use crate::yin2::set::Repr;
    use crate::yin2::FillRule;
    use proptest::prelude::*;

    /// A float set filled (non-zero) from up to three rings on a 6 × 6 lattice with ε = 1/4:
    /// crossing rings give snapped crossings, every vertex a grid point.
    fn lattice_set() -> impl Strategy<Value = YinSet2<Float>> {
        let point = (0i64..6, 0i64..6)
            .prop_map(|(x, y)| Point::new(Float::new(x as f64), Float::new(y as f64)));
        proptest::collection::vec(proptest::collection::vec(point, 3..7), 1..4).prop_map(|rings| {
            YinSet2::from_rings_filled_with(rings, FillRule::NonZero, Tolerance::new(0.25))
                .expect("finite rings")
        })
    }

    /// True if `c` projects strictly inside the segment `(a, b)`: the projection's parameter
    /// along it, a rational, is strictly between 0 and 1.
    fn along_inside((a, b): (G, G), c: G) -> bool {
        let r = |v: i64| Rational::from_integer(v.into());
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let t = (r(c.0 - a.0) * r(dx) + r(c.1 - a.1) * r(dy)) / (r(dx) * r(dx) + r(dy) * r(dy));
        t > r(0) && t < r(1)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: yinset_testkit::cases(300), failure_persistence: None, ..ProptestConfig::default() })]

        /// Grid points sort as the standard sort orders them, on each of the three ways:
        /// points on a lattice coarser than the grid (packed in a 32-bit word once the shared
        /// low bits are dropped), points spanning 2²⁶ (a 64-bit word), and points spanning 2⁵²
        /// on three vertical lines (x first, then each run by y).
        #[test]
        fn grid_points_sort_lexicographically(
            (points, way) in prop_oneof![
                (0u32..30, -1000i64..1000, proptest::collection::vec((-3000i64..3000, -3000i64..3000), 8..200))
                    .prop_map(|(s, o, v)| (v.into_iter().map(|(x, y)| ((x << s) + o, (y << s) - o)).collect::<Vec<G>>(), 0)),
                proptest::collection::vec((-(1i64 << 25)..1 << 25, -(1i64 << 25)..1 << 25), 8..200)
                    .prop_map(|v| (v, 1)),
                (-(1i64 << 50)..0, (1i64 << 40)..1 << 49, proptest::collection::vec((0i64..3, -(1i64 << 51)..1 << 51), 8..200))
                    .prop_map(|(a, d, v)| (v.into_iter().map(|(i, y)| (a + i * d, y)).collect::<Vec<G>>(), 2)),
            ],
        ) {
            let bits = Packing::of(points[0], points.iter().copied()).bits();
            let ways = [bits <= 32, (33..=64).contains(&bits), bits > 64];
            prop_assume!(ways[way]);
            let mut got = points.clone();
            sort_by_grid(&mut got, |&k| k);
            let mut want = points;
            want.sort_unstable();
            prop_assert_eq!(got, want);
        }

        /// The hot pixels are sorted and distinct, each segment's ends are found at `ends`,
        /// and the pixels each segment is rerouted through first (lazily) are exactly the
        /// pixels of its crossings that project strictly inside it, against every pair tested
        /// directly and the projection taken as a rational: segments on a 13×13
        /// lattice, whose crossings' pixels are often other segments' ends (both sorts taken).
        #[test]
        fn lazy_stops_are_the_pixels_of_each_segments_crossings(
            drawn in proptest::collection::vec(((0..=12i64, 0..=12i64), (0..=12i64, 0..=12i64)), 1..30),
        ) {
            let segments: Vec<(G, G)> = drawn.into_iter().filter(|s| s.0 != s.1).collect();
            let labels = vec![0; segments.len()];
            let snap = Snap::new(segments.clone(), labels, |_| false, true);
            prop_assert!(snap.hot.windows(2).all(|w| w[0] < w[1]));
            let own = snap.lazy.as_ref().expect("lazy rerouting");
            for (k, &s) in segments.iter().enumerate() {
                prop_assert_eq!((snap.hot[snap.ends[k].0], snap.hot[snap.ends[k].1]), s);
                let mut want: Vec<G> = segments
                    .iter()
                    .filter(|&&t| cross_properly(s, t))
                    .map(|&t| crossing_pixel(s, t))
                    .filter(|&c| along_inside(s, c))
                    .collect();
                let mut got: Vec<G> = own.get(k).iter().map(|&h| snap.hot[h]).collect();
                want.sort_unstable();
                got.sort_unstable();
                prop_assert_eq!(got, want);
            }
        }

        /// Skipping the crossing tests between segments of one valid operand (`valid`) changes
        /// nothing: the meet, join and difference of two float sets whose vertices snapping
        /// does not move, with and without (snap rounding lazy first either way).
        #[test]
        fn valid_operands_need_no_crossing_test_within(a in lattice_set(), b in lattice_set()) {
            let (Repr::Spadjor(sa), Repr::Spadjor(sb)) = (&a.repr, &b.repr) else {
                return Ok(());
            };
            let keeps: [fn(bool, bool) -> bool; 3] = [|x, y| x && y, |x, y| x || y, |x, y| x && !y];
            for keep in keeps {
                let rings = [sa, sb]
                    .into_iter()
                    .enumerate()
                    .flat_map(|(label, s)| s.curves.iter().map(move |c| (c.vertices(), label)));
                let inside = |w: Winding| {
                    keep(inside_set(w[0], !sa.bounded), inside_set(w[1], !sb.bounded))
                };
                let apart = regularize_as(rings.clone(), true, true, a.ctx, inside);
                prop_assert_eq!(apart, regularize_as(rings, false, true, a.ctx, inside));
            }
        }
    }

    #[test]
    fn floor_without_libm_is_floor() {
        let cases = [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            2.5,
            -2.5,
            1e-300,
            -1e-300,
            4503599627370495.5,
            -4503599627370495.5,
            9007199254740993.0,
            -9007199254740993.0,
            9.3e18,
            -9.3e18,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        for t in cases {
            assert_eq!(floor_i64(t), t.floor() as i64, "{t}");
        }
    }

    /// The fragments of `snap` and the pairs of them that its arrangement reports crossing.
    fn crossed(snap: &Snap) -> (Vec<Fragment>, Vec<usize>, Vec<(usize, usize)>) {
        let (fragments, owner) = snap.fragments();
        let crossed = arrange_grid(&snap.hot, fragments.iter().map(|f| f.0)).crossed;
        (fragments, owner, crossed)
    }

    #[test]
    fn hot_pixels_of_crossings_leave_no_crossing_and_a_missing_one_is_forced() {
        // Two crossing segments and a third one crossing both.
        let segments = vec![
            (((0, 0), (10, 3)), 0),
            (((0, 4), (9, 0)), 1),
            (((5, -2), (4, 7)), 0),
        ];
        let (segments, labels) = segments.into_iter().unzip();
        let mut snap = Snap::new(segments, labels, |_| false, true);
        let pixels = [(5, 2), (5, 1)];
        assert!(
            pixels.iter().all(|c| snap.hot.contains(c)),
            "{:?}",
            snap.hot
        );
        assert!(crossed(&snap).2.is_empty());
        // Hobby's rerouting, through every hot pixel met.
        snap.lazy = None;
        assert!(crossed(&snap).2.is_empty());
        // Without the crossing pixels the fragments cross: the arrangement reports them and
        // `force` adds their pixels until none is left (one may do: the third segment passes
        // through the first crossing's pixel).
        snap.hot.retain(|c| !pixels.contains(c));
        snap.locate_ends();
        let mut rounds = 0;
        loop {
            let (fragments, owner, crossed) = crossed(&snap);
            if crossed.is_empty() {
                break;
            }
            snap.force(&fragments, &owner, &crossed).unwrap();
            rounds += 1;
            assert!(rounds <= 3, "no progress");
        }
        assert!(rounds >= 1);
        assert!(
            pixels.iter().any(|c| snap.hot.contains(c)),
            "{:?}",
            snap.hot
        );
    }

    #[test]
    fn lazy_rerouting_that_leaves_a_crossing_becomes_hobbys() {
        // The first and third segments cross at (6.56, 3.64), in pixel (7, 4). The third passes
        // x = 5.82 at y = 5, in the pixel of the second one's end (6, 5), without crossing the
        // second; rerouted through (7, 4) only, it passes x = 6.375 at y = 5 and crosses it.
        let segments = vec![
            (((0, 2), (12, 5)), 0),
            (((10, 11), (6, 5)), 1),
            (((8, 1), (2, 12)), 0),
        ];
        let (segments, labels) = segments.into_iter().unzip();
        let mut snap = Snap::new(segments, labels, |_| false, true);
        let hot = snap.hot.clone();
        let paths = |fragments: &[Fragment]| -> Vec<(G, G)> {
            fragments
                .iter()
                .map(|f| (hot[f.0 .0], hot[f.0 .1]))
                .collect()
        };
        let (fragments, owner, crossing) = crossed(&snap);
        // Lazily, the first and third segments pass through their crossing's pixel only.
        let lazy = [
            ((0, 2), (7, 4)),
            ((7, 4), (12, 5)),
            ((10, 11), (6, 5)),
            ((8, 1), (7, 4)),
            ((7, 4), (2, 12)),
        ];
        assert_eq!(paths(&fragments), lazy);
        assert!(!crossing.is_empty());
        snap.force(&fragments, &owner, &crossing).unwrap();
        assert!(snap.lazy.is_none());
        assert_eq!(snap.hot, hot, "no pixel added");
        let (fragments, _, crossing) = crossed(&snap);
        let hobby = [((8, 1), (7, 4)), ((7, 4), (6, 5)), ((6, 5), (2, 12))];
        assert_eq!(paths(&fragments)[..2], lazy[..2]);
        assert_eq!(paths(&fragments)[3..], hobby);
        assert!(crossing.is_empty());
    }

    #[test]
    fn the_fill_of_arbitrary_rings_reroutes_as_hobbys_at_once() {
        // Two triangles apart, each passing through the pixel of the other's nearest vertex
        // without crossing it: the first's side from (3, 11) to (8, 2) passes (6.56, 4.6), in
        // the pixel of (7, 5); the second's from (7, 5) to (9, 1) passes (8.45, 2.1), in the
        // pixel of (8, 2). Rerouted as Hobby's, both sides run from (7, 5) to (8, 2) and the
        // triangles join along it; lazily, crossing nothing, they stay apart.
        let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
        let rings = [
            vec![p(3.0, 11.0), p(8.0, 2.0), p(1.0, 0.0)],
            vec![p(11.0, 8.0), p(7.0, 5.0), p(9.0, 1.0)],
        ];
        let rings = rings.iter().map(|r| (r.as_slice(), 0));
        let (ctx, inside) = (Tolerance::new(1.0), |w: Winding| w[0] != 0);
        let fill = regularize(rings.clone(), false, ctx, inside).unwrap();
        assert_eq!(fill.betti().components, 1);
        let lazy = regularize_as(rings, false, true, ctx, inside).unwrap();
        assert_eq!(lazy.betti().components, 2);
    }
}
