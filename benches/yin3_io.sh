#!/usr/bin/env bash
# Before/after of benches/yin3_io.rs in one run: checks REV out in a temporary git worktree
# (target/yin3_io/rev, removed at the end), copies this tree's harness into it (benches/yin3_io.rs,
# benches/yin3_work/mod.rs, benches/peers/cpu_time.rs, and the [[bench]] entry if REV lacks it),
# builds both in release (REV in a target folder of its own, seeded with this tree's build of
# the dependencies), runs the harness of each against its own `yinset` binary, REV first, and
# prints one before/after table, also written to target/yin3_io.md. Each run's own table and
# measurements stay in target/yin3_io/.
# Options after REV go to both harnesses; kigumi's meshes come from --kigumi DIR or
# $KIGUMI_MESHES.
#
#   bash benches/yin3_io.sh REV [--reps R] [--quick] [--kigumi DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ]; then
  echo "usage: bash benches/yin3_io.sh REV [--reps R] [--quick] [--kigumi DIR]" >&2
  exit 2
fi
rev=$1; shift
root=$PWD
out=$root/target/yin3_io
wt=$out/rev
drop_worktree() { if [ -e "$wt" ]; then git worktree remove --force "$wt" || rm -rf "$wt"; fi; git worktree prune; }
drop_worktree
mkdir -p "$out"
git worktree add --detach -q "$wt" "$rev"
trap drop_worktree EXIT
mkdir -p "$wt/benches/peers" "$wt/benches/yin3_work"
cp benches/yin3_io.rs "$wt/benches/"
cp benches/peers/cpu_time.rs "$wt/benches/peers/"
cp benches/yin3_work/mod.rs "$wt/benches/yin3_work/"
grep -q '^name = "yin3_io"' "$wt/Cargo.toml" ||
  printf '\n[[bench]]\nname = "yin3_io"\nharness = false\n' >>"$wt/Cargo.toml"
export CARGO_TARGET_DIR=$root/target
# The shared meshes, which the worktree does not have beside it.
YINSET_DATA=${YINSET_DATA:-$(cd "$root/../shared/data" && pwd)}
export YINSET_DATA
build() { # DIR NAME TARGET: DIR's yinset and harness, built in the target folder TARGET and
  # copied to target/yin3_io/NAME-{yinset,bench}
  (cd "$1" && CARGO_TARGET_DIR=$3 nice cargo build -q --release --bin yinset)
  cp "$3/release/yinset" "$out/$2-yinset"
  local exe
  exe=$(cd "$1" && CARGO_TARGET_DIR=$3 nice cargo bench -q --bench yin3_io --no-run --message-format=json |
    grep -o '"executable":"[^"]*/yin3_io-[0-9a-f]*"' | cut -d'"' -f4)
  cp "$exe" "$out/$2-bench"
}
# REV builds in a target folder of its own: cargo names a workspace's own packages' builds by
# package, not by path, so in this tree's folder REV would be handed this tree's build as up
# to date. The folder starts as a copy of this tree's release build less yinset's own units
# (the dependencies are not built again).
rev_target=$out/rev-target
build "$root" after "$CARGO_TARGET_DIR"
rm -rf "$rev_target"
mkdir -p "$rev_target"
cp -a --reflink=auto "$CARGO_TARGET_DIR/release" "$rev_target/"
rm -rf "$rev_target"/release/.fingerprint/yinset-* "$rev_target"/release/deps/*yinset* \
  "$rev_target"/release/deps/yin3_io-*
build "$wt" before "$rev_target"
echo "== machine"; uname -srm; grep -m1 'model name' /proc/cpuinfo || true; nproc; free -g | sed -n 2p
echo "== code"; echo "before: $(git rev-parse --short "$rev")"
echo "after: $(git rev-parse --short HEAD)"; git status --short | head
echo "== start"; date -u; uptime
for run in before after; do
  echo "== $run"
  nice "$out/$run-bench" --yinset "$out/$run-yinset" --tsv "$out/$run.tsv" --out "$out/$run.md" "$@"
done
echo "== before/after"
"$out/after-bench" --merge "$out/before.tsv" "$out/after.tsv" --out target/yin3_io.md
echo "== end"; date -u; uptime
