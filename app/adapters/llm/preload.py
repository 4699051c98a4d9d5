"""Imported by the analysis pool's fork server when the analyzer uses an LLM: imports litellm
once (the safe way, `client.load_litellm`), so the workers forked from it do not each spend
seconds importing it on their first LLM call. Importing this module is all it does."""

from __future__ import annotations

from app.adapters.llm.client import load_litellm

load_litellm()
