//! `yinset._yinset`: the native half of the Python package — the kernel's 2D and 3D Yin sets,
//! exact (every `f64` read as the rational it is) or float (a tolerance ε), behind two classes
//! whose arrays cross as little-endian bytes (the Python half turns them into numpy arrays).

mod bytes;
mod mode;
mod region;
mod solid;

use pyo3::prelude::*;

/// The allocator of everything the kernel allocates (see Cargo.toml).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

pyo3::create_exception!(
    _yinset,
    YinsetError,
    pyo3::exceptions::PyValueError,
    "Invalid input to yinset (the kernel's message says what and where), or an operation \
     float mode cannot represent."
);

/// A kernel error as a `YinsetError` with its message.
pub(crate) fn error(e: impl std::fmt::Display) -> PyErr {
    YinsetError::new_err(e.to_string())
}

/// The module: the two set classes, the error, and the codes of `locate`.
#[pymodule]
fn _yinset(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<region::Region2>()?;
    m.add_class::<solid::Solid3>()?;
    m.add("YinsetError", m.py().get_type::<YinsetError>())?;
    m.add("INSIDE", bytes::INSIDE)?;
    m.add("ON_BOUNDARY", bytes::ON_BOUNDARY)?;
    m.add("OUTSIDE", bytes::OUTSIDE)?;
    Ok(())
}
