"""The curator page in headless Chromium, against a real uvicorn server on loopback.

The whole loop through the page: a request waits for a template; the curator signs in with a
key, searches the library, starts a template from the pending extension's skeleton, sees live
validation point at a bad formula's line and column, fixes it, creates the draft, activates it,
and re-evaluates the waiting request, which is then authorized.

Chromium and its driver come from Debian (`make browsers`). Without them the test skips outside
CI (saying why) and fails in CI, where `make test` installs them first.
"""

from __future__ import annotations

import json
import os
import shutil
import socket
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest
import uvicorn

from app.config import REPO_ROOT, Settings
from app.main import create_app
from app.services.access import issue_api_key
from app.store.records import ApiKeyRole

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMEDRIVER = "/usr/bin/chromedriver"
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


def _browser_missing() -> str | None:
    if CHROMIUM is None:
        return "chromium is not installed (run `make browsers`, as root with apt)"
    if not os.access(CHROMEDRIVER, os.X_OK):
        return f"{CHROMEDRIVER} is missing (install Debian's chromium-driver: `make browsers`)"
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "selenium is not installed (pip install -e '.[dev]')"
    return None


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    missing = _browser_missing()
    if missing is not None:
        if os.environ.get("CI"):
            pytest.fail(f"browser tests must run in CI: {missing}")
        print(f"skipping the browser test: {missing}")
        pytest.skip(missing)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    os.environ.setdefault("SE_OFFLINE", "true")  # never let Selenium download a browser
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", "--window-size=1400,1000"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    try:
        yield driver
    finally:
        driver.quit()


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@pytest.fixture
def server(tmp_path: Path) -> Iterator[tuple[str, Any]]:
    """A uvicorn server on a library without sharp_laceration templates; (base URL, app)."""
    library = tmp_path / "lib"
    shutil.copytree(REPO_ROOT / "templates_db", library)
    (library / "sharp.yaml").unlink()
    app = create_app(Settings(database_url=f"sqlite:///{tmp_path / 'page.db'}",
                              templates_dir=library))
    port = _free_port()
    config = uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning")
    uvicorn_server = uvicorn.Server(config)
    thread = threading.Thread(target=uvicorn_server.run, daemon=True)
    thread.start()
    base = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        try:
            if httpx.get(base + "/readyz", timeout=1).status_code == 200:
                break
        except httpx.HTTPError:
            time.sleep(0.1)
    else:
        raise RuntimeError("server did not become ready")
    yield base, app
    uvicorn_server.should_exit = True
    thread.join(timeout=20)


def _wait_for(driver: Any, condition: Any, what: str) -> Any:
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(driver, WAIT_SECONDS).until(condition, message=what)


def _text_of(driver: Any, element_id: str) -> str:
    from selenium.webdriver.common.by import By

    text: str = driver.find_element(By.ID, element_id).text
    return text


def _type_template(driver: Any, document: dict[str, Any]) -> None:
    from selenium.webdriver.common.by import By

    editor = driver.find_element(By.ID, "editor")
    driver.execute_script(
        "arguments[0].value = arguments[1];"
        "arguments[0].dispatchEvent(new Event('input', {bubbles: true}));",
        editor, json.dumps(document, indent=2))


class TestCuratorPage:
    def test_curator_closes_the_extension_loop_in_the_page(
        self, browser: Any, server: tuple[str, Any]
    ) -> None:
        from selenium.webdriver.common.by import By

        base, app = server
        waiting = httpx.post(base + "/gate", json=SLICE_REQUEST, timeout=30).json()
        assert waiting["defer_kind"] == "extend_library"
        _, secret = issue_api_key(app.state.services.repository, ApiKeyRole.CURATOR, "page")

        browser.get(base + "/curator")
        browser.find_element(By.ID, "api-key").send_keys(secret)
        browser.find_element(By.ID, "use-key").click()
        _wait_for(browser, lambda d: "curator" in _text_of(d, "whoami"), "signed in")

        browser.find_element(By.ID, "search").send_keys("hot liquid")
        _wait_for(browser, lambda d: "templates" in _text_of(d, "template-count")
                  and 0 < len(d.find_elements(By.CSS_SELECTOR, "#template-list tr")) < 20,
                  "search results")
        rows = browser.find_elements(By.CSS_SELECTOR, "#template-list tr")
        assert all("sharp" not in row.text for row in rows)

        group = _wait_for(browser, lambda d: d.find_element(
            By.CSS_SELECTOR, "#pending .group[data-hazard-class='sharp_laceration']"),
            "pending group")
        assert "Slice the sourdough" in group.text
        group.find_element(By.CLASS_NAME, "start-template").click()
        _wait_for(browser, lambda d: _text_of(d, "validation-status") == "invalid",
                  "skeleton validated")
        assert "at least one invariant, guard or abort" in _text_of(browser, "messages")

        skeleton = json.loads(browser.find_element(By.ID, "editor").get_attribute("value"))
        formula = "@object != $obj or not sharpp($obj)"
        guard = {"id": "never_throw_blade", "action": "ThrowObject", "formula": formula,
                 "description": "Never throw the blade."}
        _type_template(browser, {**skeleton, "guards": [guard]})
        position = f"line 1, column {formula.index('sharpp') + 1}"
        _wait_for(browser, lambda d: position in _text_of(d, "messages"), "error position")
        assert "body.guards.0.formula" in _text_of(browser, "messages")

        guard["formula"] = formula.replace("sharpp", "sharp")
        _type_template(browser, {**skeleton, "guards": [guard]})
        _wait_for(browser, lambda d: _text_of(d, "validation-status") == "valid", "valid")

        browser.find_element(By.ID, "create").click()
        _wait_for(browser, lambda d: "draft" in _text_of(d, "result"), "draft stored")
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
