#!/usr/bin/env bash
# Tests of no_history.sh on small fixtures: each line it must flag is flagged (and named by its
# file and line), and the hex constants, numbers and code it must leave alone pass.
set -euo pipefail
check="$(dirname "$0")/no_history.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

# Each case: a file name, its one line, and whether the check must flag it.
expect() {
  local name=$1 line=$2 want=$3 out
  printf '%s\n' "$line" >"$dir/$name"
  if out=$(bash "$check" "$dir/$name" 2>&1); then got=pass; else got=flag; fi
  if [ "$got" != "$want" ]; then
    echo "FAIL: $name \"$line\": wanted $want, got $got: $out"
    failures=$((failures + 1))
  elif [ "$want" = flag ] && ! grep -q "$dir/$name:1:" <<<"$out"; then
    echo "FAIL: $name \"$line\": flagged without its file:line: $out"
    failures=$((failures + 1))
  fi
}

expect a.md 'Measured at 42bc18e on the AMD machine.' flag
expect b.md 'the gcd change (b4156e4) made it faster' flag
expect c.md 'a full hash 7a74da0e1f2b3c4d5e6f708192a3b4c5d6e7f809' flag
expect d.md 'the run of 3e35351' flag
expect e.md 'the run of 2026-11-29 at noon' flag
expect f.md 'as in 2026-11' flag
expect g.md 'the twentieth Session found it' flag
expect h.md 'sessions ago' flag
expect i.md 'see issue 14 item 5' flag
expect j.md 'Issues 16, 18 added it' flag
expect k.rs '    let x = 1; // since 42bc18e' flag
expect l.rs '/// Fixed in issue 6.' flag
expect m.rs '//! the seventh session' flag

expect n.md 'a constant 0x9e3779b97f4a7c15 and the colour #ff8800ff' pass
expect o.md 'an exponent "1e999999999" and 4.5040114e+00' pass
expect p.md 'plain words: defaced, cabbage, decade; numbers 1234567 and 10 000 000' pass
expect q.md 'a WKB point 0101000000000000000000f03f000000000000f03f in hex' pass
expect r.md 'Hobby (1999), seed 000 Def. 3.1, ε = 2^-20' pass
expect s.rs 'const K: u64 = 0x2545f4914f6cdd1d; let s = "42bc18e issue 5 session";' pass
expect t.rs '// a 64-bit word, 0xffff_ffff, the deadbeef pattern' pass
expect u.md 'Tissue 4 and sessional are other words' pass

# BENCHMARKS.md may name the commits it measured in its header, but none below it.
mkdir -p "$dir/benches"
printf 'Code measured: 42bc18e (2D), 1eccde4 (3D).\n\n## 2D\n\nFigures.\n' >"$dir/benches/BENCHMARKS.md"
if ! bash "$check" "$dir/benches/BENCHMARKS.md" >/dev/null 2>&1; then
  echo "FAIL: BENCHMARKS.md naming its measured commits in its header was flagged"
  failures=$((failures + 1))
fi
printf 'Code measured: 42bc18e.\n\n## 2D\n\nBefore, at 42bc18e.\n' >"$dir/benches/BENCHMARKS.md"
if out=$(bash "$check" "$dir/benches/BENCHMARKS.md" 2>&1) || ! grep -q ':5: a commit hash (42bc18e)' <<<"$out"; then
  echo "FAIL: BENCHMARKS.md naming a commit below its header was not flagged on its line 5: $out"
  failures=$((failures + 1))
fi

if [ "$failures" -ne 0 ]; then
  echo "no_history_test: $failures failure(s)"
  exit 1
fi
echo "no_history_test: all cases behave"
