"""The OpenAPI schema and the docs pages (`/openapi.json`, `/docs`, `/redoc`) as our own routes,
working offline.

FastAPI's built-in pages are plain routes that no app-wide dependency reaches, so with
`SAFEGATE_AUTH=keys` they answered without a key, and they load Swagger UI and ReDoc from a CDN,
so on the offline default they were blank. These are API routes like any other: with keys on they
need one (any role; send `Authorization: Bearer <key>` or `X-API-Key`), unless
`SAFEGATE_PUBLIC_DOCS=true` opens them (see `app/api/auth.py`); in `auth=open` they are open.
Their scripts, styles and icon come from the `fastapi-offline` package (PyPI), served by the app
under `/docs-assets` (static files, no secrets), with Swagger UI's online validator switched off.
Fails: at start-up if the package's asset directory is missing (an install without it).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import fastapi_offline
from fastapi import FastAPI, Request
from fastapi.openapi.docs import (
    get_redoc_html,
    get_swagger_ui_html,
    get_swagger_ui_oauth2_redirect_html,
)
from fastapi.responses import HTMLResponse, JSONResponse
from fastapi.staticfiles import StaticFiles

OPENAPI_URL = "/openapi.json"
DOCS_URL = "/docs"
OAUTH2_REDIRECT_URL = "/docs/oauth2-redirect"
REDOC_URL = "/redoc"
DOCS_PATHS = frozenset({OPENAPI_URL, DOCS_URL, OAUTH2_REDIRECT_URL, REDOC_URL})
ASSETS_URL = "/docs-assets"
ASSETS_DIRECTORY = Path(fastapi_offline.__file__).resolve().parent / "static"


def install(app: FastAPI) -> None:
    """Add the schema, the docs pages and their local assets to an app built with
    `openapi_url=None, docs_url=None, redoc_url=None`."""
    app.mount(ASSETS_URL, StaticFiles(directory=ASSETS_DIRECTORY, check_dir=True),
              name="docs-assets")

    @app.get(OPENAPI_URL, include_in_schema=False)
    async def openapi_schema() -> JSONResponse:
        schema: dict[str, Any] = app.openapi()
        return JSONResponse(schema)

    @app.get(DOCS_URL, include_in_schema=False)
    async def swagger_ui(request: Request) -> HTMLResponse:
        root = request.scope.get("root_path", "")
        return get_swagger_ui_html(
            openapi_url=f"{root}{OPENAPI_URL}", title=f"{app.title} - Swagger UI",
            oauth2_redirect_url=f"{root}{OAUTH2_REDIRECT_URL}",
            swagger_js_url=f"{root}{ASSETS_URL}/swagger-ui-bundle.js",
            swagger_css_url=f"{root}{ASSETS_URL}/swagger-ui.css",
            swagger_favicon_url=f"{root}{ASSETS_URL}/favicon.png",
            init_oauth=app.swagger_ui_init_oauth,
            # validatorUrl None: no badge fetched from the online validator.
            swagger_ui_parameters={**(app.swagger_ui_parameters or {}), "validatorUrl": None})

    @app.get(OAUTH2_REDIRECT_URL, include_in_schema=False)
    async def swagger_ui_redirect() -> HTMLResponse:
        return get_swagger_ui_oauth2_redirect_html()

    @app.get(REDOC_URL, include_in_schema=False)
    async def redoc(request: Request) -> HTMLResponse:
        root = request.scope.get("root_path", "")
        return get_redoc_html(
            openapi_url=f"{root}{OPENAPI_URL}", title=f"{app.title} - ReDoc",
            redoc_js_url=f"{root}{ASSETS_URL}/redoc.standalone.js",
            redoc_favicon_url=f"{root}{ASSETS_URL}/favicon.png", with_google_fonts=False)
