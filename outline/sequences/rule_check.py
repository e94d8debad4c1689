"""The rule-based exclusions of `make mutate` through the differential checker (issue 31): `make equivalence`
(`python -m outline.sequences.rule_check --per-rule 6`).

outline/mutate/mutation.py passes over, while drawing, the mutants its rules call unobservable (usage errors, a
backend's self-description and stimulus read-back, unread events and fields, faulty-variant branches, code
the switches leave unrun). A rule is code, not a mark, and covers thousands of mutants; a seeded sample of
each rule's mutants (every mutant mutmut writes for the references, found with mutmut's own
`create_mutations`, which runs nothing; the 40-minute map of scenarios is not needed) is built and driven
beside the reference in the marks' budget (equivalence.BUDGET). Overturned: the rule passed over a mutant
that changes what the driver interface shows. The counts per rule and each overturned mutant go to
reports/equivalence.json (`rules`) and its .md.
"""
from __future__ import annotations

import argparse
import multiprocessing
import random
import sys
import time
from pathlib import Path
from typing import Any

from outline.mutate import mutation

from . import equivalence
from .equivalence import ROOT, Site, budget_id, check_site, mutmut_sites, profiles_of


def rule_mutants(root: Path = ROOT) -> dict[str, list[Site]]:
    """Every mutant of the references that a rule (not a mark) passes over, by the rule."""
    by_rule: dict[str, list[Site]] = {}
    marked = set(mutation.equivalents())
    for path in sorted(p.relative_to(root).as_posix() for p in (root / "sut" / "reference").rglob("*.py")):
        for site in mutmut_sites(path, root):
            mutant = mutation.Mutant(site.name, mutation.part_of(path), path, site.line, site.before, site.after)
            reason = mutation.passed_over(mutant, marked)
            if reason and reason != "marked equivalent":
                by_rule.setdefault(reason, []).append(site)
    return by_rule


def draw(by_rule: dict[str, list[Site]], per_rule: int, seed: int) -> list[tuple[str, Site]]:
    rng = random.Random(seed)
    return [(reason, site) for reason in sorted(by_rule)
            for site in rng.sample(by_rule[reason], min(per_rule, len(by_rule[reason])))]


# The rules whose claim is that the reference never runs the code (a behaviour switch's untaken side, a function
# only such code calls): for them, "no stimulus of the budget, no replayed scenario and no line of the recorded
# conformance run ran it" is the evidence itself (as for a mark saying equivalence.NEVER_RUN), where for the
# others (run, but nobody reads it) it is none. One that ran and showed no difference is still confirmed
# (equivalent after all), with the rule's premise noted as broken.
NEVER_RUN_RULES = ("decided by the switches", "faulty-variant branch", "only a faulty variant calls it")


def judged(reason: str, result: dict[str, Any], ran_anywhere: bool | None) -> dict[str, Any]:
    """`ran_anywhere`: whether the recorded conformance run ran the line (None: not recorded with lines)."""
    if reason not in NEVER_RUN_RULES:
        return result
    if result["verdict"] == "confirmed":
        return {**result, "never_run": False}
    return equivalence.never_run(result, ran_anywhere)


def _job(job: tuple[str, Site]) -> dict[str, Any]:
    reason, site = job
    started = time.monotonic()
    result = check_site(site, profiles_of(site.path), equivalence.BUDGET)
    ran = equivalence.replay_ran_anywhere(site.path, equivalence.counted_line(site)) \
        if result["verdict"] == "unreached" and reason in NEVER_RUN_RULES else None
    result = judged(reason, result, ran)
    return {"rule": reason, "name": site.name, "path": site.path, "line": site.line, "before": site.before,
            "after": site.after, **result, "seconds": round(time.monotonic() - started, 1)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m outline.sequences.rule_check",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("--per-rule", type=int, default=6, help="mutants drawn from each rule (default 6)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", type=Path, default=equivalence.REPORT)
    parser.add_argument("--rule", action="append", default=[], metavar="REASON",
                        help="check only this rule's mutants (repeatable); the other rules' results are kept")
    args = parser.parse_args(argv)
    if not equivalence.have_mutmut():
        print("rule_check: needs mutmut to write the references' mutants (pip install -e '.[mutate]')")
        return 2
    by_rule = rule_mutants()
    unknown = [r for r in args.rule if r not in by_rule]
    if unknown:
        print(f"rule_check: no rule named {', '.join(map(repr, unknown))}; the rules: {', '.join(sorted(by_rule))}")
        return 2
    jobs = [job for job in draw(by_rule, args.per_rule, args.seed) if not args.rule or job[0] in args.rule]
    print("rule_check: mutants passed over by rule: " + ", ".join(f"{r} {len(s)}" for r, s in sorted(by_rule.items()))
          + f"; checking {len(jobs)} (seed {args.seed}, budget {budget_id()})", flush=True)
    started = time.monotonic()
    results = []
    with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
        for done, result in enumerate(pool.imap_unordered(_job, jobs), start=1):
            results.append(result)
            seen = result.get("difference", {})
            print(f"[{done}/{len(jobs)} {time.monotonic() - started:.0f}s] {result['verdict']}: {result['rule']}: "
                  f"{result['path']}:{result['line']} {result['before'][:50]} -> {result['after'][:50]}"
                  + (f"  ({seen.get('profile')}: {seen.get('observable')})" if seen else ""), flush=True)
    report = equivalence.load_report(args.out)
    kept = report.get("rules") or {}
    if args.rule and kept.get("budget") == budget_id():     # the other rules' results still hold
        results += [r for r in kept.get("mutants", []) if r["rule"] not in args.rule]
    per_rule: dict[str, dict[str, int]] = {}
    for reason, sites in by_rule.items():
        per_rule[reason] = {"mutants": len(sites), "checked": 0, "confirmed": 0, "overturned": 0, "unreached": 0}
    for r in results:
        if r["rule"] in per_rule:
            per_rule[r["rule"]]["checked"] += 1
            per_rule[r["rule"]][r["verdict"]] = per_rule[r["rule"]].get(r["verdict"], 0) + 1
    report["rules"] = {"per_rule": per_rule, "asked": args.per_rule, "seed": args.seed, "budget": budget_id(),
                       "mutants": sorted((r for r in results if r["rule"] in per_rule),
                                         key=lambda r: (r["rule"], r["path"], r["line"], r["after"]))}
    equivalence.write_report(report, args.out)
    overturned = sum(c["overturned"] for c in per_rule.values())
    unreached = sum(c.get("unreached", 0) for c in per_rule.values())
    print(f"rule_check: {overturned} of {len(results)} overturned, {unreached} unreached; {args.out} "
          f"({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
