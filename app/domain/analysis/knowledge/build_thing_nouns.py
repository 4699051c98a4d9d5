"""Build `thing_nouns.json`: the English nouns whose usual sense is a physical thing.

In: WordNet 3.0's `index.noun` and `data.noun`, by default from Debian's `wordnet-base`
(`/usr/share/wordnet`) or the directory given as the first argument (`apt-get download
wordnet-base` and `dpkg-deb -x` it where the package cannot be installed). Out:
`thing_nouns.json` beside this script: every single-word noun lemma one of whose three most
frequent senses WordNet files under a physical lexicographer file (artifact, food, object,
plant, animal, body, substance), or whose most frequent sense is a message (a letter, a
recipe); and, apart, the nouns whose most frequent sense is an amount (`measures`: a spoonful,
200 ml), which name what follows them ("a capful of bleach" is bleach). The reader makes up
an object the scene lacks only from such a noun: "a turn" or "the sleep" is no thing a robot
can carry.
Fails: FileNotFoundError when the WordNet files are missing.

Run: `python app/domain/analysis/knowledge/build_thing_nouns.py [/path/to/wordnet]`.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

# WordNet's lexicographer files (lexnames(5WN)) that hold physical things.
PHYSICAL_FILES = {5: "animal", 6: "artifact", 8: "body", 13: "food", 17: "object", 20: "plant",
                  27: "substance"}
SENSES_CONSIDERED = 3
COMMUNICATION = 10  # a letter, a recipe, a name: what a robot reads out, carries or posts
QUANTITY = 23  # a spoonful, a capful, 200 ml: an amount of what follows or was named


def _lexfile_by_offset(data_noun: Path) -> dict[str, int]:
    found: dict[str, int] = {}
    for line in data_noun.read_text(encoding="latin-1").splitlines():
        if line and not line.startswith(" "):
            offset, lexfile = line.split()[:2]
            found[offset] = int(lexfile)
    return found


def build(source: Path) -> dict[str, object]:
    """The noun table from the WordNet files in `source`."""
    lexfile = _lexfile_by_offset(source / "data.noun")
    nouns: set[str] = set()
    measures: set[str] = set()
    for line in (source / "index.noun").read_text(encoding="latin-1").splitlines():
        if not line or line.startswith(" "):
            continue
        fields = line.split()
        lemma, pointer_count = fields[0], int(fields[3])
        # lemma pos synset_cnt p_cnt [ptr_symbol...] sense_cnt tagsense_cnt offsets (by frequency)
        offsets = fields[4 + pointer_count + 2:]
        if "_" in lemma or not lemma.isascii():
            continue
        senses = [lexfile[o] for o in offsets]
        if senses[0] == QUANTITY:
            measures.add(lemma)
        elif any(f in PHYSICAL_FILES for f in senses[:SENSES_CONSIDERED]) or (
                senses[0] == COMMUNICATION):
            nouns.add(lemma)
    return {"_provenance": "Derived from WordNet 3.0 (Princeton University, WordNet licence) as "
                           "packaged by Debian's wordnet-base, by build_thing_nouns.py.",
            "nouns": sorted(nouns), "measures": sorted(measures)}


if __name__ == "__main__":
    wordnet = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("/usr/share/wordnet")
    target = Path(__file__).with_name("thing_nouns.json")
    target.write_text(json.dumps(build(wordnet), separators=(",", ":")) + "\n")
