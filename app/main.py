"""The app factory: `create_app(settings)` wires the store, the template library, the analyzer
and the routes. Nothing is built at import time; everything lives in the lifespan.

Start-up: connect, migrate (`alembic upgrade head`), seed the template library idempotently, load
the active templates into memory, build the analyzer and every service (`build_components`), the
gatekeeper that checks API keys, start the analysis pool's workers (Stages 1-5 run there, off the
event loop), the monitoring service (on PostgreSQL with the LISTEN/NOTIFY fan-out that carries
halts to the other replicas' listeners) and the watch that closes websockets of revoked keys.
Each lands on `app.state`, from where `app/api/deps.py` hands it to the routes that use it.
A failure there stops the start-up (it never serves with a half-built gate).
"""

from __future__ import annotations

from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import Any

import anyio.to_thread
from fastapi import Depends, FastAPI

from app.adapters.tracing import start_tracing
from app.api import docs, observability, openapi, problems, revocations
from app.api.auth import Gatekeeper, RouteAccess
from app.api.deps import check_access, robot_writes
from app.api.limits import json_body_within_limits
from app.api.routes import (
    contracts,
    curator,
    extensions,
    gate,
    health,
    keys,
    monitor,
    templates,
    verify,
    vocabulary,
)
from app.config import Settings
from app.metrics import Metrics
from app.services import Components, build_components
from app.services.analysis_pool import AnalysisPool
from app.services.monitoring_fanout import monitoring_for


def create_app(settings: Settings | None = None, *, span_exporter: Any = None) -> FastAPI:
    """Build a SafeGate app.

    Args:
        settings: configuration; read from `SAFEGATE_*` environment variables when omitted.
        span_exporter: with `otel_enabled`, an OpenTelemetry span exporter to use instead of
            the configured one (tests and benchmarks keep spans in memory).

    Returns:
        A FastAPI app whose lifespan opens and closes every resource.
    """
    resolved = settings or Settings()
    metrics = Metrics()
    tracing = start_tracing(resolved, span_exporter)

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        components: Components = build_components(resolved, metrics=metrics)
        app.state.components = components
        # Read once every route is in place, routers' dependencies included.
        app.state.gatekeeper = Gatekeeper(components.keys, RouteAccess(app.routes),
                                          mode=resolved.auth, public_docs=resolved.public_docs)
        pool = AnalysisPool(resolved, components.templates, metrics, tracing)
        try:
            await pool.start()
            app.state.analysis_pool = pool
            async with (monitoring_for(resolved.database_url, components.monitor_service) as (
                            app.state.monitoring, app.state.monitor_fanout),
                        revocations.watching(app, components.keys,
                                             resolved.revocation_poll_seconds)):
                yield
        finally:
            await anyio.to_thread.run_sync(pool.close)
            components.close()
            metrics.process_exiting()
            tracing.shutdown()

    app = FastAPI(
        title="SafeGate",
        version="0.1.0",
        summary="Pre-execution safety gate and Task Safety Contracts for LLM-controlled robots",
        lifespan=lifespan,
        # The one access check per request (websockets too): the caller against what the route
        # declares, and with SAFEGATE_AUTH=keys a valid key everywhere; every JSON body is
        # checked for depth, numbers and unstorable text before any route sees it.
        dependencies=[Depends(check_access), Depends(json_body_within_limits)],
        # The schema and the docs pages are routes of ours (`app/api/docs.py`): with
        # SAFEGATE_AUTH=keys they need a key like any other (SAFEGATE_PUBLIC_DOCS opens them),
        # and they load their assets from the app, not a CDN.
        openapi_url=None,
        docs_url=None,
        redoc_url=None,
    )
    app.state.settings = resolved
    app.state.tracing = tracing
    problems.install(app)
    docs.install(app)
    openapi.install(app)
    observability.install(app, metrics, max_body_bytes=resolved.max_body_bytes, tracing=tracing)
    app.add_middleware(revocations.RevocationMiddleware)
    # Robot operations: reads as ReadAccess, the rest (websockets included) as RobotAccess.
    # Routes are matched in order, so the robot's hot path (POST /gate) comes first.
    for router in (gate.router, verify.router, monitor.router):
        app.include_router(router, dependencies=[Depends(robot_writes)])
    for router in (health.router, contracts.router, templates.router, vocabulary.router,
                   extensions.router, keys.router, curator.router):
        app.include_router(router)
    return app
