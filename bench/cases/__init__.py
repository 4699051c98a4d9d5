"""The project's benchmark: `benchmark.jsonl`, built by `build_benchmark.py` from `data/`."""
