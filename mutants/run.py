#!/usr/bin/env python3
"""Test the sampled mutants (mutants/sample.txt) on the sample's commit, resumably.

    nice -n 19 python3 mutants/run.py [--limit N]

Each mutant is applied (its cargo-mutants diff) to a worktree checked out at the sample's
commit (target/mutants/wt), built once, and tested only by what can catch it: the unit tests
of its module (`cargo test --lib -- <module>::`), then the module's integration tests
(plan.INTEGRATION), with property tests capped at plan.CASES cases (YINSET_CASES). One line per
mutant is appended to mutants/results.txt (name, outcome, seconds); mutants already there are
skipped, so an interrupted run resumes where it stopped. Test logs are kept in
target/mutants/logs.

    nice -n 19 python3 mutants/run.py --retest [--mutant NAME ...]

The triage's rerun: the missed mutants not yet in mutants/triage.txt (or the named ones), each
its diff from the sample's commit patched onto a worktree at this checkout's HEAD
(target/mutants/head), where the tests written for the survivors are, and tested the same
way; the outcome and the commit go to mutants/triage.txt. Commit the tests first.
`--all-cases` runs the property tests at their own case counts, as `cargo test` does.
"""

import argparse
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import plan

LOGS = plan.BUILD.parent / "logs"


def run(cmd, cwd, timeout, log):
    """Run `cmd`, appending its output to `log`: 'ok', 'fail' or 'timeout', and seconds."""
    env = dict(os.environ, CARGO_TARGET_DIR=str(plan.BUILDS[cwd]), **plan.ENV)
    t0 = time.monotonic()
    with open(log, "a") as out:
        out.write("$ " + " ".join(cmd) + "\n")
        out.flush()
        p = subprocess.Popen(
            cmd, cwd=cwd, env=env, stdout=out, stderr=subprocess.STDOUT, start_new_session=True
        )
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            rc = None
    status = "timeout" if rc is None else ("ok" if rc == 0 else "fail")
    secs = time.monotonic() - t0
    with open(log, "a") as out:
        out.write(f"# {status} in {secs:.1f} s\n")
    return status, secs


def cargo(module, what, file=None):
    """The cargo command that builds (`what` = 'build') or runs one of a module's test sets,
    with the feature that compiles `file` where it needs one (plan.FEATURES)."""
    config = [a for c in plan.CARGO_CONFIG for a in ("--config", c)]
    if file in plan.FEATURES:
        config += ["--features", plan.FEATURES[file]]
    tests = [a for t in plan.INTEGRATION[module] for a in ("--test", t)]
    if what == "build":
        return ["cargo", "test", "--no-run", "--lib", *tests, *config]
    if what == "unit":
        return ["cargo", "test", "--lib", *config, "--", f"{module}::"]
    return ["cargo", "test", *tests, *config]


def git(*args):
    return subprocess.check_output(["git", *args], cwd=plan.ROOT, text=True).strip()


def restore(wt):
    """The worktree `wt` as committed: the mutation reverted, and the failures proptest
    persisted (proptest-regressions/) dropped, so that no mutant's tests replay another's."""
    subprocess.check_call(["git", "checkout", "--", "."], cwd=wt)
    subprocess.check_call(["git", "clean", "-fdq"], cwd=wt)


def prepare(commit, wt):
    """The worktree `wt` at `commit` (any mutation an interrupted run left reverted) and its
    build folder, seeded with a build of the dependencies (this checkout's, or the sample's
    folder for the rerun) less the units of the workspace's own crates: cargo names those by
    package, not by path, and would take another tree's build of them as up to date."""
    if not wt.exists():
        git("worktree", "add", "--detach", str(wt), commit)
    restore(wt)
    subprocess.check_call(["git", "checkout", "--quiet", "--detach", commit], cwd=wt)
    build = plan.BUILDS[wt]
    seed = plan.ROOT / "target" / "debug" if wt == plan.WORKTREE else plan.BUILD / "debug"
    if not build.exists() and seed.exists():
        build.mkdir(parents=True)
        subprocess.check_call(["cp", "-a", "--reflink=auto", str(seed), str(build)])
        for own in (build / "debug" / ".fingerprint").glob("yinset-*"):
            shutil.rmtree(own)


def diffs(commit):
    """The mutants cargo-mutants lists in the worktree at the sample's `commit`, by name, with
    their diffs (listed once, then read from the build folder)."""
    listing = plan.BUILD.parent / f"list-{commit}.json"
    if not listing.exists():
        listing.write_text(json.dumps(plan.list_mutants(plan.WORKTREE, diffs=True)))
    return {m["name"]: m for m in json.loads(listing.read_text())}


def baseline(modules, commit, wt):
    """Seconds of each module's unit and integration tests on the unmutated tree (they must
    pass), measured once per commit and case count."""
    cases = plan.ENV.get("YINSET_CASES", "all")
    path = plan.BUILD.parent / f"baseline-{commit}-{cases}-cases.json"
    secs = json.loads(path.read_text()) if path.exists() else {}
    for m in modules:
        if m in secs:
            continue
        log = LOGS / f"baseline-{m}.log"
        log.unlink(missing_ok=True)
        for what in ("build", "unit", "integration"):
            status, t = run(cargo(m, what), wt, None, log)
            if status != "ok":
                sys.exit(f"baseline {what} of {m} failed: see {log}")
            secs.setdefault(m, {})[what] = round(t, 1)
        path.write_text(json.dumps(secs, indent=1))
        print(f"baseline {m}: {secs[m]}", flush=True)
    return secs


def mutate(mutant, wt):
    """Apply `mutant`'s one-hunk diff to `wt`: its removed lines, found verbatim (the match
    nearest the hunk's line, since the rerun's later tree may have moved them or changed the
    context around them), replaced by its added lines. Exits if they are not there."""
    body = mutant["diff"].split("\n@@ ", 1)[1].split("\n")
    start = int(body[0].split()[0].split(",")[0].lstrip("-"))
    hunk = body[1:]
    first = next(i for i, l in enumerate(hunk) if l[:1] in "-+")
    removed = [l[1:] for l in hunk if l.startswith("-")]
    added = [l[1:] for l in hunk if l.startswith("+")]
    path = wt / mutant["file"]
    lines = path.read_text().split("\n")
    at = [i for i in range(len(lines)) if lines[i : i + len(removed)] == removed]
    if not removed or not at:
        sys.exit(f"{mutant['name']}: its lines are not in {path}")
    i = min(at, key=lambda i: abs(i - (start - 1 + first)))
    lines[i : i + len(removed)] = added
    path.write_text("\n".join(lines))


def test(mutant, base, wt):
    """Apply `mutant` to `wt`, build, run its module's tests, revert: the outcome and the
    seconds."""
    module = plan.module_of(mutant["name"])
    log = LOGS / (hashlib.sha1(mutant["name"].encode()).hexdigest()[:12] + ".log")
    log.write_text(mutant["name"] + "\n" + mutant["diff"] + "\n")
    mutate(mutant, wt)
    t0 = time.monotonic()
    try:
        status, _ = run(cargo(module, "build", mutant["file"]), wt, 3600, log)
        if status != "ok":
            return "unviable", time.monotonic() - t0
        for what in ("unit", "integration"):
            limit = 3 * base[module][what] + 30
            status, _ = run(cargo(module, what, mutant["file"]), wt, limit, log)
            if status == "fail":
                return "caught", time.monotonic() - t0
            if status == "timeout":
                return "timeout", time.monotonic() - t0
        return "missed", time.monotonic() - t0
    finally:
        restore(wt)


def retest(names, by_name):
    """The triage's rerun: each named mutant (its diff at the sample's commit, patched with
    context) on this checkout's HEAD in plan.RETEST_TREE, where the tests added for the
    survivors are; one line per mutant appended to plan.TRIAGE."""
    head = git("rev-parse", "HEAD")
    prepare(head, plan.RETEST_TREE)
    base = baseline(sorted({plan.module_of(n) for n in names}), head, plan.RETEST_TREE)
    for name in names:
        outcome, secs = test(by_name[name], base, plan.RETEST_TREE)
        with open(plan.TRIAGE, "a") as f:
            cases = "capped" if "YINSET_CASES" in plan.ENV else "all"
            f.write(f"{name}\t{outcome}\tat {head[:12]}, {cases} cases, {secs:.0f} s\n")
        print(f"retest {outcome:8} {secs:5.0f} s  {name}", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--limit", type=int, help="test at most this many mutants in this run")
    ap.add_argument(
        "--mutant", action="append", help="test this sampled mutant first (repeatable)"
    )
    ap.add_argument(
        "--retest",
        action="store_true",
        help="rerun the missed mutants not yet triaged (or those of --mutant) on HEAD",
    )
    ap.add_argument(
        "--all-cases",
        action="store_true",
        help="property tests at their own case counts, as `cargo test` runs them (no cap)",
    )
    args = ap.parse_args()
    if args.all_cases:
        del plan.ENV["YINSET_CASES"]
    if shutil.which("cargo-mutants") is None:
        sys.exit("cargo-mutants is needed for the mutants' diffs: cargo install cargo-mutants --locked")
    commit, names = plan.read_sample()
    done = plan.read_results()
    first = args.mutant or []
    unknown = [n for n in first if n not in names]
    if unknown:
        sys.exit(f"not in the sample: {unknown}")
    LOGS.mkdir(parents=True, exist_ok=True)
    prepare(commit, plan.WORKTREE)
    by_name = diffs(commit)
    missing = [n for n in names if n not in by_name]
    if missing:
        sys.exit(f"{len(missing)} sampled mutants are not cargo-mutants' at {commit}: {missing[:3]}")
    if args.retest:
        triaged = plan.read_triage()
        todo = first or [n for n in names if done.get(n, ("",))[0] == "missed" and n not in triaged]
        retest(todo, by_name)
        return
    todo = [n for n in first + [n for n in names if n not in first] if n not in done]
    todo = todo[: args.limit]
    base = baseline(sorted({plan.module_of(n) for n in todo}), commit, plan.WORKTREE)
    for k, name in enumerate(todo, 1):
        outcome, secs = test(by_name[name], base, plan.WORKTREE)
        with open(plan.RESULTS, "a") as f:
            f.write(f"{name}\t{outcome}\t{secs:.0f}\n")
        print(f"[{len(done) + k}/{len(names)}] {outcome:8} {secs:5.0f} s  {name}", flush=True)


if __name__ == "__main__":
    main()
