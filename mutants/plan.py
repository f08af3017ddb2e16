"""The mutation run's plan, shared by sample.py, run.py and score.py: the examined modules,
the tests that can catch a mutant of each, the build settings, and the sample and results
files' formats."""

import json
import pathlib
import subprocess
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
SAMPLE = ROOT / "mutants" / "sample.txt"
RESULTS = ROOT / "mutants" / "results.txt"
# The survivors' triage: each missed mutant rerun on a later commit that has tests for it, or
# argued equivalent.
TRIAGE = ROOT / "mutants" / "triage.txt"
# The worktree at the sample's commit and its build folder (ignored by git: under target/).
WORKTREE = ROOT / "target" / "mutants" / "wt"
BUILD = ROOT / "target" / "mutants" / "build"
# The worktree of the triage's rerun, at the checkout's HEAD, and its build folder.
RETEST_TREE = ROOT / "target" / "mutants" / "head"
RETEST_BUILD = ROOT / "target" / "mutants" / "build-head"
# Each worktree's build folder (one each: see run.py, prepare).
BUILDS = {WORKTREE: BUILD, RETEST_TREE: RETEST_BUILD}

# cargo-mutants' configuration: the examined files (src/<module>/**/*.rs), the excluded ones
# and the build settings (its `--config` arguments), shared with a plain `cargo mutants`.
CONFIG = tomllib.loads((ROOT / ".cargo" / "mutants.toml").read_text())
# The examined modules, in the order of the score table.
MODULES = [g.split("/")[1] for g in CONFIG["examine_globs"]]

# The integration tests (tests/<name>.rs) that exercise each module, run after the module's
# own unit tests (`cargo test --lib -- <module>::`). The kernel's points serve both
# dimensions; the numbers serve everything, and the suites below are the ones that check
# them directly (exact values, float against exact in 2D and 3D, the readers' numbers).
# float_measures, the exact areas and volumes of float sets, joined the sets' lists after the
# sample's run: the triage's rerun runs it.
INTEGRATION = {
    "num": ["degenerate", "oracles", "float_mode", "fuzz_regressions", "float_mode3"],
    "kernel": ["degenerate", "oracles", "yin3_degenerate"],
    "yin2": ["degenerate", "oracles", "axioms_proptest", "float_mode", "float_measures"],
    "yin3": ["yin3_degenerate", "oracles3", "axioms3_proptest", "float_mode3", "float_measures"],
}

# Files compiled only under a cargo feature, and that feature: their mutants are built and
# tested with it (the other mutants without, as `cargo test` runs by default).
FEATURES = {"src/num/gmp.rs": "gmp"}

# Property tests run at most this many cases per property (tests/kit: `cases`).
CASES = "32"

# The build settings for one rebuild per mutant (.cargo/mutants.toml explains them).
CARGO_CONFIG = [
    a for k, a in zip(CONFIG["additional_cargo_args"], CONFIG["additional_cargo_args"][1:])
    if k == "--config"
]
# Incremental compilation of the workspace's crates (the test profile's default, made sure),
# and the shared data at its place beside this checkout (the worktrees are not beside it),
# with CI set so that a test missing it fails instead of passing as skipped.
ENV = {
    "CARGO_INCREMENTAL": "1",
    "YINSET_CASES": CASES,
    "YINSET_DATA": str(ROOT.parent / "shared" / "data"),
    "CI": "1",
}

# The outcomes a mutant can have (timeout: the tests ran past their limit).
OUTCOMES = ["caught", "missed", "unviable", "timeout"]


def module_of(name):
    """The examined module of a mutant named `src/<module>/...: ...`."""
    return name.split("/")[1]


def list_mutants(tree, diffs):
    """cargo-mutants' mutants of the examined modules in `tree`, as its JSON objects."""
    cmd = ["cargo", "mutants", "--list", "--json", "--no-config"]
    for g in CONFIG["examine_globs"]:
        cmd += ["--file", g]
    for g in CONFIG["exclude_globs"]:
        cmd += ["--exclude", g]
    if diffs:
        cmd.append("--diff")
    return json.loads(subprocess.check_output(cmd, cwd=tree, text=True))


def read_sample(path=SAMPLE):
    """The sample's commit and its mutants' names."""
    commit, names = None, []
    for line in open(path):
        line = line.rstrip("\n")
        if line.startswith("# commit "):
            commit = line.split()[2]
        elif line and not line.startswith("#"):
            names.append(line)
    return commit, names


def read_results(path=RESULTS):
    """Tested mutants: name -> (outcome, seconds); lines are `name<TAB>outcome<TAB>seconds`."""
    out = {}
    if path.exists():
        for line in open(path):
            if line.strip() and not line.startswith("#"):
                name, outcome, secs = line.rstrip("\n").split("\t")
                out[name] = (outcome, float(secs))
    return out


def read_triage(path=TRIAGE):
    """Triaged survivors: name -> (verdict, note); lines are `name<TAB>verdict<TAB>note`, the
    verdict an outcome of the rerun (caught, missed, ...) or `equivalent` with its argument."""
    out = {}
    if path.exists():
        for line in open(path):
            if line.strip() and not line.startswith("#"):
                name, verdict, note = line.rstrip("\n").split("\t")
                out[name] = (verdict, note)
    return out
