"""`safegate templates export|import`: the Hazard Template Library as a YAML file.

In: the configured database; for import, a YAML file shaped like `templates_db/*.yaml` whose
entries may carry a `status` (an export's own shape). Out: the YAML on stdout or in a file; for
import, a table of what was created, revised, re-statused or left unchanged, and the validation's
warnings. A running server reloads its active templates at its next start or library change.
Fails: exit 1 with a table of every problem when any entry is invalid (nothing is imported), or
with one line for an unreadable file or a database error.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.markup import escape
from rich.table import Table

from app.commands.shared import err, fail, out, repository, settings
from app.domain.errors import Conflict, TemplateInvalid, Unavailable
from app.domain.models import TemplateStatus

if TYPE_CHECKING:
    from app.services.template_transfer import ImportReport

templates_cli = typer.Typer(help="Export and import the Hazard Template Library (YAML).",
                            no_args_is_help=True)


@templates_cli.command("export")
def templates_export(
    output: Annotated[Path | None, typer.Option(
        "--out", "-o", help="Write here instead of stdout.", dir_okay=False)] = None,
    status: Annotated[TemplateStatus | None, typer.Option(
        help="Only templates with this status.")] = None,
) -> None:
    """Write every template at its current version, with its status, as YAML."""
    from app.services.template_transfer import export_yaml

    try:
        exported = export_yaml(repository(), status=status)
    except Unavailable as error:
        fail(f"error: {error.detail}")
    if output is None:
        typer.echo(exported.text, nl=False)
        return
    output.write_text(exported.text, encoding="utf-8")
    err().print(f"wrote {exported.count} templates to {output}", markup=False)


def _problems(error: TemplateInvalid) -> Table:
    table = Table(title=escape(error.detail), title_justify="left")
    table.add_column("entry")
    table.add_column("field")
    table.add_column("problem")
    errors = error.extra.get("errors")
    rows = errors if isinstance(errors, list) else [
        {"where": "file", "field": error.field or "", "message": error.detail}]
    for row in rows:
        table.add_row(escape(str(row["where"])), escape(str(row["field"])),
                      escape(str(row["message"])))
    return table


def _summary(report: ImportReport, dry_run: bool) -> Table:
    table = Table(title="would import" if dry_run else "imported", title_justify="left")
    table.add_column("outcome")
    table.add_column("count", justify="right")
    table.add_column("templates")
    for outcome, ids in (("created", report.created), ("new version", report.revised),
                         ("status changed", report.status_changed),
                         ("unchanged", report.unchanged)):
        table.add_row(outcome, str(len(ids)), escape(", ".join(ids)))
    return table


@templates_cli.command("import")
def templates_import(
    file: Annotated[Path, typer.Argument(help="A YAML file with a `templates:` list.",
                                         exists=True, dir_okay=False)],
    author: Annotated[str, typer.Option(help="Who the new versions are credited to.")]
    = "cli import",
    dry_run: Annotated[bool, typer.Option(help="Validate and report; store nothing.")] = False,
) -> None:
    """Validate every entry as the API does, then store the whole file or nothing.

    A new id is created (as a draft unless the entry says `status`); a changed template gets a
    new version; a status is changed as `activate`/`deprecate` would change it.
    """
    from app.services.template_transfer import import_yaml

    configured = settings()
    try:
        text = file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        fail(f"error: cannot read {file}: {error}")
    try:
        report = import_yaml(repository(configured), text, author=author,
                             timeout_ms=configured.solver_timeout_ms, dry_run=dry_run)
    except TemplateInvalid as error:
        err().print(_problems(error))
        raise typer.Exit(code=1) from error
    except (Conflict, Unavailable) as error:
        fail(f"error: {error.detail}; nothing was imported")
    out().print(_summary(report, dry_run))
    if report.warnings:
        warnings = Table(title=f"{len(report.warnings)} warnings", title_justify="left")
        for column in ("entry", "field", "warning"):
            warnings.add_column(column)
        for issue in report.warnings:
            warnings.add_row(escape(issue.where), escape(issue.field), escape(issue.message))
        err().print(warnings)
