#!/usr/bin/env bash
# Every table of benches/BENCHMARKS.md in one run, on the committed code at HEAD (the commit
# the file names): 2D against the peers, 3D against the peers (with peak memory), 3D input and
# output before and after BEFORE_REV, the parallel speedups, the 2D peak memory and the Python
# call's overhead. Each family's log goes to target/bench-all/FAMILY.log; nothing else should
# run on the machine meanwhile (about 40 minutes on two cores).
#
#   KIGUMI_MESHES=DIR bash benches/all.sh BEFORE_REV
#
# DIR holds checker.obj, text.obj and plate.obj of kigumi's repository (meshes/).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 1 ]; then
  echo "usage: KIGUMI_MESHES=DIR bash benches/all.sh BEFORE_REV" >&2
  exit 2
fi
before=$1
: "${KIGUMI_MESHES:?the folder of checker.obj, text.obj and plate.obj from kigumi meshes/}"
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "commit first: the figures are those of HEAD" >&2
  exit 2
fi
out=target/bench-all
mkdir -p "$out"
stamp() { echo "$(date -u +%T), load $(cut -d' ' -f1-3 /proc/loadavg)"; }
family() { # NAME COMMAND...: run it, its output to the terminal and to $out/NAME.log; a
  # family that fails is reported and the run goes on to the next
  local name=$1
  shift
  echo "== $name ($(stamp)): $*"
  "$@" 2>&1 | tee "$out/$name.log" || echo "!! $name failed: see $out/$name.log"
}
{
  echo "commit $(git rev-parse --short HEAD)"
  uname -srm
  grep -m1 'model name' /proc/cpuinfo || true
  echo "$(nproc) CPUs, $(free -g | awk '/Mem:/ {print $2}') GB"
  rustc --version
} | tee "$out/machine.log"
cargo build -q --release

family 2d bash benches/peers2d_cgal.sh W2 W4/ W3/ W1/meet W6/
family 3d bash benches/yin3_peers.sh --max-exact-s 30 --max-m 128 --reps 3 --peak-m 128 --peak-exact-m 128
family 3d-io bash benches/yin3_io.sh "$before" --reps 3
family parallel-1 env RAYON_NUM_THREADS=1 cargo bench --bench parallel
family parallel-2 env RAYON_NUM_THREADS=2 cargo bench --bench parallel
family parallel-3d cargo bench --bench yin3_ops -- V4

peak=$(cargo bench --bench peak_w1 --no-run 2>&1 | grep -o 'target/release/deps/peak_w1-[0-9a-f]*' | head -1)
family memory-2d /usr/bin/time -v "$peak" 1000000 float

# The Python package in its own virtual environment, then the Rust and the Python sides of
# python/bench/overhead.py on the same files.
venv=target/bench-venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install -q ./ numpy
data=$(cd ../shared/data/2d && pwd)
family python-py "$venv/bin/python" python/bench/overhead.py "$data" "$out/spheres" 31
family python-rs cargo run -q --release --manifest-path python/Cargo.toml --example overhead -- \
  "$data/panda" "$data/mickey" "$out/spheres/sphere_a.obj" "$out/spheres/sphere_b.obj" 31
echo "== end ($(stamp))"
