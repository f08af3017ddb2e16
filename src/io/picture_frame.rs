//! The pictures' own coordinates (SVG, and the PNG and HTML pictures of 3D sets): a point's
//! offset from the lower corner of the drawn sets' bounding box, divided by the box's larger
//! side, computed in the sets' number type and only then rounded to `f64`. So a set is drawn
//! alike at any position and scale — coordinates near 10⁴⁰⁰ or 10⁻⁴⁰⁰ included, which have no
//! `f64` — and every number a picture holds is finite, within [0, 1].

use crate::num::Num;
use std::cmp::Ordering;

/// The map from world coordinates to picture coordinates of one picture.
pub(crate) struct PictureFrame<N> {
    /// The lower corner of the box, per axis.
    origin: Vec<N>,
    /// The box's larger side (1 if the box is a point); halved where `halved`.
    side: N,
    /// Whether offsets are taken between halves (in float mode, where a box wider than the
    /// range of `f64` would overflow).
    halved: bool,
}

impl<N: Num> PictureFrame<N> {
    /// The frame of the box around `boxes` (each its lower and upper corner, per axis), or of
    /// the unit box at the origin if there are none.
    pub fn around(boxes: impl IntoIterator<Item = (Vec<N>, Vec<N>)>) -> PictureFrame<N> {
        let hull = |(a, b): (Vec<N>, Vec<N>), (c, d): (Vec<N>, Vec<N>)| {
            let min = a.into_iter().zip(c).map(|(x, y)| x.min(y)).collect();
            let max = b.into_iter().zip(d).map(|(x, y)| x.max(y)).collect();
            (min, max)
        };
        let Some((min, max)) = boxes.into_iter().reduce(hull) else {
            return PictureFrame {
                origin: Vec::new(),
                side: N::from_i64(1),
                halved: false,
            };
        };
        let sides = || min.iter().zip(&max).map(|(a, b)| b.clone() - a.clone());
        let side = sides().max().unwrap_or_else(N::zero);
        let (side, halved) = if side.is_finite() {
            (side, false)
        } else {
            let halves = min.iter().zip(&max).map(|(a, b)| b.half() - a.half());
            (halves.max().unwrap_or_else(N::zero), true)
        };
        let side = match side.sign() {
            Ordering::Greater => side,
            _ => N::from_i64(1),
        };
        PictureFrame {
            origin: min,
            side,
            halved,
        }
    }

    /// Coordinate `n` of `axis` in the picture: its offset from the box's lower corner over
    /// the box's larger side, rounded to `f64` once.
    pub fn coordinate(&self, axis: usize, n: &N) -> f64 {
        let zero = N::zero();
        let origin = self.origin.get(axis).unwrap_or(&zero);
        let offset = if self.halved {
            n.half() - origin.half()
        } else {
            n.clone() - origin.clone()
        };
        (offset / self.side.clone()).to_f64()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational};

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    #[test]
    fn boxes_beyond_f64_map_to_the_unit_box_exactly() {
        for (lo, side) in [("1e400", "1e400"), ("-3e-400", "1e-400"), ("0", "7")] {
            let min = vec![q(lo), q(lo)];
            let max = vec![q(lo) + q(side), q(lo) + q(side).half()];
            let inside = (vec![q(lo), q(lo)], vec![q(lo) + q(side).half(); 2]);
            let frame = PictureFrame::around([inside, (min.clone(), max.clone())]);
            assert_eq!(frame.coordinate(0, &min[0]), 0.0);
            assert_eq!(frame.coordinate(0, &max[0]), 1.0);
            assert_eq!(frame.coordinate(1, &max[1]), 0.5);
            let quarter = q(lo) + q(side) / Rational::from_i64(4);
            assert_eq!(frame.coordinate(1, &quarter), 0.25);
        }
    }

    #[test]
    fn float_boxes_wider_than_f64_do_not_overflow() {
        // The box [−2¹⁰²³, 2¹⁰²³] × [−2¹⁰²³, 0]: its side 2¹⁰²⁴ is no f64.
        let (a, b) = (Float::new(-(2f64.powi(1023))), Float::new(2f64.powi(1023)));
        let frame = PictureFrame::around([(vec![a, a], vec![b, Float::new(0.0)])]);
        assert_eq!(frame.coordinate(0, &a), 0.0);
        assert_eq!(frame.coordinate(0, &b), 1.0);
        assert_eq!(frame.coordinate(1, &Float::new(0.0)), 0.5);
    }

    #[test]
    fn no_box_is_the_unit_box_at_the_origin() {
        let frame = PictureFrame::<Rational>::around([]);
        assert_eq!(frame.coordinate(2, &q("1/2")), 0.5);
    }
}
