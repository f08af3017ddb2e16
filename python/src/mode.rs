//! Exact or float mode: a set of one or the other backend, chosen by `eps` when built, and the
//! rule that binary operations take two sets of the same mode.

use crate::error;
use pyo3::{PyErr, PyResult};
use yinset::num::Tolerance;

/// `$body` on the value `$s` of the `Modal` `$set`, whatever its mode.
macro_rules! on {
    ($set:expr, $s:ident => $body:expr) => {
        match $set {
            $crate::mode::Modal::Exact($s) => $body,
            $crate::mode::Modal::Float($s) => $body,
        }
    };
}
pub(crate) use on;

/// The value `$body` computed from the value `$s` of the `Modal` `$set`, in the same mode.
macro_rules! map {
    ($set:expr, $s:ident => $body:expr) => {
        match $set {
            $crate::mode::Modal::Exact($s) => $crate::mode::Modal::Exact($body),
            $crate::mode::Modal::Float($s) => $crate::mode::Modal::Float($body),
        }
    };
}
pub(crate) use map;

/// A value in exact mode (`E`: rationals) or float mode (`F`: `f64` with a tolerance).
#[derive(Clone)]
pub enum Modal<E, F> {
    /// Exact rationals.
    Exact(E),
    /// Float mode.
    Float(F),
}

/// The float tolerance `eps` asks for (None: exact mode).
fn float_mode(eps: Option<f64>) -> PyResult<Option<Tolerance>> {
    match eps {
        None => Ok(None),
        Some(e) if e.is_finite() && e > 0.0 => Ok(Some(Tolerance::new(e))),
        Some(e) => Err(error(format!(
            "eps = {e}: the tolerance must be finite and positive"
        ))),
    }
}

/// The error of an operation on an exact and a float set.
pub fn mixed_modes() -> PyErr {
    error("the operands mix exact and float mode: build both with eps or both without")
}

impl<E, F> Modal<E, F> {
    /// `exact()` if `eps` is None, else `float(ε)`.
    pub fn new_in(
        eps: Option<f64>,
        exact: impl FnOnce() -> PyResult<E>,
        float: impl FnOnce(Tolerance) -> PyResult<F>,
    ) -> PyResult<Modal<E, F>> {
        Ok(match float_mode(eps)? {
            None => Modal::Exact(exact()?),
            Some(t) => Modal::Float(float(t)?),
        })
    }

    /// `exact(a, b)` or `float(a, b)` of two values of the same mode (else an error).
    pub fn pair<R, S>(
        &self,
        other: &Modal<E, F>,
        exact: impl FnOnce(&E, &E) -> PyResult<R>,
        float: impl FnOnce(&F, &F) -> PyResult<S>,
    ) -> PyResult<Modal<R, S>> {
        match (self, other) {
            (Modal::Exact(a), Modal::Exact(b)) => Ok(Modal::Exact(exact(a, b)?)),
            (Modal::Float(a), Modal::Float(b)) => Ok(Modal::Float(float(a, b)?)),
            _ => Err(mixed_modes()),
        }
    }

    /// The exact value, if in exact mode.
    pub fn exact(&self) -> Option<&E> {
        match self {
            Modal::Exact(e) => Some(e),
            Modal::Float(_) => None,
        }
    }

    /// The float value, if in float mode.
    pub fn float(&self) -> Option<&F> {
        match self {
            Modal::Exact(_) => None,
            Modal::Float(f) => Some(f),
        }
    }
}

impl<T> Modal<T, T> {
    /// The value, whatever its mode.
    pub fn value(self) -> T {
        match self {
            Modal::Exact(v) | Modal::Float(v) => v,
        }
    }
}

/// The values `pick` finds in `items`, which must all be in the mode `pick` asks for.
pub fn all_in<'a, M: 'a, T: Clone + 'a>(
    items: impl IntoIterator<Item = &'a M>,
    pick: impl Fn(&'a M) -> Option<&'a T>,
) -> PyResult<Vec<T>> {
    items
        .into_iter()
        .map(|m| pick(m).cloned().ok_or_else(mixed_modes))
        .collect()
}
