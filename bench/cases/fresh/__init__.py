"""An independent evaluation set (`fresh.jsonl`), written without sight of the analyzer or the
main benchmark, to measure how the gate generalises; built by `build_fresh.py`."""
