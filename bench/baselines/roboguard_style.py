"""The RoboGuard-style baseline: pre-authored safety rules grounded in the scene graph.

Re-implemented from the published description of RoboGuard (Ravichandran et al. 2025): a fixed
set of safety rules is contextualised with the robot's world model (objects, relations, people,
rooms) into grounded specifications, and the actions a plan implies are checked against them.
Our version has no LLM: the scene graph and the command's grounding come from
`bench/baselines/grounding.py`, the rules from `data/roboguard_rules.yaml`, and each rule's
`check` names one of the grounded checks below. It never sees SafeGate's analyzer or templates.
A fact the scene does not state grounds nothing, so the method never defers.

In: a `GateRequest`. Out: a `Verdict`, "reject" naming each violated rule and the entities it
was grounded on, else "authorize".
Fails: `BaselineDataError` at load on a malformed rules file or an unknown check name.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from contextlib import AbstractContextManager, contextmanager
from typing import Any

from app.domain.models import GateRequest
from bench.baselines.grounding import (
    Entity,
    Grounding,
    SceneGraph,
    build_scene_graph,
    ground_command,
    matches,
    matches_any,
)
from bench.baselines.text import BaselineDataError, Lexicon, load_yaml
from bench.method import Decide, Verdict

Rule = Mapping[str, Any]
Check = Callable[[Rule, SceneGraph, Grounding], str | None]
_ADULTS = ("adult", "older_adult", "teen")


def _acts(rule: Rule, grounding: Grounding) -> bool:
    wanted = rule.get("actions")
    return wanted is None or bool(grounding.actions & set(wanted))


def _ids(entities: list[Entity]) -> str:
    return ",".join(e.id for e in entities)


def _give_to(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    items = [o for o in g.objects if matches_any(o.attrs, rule["object_any"])]
    people = [p for p in g.recipients if matches(p.attrs, rule["person"])]
    return f"{_ids(items)} to {_ids(people)}" if _acts(rule, g) and items and people else None


def _allergen(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if not _acts(rule, g):
        return None
    for item in g.objects:
        allergens = set(map(str, item.attrs.get("allergens") or []))
        for person in g.recipients:
            if allergens & set(map(str, person.attrs.get("allergies") or [])):
                return f"{item.id} to allergic {person.id}"
    return None


def _prescription(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if not _acts(rule, g):
        return None
    for item in g.objects:
        owner = item.attrs.get("prescribed_for")
        wrong = [p for p in g.recipients if owner is not None and p.id != owner]
        if wrong:
            return f"{item.id} (for {owner}) to {_ids(wrong)}"
    return None


def _target_rooms(graph: SceneGraph, g: Grounding, moved: list[Entity]) -> set[str]:
    moved_ids = {m.id for m in moved}
    rooms = set(g.rooms) | {o.room for o in g.objects if o.id not in moved_ids and o.room}
    return rooms | {p.room for p in g.people if p.room and p.id != graph.user_id}


def _place_near(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    items = [o for o in g.objects if matches_any(o.attrs, rule["object_any"])]
    if not (_acts(rule, g) and items):
        return None
    rooms = _target_rooms(graph, g, items)
    exposed = [p for p in graph.people_in(rooms) if matches(p.attrs, rule["person"])]
    return f"{_ids(items)} near {_ids(exposed)}" if exposed else None


def _active_heat(rule: Rule, g: Grounding) -> list[Entity]:
    switching = bool(g.actions & {"switch_on", "heat"})
    return [
        o for o in g.objects
        if matches_any(o.attrs, rule["heat_any"])
        and (o.attrs.get("on") is True or o.attrs.get("pilot_flame") is True or switching)
    ]


def _near_heat(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    fuel = [o for o in g.objects if matches_any(o.attrs, rule["object_any"])]
    heat = [h for h in _active_heat(rule, g) if h not in fuel]
    return f"{_ids(fuel)} at {_ids(heat)}" if _acts(rule, g) and fuel and heat else None


def _incompatible(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    first = [o for o in g.objects if matches(o.attrs, rule["first"])]
    second = [o for o in g.objects if matches(o.attrs, rule["second"])]
    return f"{_ids(first)} with {_ids(second)}" if _acts(rule, g) and first and second else None


def _electrical_near_water(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    powered = [o for o in g.objects if o.attrs.get("electrical") is True]
    if not (_acts(rule, g) and powered):
        return None
    rooms = _target_rooms(graph, g, powered)
    water = [o for o in graph.objects
             if o.room in rooms and matches_any(o.attrs, rule["water_any"])]
    bathing = [p for p in graph.people_in(rooms) if matches(p.attrs, rule["person"])]
    return f"{_ids(powered)} by {_ids(water + bathing)}" if water or bathing else None


def _pour_on_electrical(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    exempt = set(rule.get("exempt_types", []))
    powered = [
        o for o in g.objects
        if (o.attrs.get("electrical") is True or o.type in {"Toaster", "Socket", "PowerStrip"})
        and o.type not in exempt
    ]
    return f"liquid on {_ids(powered)}" if _acts(rule, g) and powered else None


def _metal_in_microwave(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    ovens = [o for o in g.objects if o.type == "Microwave"]
    metal = [o for o in g.objects if matches_any(o.attrs, rule["metal_any"])]
    return f"{_ids(metal)} in {_ids(ovens)}" if _acts(rule, g) and ovens and metal else None


def _payload(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    limit = graph.robot.payload_kg if graph.robot else None
    if limit is None or not _acts(rule, g):
        return None
    heavy = [
        o for o in g.objects
        if isinstance(o.attrs.get("mass_kg"), int | float) and o.attrs["mass_kg"] > limit
    ]
    return f"{_ids(heavy)} over {limit} kg" if heavy else None


def _skill(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    skills = graph.robot.skills if graph.robot else None
    if skills is None:
        return None
    needed: Mapping[str, str] = rule["skills"]
    missing = sorted({needed[a] for a in g.actions if a in needed} - set(skills))
    return "lacks " + ",".join(missing) if missing else None


def _stairs(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    robot = graph.robot
    if robot is None or robot.skills is None or "climb_stairs" in robot.skills:
        return None
    if not _acts(rule, g):
        return None
    for room in sorted(_target_rooms(graph, g, [])):
        route = graph.route(robot.room, room)
        if route and any("stairs" in r for r in route):
            return f"route to {room} crosses stairs"
    return None


def _privacy(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if not _acts(rule, g):
        return None
    rooms = _target_rooms(graph, g, [])
    private = sorted(rooms & set(rule["private_rooms"]))
    watched = [p for p in g.people if p.id != graph.user_id]
    watched += [p for p in graph.people_in(rooms) if p.id != graph.user_id and p not in watched]
    if watched or private:
        return f"imaging {_ids(watched) or ','.join(private)}"
    return None


def _mobility_aid(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    aids = [o for o in g.objects if o.type in set(rule["aid_types"])]
    users = [p for p in graph.people if matches(p.attrs, rule["person"])]
    handed_back = any(p in g.recipients for p in users) and "handover" in g.actions
    if _acts(rule, g) and aids and users and not handed_back:
        return f"{_ids(aids)} away from {_ids(users)}"
    return None


def _egress(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if not _acts(rule, g):
        return None
    exits = [o for o in g.objects if matches_any(o.attrs, rule["egress_any"])]
    rooms = sorted(g.rooms & set(rule["egress_rooms"]))
    return f"blocks {_ids(exits) or ','.join(rooms)}" if exits or rooms else None


def _unattended_heat(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if "leave_unattended" not in g.actions:
        return None
    switching = _acts(rule, g)
    for heat in (o for o in g.objects if matches_any(o.attrs, rule["heat_any"])):
        if not (switching or heat.attrs.get("on") is True):
            continue
        watchers = [p for p in graph.people_in([heat.room] if heat.room else [])
                    if p.attrs.get("age_group") in _ADULTS
                    and p.attrs.get("cognitive_state") != "asleep"]
        if not watchers:
            return f"{heat.id} left on unwatched"
    return None


def _speed(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if not _acts(rule, g) or graph.robot is None:
        return None
    rooms = set()
    for target in _target_rooms(graph, g, []):
        rooms |= set(graph.route(graph.robot.room, target) or [target])
    near = [p for p in graph.people_in(rooms) if p.id != graph.user_id]
    near += [p for p in g.people if p.id != graph.user_id and p not in near]
    return f"fast near {_ids(near)}" if near else None


def _startle(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    if not _acts(rule, g):
        return None
    targets = [p for p in g.people if p.id != graph.user_id]
    targets += [p for p in graph.people
                if (p.attrs.get("cognitive_state") == "asleep" or p.attrs.get("posture") == "lying")
                and p not in targets]
    return f"startles {_ids(targets)}" if targets else None


def _leave_vulnerable(rule: Rule, graph: SceneGraph, g: Grounding) -> str | None:
    left = [p for p in g.people if matches_any(p.attrs, rule["person_any"])]
    return f"leaves {_ids(left)} alone" if _acts(rule, g) and left else None


CHECKS: dict[str, Check] = {
    "give_to": _give_to, "allergen": _allergen, "prescription": _prescription,
    "place_near": _place_near, "near_heat": _near_heat, "pour_on_electrical": _pour_on_electrical,
    "metal_in_microwave": _metal_in_microwave, "incompatible": _incompatible,
    "electrical_near_water": _electrical_near_water, "payload": _payload, "skill": _skill,
    "stairs": _stairs, "privacy": _privacy, "mobility_aid": _mobility_aid, "egress": _egress,
    "unattended_heat": _unattended_heat, "speed": _speed, "startle": _startle,
    "leave_vulnerable": _leave_vulnerable,
}


class RoboGuardStyle:
    """The RoboGuard-style method: reject when a grounded rule is violated."""

    name = "roboguard-style"
    description = (
        "RoboGuard-style (after Ravichandran et al. 2025), re-implemented from the paper's "
        "description: pre-authored safety rules grounded in the request's scene graph, checked "
        "against the command's implied actions; binary (never defers)."
    )

    def __init__(self, rules: tuple[Rule, ...], synonyms: Mapping[str, Any],
                 actions: Lexicon) -> None:
        """Args: the rules, the synonym tables and the action lexicon (see `from_data`)."""
        self.rules = rules
        self.synonyms = synonyms
        self.actions = actions

    @classmethod
    def from_data(cls) -> RoboGuardStyle:
        """Load `data/roboguard_rules.yaml` and `data/actions.yaml`.

        Raises:
            BaselineDataError: a malformed file or a rule naming an unknown check.
        """
        raw = load_yaml("roboguard_rules.yaml")
        if not isinstance(raw, dict) or not isinstance(raw.get("rules"), list):
            raise BaselineDataError("roboguard_rules.yaml: needs a `rules` list")
        for rule in raw["rules"]:
            if rule.get("check") not in CHECKS:
                raise BaselineDataError(f"roboguard rule {rule.get('id')}: unknown check")
        actions = Lexicon.from_mapping(load_yaml("actions.yaml"), "actions.yaml")
        return cls(tuple(raw["rules"]), raw.get("synonyms") or {}, actions)

    def violations(self, request: GateRequest) -> list[str]:
        """`rule id (grounded entities)` for every violated rule, in file order."""
        graph = build_scene_graph(request, self.synonyms)
        grounding = ground_command(graph, request.command, self.actions, self.synonyms)
        found: list[str] = []
        for rule in self.rules:
            detail = CHECKS[rule["check"]](rule, graph, grounding)
            if detail is not None:
                found.append(f"{rule['id']} ({detail})")
        return found

    def decide(self, request: GateRequest) -> Verdict:
        """Reject on any violated rule, else authorize."""
        violated = self.violations(request)
        if violated:
            return Verdict("reject", "violates " + "; ".join(violated))
        return Verdict("authorize", "no grounded rule violated")

    def unavailable_reason(self) -> str | None:
        """The baseline always runs."""
        return None

    def open(self) -> AbstractContextManager[Decide]:
        """Yield `decide` (the baseline holds no resources)."""
        return self._deciding()

    @contextmanager
    def _deciding(self) -> Iterator[Decide]:
        yield self.decide
