//! Float mode's normalization (seed 000 §5.2 made consistent): iterated snap rounding of the
//! boundary pieces to the ε-grid, then regularization by winding numbers. Every float result is
//! thereby exactly a valid Yin set whose vertices are grid points, decided with exact predicates.

use super::error::YinError;
use super::fill::fill_arranged;
use super::grid_arrange::{arrange_grid, crossing_pixel, unit, G};
use super::grid_pairs::grid_crossing_pairs;
use super::intersect::Edge;
use super::set::YinSet2;
use super::winding::{Pair, Winding};
use crate::kernel::Point;
use crate::num::{Float, Num, Tolerance};
use rstar::{RTree, SelectionFunction, AABB};
use std::cell::{Cell, OnceCell};
use std::collections::BTreeSet;

/// A grid segment with the operand (`0` or `1`) its piece came from.
type Labelled = ((G, G), usize);

/// The Yin set of the faces where `inside` holds, given the directed pieces of the operands'
/// boundaries labelled by operand (`0` or `1`), after snapping them to the grid of `ctx`
/// (float mode, [`crate::num::Tolerance`]). The whole computation runs on grid integers
/// relative to a local origin ([`Frame`]), with exact integer-valued predicates; only the
/// result's vertices are mapped back to coordinates. Every piece set must be a union of closed
/// cycles, so that winding numbers are defined.
pub(crate) fn regularize<N: Num>(
    pieces: &[(Edge<N>, usize)],
    ctx: N::Ctx,
    inside: impl Fn(Winding) -> bool,
) -> Result<YinSet2<N>, YinError> {
    let frame = Frame::of(pieces.iter().flat_map(|((a, b), _)| [a, b]), ctx);
    let ctx = frame.ctx;
    let segments: Vec<Labelled> = pieces
        .iter()
        .map(|((a, b), l)| ((frame.to_grid(a), frame.to_grid(b)), *l))
        .filter(|((a, b), _)| a != b)
        .collect();
    // Snapped fragments do not cross: their arrangement is swept on the grid integers with
    // exact integer orientations. Where two still cross (the arrangement reports them), their
    // crossing pixel is added and the segments rerouted.
    let mut snap = Snap::new(segments);
    loop {
        let (fragments, owner) = snap.fragments();
        let arr = arrange_grid(&snap.hot, fragments.iter().map(|f| f.0));
        if !arr.crossed.is_empty() {
            snap.force(&fragments, &owner, &arr.crossed)?;
            continue;
        }
        let label = |e: usize| Pair::unit(fragments[e].1);
        let ascending = |e: usize| {
            let (a, b) = fragments[e].0;
            a < b
        };
        let inside = |w: Pair| inside(w.0);
        let exact = Tolerance::default();
        let unit_set = fill_arranged(arr, unit, label, ascending, exact, inside)?;
        return Ok(unit_set.map_points(|p| frame.to_point(p), ctx));
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
    /// The frame for `points` under the grid of `ctx`.
    fn of<'a>(points: impl Iterator<Item = &'a Point<N>> + Clone, ctx: N::Ctx) -> Frame<N> {
        let magnitude = points
            .clone()
            .map(|p| p.x.to_f64().abs().max(p.y.to_f64().abs()))
            .fold(0.0, f64::max);
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
        let (lo, hi) = points.map(|p| frame.to_grid(p)).fold(
            ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN)),
            |(lo, hi), k| {
                (
                    (lo.0.min(k.0), lo.1.min(k.1)),
                    (hi.0.max(k.0), hi.1.max(k.1)),
                )
            },
        );
        if lo.0 <= hi.0 {
            frame.origin = (lo.0 / 2 + hi.0 / 2, lo.1 / 2 + hi.1 / 2);
        }
        frame
    }

    /// The grid point nearest `p` (ties up, as [`crossing_pixel`] rounds, so that snapping
    /// commutes with translations by the grid), relative to the origin: exact, as every
    /// coordinate is at most 2⁵¹ grid steps from 0 and g is a power of two.
    fn to_grid(&self, p: &Point<N>) -> G {
        let k = |v: &N| (v.to_f64() / self.g + 0.5).floor() as i64;
        (k(&p.x) - self.origin.0, k(&p.y) - self.origin.1)
    }

    /// The point of a vertex given in grid units relative to the origin (exact).
    fn to_point(&self, p: &Point<Float>) -> Point<N> {
        let c = |k: &Float, o: i64| {
            N::from_f64((k.get() as i64 + o) as f64 * self.g).unwrap_or_else(|_| N::zero())
        };
        Point::new(c(&p.x, self.origin.0), c(&p.y, self.origin.1))
    }
}

/// Whether a face of winding `w` lies in a Yin set bounded by closed cycles: positive winding,
/// or non-negative if the set is unbounded (its far face, of winding 0, is inside).
pub(crate) fn inside_set(w: i64, unbounded: bool) -> bool {
    w + i64::from(unbounded) > 0
}

/// Snap rounding (Hobby 1999; Guibas and Marimont 1998) of grid segments: each segment is
/// rerouted, in order along it, through the centres of the hot pixels it meets — the pixels of
/// the segments' endpoints and of their crossings ([`grid_crossing_pairs`]) — which leaves no
/// two fragments crossing. Where two fragments still cross (half-open pixels, see
/// [`meets_pixel`]), [`Snap::force`] adds the pixel of their crossing and forces it into both
/// paths where their segments do not meet it; paths stay monotone along their segments and
/// every such round adds a new (segment, centre) stop, so the iteration ends.
struct Snap {
    segments: Vec<Labelled>,
    /// Sorted, without repeats.
    hot: Vec<G>,
    forced: Vec<BTreeSet<G>>,
}

impl Snap {
    /// The hot pixels of `segments`: endpoints and the pixels of crossings.
    fn new(segments: Vec<Labelled>) -> Snap {
        let mut hot: Vec<G> = segments.iter().flat_map(|&((a, b), _)| [a, b]).collect();
        let grid: Vec<(G, G)> = segments.iter().map(|s| s.0).collect();
        hot.extend(
            grid_crossing_pairs(&grid)
                .into_iter()
                .map(|(i, j)| crossing_pixel(grid[i], grid[j])),
        );
        hot.sort_unstable();
        hot.dedup();
        let forced = vec![BTreeSet::new(); segments.len()];
        Snap {
            segments,
            hot,
            forced,
        }
    }

    /// The fragments of all segments (with their labels) and the segment each comes from.
    fn fragments(&self) -> (Vec<Labelled>, Vec<usize>) {
        let pixels = HotPixels::new(&self.hot);
        let (mut fragments, mut owner, mut path) = (Vec::new(), Vec::new(), Vec::new());
        for (k, &(s, label)) in self.segments.iter().enumerate() {
            reroute(s, &pixels, &self.forced[k], &mut path);
            for w in path.windows(2) {
                owner.push(k);
                fragments.push(((w[0], w[1]), label));
            }
        }
        (fragments, owner)
    }

    /// The pairs `crossed` of `fragments` (from segments `owner`) cross: their pixels become
    /// hot and are forced into both segments' paths.
    fn force(
        &mut self,
        fragments: &[Labelled],
        owner: &[usize],
        crossed: &[(usize, usize)],
    ) -> Result<(), YinError> {
        let mut progress = false;
        for &(i, j) in crossed {
            let c = crossing_pixel(fragments[i].0, fragments[j].0);
            if let Err(at) = self.hot.binary_search(&c) {
                self.hot.insert(at, c);
                progress = true;
            }
            for k in [owner[i], owner[j]] {
                progress |= inside_projection(self.segments[k].0, c) && self.forced[k].insert(c);
            }
        }
        if progress {
            return Ok(());
        }
        // Cannot happen for a crossing strictly inside two fragments; never loop forever.
        let (i, j) = crossed[0];
        let c = crossing_pixel(fragments[i].0, fragments[j].0);
        Err(YinError::SnapStalled {
            point: format!("{c:?}"),
        })
    }
}

/// True if `c` projects strictly inside the segment `s`.
fn inside_projection(s: (G, G), c: G) -> bool {
    let (a, b) = s;
    let d = ((b.0 - a.0) as i128, (b.1 - a.1) as i128);
    let t = (c.0 - a.0) as i128 * d.0 + (c.1 - a.1) as i128 * d.1;
    t > 0 && t < d.0 * d.0 + d.1 * d.1
}

/// The hot pixels, for finding the ones a segment meets: sorted by x, so that a segment scans
/// the pixels of its x-range (its slab), and an R-tree searched along a segment
/// ([`AlongSegment`]), whose cost follows the pixels near the segment, not all pixels in its
/// slab. The tree is built once crowded slabs (over [`SLAB_SCAN`] pixels) have cost as much
/// scanning as building it would ([`BUILD_COST`] per pixel), as in renting before buying: few
/// long edges are scanned, many (long slanted edges side by side) are searched.
struct HotPixels<'a> {
    sorted: &'a [G],
    tree: OnceCell<RTree<[i64; 2]>>,
    /// The pixels scanned so far in crowded slabs.
    crowded: Cell<usize>,
}

/// The most hot pixels a slab may hold for it to be scanned whatever it has cost so far.
const SLAB_SCAN: usize = 64;

/// The cost of building the R-tree, per pixel, in pixels scanned (measured: about 100 ns a
/// pixel to build, 1–2 ns a pixel to scan).
const BUILD_COST: usize = 64;

impl<'a> HotPixels<'a> {
    /// The pixels `sorted` (in the order of `G`: by x, then y).
    fn new(sorted: &'a [G]) -> HotPixels<'a> {
        HotPixels {
            sorted,
            tree: OnceCell::new(),
            crowded: Cell::new(0),
        }
    }

    /// Appends to `out` the hot pixels that the segment `ab` meets ([`meets_pixel`]).
    fn met_by(&self, a: G, b: G, out: &mut Vec<G>) {
        // A pixel met by the segment has its centre within the segment's box (both on the grid).
        let from = self.sorted.partition_point(|c| c.0 < a.0.min(b.0));
        let to = self.sorted.partition_point(|c| c.0 <= a.0.max(b.0));
        let slab = to - from;
        let scan = slab <= SLAB_SCAN
            || self.tree.get().is_none()
                && self.crowded.get() + slab <= BUILD_COST * self.sorted.len();
        if scan {
            if slab > SLAB_SCAN {
                self.crowded.set(self.crowded.get() + slab);
            }
            let (lo, hi) = (a.1.min(b.1), a.1.max(b.1));
            let meets = |c: &&G| (lo..=hi).contains(&c.1) && meets_pixel(a, b, **c);
            out.extend(self.sorted[from..to].iter().filter(meets));
        } else {
            out.extend(self.along(a, b));
        }
    }

    /// The hot pixels that the segment `ab` meets, from the R-tree search along it.
    fn along(&self, a: G, b: G) -> impl Iterator<Item = G> + '_ {
        let tree = self
            .tree
            .get_or_init(|| RTree::bulk_load(self.sorted.iter().map(|&(x, y)| [x, y]).collect()));
        tree.locate_with_selection_function(AlongSegment(a, b))
            .map(|p| (p[0], p[1]))
    }
}

/// The path of the segment `s = ab` rerouted through the centres of the hot pixels it meets and
/// through the `forced` centres, in order along `s` (centres projecting strictly inside `s`
/// only), into `path` (from `a` to `b`, no point repeated in a row).
fn reroute(s: (G, G), hot: &HotPixels<'_>, forced: &BTreeSet<G>, path: &mut Vec<G>) {
    let (a, b) = s;
    path.clear();
    hot.met_by(a, b, path);
    path.extend(forced);
    path.retain(|&c| c != a && c != b && inside_projection(s, c));
    let d = ((b.0 - a.0) as i128, (b.1 - a.1) as i128);
    path.sort_unstable_by_key(|c| ((c.0 - a.0) as i128 * d.0 + (c.1 - a.1) as i128 * d.1, *c));
    path.dedup();
    path.insert(0, a);
    path.push(b);
}

/// The R-tree search for the hot pixels a segment meets: a node is opened when the segment
/// meets the union of its pixels' squares (closed, a superset), a pixel is taken when
/// [`meets_pixel`] says so.
struct AlongSegment(G, G);

impl SelectionFunction<[i64; 2]> for AlongSegment {
    fn should_unpack_parent(&self, envelope: &AABB<[i64; 2]>) -> bool {
        let (lo, hi) = (envelope.lower(), envelope.upper());
        meets_box(self.0, self.1, (lo[0], lo[1]), (hi[0], hi[1]))
    }

    fn should_unpack_leaf(&self, c: &[i64; 2]) -> bool {
        meets_pixel(self.0, self.1, (c[0], c[1]))
    }
}

/// True if the segment `ab` meets the closed box of the pixel squares from `lo` to `hi` (in
/// doubled coordinates [2·lo − 1, 2·hi + 1]).
fn meets_box(a: G, b: G, lo: G, hi: G) -> bool {
    let w = |v: i64| 2 * v as i128;
    let (ax, ay, bx, by) = (w(a.0), w(a.1), w(b.0), w(b.1));
    let (x0, y0, x1, y1) = (w(lo.0) - 1, w(lo.1) - 1, w(hi.0) + 1, w(hi.1) + 1);
    if ax.max(bx) < x0 || ax.min(bx) > x1 || ay.max(by) < y0 || ay.min(by) > y1 {
        return false;
    }
    let side = |px: i128, py: i128| ((bx - ax) * (py - ay) - (by - ay) * (px - ax)).signum();
    let s = [side(x0, y0), side(x1, y0), side(x1, y1), side(x0, y1)];
    !(s.iter().all(|&v| v > 0) || s.iter().all(|&v| v < 0))
}

/// True if the segment `ab` meets the half-open pixel square of side 1 centred at `c`
/// (in doubled coordinates [2c − 1, 2c + 1)², the pixel that [`crossing_pixel`] rounds to).
/// Half-open pixels partition the plane, so a segment through a pixel corner meets one pixel
/// there, not four: closed squares let two segments through the same corner zigzag across
/// each other. The square is the closed one shifted by (−δ, −δ²) for an infinitesimal δ > 0;
/// endpoints (even) never tie with sides (odd), so only the corner side tests need it.
fn meets_pixel(a: G, b: G, c: G) -> bool {
    let sides = corner_sides(a, b, c);
    if sides.is_some_and(|s| all_on_one_side(&s)) {
        return false;
    }
    let w = |v: i64| 2 * v;
    let ((ax, ay), (bx, by), (cx, cy)) = ((w(a.0), w(a.1)), (w(b.0), w(b.1)), (w(c.0), w(c.1)));
    if ax.max(bx) < cx - 1 || ax.min(bx) > cx + 1 || ay.max(by) < cy - 1 || ay.min(by) > cy + 1 {
        return false;
    }
    !all_on_one_side(&sides.unwrap_or_else(|| exact_corner_sides(a, b, c)))
}

/// True if every side is strictly the same (a segment of one point has sides 0).
fn all_on_one_side(sides: &[i8; 4]) -> bool {
    sides.iter().all(|&v| v > 0) || sides.iter().all(|&v| v < 0)
}

/// The sides of the line through `a` and `b` on which the corners of the pixel square centred
/// at `c` lie, by exact integer side tests in doubled coordinates, a corner on the line
/// counted on the side of the square shifted by (−δ, −δ²) ([`meets_pixel`]).
fn exact_corner_sides(a: G, b: G, c: G) -> [i8; 4] {
    let w = |v: i64| 2 * v as i128;
    let ((ax, ay), (bx, by), (cx, cy)) = ((w(a.0), w(a.1)), (w(b.0), w(b.1)), (w(c.0), w(c.1)));
    let (dx, dy) = (bx - ax, by - ay);
    // Sign of d × (p − (δ, δ²) − a) = d × (p − a) + δ·dy − δ²·dx.
    let side = |px: i128, py: i128| match (dx * (py - ay) - dy * (px - ax)).signum() {
        0 if dy != 0 => dy.signum() as i8,
        0 => -dx.signum() as i8,
        s => s as i8,
    };
    [
        side(cx - 1, cy - 1),
        side(cx + 1, cy - 1),
        side(cx + 1, cy + 1),
        side(cx - 1, cy + 1),
    ]
}

/// The sides of the line through `a` and `b` on which the corners of the pixel square centred
/// at `c` lie (as in [`meets_pixel`]), where `f64` arithmetic is certain of every one: none on
/// the line, each side value d × (corner − a) farther from 0 than its rounding error. A filter
/// in front of [`meets_pixel`]'s integer side tests; a centre far off the line settles all
/// four corners at once.
fn corner_sides(a: G, b: G, c: G) -> Option<[i8; 4]> {
    let f = |v: i64| v as f64;
    // Grid coordinates are at most 2⁵¹ from 0: these differences are exact.
    let (dx, dy) = (f(b.0) - f(a.0), f(b.1) - f(a.1));
    let (ex, ey) = (f(c.0) - f(a.0), f(c.1) - f(a.1));
    // The centre's side value d × (c − a), and a corner's: that plus dx·oy − dy·ox for an
    // offset o of (±½, ±½), at most `reach` away. Each product, difference and sum is within
    // 2⁻⁵³ of its value, so either is within `error` of the exact value (with room to spare).
    let (p, q) = (dx * ey, dy * ex);
    let centre = p - q;
    let reach = (dx.abs() + dy.abs()) * 0.5;
    let error = (p.abs() + q.abs()) * (3.0 * f64::EPSILON) + reach * (2.0 * f64::EPSILON);
    let sign = |v: f64| if v > 0.0 { 1 } else { -1 };
    if centre.abs() > reach + error {
        return Some([sign(centre); 4]);
    }
    let side = |ox: f64, oy: f64| {
        let v = centre + (dx * oy - dy * ox);
        (v.abs() > error).then(|| sign(v))
    };
    Some([
        side(-0.5, -0.5)?,
        side(0.5, -0.5)?,
        side(0.5, 0.5)?,
        side(-0.5, 0.5)?,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// [`meets_pixel`] by its integer side tests alone (no filter).
    fn meets_pixel_exactly(a: G, b: G, c: G) -> bool {
        let w = |p: G| (2 * p.0 as i128, 2 * p.1 as i128);
        let ((ax, ay), (bx, by), (cx, cy)) = (w(a), w(b), w(c));
        if ax.max(bx) < cx - 1 || ax.min(bx) > cx + 1 || ay.max(by) < cy - 1 || ay.min(by) > cy + 1
        {
            return false;
        }
        let (dx, dy) = (bx - ax, by - ay);
        let side = |px: i128, py: i128| match (dx * (py - ay) - dy * (px - ax)).signum() {
            0 if dy != 0 => dy.signum(),
            0 => -dx.signum(),
            s => s,
        };
        let s = [(-1, -1), (1, -1), (1, 1), (-1, 1)].map(|(x, y)| side(cx + x, cy + y));
        !(s.iter().all(|&v| v > 0) || s.iter().all(|&v| v < 0))
    }

    /// The fragments of `snap` and the pairs of them that its arrangement reports crossing.
    fn crossed(snap: &Snap) -> (Vec<Labelled>, Vec<usize>, Vec<(usize, usize)>) {
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
        let mut snap = Snap::new(segments);
        let pixels = [(5, 2), (5, 1)];
        assert!(
            pixels.iter().all(|c| snap.hot.contains(c)),
            "{:?}",
            snap.hot
        );
        assert!(crossed(&snap).2.is_empty());
        // Without the crossing pixels the fragments cross: the arrangement reports them and
        // `force` adds their pixels until none is left (one may do: the third segment passes
        // through the first crossing's pixel).
        snap.hot.retain(|c| !pixels.contains(c));
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
    fn a_segment_meets_the_pixels_it_passes_through() {
        // Vertical, through the middle of pixel (1, 1), away from the origin.
        assert!(meets_pixel((1, 0), (1, 2), (1, 1)));
        assert!(!meets_pixel((1, 0), (1, 2), (2, 1)));
        // Slanted, through the centre of pixel (5, 2) and clear of pixel (5, 4).
        assert!(meets_pixel((3, 1), (7, 3), (5, 2)));
        assert!(!meets_pixel((3, 1), (7, 3), (5, 4)));
    }

    proptest! {
        /// The `f64` filter never decides against the exact side tests: segments between grid
        /// points up to 2⁵¹ (small ones too), pixels at and around points of the segment, so
        /// that lines through corners and along sides occur.
        #[test]
        fn the_filter_agrees_with_the_exact_pixel_test(
            scale in prop_oneof![Just(4i64), Just(1 << 20), Just(1 << 51)],
            a in (-1.0..1.0, -1.0..1.0f64), b in (-1.0..1.0, -1.0..1.0f64),
            t in 0.0..1.0f64, offset in (-2i64..=2, -2i64..=2),
        ) {
            let grid = |p: (f64, f64)| ((p.0 * scale as f64) as i64, (p.1 * scale as f64) as i64);
            let (a, b) = (grid(a), grid(b));
            let on = |u: i64, v: i64| u + ((v - u) as f64 * t) as i64;
            let c = (on(a.0, b.0) + offset.0, on(a.1, b.1) + offset.1);
            prop_assert_eq!(meets_pixel(a, b, c), meets_pixel_exactly(a, b, c));
        }

        /// The same on lines through a corner of the pixel exactly (the tie the δ-shift
        /// breaks), at coordinates up to 2⁵⁰, where rounding the side values in `f64` could give
        /// the tie either sign: the segment from c + ((1 − dx)/2, (1 − dy)/2) along an odd
        /// (dx, dy) passes through the corner c + (½, ½) halfway.
        #[test]
        fn the_filter_leaves_lines_through_corners_to_the_exact_test(
            c in (-(1i64 << 50)..1 << 50, -(1i64 << 50)..1 << 50),
            d in (-(1i64 << 49)..1 << 49, -(1i64 << 49)..1 << 49),
            flip in any::<bool>(),
        ) {
            let (dx, dy) = (2 * d.0 + 1, 2 * d.1 + 1);
            let a = (c.0 + (1 - dx) / 2, c.1 + (1 - dy) / 2);
            let (a, b) = if flip { ((a.0 + dx, a.1 + dy), a) } else { (a, (a.0 + dx, a.1 + dy)) };
            for k in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let pixel = (c.0 + k.0, c.1 + k.1);
                prop_assert_eq!(meets_pixel(a, b, pixel), meets_pixel_exactly(a, b, pixel));
            }
        }

        /// The hot pixels a segment meets, by the slab scan ([`HotPixels::met_by`] on one
        /// segment's slab of at most 80 pixels: never enough to build the tree) and by the
        /// R-tree search ([`HotPixels::along`]), are exactly the pixels that `meets_pixel`
        /// accepts among all of them (segments through corners and along pixel edges included).
        #[test]
        fn hot_pixels_met_by_a_segment_are_the_pixels_it_meets(
            a in (0i64..12, 0i64..12),
            b in (0i64..12, 0i64..12),
            pixels in proptest::collection::btree_set((0i64..12, 0i64..12), 0..80),
        ) {
            let sorted: Vec<G> = pixels.iter().copied().collect();
            let hot = HotPixels::new(&sorted);
            let want: Vec<G> = pixels.iter().copied().filter(|&c| meets_pixel(a, b, c)).collect();
            let mut found = Vec::new();
            hot.met_by(a, b, &mut found);
            found.sort();
            prop_assert_eq!(&found, &want);
            let mut found: Vec<G> = hot.along(a, b).collect();
            found.sort();
            prop_assert_eq!(found, want);
        }
    }
}
