#!/usr/bin/env bash
# The 3D table of BENCHMARKS.md in one go: builds the peers if missing (Manifold's PyPI wheel in a
# venv at target/m3venv, CGAL's harness at target/cgal3d/cgal3d, boolmesh at
# target/mesh_peers, kigumi's harness at target/kigumi3d/kigumi3d, built by its own build.sh),
# runs benches/yin3_table.rs (ours and every peer on the same OBJ files in
# target/yin3_workloads), then the peak memory of one V1 meet at the largest size, ours and the
# peers', under /usr/bin/time -v. The table goes to stdout and target/yin3_table.md.
#
#   bash benches/yin3_peers.sh [--max-exact-s S] [--max-float-s F] [--max-m M] [--reps R]
#                              [--peak-m M] [--peak-exact-m M]
set -euo pipefail
cd "$(dirname "$0")/.."
peak_m=128
peak_exact_m=16
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --peak-m) peak_m="$2"; shift 2 ;;
    --peak-exact-m) peak_exact_m="$2"; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
tools=../shared/tools
mkdir -p target/cgal3d
if [ ! -x target/m3venv/bin/python ]; then
  python3 -m venv target/m3venv
  target/m3venv/bin/pip install -q manifold3d numpy
fi
if [ ! -x target/cgal3d/cgal3d ]; then
  dpkg -s libcgal-dev libmpfr-dev >/dev/null 2>&1 ||
    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libcgal-dev libmpfr-dev; }
  g++ -std=c++17 -O2 -DNDEBUG -DCGAL_USE_GMPXX=1 -frounding-math "$tools/cgal3d/cgal3d.cpp" \
    -o target/cgal3d/cgal3d -lgmpxx -lgmp -lmpfr -pthread
fi
if [ ! -x target/kigumi3d/kigumi3d ]; then
  bash "$tools/kigumi3d/build.sh"
  mkdir -p target/kigumi3d && cp "$tools/kigumi3d/kigumi3d" target/kigumi3d/
fi
CARGO_TARGET_DIR=target/mesh_peers cargo build -q --release --manifest-path benches/mesh_peers/Cargo.toml
echo "== machine"; uname -srm; grep -m1 'model name' /proc/cpuinfo; nproc; free -g | sed -n 2p
echo "== code"; git rev-parse --short HEAD; git status --short | head
echo "== start"; date -u; uptime
echo "== table"
cargo bench --bench yin3_table -- "${args[@]}"
bin=$(cargo bench --bench yin3_table --no-run 2>&1 | grep -o 'target/release/deps/yin3_table-[0-9a-f]*' | head -1)
peak() { # label, command...: the maximum resident set size of the command
  local label=$1; shift
  /usr/bin/time -v "$@" >/dev/null 2>target/yin3_peak.log || true
  echo "| $label | $(grep 'Maximum resident' target/yin3_peak.log | awk '{print $NF}') kB |"
}
echo "== peak memory, V1 at m=$peak_m (n = 8m² per sphere; ours exact at m=$peak_exact_m)"
echo "| contender | max RSS |"; echo "|---|---|"
peak "ours float" "$bin" --peak float "$peak_m"
peak "ours exact (m=$peak_exact_m)" "$bin" --peak exact "$peak_exact_m"
a=target/yin3_workloads/v1_a_$peak_m.obj; b=target/yin3_workloads/v1_b_$peak_m.obj
peak Manifold target/m3venv/bin/python "$tools/manifold3d/m3.py" meet "$a" "$b" --reps 1
peak "CGAL corefine" target/cgal3d/cgal3d meet "$a" "$b" --engine corefine --reps 1
peak boolmesh target/mesh_peers/release/mesh_peers boolmesh meet "$a" "$b" --reps 1
peak kigumi target/kigumi3d/kigumi3d meet "$a" "$b" --reps 1
echo "== end"; date -u; uptime
