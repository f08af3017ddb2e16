//! When yin3's stages hand their work to rayon's threads: from a size on, below which handing
//! it over costs more than it saves.

use rayon::prelude::*;

/// Triangles (of both operands, or of a rounded result) from which the meet and the rounding
/// check run on rayon's threads (16 in unit tests, so that they take both ways): handing small
/// work over costs more than it saves.
pub(crate) const PARALLEL_FROM: usize = if cfg!(test) { 16 } else { 8192 };

/// `f` on each of `items`, in order, on rayon's threads if `parallel`.
pub(super) fn map_all<T: Sync, R: Send>(
    items: &[T],
    parallel: bool,
    f: impl Fn(&T) -> R + Sync + Send,
) -> Vec<R> {
    if parallel {
        items.par_iter().map(f).collect()
    } else {
        items.iter().map(f).collect()
    }
}
