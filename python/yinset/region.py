"""``Region``: a 2D Yin set, exact or float, with shapely, numpy and OGC conversions."""

import numpy as np

from . import _arrays
from ._algebra import Algebra
from ._yinset import Region2, YinsetError


class Region(Algebra):
    """A 2D Yin set: a regular open region of the plane, exact by default.

    ``Region(rings, eps=None, fill=None)`` builds it from a list of rings, each an (n, 2)
    array-like of vertices (not closed: the first point is not repeated; a repeated one is
    dropped). Without ``fill`` the rings must be the boundary of a Yin set: counterclockwise
    around the region, clockwise around holes, no crossings (else ``YinsetError``). With
    ``fill="nonzero"`` or ``fill="evenodd"`` the rings are polygon soup and the region is what
    they cover under that rule. ``eps=None`` is exact mode; a positive ``eps`` is float mode.
    """

    __slots__ = ()

    def __init__(self, rings=(), *, eps=None, fill=None):
        if isinstance(rings, np.ndarray) and rings.ndim == 2:
            rings = [rings]
        arrays = [_open(_arrays.points(r, 2, f"ring {k}")) for k, r in enumerate(rings)]
        xy = b"".join(a.tobytes() for a in arrays)
        self._set = Region2.from_rings(xy, [len(a) for a in arrays], eps, fill)

    @classmethod
    def from_wkt(cls, text, *, eps=None, fill=None):
        """The region of a WKT (Multi)Polygon (coordinates as decimals or ``p/q``)."""
        return cls._wrap(Region2.from_ogc(text.encode(), "wkt", eps, fill))

    @classmethod
    def from_wkb(cls, data, *, eps=None, fill=None):
        """The region of a WKB (Multi)Polygon: bytes, or their hex digits as str or bytes."""
        if isinstance(data, str):
            data = data.encode()
        return cls._wrap(Region2.from_ogc(bytes(data), "wkb", eps, fill))

    @classmethod
    def from_geojson(cls, text, *, eps=None, fill=None):
        """The region of a GeoJSON Polygon, MultiPolygon, Feature or FeatureCollection."""
        return cls._wrap(Region2.from_ogc(text.encode(), "geojson", eps, fill))

    @classmethod
    def from_yin2(cls, text, *, eps=None):
        """The region of a yin2 text: curves of ``x y`` lines (interior on the left),
        separated by blank lines; ``plane`` for the whole plane."""
        return cls._wrap(Region2.from_yin2(text, eps))

    @classmethod
    def from_shapely(cls, geometry, *, eps=None, fill=None):
        """The region of a shapely Polygon or MultiPolygon (through its WKB, exactly)."""
        import shapely

        return cls.from_wkb(shapely.to_wkb(geometry), eps=eps, fill=fill)

    @classmethod
    def empty(cls, *, eps=None):
        """The empty region."""
        return cls._wrap(Region2.empty(eps))

    @classmethod
    def full(cls, *, eps=None):
        """The whole plane."""
        return cls._wrap(Region2.full(eps))

    @property
    def eps(self):
        """The tolerance in float mode, None in exact mode."""
        return self._set.eps

    def __le__(self, other):
        """Subset: every point of A is in B."""
        o = self._operand(other)
        return NotImplemented if o is None else self._set.is_subset(o)

    def __hash__(self):
        """A hash consistent with set equality."""
        return hash(self._set.hash())

    def __repr__(self):
        mode = "exact" if self.exact else f"eps={self.eps!r}"
        if self._set.is_full():
            return f"Region.full({mode})"
        return f"<Region {mode}, {len(self.curves())} curves, area {self.area}>"

    def meet_each(self, cells):
        """[A ∧ C for C in cells], in parallel: the cut of A by control volumes."""
        natives = []
        for k, c in enumerate(cells):
            if not isinstance(c, Region):
                raise YinsetError(f"cell {k} is a {type(c).__name__}, not a Region")
            natives.append(c._set)
        return [self._wrap(p) for p in self._set.meet_each(natives)]

    @property
    def area(self):
        """The area: a Fraction in exact mode, a float in float mode, None if unbounded."""
        return _arrays.measure(self._set.area())

    @property
    def betti(self):
        """(b0, b1): components and holes, as the Yin-set papers count them."""
        return self._set.betti()

    @property
    def homology(self):
        """(b0, b1): the ranks of the homology groups (holes touching at a point are one)."""
        return self._set.homology()

    def locate(self, points):
        """The location codes (int8: INSIDE 1, ON_BOUNDARY 0, OUTSIDE -1) of an (n, 2) array."""
        a = _arrays.points(points, 2, "points")
        return _arrays.located(self._set.locate(a.tobytes()))

    def curves(self):
        """The boundary curves as (n, 2) float64 arrays, interior on the left (exact vertices
        rounded to the nearest float64)."""
        return [_arrays.coordinates(data, 2) for data, _ in self._set.curves()]

    def to_wkt(self, *, exact=False):
        """WKT MULTIPOLYGON of a bounded region: shortest decimals of the nearest float64s, or
        with ``exact`` every coordinate's exact digits (``p/q`` where they do not end). Readers
        take decimals as the decimals they are (``5.1`` is 51/10), so only ``exact`` WKT reads
        back as the same exact region."""
        return self._set.to_wkt(exact)

    def to_wkb(self):
        """Little-endian WKB MULTIPOLYGON of a bounded region (nearest float64s)."""
        return self._set.to_wkb()

    def to_geojson(self):
        """GeoJSON MultiPolygon geometry of a bounded region (shortest decimals)."""
        return self._set.to_geojson()

    def to_shapely(self):
        """The shapely MultiPolygon of a bounded region."""
        import shapely

        return shapely.from_wkb(self.to_wkb())


def _open(ring):
    """``ring`` without the closing repetition of its first point."""
    if len(ring) > 1 and np.array_equal(ring[0], ring[-1]):
        return ring[:-1]
    return ring
