#!/usr/bin/env bash
# The 2D peer table of benches/BENCHMARKS.md with CGAL's exact kernel (Epeck) as a column:
# builds ../shared/tools/cgal2d into target/cgal2d (needs libcgal-dev, libgmp-dev,
# libmpfr-dev), then runs `cargo bench --bench peers` with YINSET_CGAL2D set, once per filter.
#
#   bash benches/peers2d_cgal.sh              # W4/ W3/ W6/ W1/meet (the default filters)
#   bash benches/peers2d_cgal.sh W4/ W2       # other filters
#
# The log (with `uptime` before and after) goes to target/peers2d_cgal.log.
set -euo pipefail
cd "$(dirname "$0")/.."
src=../shared/tools/cgal2d/cgal2d.cpp
if [ ! target/cgal2d -nt "$src" ]; then
  mkdir -p target
  g++ -std=c++17 -O2 -DNDEBUG -DCGAL_USE_GMPXX=1 -frounding-math "$src" -o target/cgal2d \
    -lgmpxx -lgmp -lmpfr
fi
export YINSET_CGAL2D="$PWD/target/cgal2d"
filters=("$@")
if [ ${#filters[@]} -eq 0 ]; then filters=(W4/ W3/ W6/ W1/meet); fi
{
  echo "# start $(date -u) commit $(git rev-parse --short HEAD)"
  echo "# uptime $(uptime)"
  for f in "${filters[@]}"; do
    cargo bench --bench peers -- "$f"
  done
  echo "# uptime $(uptime)"
  echo "# end $(date -u)"
} 2>&1 | tee target/peers2d_cgal.log
