"""Arrays to and from the native module's little-endian bytes, with shape checks."""

from fractions import Fraction

import numpy as np

from ._yinset import YinsetError


def points(array, width, what):
    """The C-contiguous little-endian float64 copy of an (n, width) array-like ``what``."""
    a = np.asarray(array, dtype="<f8")
    if a.ndim != 2 or a.shape[1] != width:
        raise YinsetError(f"{what} has shape {a.shape}, not (n, {width})")
    return np.ascontiguousarray(a)


def located(codes):
    """The int8 array of location codes the native module returned as bytes."""
    return np.frombuffer(codes, dtype=np.int8).copy()


def coordinates(data, width):
    """The (n, width) float64 array of little-endian bytes ``data``."""
    return np.frombuffer(data, dtype="<f8").reshape(-1, width).copy()


def measure(m):
    """A native measure as Python's: a Fraction from exact texts, a float, or None."""
    if isinstance(m, tuple):
        return Fraction(int(m[0]), int(m[1]))
    return m
