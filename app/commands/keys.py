"""`safegate keys create|list|revoke`: API keys for `SAFEGATE_AUTH=keys`.

In: a role and a name; a key id. Out: a new key printed once (only its hash is stored), a table of
keys (never their secrets), or the revoked key. Fails: exit 1 with one line for an unknown key id
or a database error; exit 2 (Typer's usage error) for an unknown role.
"""

from __future__ import annotations

from typing import Annotated

import typer
from rich.markup import escape
from rich.table import Table

from app.commands.shared import err, fail, out, repository
from app.domain.errors import NotFound, Unavailable
from app.store.records import ApiKeyRole

keys_cli = typer.Typer(help="Manage API keys (stored hashed; a key is printed once).",
                       no_args_is_help=True)


@keys_cli.command("create")
def keys_create(
    role: Annotated[ApiKeyRole, typer.Option(help="What the key may do.")],
    name: Annotated[str, typer.Option(help="Who or what holds the key.")] = "",
) -> None:
    """Create a key and print it once (only its hash is stored)."""
    from app.services.access import issue_api_key

    try:
        record, secret = issue_api_key(repository(), role, name or f"{role.value} key")
    except Unavailable as error:
        fail(f"error: {error.detail}")
    typer.echo(secret)
    err().print(f"created {record.role.value} key {record.id} ({record.name}); "
                "store it now, it cannot be shown again", markup=False)


@keys_cli.command("list")
def keys_list() -> None:
    """List keys (id, role, state, created, name); never their secrets."""
    try:
        keys = repository().list_api_keys()
    except Unavailable as error:
        fail(f"error: {error.detail}")
    table = Table(title=f"{len(keys)} API keys")
    table.add_column("id", no_wrap=True, min_width=max((len(k.id) for k in keys), default=2))
    table.add_column("role")
    table.add_column("state")
    table.add_column("created (UTC)", no_wrap=True)
    table.add_column("name")
    for key in keys:
        table.add_row(key.id, key.role.value, "revoked" if key.revoked else "active",
                      f"{key.created_at:%Y-%m-%d %H:%M}", escape(key.name))
    out().print(table)


@keys_cli.command("revoke")
def keys_revoke(
    key_id: Annotated[str, typer.Argument(help="The key's id (see `keys list`).")],
) -> None:
    """Revoke a key for good."""
    try:
        key = repository().revoke_api_key(key_id)
    except (NotFound, Unavailable) as error:
        fail(error.detail)
    typer.echo(f"revoked {key.role.value} key {key.id} ({key.name})")
