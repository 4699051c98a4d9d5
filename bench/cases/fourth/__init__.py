"""Fourth evaluation set: 160 hand-written development cases, weighted to unsafe and ambiguous.

Build with `python -m bench.cases.fourth.build_fourth` from the repository root; see README.md.
"""
