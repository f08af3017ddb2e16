"""The Python call's overhead over the Rust operation alone: panda ∧ Mickey (exact) and the
meet of two UV spheres of about 10^4 triangles (exact), medians of repeated runs.

    python python/bench/overhead.py DATA_2D_DIR OUT_DIR RUNS

writes the spheres as OBJ to OUT_DIR, times the Python calls, and prints the times; the Rust
side is ``cargo run --release --example overhead`` (python/examples/overhead.rs) on the same
files.
"""

import pathlib
import statistics
import sys
import time

import numpy as np

import yinset


def uv_sphere(center, radius, slices, stacks):
    """A UV sphere: 2·slices·(stacks − 1) triangles, counterclockwise seen from outside."""
    vertices = [(0.0, 0.0, 1.0)]
    for i in range(1, stacks):
        theta = np.pi * i / stacks
        for j in range(slices):
            phi = 2 * np.pi * j / slices
            vertices.append((np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)))
    vertices.append((0.0, 0.0, -1.0))
    ring = lambda i, j: 1 + (i - 1) * slices + j % slices  # noqa: E731
    faces = [(0, ring(1, j), ring(1, j + 1)) for j in range(slices)]
    for i in range(1, stacks - 1):
        for j in range(slices):
            faces.append((ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)))
            faces.append((ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)))
    south = len(vertices) - 1
    faces += [(south, ring(stacks - 1, j + 1), ring(stacks - 1, j)) for j in range(slices)]
    return np.array(vertices) * radius + np.array(center), np.array(faces)


def yin2_dir(path):
    """The yin2 text of the curve files of ``path``, in name order."""
    return "".join(f.read_text() + "\n\n" for f in sorted(pathlib.Path(path).glob("*.txt")))


def median_ms(runs, f):
    """The median time of ``runs`` calls of ``f``, in milliseconds."""
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        f()
        times.append((time.perf_counter() - t) * 1e3)
    return statistics.median(times)


def main():
    data, out, runs = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), int(sys.argv[3])
    panda = yinset.Region.from_yin2(yin2_dir(data / "panda"))
    mickey = yinset.Region.from_yin2(yin2_dir(data / "mickey"))
    a = yinset.Solid(*uv_sphere((0, 0, 0), 1.0, 72, 70))
    b = yinset.Solid(*uv_sphere((0.3, 0.2, 0.1), 1.0, 72, 70))
    out.mkdir(parents=True, exist_ok=True)
    a.write(out / "sphere_a.obj")
    b.write(out / "sphere_b.obj")
    assert yinset.Solid.read(out / "sphere_a.obj") == a, "the OBJ holds the exact sphere"
    print("sphere_triangles", len(a.arrays()[1]))
    print(f"panda_mickey_ms {median_ms(runs, lambda: panda & mickey):.3f}")
    print(f"spheres_ms {median_ms(runs, lambda: a & b):.3f}")


if __name__ == "__main__":
    main()
