# SafeGate: two commands do all the set-up on a fresh machine: `make run` and `make test`.
PY ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test lint install bench perf clean

$(STAMP): pyproject.toml
	$(PY) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[dev]'
	touch $(STAMP)

install: $(STAMP)

## Serve SafeGate on 127.0.0.1:8000 (SQLite file, offline symbolic analyzer, no network).
run: $(STAMP)
	$(BIN)/safegate serve --host 127.0.0.1 --port 8000

## Run every test (SQLite and PostgreSQL for real), then the static checks.
test: $(STAMP)
	$(BIN)/python -m pytest
	$(MAKE) --no-print-directory lint

lint: $(STAMP)
	$(BIN)/ruff check app bench sim tests
	$(BIN)/mypy app
	$(BIN)/lint-imports

## Performance benchmarks: each prints a table.
perf: $(STAMP)
	@for f in bench/perf/*.py; do echo "== $$f"; $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) safegate.db build *.egg-info
