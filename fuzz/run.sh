#!/usr/bin/env bash
# Build and run yinset's fuzz targets on the stable toolchain.
#
#   fuzz/run.sh TARGET SECONDS [libFuzzer args...]   one target for SECONDS
#   fuzz/run.sh all SECONDS [libFuzzer args...]      every target in turn, SECONDS each
#   fuzz/run.sh list                                 the targets
#
# Installs cargo-fuzz (crates.io, `cargo install cargo-fuzz --locked`) if it is missing.
# cargo-fuzz hands rustc nightly-only flags; RUSTC_BOOTSTRAP=1 lets the stable toolchain take
# them. Targets are built optimized with debug assertions and overflow checks, without a
# sanitizer (the crate has no unsafe code; FUZZ_SANITIZER=address turns ASan on).
#
# The working corpus is fuzz/corpus/TARGET (new inputs are added there), read together with
# the committed seeds fuzz/seeds/<corpus>; crashes, timeouts and out-of-memory inputs go to
# fuzz/artifacts/TARGET/ (corpus/ and artifacts/ are git-ignored). Reproduce one with
#   RUSTC_BOOTSTRAP=1 cargo fuzz run -O -s none TARGET fuzz/artifacts/TARGET/crash-…
# Exit status: 0 if no target failed, non-zero otherwise (a crash or a hang is a failure),
# except that failures of the targets listed in FUZZ_ADVISORY (space-separated) are reported
# but do not count: for targets that still find known, pinned kernel bugs.
set -euo pipefail
cd "$(dirname "$0")/.."

TARGETS=(parse_yin2 parse_wkt parse_geojson construct ops_exact ops_float parse_obj construct3 ops3_exact ops3_float)

usage() {
    sed -n '3,6p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
}

seeds_of() {
    case "$1" in
    ops_exact | ops_float) echo ops ;;
    ops3_exact | ops3_float) echo ops3 ;;
    *) echo "$1" ;;
    esac
}

max_len_of() {
    case "$1" in
    parse_*) echo 8192 ;;
    *) echo 512 ;;
    esac
}

[ $# -ge 1 ] || usage
target="$1"
shift
if [ "$target" = list ]; then
    printf '%s\n' "${TARGETS[@]}"
    exit 0
fi
[ $# -ge 1 ] || usage
seconds="$1"
shift
case "$seconds" in '' | *[!0-9]*) usage ;; esac
if [ "$target" = all ]; then
    selected=("${TARGETS[@]}")
else
    case " ${TARGETS[*]} " in
    *" $target "*) selected=("$target") ;;
    *)
        echo "unknown target $target (fuzz/run.sh list)" >&2
        exit 2
        ;;
    esac
fi

export RUSTC_BOOTSTRAP=1
if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "== installing cargo-fuzz"
    cargo install cargo-fuzz --locked
fi
flags=(-O -s "${FUZZ_SANITIZER:-none}")

echo "== building fuzz targets ($(cargo fuzz --version))"
cargo fuzz build "${flags[@]}"

failed=()
advisory=()
for t in "${selected[@]}"; do
    echo "== fuzzing $t for ${seconds}s"
    mkdir -p "fuzz/corpus/$t" "fuzz/artifacts/$t"
    if ! cargo fuzz run "${flags[@]}" "$t" "fuzz/corpus/$t" "fuzz/seeds/$(seeds_of "$t")" -- \
        -max_total_time="$seconds" -max_len="$(max_len_of "$t")" \
        -timeout="${FUZZ_TIMEOUT:-30}" -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="fuzz/artifacts/$t/" "$@"; then
        case " ${FUZZ_ADVISORY:-} " in
        *" $t "*)
            advisory+=("$t")
            echo "!! $t failed (advisory: known open bugs, not counted): see fuzz/artifacts/$t/"
            ;;
        *)
            failed+=("$t")
            echo "!! $t failed: see fuzz/artifacts/$t/"
            ;;
        esac
    fi
done
if [ ${#advisory[@]} -gt 0 ]; then
    echo "fuzz: advisory targets that failed (known open bugs): ${advisory[*]}"
fi
# One summary line in the plain "N passed, N failed" form, counting targets.
echo "fuzz: $((${#selected[@]} - ${#failed[@]} - ${#advisory[@]})) passed, ${#failed[@]} failed"
if [ ${#failed[@]} -gt 0 ]; then
    echo "failed targets: ${failed[*]} (inputs in fuzz/artifacts/)"
    exit 1
fi
