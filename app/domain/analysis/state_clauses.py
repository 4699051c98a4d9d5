"""People's states stated by the command ("while grandpa is asleep", "the baby is napping").

In: the grounder, the grounded steps, the scene view and the knowledge tables. Out: the scene
view's people updated in place (a person named with a sleep word becomes `asleep`; a made-up
person gets the step's room, so noise and startle rules can see them). Never fails.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.mentions import Mention
from app.domain.analysis.scene_view import SceneView

if TYPE_CHECKING:
    from app.domain.analysis.grounding import GroundedStep, Grounder


def apply_state_clauses(grounder: Grounder, steps: list[GroundedStep], view: SceneView,
                        knowledge: Knowledge) -> None:
    """Read "while grandpa is asleep" / "the baby is napping" into the people's states.

    A person named with a sleep word in a step's condition (or its own clause) is marked
    asleep; a made-up person gets the step's room, so noise and startle rules can see them.
    """
    sleep_words = knowledge.vulnerability_words.get("asleep", ())
    for grounded in steps:
        text = f"{grounded.step.condition or ''} {grounded.step.text}"
        words = text.split()
        for position, word in enumerate(words):
            window = " ".join(words[position + 1:position + 5])
            if word not in knowledge.role_words or not any(w in window for w in sleep_words):
                continue
            mention = Mention(text=word, head=word, kind="person", role_word=word,
                              role=knowledge.role_words[word].name)
            rooms = [r.ids[0] for r in (*grounded.objects, grounded.destination)
                     if r is not None and r.kind == "room"]
            for person_id in grounder.resolve(mention, remember=False).ids:
                person = view.people.get(person_id)
                if person is None:
                    continue
                person.cognitive_state = person.cognitive_state or "asleep"
                if person.virtual and person.room is None and rooms:
                    person.room = rooms[0]
