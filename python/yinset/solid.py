"""``Solid``: a 3D Yin set, exact or float, with numpy, trimesh and mesh-file conversions."""

import os

import numpy as np

from . import _arrays
from ._algebra import Algebra
from ._yinset import Solid3, YinsetError

_FORMATS = {".obj": "obj", ".stl": "stl", ".off": "off", ".ply": "ply"}


def _format(path, format):
    """The mesh format of ``path``: ``format`` if given, else its extension's."""
    if format is not None:
        return format
    ext = os.path.splitext(str(path))[1].lower()
    if ext not in _FORMATS:
        raise YinsetError(f"{path}: unknown mesh extension {ext!r}; give format=")
    return _FORMATS[ext]


class Solid(Algebra):
    """A 3D Yin set: a regular open region of space, exact by default.

    ``Solid(vertices, faces, eps=None)`` builds it from an (n, 3) array of vertices and an
    (m, k) integer array of faces (k ≥ 3 vertex indices from 0 each, planar polygons,
    counterclockwise seen from outside the solid, closed and without crossings, else
    ``YinsetError`` naming the face). ``eps=None`` is exact mode; a positive ``eps`` is float
    mode (exact on the float64 values, results rounded to float64).
    """

    __slots__ = ()

    def __init__(self, vertices, faces, *, eps=None):
        xyz = _arrays.points(vertices, 3, "vertices")
        f = np.asarray(faces)
        if f.ndim != 2 or (f.size and not np.issubdtype(f.dtype, np.integer)):
            raise YinsetError(f"faces has shape {f.shape} and dtype {f.dtype}, not (m, k) integers")
        f = np.ascontiguousarray(f, dtype="<i8")
        width = f.shape[1] if f.size else 3
        self._set = Solid3.from_arrays(xyz.tobytes(), f.tobytes(), width, eps)

    @classmethod
    def from_trimesh(cls, mesh, *, eps=None):
        """The solid bounded by a ``trimesh.Trimesh`` (its vertices and faces as they are)."""
        return cls(mesh.vertices, mesh.faces, eps=eps)

    @classmethod
    def from_bytes(cls, data, format, *, eps=None):
        """The solid of a mesh file's bytes in ``format``: "obj", "stl", "off" or "ply"."""
        return cls._wrap(Solid3.from_file(bytes(data), format, eps))

    @classmethod
    def read(cls, path, *, format=None, eps=None):
        """The solid of an OBJ, STL, OFF or PLY file (format from the extension unless given)."""
        fmt = _format(path, format)
        with open(path, "rb") as f:
            return cls.from_bytes(f.read(), fmt, eps=eps)

    @classmethod
    def empty(cls, *, eps=None):
        """The empty solid."""
        return cls._wrap(Solid3.empty(eps))

    @classmethod
    def full(cls, *, eps=None):
        """The whole space."""
        return cls._wrap(Solid3.full(eps))

    def __repr__(self):
        mode = "exact" if self.exact else "float"
        return f"<Solid {mode}, betti {self.betti}, volume {self.volume}>"

    @property
    def volume(self):
        """The volume: a Fraction in exact mode, a float in float mode, None if unbounded."""
        return _arrays.measure(self._set.volume())

    @property
    def betti(self):
        """(b0, b1, b2): components, tunnels, cavities."""
        return self._set.betti()

    def surfaces(self):
        """The glued surfaces: (triangle indices into ``arrays()[1]``, positive, genus) each."""
        return [(np.array(t, dtype=np.int64), p, g) for t, p, g in self._set.surfaces()]

    def locate(self, points):
        """The location codes (int8: INSIDE 1, ON_BOUNDARY 0, OUTSIDE -1) of an (n, 3) array."""
        a = _arrays.points(points, 3, "points")
        return _arrays.located(self._set.locate(a.tobytes()))

    def arrays(self):
        """(vertices (n, 3) float64, nearest to the exact ones; triangles (m, 3) int64,
        counterclockwise seen from outside the solid)."""
        xyz, tris = self._set.arrays()
        return _arrays.coordinates(xyz, 3), np.frombuffer(tris, dtype="<i8").reshape(-1, 3).copy()

    def to_trimesh(self):
        """The boundary as a ``trimesh.Trimesh`` (not processed: vertices kept as they are)."""
        import trimesh

        vertices, triangles = self.arrays()
        return trimesh.Trimesh(vertices=vertices, faces=triangles, process=False)

    def to_bytes(self, format):
        """The mesh file: "obj" (one object per glued surface), "stl", "stl-binary", "off", "ply"."""
        return self._set.to_file(format)

    def write(self, path, *, format=None):
        """Write the mesh file ``path`` (format from the extension unless given)."""
        data = self.to_bytes(_format(path, format))
        with open(path, "wb") as f:
            f.write(data)
