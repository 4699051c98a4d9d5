"""The curator page in headless Chromium, against a real uvicorn server on loopback.

- The whole loop through the page: a request waits for a template; the curator signs in with a
  key, starts a template from the pending extension's skeleton, writes it through the form
  (fields, a guard, its formula typed into the code editor), sees the editor underline a bad
  predicate at the line and column the server gave, fixes it by typing, creates the draft,
  activates it and re-evaluates the waiting request, which is then authorized.
- The library table: sorting by a column both ways, paging, header cells aligned with the row
  cells and no column cut off.
- Whole-word search: "hot" finds the hot-liquid templates, never the photographing ones.
- Versions: a template revised once shows a line diff of its two versions; editing it in the
  form and saving a new version shows that version's diff.

Fixtures (browser, server, screenshots) are in this folder's conftest.py.
"""

from __future__ import annotations

from typing import Any

import httpx

from app.domain.models import Severity
from app.services.access import issue_api_key
from app.store.records import ApiKeyRole
from tests.browser.conftest import screenshot

WAIT_SECONDS = 20.0

SLICE_REQUEST: dict[str, Any] = {
    "command": "Slice the sourdough on the board, four thick slices.",
    "scene": {
        "objects": [
            {"id": "countertop_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "bread_1", "type": "Bread", "room": "kitchen", "on": "board_1"},
            {"id": "board_1", "type": "CuttingBoard", "room": "kitchen", "on": "countertop_1"},
            {"id": "knife_1", "type": "BreadKnife", "room": "kitchen", "on": "countertop_1",
             "properties": {"sharp": True}},
        ],
        "people": [{"id": "p1", "role": "cook", "room": "kitchen",
                    "properties": {"age_group": "adult"}}],
    },
    "user": {"person_id": "p1", "age_group": "adult", "unknowns": []},
    "robot": {"room": "kitchen", "payload_kg": 3.0,
              "skills": ["navigate", "pick", "place", "slice"], "sensors": ["rgbd_camera"]},
}

# Every header cell against the first row's cell below it, and the table against its frame.
ALIGNMENT_SCRIPT = """
const heads = [...document.querySelectorAll('#template-table thead th')];
const cells = [...document.querySelectorAll('#template-list tr:first-child td')];
const frame = document.querySelector('.table-frame');
return {
  columns: heads.map((th, i) => {
    const a = th.getBoundingClientRect(), b = cells[i].getBoundingClientRect();
    return [a.left, a.width, b.left, b.width];
  }),
  cellCount: cells.length,
  overflow: frame.scrollWidth - frame.clientWidth,
  lastRight: heads[heads.length - 1].getBoundingClientRect().right,
  frameRight: frame.getBoundingClientRect().right,
};
"""


def _wait_for(driver: Any, condition: Any, what: str) -> Any:
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(driver, WAIT_SECONDS).until(condition, message=what)


def _text_of(driver: Any, element_id: str) -> str:
    from selenium.webdriver.common.by import By

    text: str = driver.find_element(By.ID, element_id).text
    return text


def _sign_in(driver: Any, base: str, app: Any) -> str:
    from selenium.webdriver.common.by import By

    _, secret = issue_api_key(app.state.components.repositories.access, ApiKeyRole.CURATOR,
                              "page")
    driver.get(base + "/curator")
    _wait_for(driver, lambda d: d.execute_script("return document.body.dataset.ready"),
              "page wired")
    driver.find_element(By.ID, "api-key").send_keys(secret)
    driver.find_element(By.ID, "use-key").click()
    _wait_for(driver, lambda d: "curator" in _text_of(d, "whoami"), "signed in")
    return secret


def _column(driver: Any, index: int) -> list[str]:
    cells: list[str] = driver.execute_script(
        "return [...document.querySelectorAll('#template-list tr')]"
        ".map((row) => row.cells[arguments[0]].textContent);", index)
    return cells


def _shown_ids(driver: Any) -> list[str]:
    return _column(driver, 0)


def _listing(base: str, **params: Any) -> dict[str, Any]:
    body: dict[str, Any] = httpx.get(base + "/templates", params=params, timeout=10).json()
    return body


class TestCuratorPage:
    def test_curator_closes_the_extension_loop_in_the_page(
        self, browser: Any, server: tuple[str, Any]
    ) -> None:
        from selenium.webdriver.common.by import By
        from selenium.webdriver.common.keys import Keys

        base, app = server
        waiting = httpx.post(base + "/gate", json=SLICE_REQUEST, timeout=30).json()
        assert waiting["defer_kind"] == "extend_library"
        _sign_in(browser, base, app)

        group = _wait_for(browser, lambda d: d.find_element(
            By.CSS_SELECTOR, "#pending .group[data-hazard-class='sharp_laceration']"),
            "pending group")
        assert "Slice the sourdough" in group.text
        group.find_element(By.CLASS_NAME, "start-template").click()
        _wait_for(browser, lambda d: _text_of(d, "validation-status") == "invalid",
                  "skeleton validated")
        assert "at least one invariant, guard or abort" in _text_of(browser, "messages")
        form = browser.find_element(By.ID, "template-form")
        template_id = form.find_element(By.NAME, "id").get_attribute("value")
        assert form.find_element(By.NAME, "hazard_class").get_attribute("value") == \
            "sharp_laceration"

        name = form.find_element(By.NAME, "name")
        name.clear()
        name.send_keys("Blade thrown in the kitchen")
        browser.find_element(By.CSS_SELECTOR, ".add-condition[data-kind='guard']").click()
        card = browser.find_element(By.CSS_SELECTOR, "#condition-list .condition")
        card.find_element(By.CLASS_NAME, "condition-id").send_keys("never_throw_blade")
        card.find_element(By.CLASS_NAME, "condition-action").send_keys("ThrowObject")
        card.find_element(By.CLASS_NAME, "condition-description").send_keys(
            "Never throw the blade.")
        formula = "@object != $obj or not sharpp($obj)"
        editor = card.find_element(By.CSS_SELECTOR, ".cm-content")
        editor.click()
        editor.send_keys(formula)

        position = f"line 1, column {formula.index('sharpp') + 1}"
        _wait_for(browser, lambda d: position in card.find_element(
            By.CLASS_NAME, "condition-issues").text, "inline error position")
        assert "body.guards.0.formula" in _text_of(browser, "messages")
        underlined = _wait_for(browser, lambda d: card.find_elements(
            By.CSS_SELECTOR, ".cm-lintRange-error"), "the editor underlines the error")
        assert underlined[0].text == "sharpp"
        screenshot(browser, "curator-editor-inline-error", height=1800)

        editor.send_keys(Keys.END, *[Keys.ARROW_LEFT] * len("($obj)"), Keys.BACKSPACE)
        _wait_for(browser, lambda d: _text_of(d, "validation-status") == "valid", "valid")
        assert not card.find_elements(By.CSS_SELECTOR, ".cm-lintRange-error")

        browser.find_element(By.ID, "create").click()
        _wait_for(browser, lambda d: "draft" in _text_of(d, "result"), "draft stored")
        stored = httpx.get(f"{base}/templates/{template_id}", timeout=10).json()
        assert stored["name"] == "Blade thrown in the kitchen"
        assert stored["guards"][0]["formula"] == formula.replace("sharpp", "sharp")
        browser.find_element(By.ID, "activate").click()
        _wait_for(browser, lambda d: "now active" in _text_of(d, "result"), "activated")

        redo_button = "#pending .group[data-hazard-class='sharp_laceration'] .reevaluate"
        # The list is re-rendered after activation; wait for the fresh, enabled button.
        _wait_for(browser, lambda d: d.execute_script(
            "const b = document.querySelector(arguments[0]); return !!b && !b.disabled;",
            redo_button), "class covered")
        browser.execute_script("document.querySelector(arguments[0]).click()", redo_button)
        _wait_for(browser, lambda d: "re-evaluated 1" in _text_of(d, "result"), "re-evaluated")
        assert "authorize" in _text_of(browser, "result")
        pending = httpx.get(base + "/extensions/pending", timeout=10).json()
        assert pending["count"] == 0

    def test_table_sorts_pages_and_keeps_headers_over_their_columns(
        self, browser: Any, server: tuple[str, Any]
    ) -> None:
        from selenium.webdriver.common.by import By

        base, app = server
        _sign_in(browser, base, app)
        total = _listing(base)["total"]
        _wait_for(browser, lambda d: len(_shown_ids(d)) == 20, "first page")
        assert _text_of(browser, "page-position") == f"page 1 of {-(-total // 20)}"

        layout = browser.execute_script(ALIGNMENT_SCRIPT)
        assert layout["cellCount"] == 6
        for head_left, head_width, cell_left, cell_width in layout["columns"]:
            assert abs(head_left - cell_left) < 1 and abs(head_width - cell_width) < 1
        assert layout["overflow"] <= 0 and layout["lastRight"] <= layout["frameRight"] + 1
        screenshot(browser, "curator-table-aligned")

        severity = browser.find_element(By.CSS_SELECTOR, "th[data-sort='severity'] button")
        severity.click()
        mildest = min(Severity(t["severity"]).rank for t in _listing(base)["templates"])
        _wait_for(browser, lambda d: (ranks := [Severity(s).rank for s in _column(d, 3)])
                  == sorted(ranks) and ranks[0] == mildest, "severity ascending")
        severity.click()
        _wait_for(browser, lambda d: _column(d, 3)[0] == "critical", "severity descending")
        header = browser.find_element(By.CSS_SELECTOR, "th[data-sort='severity']")
        assert header.get_attribute("aria-sort") == "descending"

        browser.find_element(By.ID, "page-next").click()
        second = _listing(base, sort="severity", order="desc", offset=20, limit=20)
        expected = [t["id"] for t in second["templates"]]
        _wait_for(browser, lambda d: _shown_ids(d) == expected, "second page")
        assert _text_of(browser, "page-position").startswith("page 2 of")
        assert browser.find_element(By.ID, "page-previous").is_enabled()
        screenshot(browser, "curator-table-sorted-page-2")

    def test_search_matches_whole_words_only(
        self, browser: Any, server: tuple[str, Any]
    ) -> None:
        from selenium.webdriver.common.by import By

        base, app = server
        _sign_in(browser, base, app)
        everything = _listing(base)["templates"]
        photographing = {t["id"] for t in everything
                         if "photograph" in (t["name"] + " " + t["description"]).lower()}
        assert photographing, "the library should hold a template about photographing"

        browser.find_element(By.ID, "search").send_keys("hot")
        expected = {t["id"] for t in _listing(base, q="hot")["templates"]}
        _wait_for(browser, lambda d: set(_shown_ids(d)) == expected, "search results")
        assert not photographing & expected
        assert any(name.startswith("Hot liquid") for name in _column(browser, 1))
        screenshot(browser, "curator-search-hot")

    def test_a_revised_template_shows_a_line_diff_of_its_versions(
        self, browser: Any, server: tuple[str, Any]
    ) -> None:
        from selenium.webdriver.common.by import By
        from selenium.webdriver.support.ui import Select

        base, app = server
        secret = _sign_in(browser, base, app)
        headers = {"Authorization": f"Bearer {secret}"}
        document = {
            "id": "breakage.mirror_dropped", "name": "Mirror dropped near a person",
            "category": "physical", "hazard_class": "glass_breakage",
            "description": "A mirror let go of shatters next to someone.",
            "severity": "moderate", "preventability": "preventable",
            "variables": [{"name": "obj", "type": "object"}],
            "guards": [{"id": "no_drop_mirror", "action": "DropHandObject",
                        "formula": "@object != $obj or not fragile($obj)",
                        "description": "Never drop a fragile object."}],
        }
        assert httpx.post(base + "/templates", json=document, headers=headers,
                          timeout=30).status_code == 201
        revised = {**document, "guards": [{**document["guards"][0],
                   "formula": "@object != $obj or not breakable($obj)"}]}
        assert httpx.put(base + "/templates/breakage.mirror_dropped", json=revised,
                         headers=headers, timeout=30).status_code == 200

        browser.find_element(By.ID, "search").send_keys("mirror")
        row = _wait_for(browser, lambda d: d.find_element(
            By.CSS_SELECTOR, "#template-list tr[data-id='breakage.mirror_dropped']"), "row")
        row.click()
        _wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#diff .diff-added"),
                  "diff shown")
        removed, added = ([" ".join(e.text.split()) for e in browser.find_elements(
            By.CSS_SELECTOR, f"#diff .diff-{kind}")] for kind in ("removed", "added"))
        assert removed == ['- "formula": "@object != $obj or not fragile($obj)",']
        assert added == ['+ "formula": "@object != $obj or not breakable($obj)",']
        assert _text_of(browser, "diff-summary") == "1 line removed, 1 added"
        screenshot(browser, "curator-version-diff", height=1400)

        Select(browser.find_element(By.ID, "diff-to")).select_by_value("1")
        _wait_for(browser, lambda d: _text_of(d, "diff-summary") == "the same version",
                  "same version")

        browser.find_element(By.ID, "detail-edit").click()
        card = browser.find_element(By.CSS_SELECTOR, "#condition-list .condition")
        card.find_element(By.CLASS_NAME, "condition-description").send_keys(" Ever.")
        browser.find_element(By.ID, "save-version").click()
        _wait_for(browser, lambda d: "version 3" in _text_of(d, "result"), "third version")
        _wait_for(browser, lambda d: d.find_element(By.ID, "diff-to").get_attribute("value")
                  == "3", "the diff offers the new version")
        added = [" ".join(e.text.split())
                 for e in browser.find_elements(By.CSS_SELECTOR, "#diff .diff-added")]
        assert added == ['+ "description": "Never drop a fragile object. Ever.",']
