//! Moving Yin sets between float and exact mode (for checking float results exactly).

use super::error::YinError;
use super::set::YinSet2;
use crate::kernel::Point;
use crate::num::{Float, Num, Rational, Tolerance};

impl YinSet2<Float> {
    /// The same curves read as exact rationals (every `f64` is a rational), validated exactly.
    pub fn to_exact(&self) -> Result<YinSet2<Rational>, YinError> {
        convert(self, ())
    }
}

impl YinSet2<Rational> {
    /// The set in float mode with tolerance `tol`: coordinates rounded to `f64`, then snapped to
    /// the ε-grid and regularized (seed 000 §5.2).
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
