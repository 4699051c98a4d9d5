"""GET /templates as a table reads it: whole-word search, sorting by a column, paging."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient

from app.domain.models import Severity


def listing(client: TestClient, **params: Any) -> dict[str, Any]:
    answer = client.get("/templates", params=params)
    assert answer.status_code == 200, answer.text
    body: dict[str, Any] = answer.json()
    return body


class TestTemplateSearch:
    def test_a_word_matches_whole_words_only(self, client: TestClient) -> None:
        names = [t["name"] for t in listing(client, q="hot")["templates"]]
        assert any("Hot liquid" in name for name in names)
        assert not any("photograph" in name.lower() for name in names)

    def test_a_word_matches_inside_ids_and_classes_split_at_underscores(
        self, client: TestClient
    ) -> None:
        found = listing(client, q="scald")["templates"]
        assert found and all("scald" in t["hazard_class"].split("_")
                             or "scald" in t["description"].lower() for t in found)

    def test_every_word_is_required(self, client: TestClient) -> None:
        both = {t["id"] for t in listing(client, q="hot liquid")["templates"]}
        hot = {t["id"] for t in listing(client, q="hot")["templates"]}
        assert both and both < hot


class TestTemplatePaging:
    def test_without_paging_every_template_comes_as_before(self, client: TestClient) -> None:
        body = listing(client)
        assert body["count"] == body["total"] == len(body["templates"]) > 20
        assert body["offset"] == 0 and body["limit"] is None
        ids = [t["id"] for t in body["templates"]]
        assert ids == sorted(ids)

    def test_pages_cover_the_sorted_list_once(self, client: TestClient) -> None:
        everything = [t["id"] for t in listing(client, sort="name")["templates"]]
        pages = [listing(client, sort="name", limit=25, offset=start)
                 for start in range(0, len(everything), 25)]
        assert all(p["total"] == len(everything) for p in pages)
        assert [t["id"] for p in pages for t in p["templates"]] == everything

    def test_an_offset_past_the_end_is_an_empty_page(self, client: TestClient) -> None:
        body = listing(client, offset=10_000, limit=10)
        assert body["count"] == 0 and body["templates"] == [] and body["total"] > 0

    def test_a_zero_limit_is_refused(self, client: TestClient) -> None:
        assert client.get("/templates", params={"limit": 0}).status_code == 422


class TestTemplateSorting:
    def test_severity_sorts_by_how_bad(self, client: TestClient) -> None:
        found = listing(client, sort="severity", order="desc")["templates"]
        ranks = [Severity(t["severity"]).rank for t in found]
        assert ranks == sorted(ranks, reverse=True)
        assert found[0]["severity"] == "critical"

    def test_ties_keep_id_order_in_both_directions(self, client: TestClient) -> None:
        for order in ("asc", "desc"):
            found = listing(client, sort="category", order=order)["templates"]
            for category in {t["category"] for t in found}:
                ids = [t["id"] for t in found if t["category"] == category]
                assert ids == sorted(ids)

    def test_an_unknown_column_is_refused(self, client: TestClient) -> None:
        assert client.get("/templates", params={"sort": "formula"}).status_code == 422
