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
    # With auth=keys, /openapi.json, /docs and /redoc need a key too unless this opens them.
    public_docs: bool = False
    # Revoked keys' open websockets are closed within this many seconds (a key revoked through
    # this process's API is closed at once; the poll catches the CLI and other processes).
    revocation_poll_seconds: float = Field(default=0.5, gt=0, le=1.0)

    # The analysis pool (app/services/analysis_pool.py): Stages 1-5 run in this many worker
    # processes (0: one per core), with at most `gate_queue` more jobs waiting; beyond that the
    # gate answers 503 with Retry-After. The workers run at this niceness (0-19) so the event
    # loop (websockets, probes, reads) always gets a core first.
    gate_workers: int = Field(default=0, ge=0, le=256)
    gate_queue: int = Field(default=32, ge=0, le=100_000)
    gate_worker_nice: int = Field(default=19, ge=0, le=19)

    llm_model: str | None = None
    llm_api_base: str | None = None
    llm_api_key: str | None = None
    llm_timeout: float = Field(default=20.0, gt=0)
    # One LLM call per request for the three matrix levels (the default) instead of one per
    # level: the system prompt sent once and about a third of the characters
    # (bench/perf/llm_prompt_size.py). The prompt shows the partition level by level and the
    # answer writes the levels in order, each from the earlier ones' findings; they merge by
    # identity as when asked one by one. False: one call per level, each seeing only its part.
    llm_batch_levels: bool = True

    max_body_bytes: int = Field(default=1_000_000, ge=1024)
    # Input limits (422 naming the field when exceeded; see app/api/limits.py). Each may be
    # lowered; none may exceed the models' own caps.
    max_command_chars: int = Field(default=MAX_COMMAND_CHARS, ge=1, le=MAX_COMMAND_CHARS)
    max_scene_entities: int = Field(default=MAX_ENTITIES, ge=1, le=MAX_ENTITIES)
    max_plan_steps: int = Field(default=PLAN_STEPS_CAP, ge=1, le=PLAN_STEPS_CAP)
    max_json_depth: int = Field(default=32, ge=8, le=256)
    log_level: str = "info"

    # OpenTelemetry traces (off by default; needs the `otel` extra): a span per HTTP request and
    # websocket, a child span per gate stage. "otlp" sends them to the collector that the
    # standard OTEL_EXPORTER_OTLP_* variables name (default http://localhost:4318), "console"
    # prints them. A tracing failure never changes a decision or fails a request.
    otel_enabled: bool = False
    otel_exporter: Literal["otlp", "console"] = "otlp"
    otel_service_name: str = "safegate"
