"""Fixtures for the evaluation's tests: the LLM adapter's scripted server, for the classifier.

The LLM classifier baseline (`bench/baselines/llm_classifier.py`) talks to the same scripted
OpenAI-compatible server on loopback as the adapter's own tests, under the same guard that
refuses any connection leaving the machine; the fixtures are those of `tests/adapters/llm/`.
"""

from tests.adapters.llm.conftest import llm_server, make_client, no_internet

__all__ = ["llm_server", "make_client", "no_internet"]
