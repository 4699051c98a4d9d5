"""SafeGate: a pre-execution safety gate for LLM-controlled robots."""
