# Train network conformance suite (CRH2, metro TCN, ATP). `make` alone lists the targets.
#   PYTEST_ARGS="..."  extra pytest arguments for the conformance run, e.g. PYTEST_ARGS="--item F-NET-03 -x"
#   SUT=...            backend for --sut (reference, or package.module:Class); unset = the suite's default
#   JOBS=N             pytest-xdist workers (default auto = one per core; JOBS=1 runs in one process)

.DEFAULT_GOAL := help
SHELL := bash

PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
VENV_STAMP := $(VENV)/.installed
NODE_STAMP := node_modules/.installed
# Debian's Chromium, for the test that opens a generated report headless (tests/test_report_in_browser.py).
CHROMIUM := /usr/bin/chromium
SUDO := $(if $(filter 0,$(shell id -u)),,sudo)
RESULTS := reports/allure-results
HTML := reports/html
# What the steps of make test's conformance run asked of the SUT, held against sut/contract/*.yaml.
CONTRACT_RECORD := reports/contract-record.json
OWN_TESTS_XML := reports/own-tests.xml

# Bytecode caches even where the machine's environment turns them off (PYTHONDONTWRITEBYTECODE=1, as on
# this project's CI machines): make test starts dozens of Python processes, and each would compile the
# project's modules again (~0.3 s each; __pycache__ is ignored by git).
unexport PYTHONDONTWRITEBYTECODE

PYTEST_ARGS ?=
SUT ?=
# Scenarios are independent simulations: spread them over every core (JOBS=1 for a single process).
JOBS ?= auto
XDIST := $(if $(filter 1,$(JOBS)),-p no:xdist,-n $(JOBS))
# The project's own tests: the costliest start first (tests/conftest.py orders them by their cost mark), and
# --dist loadgroup hands them out one by one as workers free up (no test carries a group: each is its own
# unit). The default, load, assigns the last items ahead of time: one worker then ran a queue of costly
# tests alone for minutes (own tests 10 min 15 s against 6 min 8 s, worksteal 6 min 27 s, 2026-11-25).
XDIST_TESTS := $(if $(filter 1,$(JOBS)),-p no:xdist,-n $(JOBS) --dist loadgroup)
SUT_ARG := $(if $(SUT),--sut $(SUT))

MUTANTS ?= 200
SEED ?= 1
MUTATE_STAMP := $(VENV)/.mutate-installed
BENCH_STAMP := $(VENV)/.bench-installed

SHARDS ?= 4
SHARD ?= 1
SHARD_RESULTS := reports/shards

CAMPAIGN_ITEMS := F-NET-30,F-NET-31,F-NET-32,F-NET-33,F-NET-34,F-ILK-10,F-ATP-14,F-NET-35,F-ATP-15
# Random sequences per invariant in make campaign (the features' own budget, 10-100, in make test/report).
SEQUENCES ?= 400

.PHONY: help report test check trace clean distclean mutate shard merge durations campaign performance req-sweep equivalence

help: ## list the targets
	@echo "Train network conformance suite: CRH2, metro TCN, ATP (PYTEST_ARGS=... and SUT=... pass through to pytest)"
	@grep -E '^[a-z][a-z-]*:.*## ' $(MAKEFILE_LIST) | sed -E 's/^([a-z-]+):.*## (.*)/  make \1\t\2/' | expand -t 20

report: $(VENV_STAMP) $(NODE_STAMP) ## run every feature, build reports/html/index.html (one file; a copy named by commit to archive) and reports/traceability.{md,html}, print a summary
	@rm -rf $(RESULTS) $(HTML) && mkdir -p $(RESULTS)
	@# Keep pytest's status, still build the report, exit with that status at the end.
	@$(PY) -m pytest features $(XDIST) --alluredir $(RESULTS) $(SUT_ARG) $(PYTEST_ARGS); status=$$?; \
	$(PY) -m outline trace --results $(RESULTS) --md reports/traceability.md --html reports/traceability.html \
		--allure $(RESULTS) || exit $$?; \
	$(PY) -m outline.mutate.mutation --to-allure $(RESULTS) || exit $$?; \
	npx --no-install allure generate $(RESULTS) --output $(HTML) >/dev/null || exit $$?; \
	$(PY) -m outline.report.allure_html $(HTML)/index.html; \
	archive=reports/conformance-$$(git rev-parse --short HEAD 2>/dev/null || echo local).html; \
	rm -f reports/conformance-*.html; ln -f $(HTML)/index.html $$archive 2>/dev/null || cp $(HTML)/index.html $$archive; \
	echo "report: $(HTML)/index.html (one self-contained file; to archive: $$archive)"; \
	$(PY) -m outline.report.summary $(RESULTS); \
	exit $$status

test: $(VENV_STAMP) $(MUTATE_STAMP) $(NODE_STAMP) $(CHROMIUM) ## the project's own tests, the whole conformance run, then the contract check (every catalogue entry read by some step); fails if any fails
	@$(PY) -m pytest tests $(XDIST_TESTS) --durations=15 --junitxml=$(OWN_TESTS_XML); t=$$?; \
	rm -f $(CONTRACT_RECORD)*; \
	$(PY) -m pytest features $(XDIST) $(SUT_ARG) $(PYTEST_ARGS) --contract-record $(CONTRACT_RECORD); f=$$?; \
	$(PY) -m sut.contract check $(CONTRACT_RECORD) $(if $(or $(PYTEST_ARGS),$(SUT)),--partial); c=$$?; \
	echo "make test: tests exit $$t, conformance run exit $$f, contract check exit $$c"; \
	[ $$t -eq 0 ] && [ $$f -eq 0 ] && [ $$c -eq 0 ]

mutate: $(VENV_STAMP) $(MUTATE_STAMP) ## mutation testing of the references (MUTANTS=200 SEED=1, RESUME=1 keeps the last run's kills): kill rate per reference, reports/mutation.md
	$(PY) -m outline.mutate.mutation --mutants $(MUTANTS) --seed $(SEED) $(if $(filter auto,$(JOBS)),,--jobs $(JOBS)) $(if $(RESUME),--resume)

# ~30 min on two cores for every mark (the budget: outline/sequences/equivalence.py); a mark already checked in
# the current budget is not run again unless ALL=1.
equivalence: $(VENV_STAMP) $(MUTATE_STAMP) ## the differential checker on each mark of sut/reference/EQUIVALENT_MUTANTS.txt not yet checked (ALL=1: every mark) and on PER_RULE=6 mutants of each rule-based exclusion: reports/equivalence.json/.md; an overturned mark moves to OVERTURNED_MUTANTS.txt
	$(PY) -m outline.sequences.replay --if-stale
	$(PY) -m outline.sequences.equivalence --move $(if $(ALL),--all) $(if $(filter auto,$(JOBS)),,--jobs $(JOBS))
	$(PY) -m outline.sequences.rule_check --per-rule $(or $(PER_RULE),6) $(if $(filter auto,$(JOBS)),,--jobs $(JOBS))

# No Allure report: 16,120 rows make one of ~400 MB even with evidence for failures only (3160 rows: 82 MB).
# A campaign's report: make report PYTEST_ARGS="--item F-NET-32 --evidence failed".
campaign: $(VENV_STAMP) ## the fault campaigns in full (every single and every double fault, 8 and 16 cars), and the random-sequence invariants with SEQUENCES sequences each: verdicts and each failing row
	$(PY) -m pytest features $(XDIST) -q -rf --item $(CAMPAIGN_ITEMS) --sequences $(SEQUENCES) $(SUT_ARG) $(PYTEST_ARGS)

req-sweep: $(VENV_STAMP) ## run `pytest features --req <ID>` against every faulty variant, ID the requirement it breaks: each must exit 1 (make test runs a sample)
	REQ_SWEEP=1 $(PY) -m pytest tests/test_req_selection.py $(XDIST_TESTS) -q -rf $(PYTEST_ARGS)

shard: $(VENV_STAMP) ## one shard of the conformance run (SHARDS=4 SHARD=1, balanced by .test_durations): allure results in reports/shards/<SHARD>
	@rm -rf $(SHARD_RESULTS)/$(SHARD) && mkdir -p $(SHARD_RESULTS)/$(SHARD)
	$(PY) -m pytest features $(XDIST) --splits $(SHARDS) --group $(SHARD) --splitting-algorithm least_duration --alluredir $(SHARD_RESULTS)/$(SHARD) \
		$(SUT_ARG) $(PYTEST_ARGS)

merge: $(VENV_STAMP) $(NODE_STAMP) ## one report from every shard's results (reports/shards/*, copied from the machines that ran them): reports/html/index.html
	@test -n "$$(ls -d $(SHARD_RESULTS)/*/ 2>/dev/null)" || { echo "no shard results under $(SHARD_RESULTS)/"; exit 1; }
	@rm -rf $(HTML)
	npx --no-install allure generate $(SHARD_RESULTS)/*/ --output $(HTML) >/dev/null
	@$(PY) -m outline.report.allure_html $(HTML)/index.html
	@echo "report: $(HTML)/index.html ($$(ls -d $(SHARD_RESULTS)/*/ | wc -l) shards)"
	@$(PY) -m outline.report.summary $(SHARD_RESULTS)/*/

durations: $(VENV_STAMP) ## record each scenario's duration in .test_durations (one process), which make shard balances by
	$(PY) -m pytest features -p no:xdist -q --store-durations --durations-path .test_durations $(SUT_ARG)

# Only draws: the bench scripts measure, each appending its row with --record (docs/performance.md says how).
performance: $(VENV_STAMP) $(BENCH_STAMP) ## docs/performance.md and docs/performance.svg from the benchmark history, bench/history.jsonl: today's figures against the targets, and the history plotted
	$(PY) -m bench.report

check: $(VENV_STAMP) ## python -m outline check: registry, features, steps and requirements agree
	$(PY) -m outline check

trace: $(VENV_STAMP) ## python -m outline trace: requirement <-> item <-> scenario tables
	$(PY) -m outline trace $(if $(wildcard $(RESULTS)),--results $(RESULTS))

clean: ## remove reports and caches (keeps .venv and node_modules)
	rm -rf $(RESULTS) $(HTML) $(SHARD_RESULTS) reports/history.jsonl reports/contract-record.json* $(OWN_TESTS_XML) reports/traceability.* reports/mutation.* reports/conformance-*.html mutants .pytest_cache .hypothesis
	find . -name __pycache__ -type d -not -path './$(VENV)/*' -not -path './node_modules/*' -prune -exec rm -rf {} +

distclean: clean ## also remove .venv and node_modules
	rm -rf $(VENV) node_modules *.egg-info

$(VENV_STAMP): pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet -e .
	touch $@

$(MUTATE_STAMP): pyproject.toml
	$(PY) -m pip install --quiet -e '.[mutate]'
	touch $@

$(BENCH_STAMP): pyproject.toml
	$(PY) -m pip install --quiet -e '.[bench]'
	touch $@

$(NODE_STAMP): package.json package-lock.json
	npm ci --no-audit --no-fund --loglevel=error
	touch $@

# Installed once, when missing (a fresh machine's package lists may be empty or stale: update first).
$(CHROMIUM):
	$(SUDO) apt-get update -qq
	$(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium >/dev/null
	test -x $@
