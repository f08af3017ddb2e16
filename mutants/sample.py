#!/usr/bin/env python3
"""Draw the mutation sample: a seeded uniform sample, without replacement, of cargo-mutants'
mutants of the examined modules at the checked-out commit, written to mutants/sample.txt.

    python3 mutants/sample.py --seed 58 --size 440

The full list comes from `cargo mutants --list --json` run on this checkout with the globs of
mutants/plan.py (the configuration file is ignored, so the list does not depend on it).
"""

import argparse
import json
import random
import subprocess
import sys

import plan


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, required=True)
    ap.add_argument("--size", type=int, default=440)
    ap.add_argument("--out", default=str(plan.ROOT / "mutants" / "sample.txt"))
    args = ap.parse_args()

    head = subprocess.check_output(["git", "rev-parse", "HEAD"], cwd=plan.ROOT, text=True).strip()
    dirty = subprocess.check_output(
        ["git", "status", "--porcelain", "--", "src"], cwd=plan.ROOT, text=True
    )
    if dirty:
        sys.exit("src/ has uncommitted changes: the sample must be drawn on a commit")
    names = [m["name"] for m in plan.list_mutants(plan.ROOT, diffs=False)]
    if len(set(names)) != len(names):
        sys.exit("cargo-mutants gave two mutants the same name")
    names.sort()
    drawn = sorted(random.Random(args.seed).sample(names, args.size))
    per_module = {m: sum(plan.module_of(n) == m for n in names) for m in plan.MODULES}
    with open(args.out, "w") as f:
        f.write(f"# commit {head}\n")
        f.write(
            f"# {args.size} of the {len(names)} mutants of "
            + ", ".join(f"src/{m} ({k})" for m, k in per_module.items())
            + f", drawn uniformly by mutants/sample.py --seed {args.seed} --size {args.size}.\n"
        )
        f.write(
            "# They are tested on that commit, in a worktree checked out at it\n"
            "# (mutants/run.py), whatever the branch holds since.\n"
        )
        for n in drawn:
            f.write(n + "\n")
    print(f"{args.size} of {len(names)} mutants drawn on {head[:12]} into {args.out}")


if __name__ == "__main__":
    main()
