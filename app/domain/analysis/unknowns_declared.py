"""Facts the caller's own scene marks as unknown, on the things the command acts on; and who
is at the door when the robot is told to let an unidentified someone in.

In: the `Context` and the `Involvement` (objects and people the command touches). Out: one
critical `UnknownFact` per property of an involved object or person whose value the scene gives
as explicitly unknown ("contents": "unknown", "label": "none", "occupant": "unknown",
"material": "unknown liquid"...). The caller has said in so many words that it does not know;
the gate must not fill the gap with a guess, so the robot asks. Likewise "someone's at the door,
let them in": opening up to a person nobody has identified is asked about. Never fails.
"""

from __future__ import annotations

import re
from typing import Any

from app.domain.analysis.context import Context
from app.domain.analysis.involvement import Involvement
from app.domain.analysis.unknown_rules import UnknownRules

_UNKNOWN_WORDS = frozenset({"unknown", "unclear", "not known", "unsure", "uncertain", "?",
                            "unlabelled", "unlabeled", "unmarked", "unnamed"})
# A label, name tag or marking given as "none" means there is nothing to tell the item by.
_IDENTIFYING_KEYS = ("label", "name_label", "name_labels", "name_tag", "marking", "tag")
_NO_LABEL_WORDS = frozenset({"none", "no label", "blank", "missing", "no", "false"})


def declared_unknowns(ctx: Context, involved: Involvement, rules: UnknownRules) -> None:
    """Ask about every property the scene declares unknown on what the command involves."""
    del rules  # the scene's own words decide; no table is needed
    for entity_id, label, properties in _involved(involved):
        for key, value in properties.items():
            if not _declared_unknown(key, value):
                continue
            what = key.replace("_", " ")
            ctx.unknown(
                key, f"the {what} of {label}", critical=True,
                why=f"the scene itself says the {what} of {label} is not known, and the task "
                "acts on it", entity=entity_id,
                question=f"The {what} of {label} is not known to me: what is it?")


def _involved(involved: Involvement) -> list[tuple[str, str, dict[str, Any]]]:
    found = [(o.id, o.label, o.properties) for o in involved.objects.values() if not o.virtual]
    found += [(p.id, p.label, p.properties) for p in involved.people.values() if not p.virtual]
    return found


def _declared_unknown(key: str, value: Any) -> bool:
    if not isinstance(value, str):
        return False
    text = " ".join(value.lower().split())
    if text in _UNKNOWN_WORDS or text.startswith(("unknown ", "not known")):
        return True
    return key.lower() in _IDENTIFYING_KEYS and text in _NO_LABEL_WORDS


_ADMIT = re.compile(r"\b(?:let|buzz|wave|show) (?:them|him|her|whoever|anyone|someone|it|the"
                    r" \w+) (?:in|inside|through|up)\b|\bopen (?:the|front|back)? ?door "
                    r"(?:for|to) (?:them|him|her|whoever|anyone|someone)\b|\bopen up for\b")
_UNIDENTIFIED = re.compile(r"\b(?:someone|somebody|whoever|anyone|anybody|a stranger|a man|a "
                           r"woman|a person|the person|a visitor|someone's|somebody's)\b")


def visitor_unknowns(ctx: Context, involved: Involvement, rules: UnknownRules) -> None:
    """Ask who is at the door before letting an unidentified person in."""
    del involved, rules
    if _ADMIT.search(ctx.text) and _UNIDENTIFIED.search(ctx.text):
        ctx.unknown("visitor", "who is at the door", critical=True,
                    why="letting in someone nobody has identified lets anyone into the home",
                    entity=None, question="Who is at the door? I will let them in only if you "
                    "know who they are.")
