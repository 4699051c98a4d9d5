"""The curator page's files: every one it loads is served by the app, none comes from elsewhere."""

from __future__ import annotations

import re

from fastapi.testclient import TestClient

from app.api.routes.curator import PAGE_FILES, PAGES

# Every script and style sheet the page (and its modules) names, by `src`, `href` or `import`.
_REFERENCES = re.compile(r'(?:src|href)="([^"]+)"|from "([^"]+)"')


class TestCuratorFiles:
    def test_every_page_file_is_served_with_its_type(self, client: TestClient) -> None:
        for name, media_type in PAGE_FILES.items():
            answer = client.get(f"/curator/static/{name}")
            assert answer.status_code == 200, name
            assert answer.headers["content-type"].startswith(media_type), name

    def test_other_names_are_404(self, client: TestClient) -> None:
        for name in ("curator.html", "../routes/curator.py", "vendor/x.js", "x.js", "vendor"):
            assert client.get(f"/curator/static/{name}").status_code == 404, name

    def test_the_page_loads_nothing_from_another_host(self, client: TestClient) -> None:
        texts = [client.get("/curator").text] + [
            (PAGES / name).read_text() for name in PAGE_FILES if not name.startswith("vendor/")]
        references = [ref for text in texts for pair in _REFERENCES.findall(text)
                      for ref in pair if ref]
        assert references
        for reference in references:
            assert reference.startswith(("/curator/static/", "./")), reference
            if reference.startswith("/curator/static/"):
                assert reference.removeprefix("/curator/static/") in PAGE_FILES, reference
