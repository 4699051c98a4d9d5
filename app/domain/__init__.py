"""The pure domain core: the paper's six stages, with no web, database or LLM imports."""
