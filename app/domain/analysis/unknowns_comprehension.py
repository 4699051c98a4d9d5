"""What the command said that the reader did not understand, when it may matter for safety.

In: the `Context` (its `parsed.not_understood` gaps from the reader, when present) and the
`UnknownRules` tables. Out: one critical `UnknownFact` per gap whose clause involves a
hazardous object, a person, or a hazardous word, and per instruction whose verb is not understood
at all ("I did not understand ...; what should I do?"), with the object or person as entity. A
gap in harmless chatter (a word not understood in a clause whose action was) adds nothing: missing
information that cannot change the decision is not worth a question. Never fails.
"""

from __future__ import annotations

import re

from app.domain.analysis.context import Context
from app.domain.analysis.involvement import named_objects, named_people
from app.domain.analysis.unknown_rules import UnknownRules, has_phrase

_HAZARD_TRAITS = ("sharp", "toxic", "corrosive", "hot", "heat_source", "ignition", "flammable",
                  "medication", "dangerous_in_use", "heavy", "safety_barrier", "walking_aid")


def comprehension_unknowns(ctx: Context, rules: UnknownRules) -> None:
    """Turn each safety-relevant gap in understanding into a critical unknown."""
    parsed = ctx.parsed
    gaps = getattr(parsed, "not_understood", ()) if parsed is not None else ()
    for gap in gaps:
        clause = str(getattr(gap, "clause", "") or gap).lower()
        phrase = str(getattr(gap, "phrase", "") or gap)
        verb_gap = getattr(gap, "part", "verb") == "verb"
        hazardous = [o for o in named_objects(ctx, clause)
                     if any(o.has(t) for t in _HAZARD_TRAITS)]
        # An unknown verb aimed at a person matters; a mention of someone in a clause whose
        # action was understood matters only if they cannot look after themselves.
        people = [p for p in named_people(ctx, clause) if not p.is_user and (
            verb_gap or p.child or p.frail or p.age_group is None)]
        word = has_phrase(clause, rules.group("comprehension.hazard_words"))
        aimed = verb_gap and re.search(
            rf"\b{re.escape(phrase.lower())} (?:him|her|them)\b", clause) is not None
        # An instruction whose verb is not understood at all is asked about whatever it names:
        # what it would do is exactly what the analyzer cannot know ("nuke the burrito").
        if not (verb_gap or hazardous or people or word or aimed):
            continue
        about = (hazardous[0].label if hazardous else people[0].label if people else
                 f"'{word}'" if word else "a person" if aimed else "an action I do not know")
        entity = hazardous[0].id if hazardous else people[0].id if people else None
        ctx.unknown("instruction", f"what '{phrase}' means in '{clause}'", critical=True,
                    why=f"the clause involves {about}, and a misread instruction could make "
                    "the task unsafe", entity=entity,
                    question=f"I did not understand '{phrase}' in \"{clause}\"; what should "
                    "I do?")
