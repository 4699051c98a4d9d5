"""The curator page: plain HTML, CSS and vanilla JavaScript modules served from `app/api/pages/`.

The page is a static shell (no data in it, so it is served without a key); its scripts call the
JSON API with the key the curator types in. Only the files listed in `PAGE_FILES` are served:
the page's own modules and `vendor/editor.js`, the CodeMirror bundle built from `web/` by
`make web` and committed, so the server needs no Node at run time and works offline.
Fails: 404 (problem+json) for any other name.
"""

from __future__ import annotations

from pathlib import Path

from fastapi import APIRouter
from fastapi.responses import FileResponse

from app.domain.errors import NotFound

PAGES = Path(__file__).resolve().parent.parent / "pages"
_SCRIPT = "text/javascript"
PAGE_FILES = {
    "curator.css": "text/css",
    "curator.js": _SCRIPT,
    "api.js": _SCRIPT,
    "library.js": _SCRIPT,
    "versions.js": _SCRIPT,
    "template_form.js": _SCRIPT,
    "vendor/editor.js": _SCRIPT,
}

router = APIRouter(tags=["curator"], include_in_schema=False)


@router.get("/curator")
def curator_page() -> FileResponse:
    """The curator page."""
    return FileResponse(PAGES / "curator.html", media_type="text/html")


@router.get("/curator/static/{name:path}")
def curator_static(name: str) -> FileResponse:
    """The page's scripts, style sheet and vendored editor bundle."""
    media_type = PAGE_FILES.get(name)
    if media_type is None:
        raise NotFound(f"no page file {name!r}")
    return FileResponse(PAGES / name, media_type=media_type)
