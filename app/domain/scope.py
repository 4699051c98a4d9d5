"""The task's scope: what an authorized command lets a plan do, read from Stage 1's sketch.

In: Stage 1's `Understanding` of a request (the sketch of the plan the command induces: literal,
enabling and clean-up steps, every option of every choice, each tied to the clause it serves)
and the request itself. Out: a `TaskScope`, stored with the contract: the steps the task
authorizes (action, object, target, and the words of the command each one serves), plus the
enabling moves every planner needs on anything (`ENABLING`: go anywhere, open and close what is in
the way, put down what is held) and picking up something else only to move it aside and put
it down again in the same room. `scope_lines` renders it in words for a planner.
Made-up entities (a surface or a cup Stage 1 added because the scene lacked one, the speaker
when the scene does not list them) stand for any entity of their type: `object_kind` or
`target_kind` says which (an object type, `room`, `person` for the speaker, `person:<role>` for
someone else the command names). The checks live in `scope_check.py`.
Fails: never; a command with no step yields a scope that authorizes only the enabling moves.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pydantic import BaseModel, ConfigDict

from app.domain.analysis.referents import USER_ID
from app.domain.analysis.sketch import Choice, Planned
from app.domain.models import GateRequest
from app.domain.world import WorldState, state_from_request
from app.domain.world.object_types import normalize_type

if TYPE_CHECKING:
    from app.domain.analysis import Understanding

ENABLING: tuple[str, ...] = ("GoToObject", "navigate", "OpenObject", "CloseObject", "PutObject",
                             "Wait", "Finish")
"""Actions in scope on any entity: moving, opening and closing what is in the way, setting
down what is held, waiting, ending the task."""

PICKUP = "PickupObject"


class ScopeStep(BaseModel):
    """One step the command authorizes, with the words of the command it serves."""

    model_config = ConfigDict(frozen=True)

    action: str
    object: str | None = None
    target: str | None = None
    words: str
    kind: str = "literal"
    """`literal` (what the command says), `enabling` (what it takes) or `cleanup`."""
    object_kind: str | None = None
    """Set when Stage 1 made the object up: any object of this type will do."""
    target_kind: str | None = None
    """Set when Stage 1 made the target up: an object type, `room`, `person` (the speaker: anyone)
    or `person:<role>` (someone of that role or name)."""


class TaskScope(BaseModel):
    """What the task lets a plan do (see the module docstring)."""

    model_config = ConfigDict(frozen=True)

    command: str
    steps: tuple[ScopeStep, ...] = ()
    enabling: tuple[str, ...] = ENABLING
    move_aside: bool = True
    """Whether something outside the task may be picked up to be put down in the same room."""

    def objects(self) -> tuple[str, ...]:
        """The entities the task acts on or with, in the order the command meets them."""
        found: dict[str, None] = {}
        for step in self.steps:
            for entity in (step.object, step.target):
                if entity is not None:
                    found.setdefault(entity)
        return tuple(found)


def task_scope(understanding: Understanding, request: GateRequest) -> TaskScope:
    """The scope of an authorized task, from Stage 1's reading of its command.

    Args:
        understanding: what `SymbolicAnalyzer.understand(request)` read.
        request: the gate request (as the analyzer read it).

    Returns:
        The scope: every step of the sketch (every option of every choice; the clean-up
        unless the command wants things left as they are), deduplicated, each with the words
        of the clause it serves quoted as the command spells them.
    """
    sketch = understanding.sketch
    planned: list[Planned] = []
    for item in sketch.literal:
        if isinstance(item, Choice):
            planned.extend(step for option in item.options for step in option)
        else:
            planned.append(item)
    if not sketch.leave:
        planned.extend(sketch.cleanup)
    clauses = {g.index: g.clause.text for g in understanding.grounded}
    scene, given = understanding.scene, state_from_request(request)
    steps: dict[tuple[str, str | None, str | None], ScopeStep] = {}
    for item in planned:
        action = item.action
        key = (action.name, action.object, action.target)
        if key in steps:
            continue
        words = quote(clauses.get(item.clause, request.command), request.command)
        steps[key] = ScopeStep(
            action=action.name, object=action.object, target=action.target, words=words,
            kind=item.kind, object_kind=_made_up_kind(action.object, scene, given),
            target_kind=_made_up_kind(action.target, scene, given))
    return TaskScope(command=request.command, steps=tuple(steps.values()))


def quote(words: str, command: str) -> str:
    """The words as the command spells them (Stage 1 reads a lower-cased copy)."""
    at = command.lower().find(words.lower())
    return command[at:at + len(words)] if at >= 0 and words else words


def _made_up_kind(entity: str | None, scene: WorldState, given: WorldState) -> str | None:
    """For an entity Stage 1 added (the request's scene lacks it): what stands for it."""
    if entity is None or given.entity_type(entity) is not None:
        return None
    kind = scene.entity_type(entity)
    if kind == "object":
        return normalize_type(scene.objects[entity].kind.name)
    if kind == "person" and entity != USER_ID:
        # "my sister" whom the scene does not list: a person of that role or name.
        role = normalize_type(scene.people[entity].role or "")
        return f"person:{role}" if role else kind
    return kind


def scope_lines(scope: TaskScope) -> list[str]:
    """The scope in plain words, one line each, for a planner's prompt.

    Args:
        scope: the task's scope.

    Returns:
        What the command authorizes (grouped by the words that authorize it), then what is
        allowed on anything, then the rule for everything else.
    """
    lines: list[str] = []
    by_words: dict[str, list[str]] = {}
    for step in scope.steps:
        if step.action in scope.enabling and step.kind != "literal":
            continue
        by_words.setdefault(step.words, []).append(describe_step(step))
    for words, described in by_words.items():
        lines.append(f'For "{words}" the task authorizes: {"; ".join(described)}.')
    if not by_words:
        lines.append(f'The command ("{scope.command}") authorizes no action beyond the '
                     "enabling moves below.")
    lines.append(f"On anything, a plan may also: {', '.join(scope.enabling)} (go anywhere, "
                 "open and close what is in the way, put down what it holds).")
    if scope.move_aside:
        lines.append("Anything else may be picked up only to move it aside: put it down again "
                     "in the same room before using the gripper for anything else with it.")
    lines.append("Any other step is outside the task and fails verification (kind `scope`); "
                 "the runtime monitor halts on it.")
    return lines


def describe_step(step: ScopeStep) -> str:
    """One authorized step in words, e.g. `HandOver mug_1 -> dad`."""
    obj = _entity(step.object, step.object_kind)
    target = _entity(step.target, step.target_kind)
    text = step.action + (f" {obj}" if obj else "")
    return text + (f" -> {target}" if target else "")


def _entity(entity: str | None, kind: str | None) -> str | None:
    if entity is None:
        return None
    return entity if kind is None else f"any {kind} (for {entity})"
