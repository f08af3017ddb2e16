//! Winding numbers per operand: the face labels of the arrangement behind the Boolean operations
//! (exact and float mode).

use std::ops::{Add, Sub};

/// Winding numbers of a point with respect to the boundaries of the operands (two at most).
pub(crate) type Winding = [i64; 2];

/// A [`Winding`] with the arithmetic of the arrangement's face windings.
#[derive(Clone, Copy, Default)]
pub(crate) struct Pair(pub(crate) Winding);

impl Pair {
    /// One edge of operand `label` (`0` or `1`): multiplicity 1 there, 0 for the other.
    pub(crate) fn unit(label: usize) -> Pair {
        let mut w = [0; 2];
        w[label] = 1;
        Pair(w)
    }
}

impl Add for Pair {
    type Output = Pair;
    fn add(self, o: Pair) -> Pair {
        Pair([self.0[0] + o.0[0], self.0[1] + o.0[1]])
    }
}

impl Sub for Pair {
    type Output = Pair;
    fn sub(self, o: Pair) -> Pair {
        Pair([self.0[0] - o.0[0], self.0[1] - o.0[1]])
    }
}
