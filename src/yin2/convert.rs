//! Moving Yin sets between float and exact mode (for checking float results exactly).

use super::error::YinError;
use super::set::YinSet2;
use crate::kernel::Point;
use crate::num::{Float, Num, Rational, Tolerance};

impl YinSet2<Float> {
    /// The same curves read as exact rationals (every `f64` is a rational), validated exactly.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Float, Num, Rational, Tolerance}, yin2::YinSet2};
    /// let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
    /// let a = YinSet2::from_curves_with(vec![vec![p(0.0, 0.0), p(0.5, 0.0), p(0.5, 0.5), p(0.0, 0.5)]], Tolerance::new(1e-9))?;
    /// let e = a.to_exact()?;
    /// assert_eq!(e.area(), Some(Rational::parse("1/4").unwrap()));
    /// # Ok::<(), yinset::yin2::YinError>(())
    /// ```
    pub fn to_exact(&self) -> Result<YinSet2<Rational>, YinError> {
        convert(self, ())
    }
}

impl YinSet2<Rational> {
    /// The set in float mode with tolerance `tol`: coordinates rounded to `f64`, then snapped to
    /// the ε-grid and regularized (seed 000 §5.2).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// use yinset::num::Tolerance;
    /// let f = sq(0, 0, 2).to_float(Tolerance::new(1e-9))?;
    /// assert_eq!(f.area().unwrap().get(), 4.0);
    /// assert_eq!(f.to_exact()?, sq(0, 0, 2));
    /// # Ok::<(), yinset::yin2::YinError>(())
    /// ```
    pub fn to_float(&self, tol: Tolerance) -> Result<YinSet2<Float>, YinError> {
        convert(self, tol)
    }
}

/// Rebuild `y`'s curves in another number type through the validating constructor.
fn convert<N: Num, M: Num>(y: &YinSet2<N>, ctx: M::Ctx) -> Result<YinSet2<M>, YinError> {
    if y.is_empty() || y.is_full() {
        let out = if y.is_empty() {
            YinSet2::empty()
        } else {
            YinSet2::full()
        };
        return Ok(out.with_ctx(ctx));
    }
    let num = |v: &N| M::from_f64(v.to_f64()).map_err(|_| YinError::NotCanonical);
    let curves = y
        .curves()
        .iter()
        .map(|c| {
            c.vertices()
                .iter()
                .map(|p| Ok(Point::new(num(&p.x)?, num(&p.y)?)))
                .collect::<Result<Vec<_>, YinError>>()
        })
        .collect::<Result<Vec<_>, YinError>>()?;
    YinSet2::from_curves_with(curves, ctx)
}
