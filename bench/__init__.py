"""SafeGate's evaluation, kept outside `app/`: benchmark cases, metrics and scoring.

`bench.case` holds the case model, `bench.metrics` the paper's metrics as pure functions,
`bench.score` loading a JSONL set, scoring it and rendering the report. `bench.perf` (owned
separately) holds the performance benchmarks.
"""
