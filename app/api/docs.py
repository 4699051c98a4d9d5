"""The OpenAPI schema and the docs pages (`/openapi.json`, `/docs`, `/redoc`) as our own routes.

FastAPI's built-in ones are plain routes that no app-wide dependency reaches, so with
`SAFEGATE_AUTH=keys` they answered without a key. These are API routes like any other: with keys
on they need one (any role; send `Authorization: Bearer <key>` or `X-API-Key`), unless
`SAFEGATE_PUBLIC_DOCS=true` opens them (see `app/api/auth.py`). In `auth=open` they are open.
"""

from __future__ import annotations

from typing import Any

from fastapi import FastAPI
from fastapi.openapi.docs import (
    get_redoc_html,
    get_swagger_ui_html,
    get_swagger_ui_oauth2_redirect_html,
)
from fastapi.responses import HTMLResponse, JSONResponse

OPENAPI_URL = "/openapi.json"
DOCS_URL = "/docs"
OAUTH2_REDIRECT_URL = "/docs/oauth2-redirect"
REDOC_URL = "/redoc"
DOCS_PATHS = frozenset({OPENAPI_URL, DOCS_URL, OAUTH2_REDIRECT_URL, REDOC_URL})


def install(app: FastAPI) -> None:
    """Add the schema and the docs pages to an app built with `openapi_url=None`."""

    @app.get(OPENAPI_URL, include_in_schema=False)
    async def openapi_schema() -> JSONResponse:
        schema: dict[str, Any] = app.openapi()
        return JSONResponse(schema)

    @app.get(DOCS_URL, include_in_schema=False)
    async def swagger_ui() -> HTMLResponse:
        return get_swagger_ui_html(openapi_url=OPENAPI_URL, title=f"{app.title} - Swagger UI",
                                   oauth2_redirect_url=OAUTH2_REDIRECT_URL)

    @app.get(OAUTH2_REDIRECT_URL, include_in_schema=False)
    async def swagger_ui_redirect() -> HTMLResponse:
        return get_swagger_ui_oauth2_redirect_html()

    @app.get(REDOC_URL, include_in_schema=False)
    async def redoc() -> HTMLResponse:
        return get_redoc_html(openapi_url=OPENAPI_URL, title=f"{app.title} - ReDoc")
