"""Monitor latency over a websocket, this checkout against another one, in the same run.

Run: `.venv/bin/python bench/perf/monitor_ab.py --baseline DIR [--postgres URL]`, where DIR is
another checkout of SafeGate (e.g. `git worktree add /tmp/safegate-main main`) and URL a
PostgreSQL server where databases may be created (one per server, dropped afterwards); without
it each server gets its own SQLite file. Run by hand (not by `make perf`): it needs a baseline.

Both servers run at once (one uvicorn worker each); blocks of sequential actions (a `before` and
an `after` each, on a fresh session per block, the `monitor_ws.py` contract and actions) alternate
between them, first one then the other, so a busy machine slows both alike. Prints ms per action
(p50, p90, p99, max) for each, and the load average before and after.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import sys
import tempfile
import uuid
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path

import httpx
from rich.console import Console
from rich.table import Table
from sqlalchemy import create_engine, make_url, text

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _server import running_server
from monitor_ws import Tally, percentile, run_session, store_contract

from app.store.db import migrate

HERE = Path(__file__).resolve().parents[2]


@contextmanager
def database(postgres: str | None, tmp: Path, name: str) -> Iterator[str]:
    """A fresh database URL: a SQLite file, or a new PostgreSQL database dropped afterwards."""
    if postgres is None:
        yield f"sqlite:///{tmp / f'{name}.db'}"
        return
    admin = create_engine(postgres, isolation_level="AUTOCOMMIT")
    db = f"safegate_ab_{name}_{uuid.uuid4().hex[:8]}"
    with admin.connect() as connection:
        connection.execute(text(f'CREATE DATABASE "{db}"'))
    try:
        yield make_url(postgres).set(database=db).render_as_string(hide_password=False)
    finally:
        with admin.connect() as connection:
            connection.execute(text(f'DROP DATABASE IF EXISTS "{db}" WITH (FORCE)'))
        admin.dispose()


async def block(base: str, contract_id: str, actions: int, tally: Tally) -> None:
    async with httpx.AsyncClient(base_url=base, timeout=30) as http:
        session_id = (await http.post("/monitor", json={"contract_id": contract_id})).json()[
            "session_id"]
    await run_session(base.replace("http://", "ws://"), session_id, 1, actions, tally)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", type=Path, required=True, help="another checkout")
    parser.add_argument("--postgres", help="a PostgreSQL URL allowed to CREATE DATABASE")
    parser.add_argument("--blocks", type=int, default=10, help="blocks per server")
    parser.add_argument("--actions", type=int, default=200, help="actions per block")
    args = parser.parse_args()
    names = {"baseline": args.baseline.resolve(), "this checkout": HERE}
    load_before = os.getloadavg()
    tallies = {name: Tally() for name in names}
    with tempfile.TemporaryDirectory(prefix="safegate-monitor-ab-") as tmp, ExitStack() as stack:
        servers: dict[str, tuple[str, str]] = {}
        for n, (name, checkout) in enumerate(names.items()):
            url = stack.enter_context(database(args.postgres, Path(tmp), f"s{n}"))
            migrate(url)
            contract_id = store_contract(url)
            base = stack.enter_context(running_server({"SAFEGATE_DATABASE_URL": url},
                                                      checkout=checkout))
            servers[name] = (base, contract_id)
        for base, contract_id in servers.values():  # warm-up, not counted
            asyncio.run(block(base, contract_id, 50, Tally()))
        order = list(servers)
        for i in range(args.blocks):
            for name in order if i % 2 == 0 else order[::-1]:
                base, contract_id = servers[name]
                asyncio.run(block(base, contract_id, args.actions, tallies[name]))
    load_after = os.getloadavg()

    database_name = "PostgreSQL" if args.postgres else "SQLite"
    table = Table(title=f"Monitor over a websocket, {database_name}: ms per action (before + "
                        f"after), {args.blocks} alternating blocks of {args.actions}")
    for column in ("checkout", "actions", "p50", "p90", "p99", "max", "refused/lost"):
        table.add_column(column, justify="left" if column == "checkout" else "right")
    for name, tally in tallies.items():
        ms = tally.action_ms
        table.add_row(f"{name} ({names[name]})", str(len(ms)), f"{percentile(ms, 0.5):.2f}",
                      f"{percentile(ms, 0.9):.2f}", f"{percentile(ms, 0.99):.2f}",
                      f"{max(ms):.2f}", f"{tally.refused}/{tally.lost}")
    console = Console()
    console.print(table)
    console.print(f"load average (1 min) before {load_before[0]:.2f}, after {load_after[0]:.2f}"
                  f" on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
