"""Third evaluation set: 120 hand-written cases written independently of SafeGate's analyzer.

Build with `python -m bench.cases.third.build_third` from the repository root; see README.md.
"""
