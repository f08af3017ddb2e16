"""The Solid type: exact identities, measures, Betti numbers, location, files and errors."""

from fractions import Fraction

import numpy as np
import pytest

from yinset import INSIDE, ON_BOUNDARY, OUTSIDE, Solid, YinsetError

# The unit cube's corners and its faces as quads, counterclockwise seen from outside.
CORNERS = np.array(
    [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    dtype=float,
)
QUADS = np.array(
    [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
)


def cube(x, y, z, s, eps=None):
    """The open cube [x, x+s] × [y, y+s] × [z, z+s]."""
    return Solid(CORNERS * s + np.array([x, y, z]), QUADS, eps=eps)


PAIRS = [
    (cube(0, 0, 0, 2), cube(1, 1, 1, 2)),
    (cube(0.1, 0.2, 0.3, 0.7), cube(0.3, 0.1, 0.2, 0.5)),
    (cube(0, 0, 0, 3), cube(1, 1, 1, 1)),
    (cube(0, 0, 0, 1), cube(1, 0, 0, 1)),
]


def test_an_f64_cube_has_the_exact_volume_of_its_binary_value():
    assert cube(0, 0, 0, 0.1).volume == Fraction(0.1) ** 3
    assert cube(0, 0, 0, 1).betti == (1, 0, 0)


def test_operators_on_overlapping_cubes():
    a, b = cube(0, 0, 0, 2), cube(1, 1, 1, 2)
    assert (a & b).volume == 1
    assert (a | b).volume == 15
    assert (a - b).volume == 7
    assert (a ^ b).volume == 14
    assert (a & b) == cube(1, 1, 1, 1)


@pytest.mark.parametrize("a,b", PAIRS)
def test_de_morgan_absorption_and_volume_identity(a, b):
    assert ~(a & b) == (~a | ~b)
    assert (a | (a & b)) == a
    assert (a & b).volume + (a | b).volume == a.volume + b.volume


def test_a_cavity_and_a_tunnel():
    hollow = cube(0, 0, 0, 3) - cube(1, 1, 1, 1)
    assert hollow.betti == (1, 0, 1)
    assert hollow.volume == 26
    assert len(hollow.surfaces()) == 2
    # A 3 × 3 × 1 slab with the middle column removed: a solid torus.
    slab = Solid(CORNERS * [3, 3, 1], QUADS)
    hole = Solid(CORNERS * [1, 1, 3] + [1, 1, -1], QUADS)
    torus = slab - hole
    assert torus.betti == (1, 1, 0)
    assert torus.volume == 8


def test_complement_and_bounds():
    a = cube(0, 0, 0, 1)
    assert not (~a).bounded and (~a).volume is None
    assert (a & ~a) == Solid.empty() and (a | ~a) == Solid.full()


def test_locate_returns_an_array_of_codes():
    codes = cube(0, 0, 0, 2).locate([[1, 1, 1], [2, 1, 1], [3, 3, 3]])
    assert codes.dtype == np.int8
    assert codes.tolist() == [INSIDE, ON_BOUNDARY, OUTSIDE]


def test_arrays_round_trip():
    a = cube(0, 0, 0, 2) | cube(1, 1, 1, 2)
    vertices, triangles = a.arrays()
    assert vertices.shape[1] == 3 and triangles.shape[1] == 3
    assert Solid(vertices, triangles) == a


@pytest.mark.parametrize("fmt", ["obj", "stl", "stl-binary", "off", "ply"])
def test_file_formats_round_trip(fmt, tmp_path):
    a = cube(0, 0, 0, 2) - cube(1, 1, 1, 2)
    data = a.to_bytes(fmt)
    assert Solid.from_bytes(data, "stl" if fmt == "stl-binary" else fmt) == a
    if fmt != "stl-binary":
        path = tmp_path / f"a.{fmt}"
        a.write(path)
        assert Solid.read(path) == a


def test_float_mode():
    a, b = cube(0, 0, 0, 2, eps=1e-9), cube(1, 1, 1, 2, eps=1e-9)
    assert not a.exact
    assert (a | b).volume == 15.0 and isinstance((a | b).volume, float)
    with pytest.raises(YinsetError, match="mix exact and float"):
        a & cube(0, 0, 0, 1)


def test_invalid_meshes_raise_value_errors_naming_the_face():
    with pytest.raises(YinsetError) as e:
        Solid(CORNERS, QUADS[:5])
    assert isinstance(e.value, ValueError)
    assert "face" in str(e.value)
    with pytest.raises(YinsetError, match="face index 3: index -1 is negative"):
        Solid(CORNERS, [[0, 1, 2, -1]])
    with pytest.raises(YinsetError, match=r"vertices has shape \(8, 2\)"):
        Solid(CORNERS[:, :2], QUADS)
    with pytest.raises(YinsetError, match="not \\(m, k\\) integers"):
        Solid(CORNERS, QUADS.astype(float))
    with pytest.raises(YinsetError, match="unknown mesh extension"):
        Solid.read("cube.xyz")
    with pytest.raises(YinsetError, match="line 2"):
        Solid.from_bytes(b"v 0 0 0\nv 1 x 0\n", "obj")


def test_trimesh_round_trip():
    trimesh = pytest.importorskip("trimesh")
    box = trimesh.creation.box(extents=(2, 2, 2))
    s = Solid.from_trimesh(box)
    assert s.volume == 8 and s.betti == (1, 0, 0)
    back = (s - cube(0, 0, 0, 1)).to_trimesh()
    assert back.is_watertight
    assert back.volume == pytest.approx(7.0)
    assert Solid.from_trimesh(back) == s - cube(0, 0, 0, 1)
