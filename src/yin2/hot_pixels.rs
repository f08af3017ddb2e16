//! The hot pixels of float mode's snap rounding and the ones a segment meets (Hobby 1999): a
//! segment meets a pixel when it meets its half-open unit square ([`meets_pixel`]). A segment
//! whose slab (its x-range) holds few pixels scans them; one whose slab is crowded walks a
//! uniform grid of cells column by column and looks only at the pixels of the cells along it.

use super::buckets::Buckets;
use super::grid_arrange::G;
use std::cell::OnceCell;

/// The hot pixels, sorted by x, for finding the ones a segment meets: by scanning its slab
/// where that holds at most [`SLAB_SCAN`] pixels, else along the cells of a [`CellGrid`],
/// built on first need.
pub(crate) struct HotPixels<'a> {
    sorted: &'a [G],
    grid: OnceCell<CellGrid>,
}

/// The most hot pixels a slab may hold for it to be scanned (8 in unit tests, so that both
/// ways are taken).
const SLAB_SCAN: usize = if cfg!(test) { 8 } else { 128 };

impl<'a> HotPixels<'a> {
    /// The pixels `sorted` (pairwise distinct, in the order of `G`: by x, then y; at most 2⁵¹
    /// from 0).
    pub(crate) fn new(sorted: &'a [G]) -> HotPixels<'a> {
        HotPixels {
            sorted,
            grid: OnceCell::new(),
        }
    }

    /// Appends to `out` the hot pixels other than its ends that the segment `ab` meets
    /// ([`meets_pixel`]), as indices of the sorted pixels; `ends` are the indices of `a` and `b`.
    pub(crate) fn met_by(&self, (a, b): (G, G), ends: (usize, usize), out: &mut Vec<usize>) {
        // A pixel met by the segment has its centre within the segment's box (both on the grid):
        // its x-slab runs from the lower end's index down to the first pixel of its x, and from
        // the upper end's index up to the last pixel of its x.
        let sorted = self.sorted;
        let (lower, upper) = (ends.0.min(ends.1), ends.0.max(ends.1));
        let (x0, x1) = (sorted[lower].0, sorted[upper].0);
        let from = gallop(lower + 1, |k| sorted[lower - k].0 < x0).map_or(0, |k| lower - k + 1);
        let to = gallop(sorted.len() - upper, |k| sorted[upper + k].0 > x1)
            .map_or(sorted.len(), |k| upper + k);
        let own = |k: usize| k == ends.0 || k == ends.1;
        if to - from <= SLAB_SCAN {
            let (lo, hi) = (a.1.min(b.1), a.1.max(b.1));
            let meets = |&k: &usize| {
                let c = sorted[k];
                (lo..=hi).contains(&c.1) && !own(k) && meets_pixel(a, b, c)
            };
            out.extend((from..to).filter(meets));
        } else {
            let grid = self.grid.get_or_init(|| CellGrid::new(sorted));
            grid.met_by(sorted, (a, b), |k| !own(k), out);
        }
    }
}

/// The least `k` in `1..n` with `past(k)`, where `past` is monotone (false, then true), by
/// doubling steps and then bisecting: O(log k) calls; `None` if there is none.
fn gallop(n: usize, past: impl Fn(usize) -> bool) -> Option<usize> {
    let mut step = 1;
    while step < n && !past(step) {
        step *= 2;
    }
    // Every k up to step / 2 is not past; step is, unless it reached n.
    let (mut lo, mut hi) = (step / 2 + 1, step.min(n));
    while lo < hi {
        let mid = (lo + hi) / 2;
        if past(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    (lo < n).then_some(lo)
}

/// Pixels in a uniform grid of square cells of side 2^`shift` grid units from `origin` (the
/// pixels' lowest corner), about one pixel a cell, stored cell by cell (column after column,
/// each from the bottom) as indices of the sorted pixels.
struct CellGrid {
    origin: G,
    shift: u32,
    columns: usize,
    rows: usize,
    /// The pixels of each cell.
    pixels: Buckets,
}

impl CellGrid {
    /// The grid of the pixels `hot` (at least one).
    fn new(hot: &[G]) -> CellGrid {
        let lo = hot
            .iter()
            .fold((i64::MAX, i64::MAX), |m, c| (m.0.min(c.0), m.1.min(c.1)));
        let hi = hot
            .iter()
            .fold((i64::MIN, i64::MIN), |m, c| (m.0.max(c.0), m.1.max(c.1)));
        let (width, height) = ((hi.0 - lo.0) as f64 + 1.0, (hi.1 - lo.1) as f64 + 1.0);
        // Cells of about the area per pixel, a power of two on a side.
        let side = (width * height / hot.len() as f64).sqrt().max(1.0);
        let shift = (side.log2().floor() as u32).min(62);
        let count = |extent: i64| (extent >> shift) as usize + 1;
        let (columns, rows) = (count(hi.0 - lo.0), count(hi.1 - lo.1));
        let mut grid = CellGrid {
            origin: lo,
            shift,
            columns,
            rows,
            pixels: Buckets::new(0, std::iter::empty()),
        };
        let cells = hot.iter().enumerate().map(|(i, &c)| (grid.cell(c), i));
        grid.pixels = Buckets::new(columns * rows, cells);
        grid
    }

    /// The cell of pixel `c`.
    fn cell(&self, c: G) -> usize {
        self.column_of(c.0) * self.rows + self.row_of(c.1)
    }

    /// The column of cells holding x (clamped to the grid).
    fn column_of(&self, x: i64) -> usize {
        (((x - self.origin.0).max(0) >> self.shift) as usize).min(self.columns - 1)
    }

    /// The row of cells holding y (clamped to the grid).
    fn row_of(&self, y: i64) -> usize {
        (((y - self.origin.1).max(0) >> self.shift) as usize).min(self.rows - 1)
    }

    /// Appends to `out` the pixels (indices of `sorted`, the pixels the grid was built on) that
    /// the segment `ab` meets ([`meets_pixel`]) and `keep` accepts: those of the cells that the
    /// segment's pixels can lie in, column by column.
    fn met_by(
        &self,
        sorted: &[G],
        (a, b): (G, G),
        keep: impl Fn(usize) -> bool,
        out: &mut Vec<usize>,
    ) {
        // A pixel met by the segment has its centre within the segment's box (both on the grid)
        // and within ½ of a point of the segment in each coordinate.
        let (x0, x1) = (a.0.min(b.0), a.0.max(b.0));
        let (y0, y1) = (a.1.min(b.1), a.1.max(b.1));
        let (first, last) = (self.column_of(x0), self.column_of(x1));
        let slope = (b.1 - a.1) as f64 / (b.0 - a.0) as f64;
        for column in first..=last {
            let (mut lo, mut hi) = (y0, y1);
            if first < last {
                // Centres in the column are within ½ of points of the segment over its x-range
                // widened by one (within the segment's), whose y lie between the integers
                // around the ends' y; a centre within ½ of a y lies between them too.
                let left = self.origin.0 + ((column as i64) << self.shift);
                let right = left + (1 << self.shift) - 1;
                let (from, to) = ((left - 1).max(x0), (right + 1).min(x1));
                let (u, v) = (y_near(a, slope, from), y_near(a, slope, to));
                lo = lo.max(u.0.min(v.0));
                hi = hi.min(u.1.max(v.1));
            }
            if lo > hi {
                continue;
            }
            let cells = column * self.rows + self.row_of(lo)..=column * self.rows + self.row_of(hi);
            let pixels = self.pixels.range(cells);
            out.extend(pixels.iter().filter(|&&k| {
                let c = sorted[k];
                (x0..=x1).contains(&c.0)
                    && (lo..=hi).contains(&c.1)
                    && keep(k)
                    && meets_pixel(a, b, c)
            }));
        }
    }
}

/// Integers at or below and at or above the y of the line through `a` with slope `slope`
/// (not vertical) at `x`: its `f64` value, within 2⁻⁵⁰ of the magnitudes involved
/// (coordinates below 2⁵²), widened by that and rounded outwards.
fn y_near(a: G, slope: f64, x: i64) -> (i64, i64) {
    let rise = (x - a.0) as f64 * slope;
    let y = a.1 as f64 + rise;
    let error = (rise.abs() + (a.1 as f64).abs()) * (4.0 * f64::EPSILON);
    ((y - error).floor() as i64, (y + error).ceil() as i64)
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
        let (x0, x1, y0, y1) = (a.0.min(b.0), a.0.max(b.0), a.1.min(b.1), a.1.max(b.1));
        let near = |v: i64, lo: i64, hi: i64| 2 * lo <= 2 * v + 1 && 2 * v - 1 <= 2 * hi;
        near(c.0, x0, x1) && near(c.1, y0, y1) && !all_on_one_side(&exact_corner_sides(a, b, c))
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

    /// A segment whose line runs through the middle of a pixel's square, but which ends before
    /// the square in x or in y, does not meet the pixel: the squares of pixels (5, 0) and
    /// (−3, 0) span x in [4.5, 5.5) and [−3.5, −2.5), beyond the segment's x-range [0, 2];
    /// likewise in y for the vertical segment.
    #[test]
    fn a_segment_ending_before_a_pixel_on_its_line_misses_it() {
        assert!(!meets_pixel((0, 0), (2, 0), (5, 0)));
        assert!(!meets_pixel((0, 0), (2, 0), (-3, 0)));
        assert!(!meets_pixel((0, 0), (0, 2), (0, 5)));
        assert!(!meets_pixel((0, 0), (0, 2), (0, -3)));
    }

    /// `gallop` returns the least k in 1..n with `past(k)` wherever it lies (at a doubling
    /// step or between two), and `None` where no k below n is past: `past` true from `first`
    /// on, so the answer is `first` when `first < n`.
    #[test]
    fn gallop_finds_the_least_index_past() {
        for n in 1..20 {
            for first in 1..=n {
                let want = (first < n).then_some(first);
                assert_eq!(gallop(n, |k| k >= first), want, "n = {n}, first = {first}");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
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

        /// The hot pixels a segment meets, found by scanning its slab or by walking the grid,
        /// are exactly the pixels other than its ends that `meets_pixel` accepts: segments
        /// through corners and along pixel sides, vertical and horizontal, among pixels in
        /// columns (the slab's ends found by galloping past pixels of the ends' x, a column
        /// below the lower end among them); from one pixel to hundreds (cells of one unit to
        /// many), at small coordinates and far from 0 (spread by up to 2³⁰ and shifted by up
        /// to 2⁴⁸).
        #[test]
        fn hot_pixels_met_by_a_segment_are_the_pixels_it_meets(
            a in (-2i64..40, -2i64..40),
            b in (-2i64..40, -2i64..40),
            pixels in proptest::collection::btree_set((0i64..38, 0i64..38), 0..300),
            spread in prop_oneof![Just(1i64), Just(3), Just(1 << 30)],
            shift in prop_oneof![Just(0i64), Just(-(1i64 << 48)), Just(1i64 << 48)],
            columns in any::<bool>(),
            sparse in any::<bool>(),
        ) {
            let far = |p: G| (p.0 * spread + shift, p.1 * spread - shift);
            // Pixels right below the lower end, before it in the order of `G`: a steep segment
            // down from it meets several.
            let lower = a.min(b);
            let below = (1..=4).map(|d| (lower.0, lower.1 - d));
            let columns = columns.then_some(below).into_iter().flatten();
            // Few pixels (slabs that are scanned) as often as many.
            let few = if sparse { 6 } else { pixels.len() };
            let pixels = pixels.iter().copied().take(few).chain(columns);
            let (a, b) = (far(a), far(b));
            let mut sorted: Vec<G> = pixels.map(far).collect();
            sorted.extend([a, b]);
            sorted.sort();
            sorted.dedup();
            let hot = HotPixels::new(&sorted);
            let met = |c: &G| *c != a && *c != b && meets_pixel(a, b, *c);
            let want: Vec<G> = sorted.iter().copied().filter(met).collect();
            let index = |g: G| sorted.binary_search(&g).unwrap();
            let mut found = Vec::new();
            hot.met_by((a, b), (index(a), index(b)), &mut found);
            let mut found: Vec<G> = found.into_iter().map(|k| sorted[k]).collect();
            found.sort();
            prop_assert_eq!(found, want);
        }
    }
}
