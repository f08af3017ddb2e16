"""yinset: the Boolean algebra of 2D and 3D Yin sets, exact or float.

A Yin set is a regular open subset of the plane or of space with a finite boundary (Zhang & Li).
``Region`` holds a 2D one, ``Solid`` a 3D one. Both are exact by default: every float64
coordinate is read as the rational number it is, and every result is exact. Give ``eps=`` for
float mode (2D: snap rounding to the grid of the tolerance; 3D: exact on the float64 values,
results rounded to float64).

Operators: ``a & b`` (meet), ``a | b`` (join), ``a - b`` (difference), ``a ^ b`` (symmetric
difference), ``~a`` (complement), ``a == b`` (set equality), ``a <= b`` (subset). Measures are
``fractions.Fraction`` in exact mode. Invalid input raises ``YinsetError`` (a ``ValueError``)
with the kernel's message naming the ring, face or vertex at fault. Long operations release
the GIL.

>>> import numpy as np, yinset
>>> a = yinset.Region([np.array([[0, 0], [2, 0], [2, 2], [0, 2]])])
>>> b = yinset.Region([np.array([[1, 1], [3, 1], [3, 3], [1, 3]])])
>>> (a | b).area
Fraction(7, 1)
"""

from ._yinset import INSIDE, ON_BOUNDARY, OUTSIDE, YinsetError
from .region import Region
from .solid import Solid

__all__ = ["Region", "Solid", "YinsetError", "INSIDE", "ON_BOUNDARY", "OUTSIDE"]
