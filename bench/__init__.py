"""SafeGate's evaluation, kept outside the service package `app` (which never imports it).

`python -m bench run|score FILES` is its command line (`bench.cli`); `bench.case` holds the case
model, `bench.metrics` the paper's metrics as pure functions, `bench.score` loading a JSONL set,
scoring it and rendering the report, `bench.methods` the methods compared (SafeGate through
POST /gate, the baselines of `bench.baselines`, among them the LLM classifier), and
`bench.fingerprint` a hash of SafeGate's decisions per case set. `bench.perf` holds the
performance benchmarks. Runs from a source checkout with the `bench` extra (scipy, matplotlib).
"""
