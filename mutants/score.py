#!/usr/bin/env python3
"""The mutation score of the sample so far, per module and overall, with its 95 % Wilson
score interval, as a Markdown table.

    python3 mutants/score.py

The score is the share of viable mutants detected: caught or timed out, over caught, timed
out and missed (unviable mutants do not build and are left out). The interval treats the
viable mutants tested as a uniform sample of the module's viable mutants.

The second table is the score after triage (mutants/triage.txt): a missed mutant that the
rerun on a later commit caught counts as caught, one argued equivalent is left out, one that
does not build under the feature its file needs counts as unviable.
"""

import math

import plan

Z = 1.959963984540054  # the 97.5 % quantile of the standard normal distribution


def wilson(k, n):
    """The 95 % Wilson score interval of a proportion with k successes in n trials."""
    if n == 0:
        return (0.0, 1.0)
    p = k / n
    centre = p + Z * Z / (2 * n)
    half = Z * math.sqrt(p * (1 - p) / n + Z * Z / (4 * n * n))
    return ((centre - half) / (1 + Z * Z / n), (centre + half) / (1 + Z * Z / n))


def row(label, outcomes, sampled):
    count = {o: sum(x == o for x in outcomes) for o in plan.OUTCOMES}
    detected = count["caught"] + count["timeout"]
    viable = detected + count["missed"]
    lo, hi = wilson(detected, viable)
    score = f"{100 * detected / viable:.1f} %" if viable else "–"
    interval = f"{100 * lo:.1f} – {100 * hi:.1f} %" if viable else "–"
    return (
        f"| {label} | {len(outcomes)} of {sampled} | {count['unviable']} | {count['caught']} "
        f"| {count['timeout']} | {count['missed']} | {score} | {interval} |"
    )


def triaged(outcome, verdict):
    """The outcome after triage: the rerun's for a missed mutant, None for an equivalent one."""
    if outcome != "missed" or verdict is None:
        return outcome
    return None if verdict == "equivalent" else verdict


def table(names, outcome):
    """The score table of the sampled `names` whose outcome (None: left out) is known."""
    print("| module | tested | unviable | caught | timeout | missed | score | 95 % Wilson |")
    print("|---|---|---|---|---|---|---|---|")
    for m in plan.MODULES + [None]:
        mine = [n for n in names if m is None or plan.module_of(n) == m]
        got = [outcome(n) for n in mine]
        print(row(f"`{m}`" if m else "all", [o for o in got if o is not None], len(mine)))


def main():
    commit, names = plan.read_sample()
    results = plan.read_results()
    triage = plan.read_triage()
    print(f"Sample at commit {commit[:12]}: {len(results)} of {len(names)} mutants tested.\n")
    table(names, lambda n: results[n][0] if n in results else None)
    count = {v: sum(x == v for x, _ in triage.values()) for v in ["equivalent", *plan.OUTCOMES]}
    print(
        f"\nAfter triage ({len(triage)} survivors: {count['equivalent']} equivalent, "
        f"{count['unviable']} unviable, {count['caught'] + count['timeout']} caught and "
        f"{count['missed']} missed on a rerun or since):\n"
    )
    table(
        names,
        lambda n: triaged(results[n][0], triage.get(n, (None,))[0]) if n in results else None,
    )


if __name__ == "__main__":
    main()
