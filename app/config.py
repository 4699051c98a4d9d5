"""Settings: every knob is a `SAFEGATE_*` environment variable (pydantic-settings).

The defaults are the embedded mode: SQLite in a local file, the offline symbolic analyzer, no LLM,
no network, open endpoints on 127.0.0.1. Tests build their own `Settings(...)`; nothing reads the
environment at import time.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import Field
from pydantic_settings import BaseSettings, SettingsConfigDict

from app.domain.models import Severity
from app.domain.models.request import MAX_COMMAND_CHARS, MAX_ENTITIES

# The most a plan may have, whatever the settings say (the /verify model's own cap).
PLAN_STEPS_CAP = 1000

REPO_ROOT = Path(__file__).resolve().parent.parent


class Settings(BaseSettings):
    """SafeGate's configuration."""

    model_config = SettingsConfigDict(env_prefix="SAFEGATE_", extra="ignore")

    database_url: str = "sqlite:///./safegate.db"
    templates_dir: Path = REPO_ROOT / "templates_db"
    migrate_on_startup: bool = True
    seed_on_startup: bool = True

    analyzer: Literal["symbolic", "llm", "ensemble"] = "symbolic"
    theta: Severity = Severity.HIGH
    max_verify_attempts: int = Field(default=3, ge=1)
    solver_timeout_ms: int = Field(default=2000, ge=10)

    auth: Literal["open", "keys"] = "open"

    llm_model: str | None = None
    llm_api_base: str | None = None
    llm_api_key: str | None = None
    llm_timeout: float = Field(default=20.0, gt=0)

    max_body_bytes: int = Field(default=1_000_000, ge=1024)
    # Input limits (422 naming the field when exceeded; see app/api/limits.py). Each may be
    # lowered; none may exceed the models' own caps.
    max_command_chars: int = Field(default=MAX_COMMAND_CHARS, ge=1, le=MAX_COMMAND_CHARS)
    max_scene_entities: int = Field(default=MAX_ENTITIES, ge=1, le=MAX_ENTITIES)
    max_plan_steps: int = Field(default=PLAN_STEPS_CAP, ge=1, le=PLAN_STEPS_CAP)
    max_json_depth: int = Field(default=32, ge=8, le=256)
    log_level: str = "info"
