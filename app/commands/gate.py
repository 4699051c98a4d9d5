"""`safegate gate "command" --scene scene.json`: try the gate from a terminal.

In: a command and a JSON file holding either a scene (`layout`, `objects`, `people`...) or a
request's `scene`/`user`/`robot` (any `command` in it is replaced by the argument), run in
process on the configured database and library, as `POST /gate` would (the decision is audited).
Out: the decision, the rule, the reason and the question, then the hazards (class, severity,
category, template) and the unknowns as tables; with `--reference-plan`, as
`POST /gate?reference_plan=true` would, the plan Stage 5 proved keeps the contract (a numbered
table of its steps, its goal) or why there is none, also kept in the audit record; with `--json`
the API's `GateResponse`.
Fails: exit 1 with one line for an unreadable or invalid file or a database error.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from pydantic import ValidationError
from rich.markup import escape
from rich.table import Table

from app.commands.shared import fail, out, settings
from app.domain.errors import SafeGateError
from app.domain.models import GateRequest

if TYPE_CHECKING:
    from app.api.schemas import GateResponse

_REQUEST_KEYS = frozenset({"scene", "user", "robot", "command"})
_DECISION_STYLE = {"authorize": "bold green", "defer": "bold yellow", "reject": "bold red"}


def _request(command: str, scene_file: Path | None) -> GateRequest:
    body: dict[str, Any] = {}
    if scene_file is not None:
        try:
            loaded = json.loads(scene_file.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, ValueError) as error:
            fail(f"error: cannot read {scene_file} as JSON: {error}")
        if not isinstance(loaded, dict):
            fail(f"error: {scene_file} must hold a JSON object")
        body = dict(loaded) if _REQUEST_KEYS & loaded.keys() else {"scene": loaded}
    body["command"] = command
    try:
        return GateRequest.model_validate(body)
    except ValidationError as error:
        first = error.errors()[0]
        where = ".".join(str(part) for part in first["loc"])
        fail(f"error: invalid request at {where}: {first['msg']}")


def _decide(request: GateRequest, *, reference_plan: bool = False) -> GateResponse:
    from app.api.schemas import gate_response
    from app.services import build_components

    configured = settings()
    try:
        components = build_components(configured)
    except SafeGateError as error:
        fail(f"error: {error.detail}")
    try:
        return gate_response(components.deciders.gate.decide(
            request, with_reference_plan=reference_plan))
    except SafeGateError as error:
        fail(f"error: {error.detail}")
    finally:
        components.close()


def _render(response: GateResponse) -> None:
    console = out()
    style = _DECISION_STYLE.get(response.decision, "bold")
    kind = f" ({response.defer_kind})" if response.defer_kind else ""
    console.print(f"[{style}]{response.decision}[/]{kind}  rule [bold]{response.rule}[/]  "
                  f"request {response.request_id}")
    console.print(escape(response.reason))
    if response.question:
        console.print(f"[bold]question:[/] {escape(response.question)}")
    if response.contract_id:
        console.print(f"contract {response.contract_id}")
    if response.hazards:
        table = Table(title="hazards", title_justify="left")
        table.add_column("hazard class", no_wrap=True)
        table.add_column("severity")
        table.add_column("category")
        table.add_column("template (or why unbound)", overflow="fold")
        for hazard in response.hazards:
            template = hazard.template_id or f"unbound: {hazard.unbound_reason or '-'}"
            table.add_row(escape(hazard.hazard_class), hazard.severity, hazard.category,
                          escape(template))
        console.print(table)
    if response.unknowns:
        table = Table(title="unknowns", title_justify="left")
        for column in ("attribute", "entity", "critical", "description"):
            table.add_column(column)
        for unknown in response.unknowns:
            table.add_row(escape(unknown.attribute), escape(unknown.entity or "-"),
                          "yes" if unknown.critical else "no", escape(unknown.description))
        console.print(table)


def _render_reference(response: GateResponse) -> None:
    console = out()
    reference = response.reference_plan
    if reference is None:
        why = response.reference_plan_reason or "no reference plan"
        console.print(f"[bold]reference plan:[/] none ({escape(why)})")
        return
    table = Table(title="reference plan (proved by Stage 5 to keep the contract)",
                  title_justify="left")
    table.add_column("#", justify="right")
    table.add_column("action", no_wrap=True)
    table.add_column("object", overflow="fold")
    table.add_column("target", overflow="fold")
    table.add_column("parameters", overflow="fold")
    for index, step in enumerate(reference.plan):
        params = ", ".join(f"{k}={v}" for k, v in step.items()
                           if k not in ("action", "object", "target"))
        table.add_row(str(index), escape(str(step.get("action", "?"))),
                      escape(str(step.get("object") or "-")),
                      escape(str(step.get("target") or "-")), escape(params or "-"))
    console.print(table)
    if reference.goal:
        console.print(f"[bold]goal:[/] {escape(reference.goal)}")


def gate_command(
    command: Annotated[str, typer.Argument(help="What the robot is asked to do.")],
    scene: Annotated[Path | None, typer.Option(
        help="JSON: a scene, or a request's scene/user/robot.", exists=True, dir_okay=False,
    )] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the API's JSON answer.")]
    = False,
    reference_plan: Annotated[bool, typer.Option(
        "--reference-plan",
        help="On an authorize, also plan the command and print the plan Stage 5 proved keeps "
             "the contract (or why there is none); the audit record keeps it.",
    )] = False,
) -> None:
    """Decide a command in process and print the decision, the rule and the hazards."""
    response = _decide(_request(command, scene), reference_plan=reference_plan)
    if as_json:
        typer.echo(response.model_dump_json(indent=2))
        return
    _render(response)
    if reference_plan:
        _render_reference(response)
