//! Rational rotations of space, for putting test shapes and cell grids in general position:
//! integer matrices over a common denominator, so that lattice points go to exact rationals.

use crate::{q, P3};
use yinset::kernel::Point3;
use yinset::num::Rational;

/// The unit quaternion (4 + i + 2j + 3k)/√30 of [`Rot::Quaternion`] used for general
/// position: about the oblique axis (1, 2, 3) with cos θ = 1/15. Every entry of its matrix is
/// non-zero (4, −20, 22; 28, 10, 4; −10, 20, 20, over 30), so no face, edge or normal of a
/// rotated box is parallel to a coordinate plane or axis.
pub const GENERAL: [i64; 4] = [4, 1, 2, 3];

/// A rotation by a rational orthogonal matrix, or none.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Rot {
    /// The identity.
    None,
    /// About the z axis by the angle with cos = 3/5, sin = 4/5.
    Z,
    /// About an oblique axis: the rotation about z above, then about the x axis by the angle
    /// with cos = 12/13, sin = 5/13.
    Oblique,
    /// By the unit quaternion (a + bi + cj + dk)/√n, n = a² + b² + c² + d², whose rotation
    /// matrix is rational (entries over n).
    Quaternion([i64; 4]),
}

impl Rot {
    /// The matrix, as integer entries over a common denominator.
    fn matrix(self) -> ([[i64; 3]; 3], i64) {
        match self {
            Rot::None => ([[1, 0, 0], [0, 1, 0], [0, 0, 1]], 1),
            Rot::Z => ([[3, -4, 0], [4, 3, 0], [0, 0, 5]], 5),
            // Rx · Rz with Rx = [[13,0,0],[0,12,-5],[0,5,12]]/13, Rz = [[3,-4,0],[4,3,0],[0,0,5]]/5.
            Rot::Oblique => ([[39, -52, 0], [48, 36, -25], [20, 15, 60]], 65),
            Rot::Quaternion([a, b, c, d]) => (
                [
                    [
                        a * a + b * b - c * c - d * d,
                        2 * (b * c - a * d),
                        2 * (b * d + a * c),
                    ],
                    [
                        2 * (b * c + a * d),
                        a * a - b * b + c * c - d * d,
                        2 * (c * d - a * b),
                    ],
                    [
                        2 * (b * d - a * c),
                        2 * (c * d + a * b),
                        a * a - b * b - c * c + d * d,
                    ],
                ],
                a * a + b * b + c * c + d * d,
            ),
        }
    }

    /// The matrix's entries as exact rationals (row-major).
    pub fn entries(self) -> [[Rational; 3]; 3] {
        let (m, d) = self.matrix();
        m.map(|row| row.map(|v| q(v, d)))
    }

    /// The image of the point `p / den` under the rotation about the centre `c / den`.
    pub fn apply(self, p: [i64; 3], c: [i64; 3], den: i64) -> P3 {
        let (m, d) = self.matrix();
        let v = [0, 1, 2].map(|k| p[k] - c[k]);
        let r = [0, 1, 2].map(|i| {
            let s: i64 = (0..3).map(|j| m[i][j] * v[j]).sum();
            q(s + d * c[i], d * den)
        });
        let [x, y, z] = r;
        Point3::new(x, y, z)
    }

    /// How a shape is turned, for names: empty for the identity.
    pub fn describe(self) -> String {
        match self {
            Rot::None => String::new(),
            Rot::Quaternion([a, b, c, d]) => format!(
                "rotated by ({a} + {b}i + {c}j + {d}k)/√{}",
                a * a + b * b + c * c + d * d
            ),
            r => format!("turned by {r:?}"),
        }
    }
}
