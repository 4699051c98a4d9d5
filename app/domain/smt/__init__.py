"""The Z3 adapter: the only package that imports z3.

In: formulas over `Facts` states. Out: Z3 encodings whose free variables are the unknown facts, and
proofs/satisfiability checks with counterexamples. A solver `unknown` or timeout is its own
outcome (UNKNOWN), which every caller must treat as failure.
"""

from app.domain.smt.encoder import Encoding, encode
from app.domain.smt.solver import (
    DEFAULT_TIMEOUT_MS,
    Claim,
    Outcome,
    ProofResult,
    Satisfiability,
    SatResult,
    prove,
    satisfiable,
    valid,
)
from app.domain.smt.symbolic import encode_symbolic

__all__ = [
    "DEFAULT_TIMEOUT_MS",
    "Claim",
    "Encoding",
    "Outcome",
    "ProofResult",
    "SatResult",
    "Satisfiability",
    "encode",
    "encode_symbolic",
    "prove",
    "satisfiable",
    "valid",
]
