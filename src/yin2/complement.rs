//! Complement (seed 000 Def. 4.4): 𝒥' = S_V⁻¹ ∘ R ∘ S_V (𝒥), in O(n).

use super::paste::{or_kernel_bug, Segmented};
use super::set::{Repr, YinSet2};
use crate::num::Num;

impl<N: Num> YinSet2<N> {
    /// The complement 𝒥' (seed 000 Def. 4.4): 0̂ ↔ 1̂; otherwise reverse every piece and paste.
    /// Every touching point is a vertex, so cutting at all vertices is S_V.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// use yinset::yin2::Location;
    /// let a = sq(0, 0, 2);
    /// let out = a.complement(); // also `!&a`
    /// assert!(!out.is_bounded());
    /// assert_eq!(out.locate(&[Point::int(9, 9)]), vec![Location::Inside]);
    /// assert_eq!(out.complement(), a);
    /// assert_eq!(a.meet(&out), YinSet2::empty());
    /// ```
    pub fn complement(&self) -> YinSet2<N> {
        let s = match &self.repr {
            Repr::Empty => return YinSet2::full().with_ctx(self.ctx),
            Repr::Full => return YinSet2::empty().with_ctx(self.ctx),
            Repr::Spadjor(s) => s,
        };
        let mut g = Segmented::new();
        for c in &s.curves {
            let ids: Vec<usize> = c.vertices().iter().map(|p| g.id(p)).collect();
            for k in 0..ids.len() {
                g.push(ids[(k + 1) % ids.len()], ids[k]);
            }
        }
        // Reversal keeps the curves' vertices, so pasting needs no snapping even in float mode.
        or_kernel_bug(g.paste_exact(N::Ctx::default())).with_ctx(self.ctx)
    }
}
