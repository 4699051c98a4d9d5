"""An LLM planner in the SMART-LLM style, writing plans in SafeGate's action model.

In: a `GateRequest` (command, scene, robot) and optionally a compiled `Contract`, rendered as
plain-language planning constraints (`planner_constraints`). The prompt lists the canonical
actions of `app.domain.world` with their arguments. Out: the plan as wire-shape action dicts
(`shared/spec/plans-and-monitoring.md`), ready for POST /verify. Each answer is validated by
parsing every step against the symbolic world, stepping through the plan (known action names,
ids of the right kind, an object to act on), with one repair round. Whether the plan obeys the
contract is for /verify to decide, not for this module.
Fails: `LlmError` (timeout, connection, 5xx, 429, or `LlmOutputInvalid` when no valid plan
came after the repair); the caller then has no plan and nothing runs.
"""

from __future__ import annotations

import json
from typing import Any

from app.adapters.llm.client import ChatClient
from app.adapters.llm.prompting import PromptSet
from app.adapters.llm.rendering import information
from app.adapters.llm.schemas import PlanAnswer, json_schema
from app.adapters.llm.structured import ask_structured
from app.domain.contracts import Contract, planner_constraints
from app.domain.errors import PlanError
from app.domain.models import GateRequest, Level
from app.domain.world import describe_actions, parse_action, state_from_request, step


def _action_lines() -> str:
    lines = []
    for action in describe_actions():
        arguments = ", ".join(
            f"{a['name']} ({a['type']}{'' if a['required'] else ', optional'})"
            for a in action["arguments"]
        )
        lines.append(f"- {action['name']}: {action['summary']}; {arguments or 'no arguments'}")
    return "\n".join(lines)


class LlmPlanner:
    """Writes a plan for a command, under a contract's constraints."""

    name = "llm-planner"

    def __init__(self, client: ChatClient, *, prompts: PromptSet | None = None) -> None:
        """Set the planner up.

        Args:
            client: the chat client.
            prompts: the prompt version to use (default v1).
        """
        self._client = client
        self._prompts = prompts or PromptSet()
        self._system = self._prompts.render(
            "planner_system",
            actions=_action_lines(),
            schema=json.dumps(json_schema(PlanAnswer)),
        )

    def plan(
        self, request: GateRequest, contract: Contract | None = None
    ) -> list[dict[str, Any]]:
        """Write a plan for the request's command.

        Args:
            request: the gate request (its command, scene and robot).
            contract: the task's contract; None plans without safety constraints (the plain
                SMART-LLM baseline).

        Returns:
            The plan's actions in the wire shape.

        Raises:
            LlmError: the LLM failed or gave no valid plan after one repair.
        """
        constraints = planner_constraints(contract) if contract is not None else []
        user = self._prompts.render(
            "planner",
            command=request.command,
            information=information(request, Level.USER, with_command=False),
            constraints="\n".join(f"- {c}" for c in constraints) or "- none",
        )
        answer = ask_structured(
            self._client,
            system=self._system,
            user=user,
            answer_model=PlanAnswer,
            prompts=self._prompts,
            check=lambda plan: _plan_problems(request, plan),
        )
        return [s.to_wire() for s in answer.steps]


def _plan_problems(request: GateRequest, plan: PlanAnswer) -> list[str]:
    state = state_from_request(request)
    for index, raw in enumerate(plan.steps):
        try:
            action = parse_action(raw.to_wire(), step=index, state=state)
            state = step(state, action)
        except PlanError as error:
            return [error.detail]
    return []
