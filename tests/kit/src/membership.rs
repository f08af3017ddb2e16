//! The point-membership oracle: at a point off the boundaries of both operands a and b, the
//! location in a op b is the Boolean combination op of the locations in a and b, and never on
//! the boundary. It needs nothing but the kernel's point location on each set, so it serves
//! exact and float mode alike.

use yinset::yin2::Location;

/// A Boolean operation's truth table: whether a point is in the result, given whether it is in
/// a and in b.
pub type Truth = fn(bool, bool) -> bool;

/// a ∧ b.
pub const MEET: Truth = |p, q| p && q;
/// a ∨ b.
pub const JOIN: Truth = |p, q| p || q;
/// a ∖ b.
pub const DIFFERENCE: Truth = |p, q| p && !q;
/// a ⊕ b.
pub const SYMMETRIC_DIFFERENCE: Truth = |p, q| p != q;
/// a'.
pub const COMPLEMENT_A: Truth = |p, _| !p;
/// b'.
pub const COMPLEMENT_B: Truth = |_, q| !q;

/// The location a result of `f` must have at a point located at `a` and `b` in the operands:
/// `None` (no expectation) if it is on either operand's boundary.
pub fn expected(a: Location, b: Location, f: Truth) -> Option<Location> {
    if a == Location::OnBoundary || b == Location::OnBoundary {
        return None;
    }
    Some(if f(a == Location::Inside, b == Location::Inside) {
        Location::Inside
    } else {
        Location::Outside
    })
}

/// Every point the oracle judges, as (index, location in the result, location expected): the
/// points off both operands' boundaries, given the locations `la`, `lb` in the operands and
/// `lr` in the result of `f`.
pub fn judged<'a>(
    la: &'a [Location],
    lb: &'a [Location],
    lr: &'a [Location],
    f: Truth,
) -> impl Iterator<Item = (usize, Location, Location)> + 'a {
    (0..lr.len()).filter_map(move |k| expected(la[k], lb[k], f).map(|want| (k, lr[k], want)))
}

/// The first point where the result's location is not the one expected, as [`judged`] gives
/// it; `None` if the oracle holds.
pub fn first_failure(
    la: &[Location],
    lb: &[Location],
    lr: &[Location],
    f: Truth,
) -> Option<(usize, Location, Location)> {
    judged(la, lb, lr, f).find(|(_, got, want)| got != want)
}
