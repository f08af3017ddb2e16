"""The Region type: exact identities, measures, location, formats and errors."""

import json
from fractions import Fraction

import numpy as np
import pytest

import yinset
from yinset import INSIDE, ON_BOUNDARY, OUTSIDE, Region, YinsetError


def square(x, y, s, eps=None):
    """The open square [x, x+s] × [y, y+s], counterclockwise."""
    return Region([[(x, y), (x + s, y), (x + s, y + s), (x, y + s)]], eps=eps)


def triangle(points, eps=None):
    return Region([points], eps=eps)


# Pairs of operands with coordinates that are not short decimals in binary (0.1, 1/3, ...),
# overlapping, nested, disjoint, touching along an edge and at a corner.
PAIRS = [
    (square(0, 0, 2), square(1, 1, 2)),
    (square(0.1, 0.2, 0.7), square(0.3, 0.1, 0.5)),
    (square(0, 0, 3), square(1, 1, 1)),
    (square(0, 0, 1), square(5, 5, 1)),
    (square(0, 0, 1), square(1, 0, 1)),
    (square(0, 0, 1), square(1, 1, 1)),
    (triangle([(0, 0), (1 / 3, 0), (0, 1 / 7)]), square(0.01, 0.01, 0.05)),
]


def test_an_f64_square_has_the_exact_area_of_its_binary_value():
    # 0.1 is 3602879701896397 / 2**55; its square, not 1/100, is the area.
    assert square(0, 0, 0.1).area == Fraction(0.1) ** 2
    assert square(0, 0, 0.1).area != Fraction(1, 100)


def test_operators_on_overlapping_squares():
    a, b = square(0, 0, 2), square(1, 1, 2)
    assert (a & b).area == 1
    assert (a | b).area == 7
    assert (a - b).area == 3
    assert (a ^ b).area == 6
    assert (a & b) == square(1, 1, 1)
    assert isinstance((a | b).area, Fraction)


@pytest.mark.parametrize("a,b", PAIRS)
def test_de_morgan_and_absorption(a, b):
    assert ~(a & b) == (~a | ~b)
    assert ~(a | b) == (~a & ~b)
    assert (a | (a & b)) == a
    assert (a & (a | b)) == a
    assert ~~a == a
    assert (a ^ b) == ((a - b) | (b - a))


@pytest.mark.parametrize("a,b", PAIRS)
def test_area_identity_is_exact(a, b):
    assert (a & b).area + (a | b).area == a.area + b.area
    assert (a - b).area == a.area - (a & b).area


def test_complement_is_unbounded_and_the_algebra_has_its_bounds():
    a = square(0, 0, 1)
    assert not (~a).bounded and (~a).area is None
    assert (a & ~a) == Region.empty()
    assert (a | ~a) == Region.full()
    assert not Region.empty() and bool(a)
    assert a <= square(-1, -1, 3) and not square(-1, -1, 3) <= a


def test_locate_returns_an_array_of_codes():
    codes = square(0, 0, 2).locate(np.array([[1, 1], [2, 1], [3, 3], [0, 0]]))
    assert codes.dtype == np.int8
    assert codes.tolist() == [INSIDE, ON_BOUNDARY, OUTSIDE, ON_BOUNDARY]
    assert (INSIDE, ON_BOUNDARY, OUTSIDE) == (1, 0, -1)


def test_betti_and_homology_of_a_square_with_a_hole():
    ring = square(0, 0, 3) - square(1, 1, 1)
    assert ring.betti == (1, 1)
    assert ring.homology == (1, 1)
    assert ring.area == 8
    # Two squares touching at a corner: two components, no loop.
    assert (square(0, 0, 1) | square(1, 1, 1)).homology == (2, 0)


def test_fill_rules_on_polygon_soup():
    bow = [[(0, 0), (2, 2), (2, 0), (0, 2)]]
    nonzero = Region(bow, fill="nonzero")
    assert nonzero.area == 2 and nonzero.betti[0] == 2
    nested = [[(0, 0), (4, 0), (4, 4), (0, 4)], [(1, 1), (3, 1), (3, 3), (1, 3)]]
    assert Region(nested, fill="evenodd").area == 12
    assert Region(nested, fill="nonzero").area == 16


def test_a_closed_ring_and_a_single_array_are_accepted():
    closed = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], dtype=float)
    assert Region(closed) == square(0, 0, 1)


def test_meet_each_cuts_by_control_volumes():
    cells = [square(x, y, 1) for x in (0, 1) for y in (0, 1)]
    parts = square(0.5, 0.5, 1).meet_each(cells)
    assert [p.area for p in parts] == [Fraction(1, 4)] * 4
    assert parts[3] == square(1, 1, 0.5)


def test_float_mode_gives_floats():
    a, b = square(0, 0, 2, eps=1e-9), square(1, 1, 2, eps=1e-9)
    assert not a.exact and a.eps == 1e-9
    assert (a | b).area == 7.0 and isinstance((a | b).area, float)
    with pytest.raises(YinsetError, match="mix exact and float"):
        a & square(0, 0, 1)


def test_curves_are_the_boundary_vertices():
    (curve,) = (square(0, 0, 2) & square(1, 1, 2)).curves()
    assert curve.shape == (4, 2)
    assert sorted(map(tuple, curve.tolist())) == [(1, 1), (1, 2), (2, 1), (2, 2)]


def test_wkt_wkb_geojson_round_trips():
    r = square(0, 0, 3) - square(1, 1, 1) | square(5, 5, 0.1)
    # WKB holds the f64s; exact WKT their full decimal expansions.
    assert Region.from_wkb(r.to_wkb()) == r
    assert Region.from_wkb(r.to_wkb().hex()) == r
    assert Region.from_wkt(r.to_wkt(exact=True)) == r
    # Shortest decimals are read back as the decimals they are: 5.1 is 51/10, not the f64.
    assert Region.from_wkt(r.to_wkt()) != r
    assert Region.from_wkt(r.to_wkt()).area == 8 + Fraction(1, 100)
    d = square(0, 0, 3) - square(1, 1, 1) | square(5, 5, 0.25)
    assert Region.from_wkt(d.to_wkt()) == d
    assert Region.from_geojson(d.to_geojson()) == d
    assert json.loads(d.to_geojson())["type"] == "MultiPolygon"


def test_exact_wkt_keeps_rational_vertices():
    # The diagonals of two triangles cross at (2/3, 2/3)... exactly, written as p/q.
    a = triangle([(0, 0), (2, 0), (0, 1)])
    b = triangle([(0, 0), (1, 0), (0, 2)])
    m = a & b
    assert "2/3" in m.to_wkt(exact=True)
    assert Region.from_wkt(m.to_wkt(exact=True)) == m
    assert m.area == Fraction(2, 3)


def test_yin2_text():
    r = Region.from_yin2("0 0\n1 0\n1 1\n0 1\n")
    assert r == square(0, 0, 1)
    assert Region.from_yin2("plane\n") == Region.full()


def test_invalid_rings_raise_a_value_error_with_the_kernel_message():
    with pytest.raises(YinsetError, match="not simple") as e:
        Region([[(0, 0), (1, 1), (1, 0), (0, 1)]])
    assert isinstance(e.value, ValueError)
    with pytest.raises(YinsetError, match=r"ring 1 has shape \(3, 3\), not \(n, 2\)"):
        Region([[(0, 0), (1, 0), (0, 1)], np.zeros((3, 3))])
    with pytest.raises(YinsetError, match="ring 0, point 1: coordinate NaN is not finite"):
        Region([[(0, 0), (np.nan, 0), (0, 1)]])
    with pytest.raises(YinsetError, match="fill rule"):
        Region([[(0, 0), (1, 0), (0, 1)]], fill="winding")
    with pytest.raises(YinsetError, match="tolerance must be finite and positive"):
        square(0, 0, 1, eps=-1.0)
    with pytest.raises(YinsetError, match="line 1"):
        Region.from_wkt("POLYGON ((0 0, 1 0")
    with pytest.raises(YinsetError, match="unbounded"):
        (~square(0, 0, 1)).to_wkt()
    with pytest.raises(YinsetError, match="not a Region"):
        square(0, 0, 1).meet_each([square(0, 0, 1), 3])


def test_shapely_round_trip():
    shapely = pytest.importorskip("shapely")
    from shapely.geometry import Polygon

    p = Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (1, 2), (2, 2), (2, 1)]])
    r = Region.from_shapely(p)
    assert r.area == 15 and r.betti == (1, 1)
    back = r.to_shapely()
    assert back.geom_type == "MultiPolygon"
    assert shapely.equals(back, p)
    assert Region.from_shapely(back) == r
    # shapely's result and ours agree on an intersection of f64 polygons.
    q = Polygon([(0.3, 0.1), (5.1, 0.7), (2.2, 4.9)])
    ours = (r & Region.from_shapely(q)).to_shapely()
    assert ours.symmetric_difference(p.intersection(q)).area < 1e-12


def test_help_has_docstrings():
    assert "Yin set" in yinset.__doc__
    for name in ["__and__", "area", "locate", "meet_each", "to_shapely", "from_wkb"]:
        assert getattr(Region, name).__doc__
