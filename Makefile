# SafeGate: two commands do all the set-up on a fresh machine: `make run` and `make test`.
PY ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test lint install browsers bench perf sim clean

$(STAMP): pyproject.toml
	$(PY) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[dev]'
	touch $(STAMP)

install: $(STAMP)

## Serve SafeGate on 127.0.0.1:8000 (SQLite file, offline symbolic analyzer, no network).
run: $(STAMP)
	$(BIN)/safegate serve --host 127.0.0.1 --port 8000

## Headless Chromium and its driver for the browser tests, from Debian's apt (CI runs as root).
## Outside CI a failed install only warns (the browser tests then skip, saying why); in CI it fails.
browsers:
	@command -v chromium >/dev/null && command -v chromedriver >/dev/null || \
	  (apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y chromium chromium-driver) || \
	  { if [ -n "$$CI" ]; then echo "browsers: cannot install chromium in CI" >&2; exit 1; \
	    else echo "browsers: could not install chromium (needs root and apt);" \
	      "the browser tests will be skipped" >&2; fi; }

## Run every test (SQLite and PostgreSQL for real, the curator page in headless Chromium),
## then the static checks.
test: $(STAMP) browsers
	$(BIN)/python -m pytest
	$(MAKE) --no-print-directory lint

lint: $(STAMP)
	$(BIN)/ruff check app bench tests $(wildcard sim)
	$(BIN)/mypy app
	$(BIN)/lint-imports

## The paper's evaluation: every method on the benchmark; report, JSON and plots from scratch
## in bench/reports/benchmark/ (embedded analyzer, no network; the LLM classifier runs only
## when SAFEGATE_LLM_MODEL is set).
bench: $(STAMP)
	$(BIN)/safegate bench run bench/cases/benchmark.jsonl --name benchmark

## Performance benchmarks: each prints a table.
perf: $(STAMP)
	@for f in bench/perf/*.py; do echo "== $$f"; $(BIN)/python $$f || exit 1; done

## Simulation: 30 hazard scenarios + safe controls end to end in the symbolic AI2-THOR household.
sim: $(STAMP)
	$(BIN)/python -m sim

clean:
	rm -rf $(VENV) safegate.db build *.egg-info
