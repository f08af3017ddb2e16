//! Complement (seed 000 Def. 4.4): 𝒥' = S_V⁻¹ ∘ R ∘ S_V (𝒥), in O(n).

use super::paste::{or_kernel_bug, Segmented};
use super::set::{Repr, YinSet2};
use crate::num::Num;

impl<N: Num> YinSet2<N> {
    /// The complement 𝒥' (seed 000 Def. 4.4): 0̂ ↔ 1̂; otherwise reverse every piece and paste.
    /// Every touching point is a vertex, so cutting at all vertices is S_V.
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
