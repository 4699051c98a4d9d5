"""Headless Chromium and a real uvicorn server on loopback, for the curator page's tests.

- `browser`: one Selenium Chrome driver for the module (Debian's chromium and chromium-driver,
  `make browsers`). Without them the tests skip outside CI (saying why) and fail in CI, where
  `make test` installs them first.
- `server`: a uvicorn server on a free loopback port, on a fresh SQLite file and a copy of the
  library without the `sharp_laceration` templates (so a slicing request waits for one);
  yields (base URL, app).
- `screenshot(driver, name)`: saves a PNG under `SAFEGATE_SCREENSHOT_DIR` when it is set
  (`docs/screenshots/` is made that way), and does nothing otherwise.
"""

from __future__ import annotations

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

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMEDRIVER = "/usr/bin/chromedriver"
SCREENSHOT_DIR_ENV = "SAFEGATE_SCREENSHOT_DIR"


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
                 "--disable-sync", "--no-first-run", "--window-size=1400,1000",
                 "--force-device-scale-factor=1"):
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


def screenshot(driver: Any, name: str, *, height: int | None = None) -> None:
    """Save the window as `<name>.png` under $SAFEGATE_SCREENSHOT_DIR, if set."""
    directory = os.environ.get(SCREENSHOT_DIR_ENV)
    if not directory:
        return
    Path(directory).mkdir(parents=True, exist_ok=True)
    size = driver.get_window_size()
    if height is not None:
        driver.set_window_size(size["width"], height)
    try:
        driver.save_screenshot(str(Path(directory) / f"{name}.png"))
    finally:
        driver.set_window_size(size["width"], size["height"])
