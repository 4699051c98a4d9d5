"""`python -m bench run|score FILES...`: the evaluation command line (`bench/cli.py`)."""

from bench.cli import main

main()
