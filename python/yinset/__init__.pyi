"""Type stubs of yinset: 2D regions and 3D solids, exact by default or float with ``eps``."""

import os
from fractions import Fraction
from typing import Iterable, List, Optional, Sequence, Tuple, TypeVar, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Measure = Union[Fraction, float]

INSIDE: int
"""Location code of a point in the set (1)."""
ON_BOUNDARY: int
"""Location code of a point on the boundary (0)."""
OUTSIDE: int
"""Location code of a point outside the closure (-1)."""

class YinsetError(ValueError):
    """Invalid input (the kernel's message names the ring, face or vertex), or an operation
    float mode cannot represent."""

_T = TypeVar("_T", bound="_Algebra")

class _Algebra:
    """The Boolean algebra of Region and Solid (yinset._algebra.Algebra)."""

    @property
    def exact(self) -> bool:
        """True in exact mode."""
    @property
    def bounded(self) -> bool:
        """True if the closure is compact."""
    def __and__(self: _T, other: _T) -> _T:
        """A ∧ B."""
    def __or__(self: _T, other: _T) -> _T:
        """A ∨ B."""
    def __sub__(self: _T, other: _T) -> _T:
        """A ∧ B′."""
    def __xor__(self: _T, other: _T) -> _T:
        """(A ∧ B′) ∨ (A′ ∧ B)."""
    def __invert__(self: _T) -> _T:
        """A′."""
    def __eq__(self, other: object) -> bool:
        """Set equality."""
    def __bool__(self) -> bool:
        """False for the empty set."""
    def validate(self) -> None:
        """Raise YinsetError if the boundary is invalid."""

class Region(_Algebra):
    """A 2D Yin set: exact by default, float mode with ``eps``."""

    def __init__(
        self,
        rings: Union[ArrayLike, Iterable[ArrayLike]] = (),
        *,
        eps: Optional[float] = None,
        fill: Optional[str] = None,
    ) -> None:
        """The region bounded by ``rings`` ((n, 2) arrays), or covered by them under ``fill``
        ("nonzero" or "evenodd")."""
    @classmethod
    def from_wkt(cls, text: str, *, eps: Optional[float] = None, fill: Optional[str] = None) -> "Region":
        """The region of a WKT (Multi)Polygon."""
    @classmethod
    def from_wkb(
        cls, data: Union[bytes, str], *, eps: Optional[float] = None, fill: Optional[str] = None
    ) -> "Region":
        """The region of a WKB (Multi)Polygon, raw or hex."""
    @classmethod
    def from_geojson(cls, text: str, *, eps: Optional[float] = None, fill: Optional[str] = None) -> "Region":
        """The region of a GeoJSON polygonal geometry, Feature or FeatureCollection."""
    @classmethod
    def from_yin2(cls, text: str, *, eps: Optional[float] = None) -> "Region":
        """The region of a yin2 curve list."""
    @classmethod
    def from_shapely(cls, geometry: object, *, eps: Optional[float] = None, fill: Optional[str] = None) -> "Region":
        """The region of a shapely Polygon or MultiPolygon."""
    @classmethod
    def empty(cls, *, eps: Optional[float] = None) -> "Region":
        """The empty region."""
    @classmethod
    def full(cls, *, eps: Optional[float] = None) -> "Region":
        """The whole plane."""
    @property
    def eps(self) -> Optional[float]:
        """The tolerance in float mode."""
    def __le__(self, other: "Region") -> bool:
        """Subset."""
    def __hash__(self) -> int:
        """A hash consistent with set equality."""
    def meet_each(self, cells: Sequence["Region"]) -> List["Region"]:
        """[A ∧ C for C in cells], in parallel."""
    @property
    def area(self) -> Optional[Measure]:
        """Fraction in exact mode, float in float mode, None if unbounded."""
    @property
    def betti(self) -> Tuple[int, int]:
        """(components, holes)."""
    @property
    def homology(self) -> Tuple[int, int]:
        """Homological (b0, b1)."""
    def locate(self, points: ArrayLike) -> "np.ndarray":
        """int8 location codes of an (n, 2) array."""
    def curves(self) -> List["np.ndarray"]:
        """The boundary curves as (n, 2) float64 arrays."""
    def to_wkt(self, *, exact: bool = False) -> str:
        """WKT MULTIPOLYGON of a bounded region."""
    def to_wkb(self) -> bytes:
        """WKB MULTIPOLYGON of a bounded region."""
    def to_geojson(self) -> str:
        """GeoJSON MultiPolygon of a bounded region."""
    def to_shapely(self) -> object:
        """shapely MultiPolygon of a bounded region."""

class Solid(_Algebra):
    """A 3D Yin set: exact by default, float mode with ``eps``."""

    def __init__(self, vertices: ArrayLike, faces: ArrayLike, *, eps: Optional[float] = None) -> None:
        """The solid bounded by (m, k) ``faces`` on (n, 3) ``vertices``."""
    @classmethod
    def from_trimesh(cls, mesh: object, *, eps: Optional[float] = None) -> "Solid":
        """The solid bounded by a trimesh.Trimesh."""
    @classmethod
    def from_bytes(cls, data: bytes, format: str, *, eps: Optional[float] = None) -> "Solid":
        """The solid of mesh-file bytes ("obj", "stl", "off", "ply")."""
    @classmethod
    def read(
        cls, path: Union[str, "os.PathLike[str]"], *, format: Optional[str] = None, eps: Optional[float] = None
    ) -> "Solid":
        """The solid of an OBJ, STL, OFF or PLY file."""
    @classmethod
    def empty(cls, *, eps: Optional[float] = None) -> "Solid":
        """The empty solid."""
    @classmethod
    def full(cls, *, eps: Optional[float] = None) -> "Solid":
        """The whole space."""
    @property
    def volume(self) -> Optional[Measure]:
        """Fraction in exact mode, float in float mode, None if unbounded."""
    @property
    def betti(self) -> Tuple[int, int, int]:
        """(b0, b1, b2)."""
    def surfaces(self) -> List[Tuple["np.ndarray", bool, int]]:
        """Glued surfaces: (triangle indices, positive, genus)."""
    def locate(self, points: ArrayLike) -> "np.ndarray":
        """int8 location codes of an (n, 3) array."""
    def arrays(self) -> Tuple["np.ndarray", "np.ndarray"]:
        """(vertices (n, 3) float64, triangles (m, 3) int64)."""
    def to_trimesh(self) -> object:
        """The boundary as a trimesh.Trimesh."""
    def to_bytes(self, format: str) -> bytes:
        """Mesh-file bytes: "obj", "stl", "stl-binary", "off", "ply"."""
    def write(self, path: Union[str, "os.PathLike[str]"], *, format: Optional[str] = None) -> None:
        """Write a mesh file."""
