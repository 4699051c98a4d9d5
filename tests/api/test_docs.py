"""`/docs` and `/redoc` work offline: every asset they load is served by the app itself."""

from __future__ import annotations

import re

import pytest
from fastapi.testclient import TestClient

_URL_ATTRIBUTES = re.compile(r"""(?:src|href)\s*=\s*["']([^"']+)["']""")
_SPEC_URL = re.compile(r"""(?:url:|spec-url=)\s*["']([^"']+)["']""")


def _referenced(html: str) -> list[str]:
    return _URL_ATTRIBUTES.findall(html) + _SPEC_URL.findall(html)


class TestOfflineDocs:
    @pytest.mark.parametrize("page", ["/docs", "/redoc"])
    def test_pages_reference_only_local_urls_that_answer(
        self, client: TestClient, page: str
    ) -> None:
        response = client.get(page)
        assert response.status_code == 200
        urls = _referenced(response.text)
        assert any(url.endswith(".js") for url in urls), urls
        assert "/openapi.json" in urls
        for url in urls:
            assert url.startswith("/") and not url.startswith("//"), url
            asset = client.get(url)
            assert asset.status_code == 200, url
            assert len(asset.content) > 100, url
        assert "cdn" not in response.text.lower()
        assert "fonts.googleapis" not in response.text

    def test_swagger_ui_is_the_real_bundle_without_the_online_validator(
        self, client: TestClient
    ) -> None:
        html = client.get("/docs").text
        assert '"validatorUrl": null' in html
        bundle = client.get("/docs-assets/swagger-ui-bundle.js")
        assert bundle.headers["content-type"].startswith(("text/javascript",
                                                          "application/javascript"))
        assert b"SwaggerUIBundle" in bundle.content
        assert client.get("/docs/oauth2-redirect").status_code == 200

    def test_assets_stay_out_of_the_openapi_spec(self, client: TestClient) -> None:
        paths = client.get("/openapi.json").json()["paths"]
        assert not any(p.startswith(("/docs", "/redoc")) for p in paths)
