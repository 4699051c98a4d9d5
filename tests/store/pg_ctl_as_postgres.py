#!/usr/bin/env python3
"""Stand-in for `pg_ctl` when the tests run as root, which PostgreSQL refuses to run as.

In: pg_ctl's own arguments (pytest-postgresql calls this file in pg_ctl's place). Out: the real
pg_ctl (the newest under /usr/lib/postgresql/*/bin, else the one on PATH) run as the `postgres`
user, after the data directory's and log file's parent is handed to that user and made reachable.
Fails: with pg_ctl's exit status, or 127 when no pg_ctl is installed.
"""

from __future__ import annotations

import glob
import os
import pwd
import shutil
import stat
import sys
from pathlib import Path

PATH_FLAGS = ("-D", "--pgdata", "-l", "--log")


def _real_pg_ctl() -> str | None:
    def major(path: str) -> int:
        version = Path(path).parents[1].name
        return int(version) if version.isdigit() else 0

    installed = sorted(glob.glob("/usr/lib/postgresql/*/bin/pg_ctl"), key=major)
    return installed[-1] if installed else shutil.which("pg_ctl")


def _paths_in(arguments: list[str]) -> list[Path]:
    paths: list[Path] = []
    for position, argument in enumerate(arguments):
        if argument in PATH_FLAGS and position + 1 < len(arguments):
            paths.append(Path(arguments[position + 1]))
        elif argument.startswith(("--pgdata=", "--log=")):
            paths.append(Path(argument.split("=", 1)[1]))
    return paths


def _hand_over(path: Path, user: pwd.struct_passwd) -> None:
    parent = path.resolve().parent
    parent.mkdir(parents=True, exist_ok=True)
    os.chown(parent, user.pw_uid, user.pw_gid)
    for ancestor in parent.parents:
        mode = ancestor.stat().st_mode
        if not mode & stat.S_IXOTH:
            ancestor.chmod(mode | stat.S_IXOTH)


def main() -> int:
    pg_ctl = _real_pg_ctl()
    if pg_ctl is None:
        print("pg_ctl_as_postgres: no pg_ctl installed", file=sys.stderr)
        return 127
    arguments = sys.argv[1:]
    if os.geteuid() != 0:
        os.execv(pg_ctl, [pg_ctl, *arguments])
    user = pwd.getpwnam("postgres")
    for path in _paths_in(arguments):
        _hand_over(path, user)
    os.execvp("runuser", ["runuser", "-u", "postgres", "--", pg_ctl, *arguments])
    return 0


if __name__ == "__main__":
    sys.exit(main())
