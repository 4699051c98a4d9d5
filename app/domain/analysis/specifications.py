"""Stage 1, step 1 (read): verbless specifications of a drink or dish ("- milk, one sugar").

In: the command's clauses, the lexicon and the test for a clause the reader cannot act on. Out:
for each specification clause, the clause that makes the thing it belongs to and the substances
it adds, so the recipe puts them in what it makes (an allergy to milk still applies).
Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from app.domain.analysis.arguments import Clause
from app.domain.analysis.lexicon import Lexicon
from app.domain.world.substances import substance_trait

_AMOUNTS = frozenset({"one", "two", "three", "a", "an", "some", "extra", "little", "bit", "splash",
                      "dash", "drop", "spoon", "spoonful", "sugars", "lump", "lumps", "of",
                      "please", "just", "lots", "plenty", "and", "with", "strong", "weak", "black",
                      "white", "milky", "hot", "warm", "cold", "thin", "thick", "slice", "slices",
                      "no", "not", "without", "too", "much", "half", "double", "single", "shot",
                      "on", "the", "side", "ta", "cheers", "thanks", "x"})
_NEGATING = frozenset({"no", "not", "without"})


def specifications(clauses: tuple[Clause, ...], lexicon: Lexicon,
                   unreadable: Callable[[Clause, Lexicon], str | None],
                   ) -> dict[int, tuple[int, list[str]]]:
    """Verbless specifications of a drink or dish ("- milk, one sugar", "extra jam"), by
    clause: the clause that makes the thing they belong to, and what they add to it."""
    found: dict[int, tuple[int, list[str]]] = {}
    for index, clause in enumerate(clauses):
        if clause.kind != "step" or unreadable(clause, lexicon) is None:
            continue
        added = ingredients(clause.text)
        makers = [i for i in range(index) if clauses[i].kind == "step"
                  and "make" in clauses[i].schemas]
        if added is not None and makers:
            found[index] = (makers[-1], added)
    return found


def ingredients(text: str) -> list[str] | None:
    """The substances a verbless specification adds ("milk, one sugar", "milky, no sugar",
    "extra jam"), or None when the words are more than a specification. Negated substances
    ("no sugar") add nothing."""
    words = re.findall(r"[a-z]+", text.lower())
    substances = [w for w in words if w not in _AMOUNTS and any(
        substance_trait(w, t) is not None for t in ("food", "liquid"))]
    if not substances or any(w not in _AMOUNTS and w not in substances for w in words):
        return None
    added = [w for i, w in enumerate(words) if w in substances
             and not (i and words[i - 1] in _NEGATING)]
    if "milky" in words:
        added.append("milk")
    return added
