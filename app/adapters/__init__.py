"""Adapters at the edge: code that talks to things we do not own (LLM providers)."""
