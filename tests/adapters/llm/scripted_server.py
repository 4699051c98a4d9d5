"""The scripted OpenAI-compatible server of the LLM tests; it lives in `bench/scripted_llm.py`
so that `make bench` can run SafeGate's LLM path against it too."""

from bench.scripted_llm import Scripted, ScriptedServer, scripted_server

__all__ = ["Scripted", "ScriptedServer", "scripted_server"]
