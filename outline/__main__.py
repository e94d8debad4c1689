"""python -m outline {check,trace,new,campaign,assertions}: consistency, traceability, new items and generated fault
campaigns of the test outline."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from outline.tree.paths import REPO, Tree


def _step_modules(tree: Tree, given: list[str] | None) -> list[str]:
    if given:
        return given
    sys.path.insert(0, str(tree.root))
    from steps import STEP_MODULES

    return list(STEP_MODULES)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m outline",
        description="Test-outline tools: the registry (features/registry.yaml), the feature files, the step "
        "library and docs/requirements.md must agree.",
    )
    parser.add_argument("--root", default=str(REPO.root), help="repository root (default: %(default)s)")
    sub = parser.add_subparsers(dest="command", required=True, metavar="{check,trace,new,campaign,assertions,steps}")

    check = sub.add_parser(
        "check",
        help="fail on any inconsistency, one 'file:line: problem' line each",
        description="Fail (exit 1) when a feature file and the registry disagree (unlisted or missing files, "
        "misplaced files, @item/@req tags vs registry, undefined requirement IDs, titles not starting "
        "with the item ID, duplicate titles), when a step matches no step definition or several, or when "
        "a required_coverage ID is carried by no scenario, or (with out_of_scope in the registry) a requirement "
        "is claimed by no item and not listed there with a reason. Warns when docs/requirements.md differs from "
        "the shared copy.",
    )
    check.add_argument(
        "--step-module",
        action="append",
        metavar="MODULE",
        help="step-definition module to load (repeatable; default: steps.STEP_MODULES)",
    )
    check.add_argument("--no-steps", action="store_true", help="skip matching steps to step definitions")

    trace = sub.add_parser(
        "trace",
        help="requirement -> items -> scenarios, item -> requirements, coverage levels (text, Markdown, HTML, "
        "an Allure entry)",
        description="Traceability tables, from the scenarios' @req tags and the registry's partly notes. "
        "Rich tables on a terminal, tab-separated text otherwise.",
    )
    trace.add_argument("--results", metavar="DIR", help="allure results directory: show each scenario's last status")
    trace.add_argument("--md", metavar="FILE", help="write the matrix as Markdown (e.g. reports/traceability.md)")
    trace.add_argument("--html", metavar="FILE", help="write the matrix as an HTML page")
    trace.add_argument("--allure", metavar="DIR", help="add the HTML page to these allure results as one entry, "
                       "'Traceability matrix' (failed when a requirement is covered by nothing)")

    new = sub.add_parser(
        "new",
        help="add a test item: a feature-file skeleton from the step library and its registry entry",
        description="Writes features/<class>/<category>/<ID>.feature (the next free ID) with a Background for "
        "the train profile and one @pending scenario, and adds the item to features/registry.yaml. Asks for "
        "what is not given when run in a terminal.",
    )
    new.add_argument("--class", dest="cls", metavar="CLASS", help="test class, e.g. function")
    new.add_argument("--category", help="category of the class, e.g. control")
    new.add_argument("--title", help="what the item checks, in a few words")
    new.add_argument("--req", help="requirement IDs it verifies, the primary first: CMD-02,PRO-01")
    new.add_argument("--profile", default="crh2", help="train profile (default: %(default)s)")

    sub.add_parser("assertions", help="how many Then assertions the features make, by what backs them "
                   "(a requirement or a project decision), per profile: the README's table")
    steps = sub.add_parser(
        "steps",
        help="the step catalogue: every sentence of the step library, its parameters, Chinese twin, what it does",
        description="Lists the step sentences whose text (English or Chinese), module, driver calls or trace event "
        "kinds contain every WORD (all of them without WORDS): parameter types and allowed values, the Chinese "
        "twin, the driver calls it makes and the contract's event kinds it reads, and a line of a feature that "
        "uses it. --md writes the whole catalogue as Markdown (docs/steps.md).",
    )
    steps.add_argument("words", nargs="*", metavar="WORD", help="words every listed step contains (any case)")
    steps.add_argument("--lang", choices=("en", "zh-CN"), default="en", help="the sentences to show first")
    steps.add_argument("--md", metavar="FILE", help="write the whole catalogue as Markdown to FILE")
    campaign = sub.add_parser(
        "campaign",
        help="write the fault-campaign features (F-NET-30..34) from the SUT's own fault space",
        description="Reads the boards, ring spans and supplies (the metro train's units, boards, modules, "
        "devices and bus lines) through the driver and writes each campaign's feature file: one scenario per "
        "single fault (or pair), its expectation the design's for that kind of fault (outline/campaigns/campaign.py, "
        "outline/campaigns/metro_campaign.py). --check compares with the checked-in files instead (exit 1 if they differ).",
    )
    campaign.add_argument("--sut", default="reference", help="SUT backend to read the fault space from "
                          "(default: %(default)s)")
    campaign.add_argument("--check", action="store_true", help="compare, write nothing")

    args = parser.parse_args(argv)
    tree = Tree.at(args.root)
    if args.command == "steps":
        from outline.tree.catalogue import entries, render_markdown, render_text

        found = entries(_step_modules(tree, None), tree.root / "features")
        if args.md:
            Path(args.md).write_text(render_markdown(found), encoding="utf-8")
            print(f"wrote {args.md} ({len(found)} step definitions)")
            return 0
        chosen = [e for e in found if e.matches(args.words)
                  and (args.lang != "zh-CN" or e.chinese)]
        if not chosen:
            print(f"no step sentence contains {' '.join(args.words)!r}", file=sys.stderr)
            return 1
        print(render_text(chosen, args.lang))
        print(f"\n{len(chosen)} of {len(found)} step definitions", file=sys.stderr)
        return 0
    if args.command == "assertions":
        from outline.tree.assertions import table

        print(table(tree.root / "features"))
        return 0
    if args.command == "campaign":
        from outline.campaigns.campaign import run as campaign_run

        sys.path.insert(0, str(tree.root))
        return campaign_run(tree.root, args.sut, args.check)
    if args.command == "check":
        from outline.tree.check import run

        return run(tree, None if args.no_steps else _step_modules(tree, args.step_module))
    if args.command == "new":
        from outline.tree.new_item import run as new_item

        return new_item(tree, args.cls, args.category, args.title, args.req, args.profile)
    from outline.tracing.render import run

    return run(tree, args.results, md=args.md, html=args.html, allure=args.allure)


if __name__ == "__main__":
    try:
        sys.exit(main())
    except BrokenPipeError:  # `python -m outline trace | head`: the reader left, nothing more to say
        sys.stderr.close()
        sys.exit(1)
