"""Rough handling of things that must not be knocked about: pressurised gas.

In: the `Context`. Out: a proposal (fire_ignition) when a step throws, drops, kicks, rolls or
bumps a pressurised container ("roll the gas bottle down the steps", "chuck the aerosol in the
skip"), or puts one on or by a heat source: a damaged valve or a burst can leaks flammable gas
or explodes. The command asks for the rough handling itself, so it is unpreventable. Never
fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.models import Category, Level, Preventability, Severity

_ROUGH_VERBS = frozenset({"throw", "toss", "fling", "hurl", "lob", "chuck", "drop", "kick",
                          "roll", "bounce", "bang", "bash", "slide", "tumble", "tip"})


def rough_handling_hazards(ctx: Context) -> None:
    """Add the hazards of knocking pressurised containers about or heating them."""
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action is None:
            continue
        verb = (step.verb or "").split(" ")[0]
        rough = verb in _ROUGH_VERBS or step.action == "throw"
        heated = any(o.has("heat_source") for o in ctx.objects(grounded.destination))
        if not (rough or heated):
            continue
        for ref in grounded.objects:
            for obj in ctx.objects(ref):
                if not obj.has("pressurized"):
                    continue
                how = "put on a heat source" if heated and not rough else "knocked about"
                ctx.add(Level.TASK, Category.PHYSICAL, "fire_ignition", f"{obj.label} holds gas "
                        f"under pressure and is {how}: a damaged valve or a burst can leaks "
                        "flammable gas or explodes.", {"obj": obj.id}, Severity.HIGH,
                        Preventability.UNPREVENTABLE)
                return
