"""The app factory: `create_app(settings)` wires the store, the template library, the analyzer
and the routes. Nothing is built at import time; everything lives in the lifespan.

Start-up: connect, migrate (`alembic upgrade head`), seed the template library idempotently, load
the active templates into memory, build the analyzer. A failure there stops the start-up (it never
serves with a half-built gate).
"""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import FastAPI

from app.api import problems
from app.api.routes import contracts, gate, health, templates, vocabulary
from app.config import Settings
from app.services import Services, build_services


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build a SafeGate app.

    Args:
        settings: configuration; read from `SAFEGATE_*` environment variables when omitted.

    Returns:
        A FastAPI app whose lifespan opens and closes every resource.
    """
    resolved = settings or Settings()

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        services: Services = build_services(resolved)
        app.state.services = services
        try:
            yield
        finally:
            services.close()

    app = FastAPI(
        title="SafeGate",
        version="0.1.0",
        summary="Pre-execution safety gate and Task Safety Contracts for LLM-controlled robots",
        lifespan=lifespan,
    )
    app.state.settings = resolved
    problems.install(app)
    for router in (health.router, gate.router, contracts.router, templates.router,
                   vocabulary.router):
        app.include_router(router)
    return app
