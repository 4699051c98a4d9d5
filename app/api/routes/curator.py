"""The curator page: plain HTML, CSS and a little vanilla JavaScript served from `app/api/pages/`.

The page is a static shell (no data in it, so it is served without a key); its script calls the
JSON API with the key the curator types in. Only the three page files are served.
"""

from __future__ import annotations

from pathlib import Path

from fastapi import APIRouter
from fastapi.responses import FileResponse

from app.domain.errors import NotFound

PAGES = Path(__file__).resolve().parent.parent / "pages"
_STATIC = {"curator.js": "text/javascript", "curator.css": "text/css"}

router = APIRouter(tags=["curator"], include_in_schema=False)


@router.get("/curator")
def curator_page() -> FileResponse:
    """The curator page."""
    return FileResponse(PAGES / "curator.html", media_type="text/html")


@router.get("/curator/static/{name}")
def curator_static(name: str) -> FileResponse:
    """The page's script and style sheet."""
    media_type = _STATIC.get(name)
    if media_type is None:
        raise NotFound(f"no page file {name!r}")
    return FileResponse(PAGES / name, media_type=media_type)
