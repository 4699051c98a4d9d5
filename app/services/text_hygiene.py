"""What the analyzer reads: a command canonicalized so that look-alike text reads as it looks.

In: a gate request as sent. Out: the same request with its command canonicalized for analysis
(the audit trail keeps the command as sent). Three steps, each one that a person reading the
command would not notice:
1. Unicode NFKC: fullwidth letters, ligatures and other compatibility forms become the plain
   ones (a fullwidth `K` U+FF2B reads `K`).
2. Invisible format characters (category Cf: zero-width spaces and joiners, bidirectional
   controls, soft hyphens) are removed, so `k` U+200B `nife` reads `knife`.
3. Cyrillic and Greek look-alikes become their Latin twins (`kn` U+0456 `fe`, with a Cyrillic
   i, reads `knife`): everywhere in a command written mostly in Latin letters (so a lone
   look-alike word such as a Cyrillic `a` is caught too), and otherwise only inside words that
   mix them with Latin letters (a word wholly in another script is left alone).
Without this the symbolic analyzer, which reads English, would see unknown words where a person
sees a knife, and an unsafe command could be disguised past its rules.
Fails: never.
"""

from __future__ import annotations

import re
import unicodedata

from app.domain.models import GateRequest

# Cyrillic and Greek letters that look like Latin ones (after the Unicode confusables data).
_LOOKALIKES = str.maketrans(
    "\u0430\u0432\u0435\u0451\u043a\u043c\u043d\u043e\u0440\u0441"
    "\u0442\u0443\u0445\u0455\u0456\u0457\u0458\u04bb\u0501\u051b"
    "\u051d\u0261\u0410\u0412\u0415\u0401\u041a\u041c\u041d\u041e"
    "\u0420\u0421\u0422\u0423\u0425\u0405\u0406\u0407\u0408\u03b1"
    "\u03b5\u03b9\u03ba\u03bd\u03bf\u03c1\u03c4\u03c5\u03c7\u0391"
    "\u0392\u0395\u0396\u0397\u0399\u039a\u039c\u039d\u039f\u03a1"
    "\u03a4\u03a5\u03a7",
    "abeekmhopctyxsiijhdqwgABEEKMHOPCTYXSIIJaeikvoptuxABEZHIKMNOPTYX",
)
_WORD = re.compile(r"\S+")
_LATIN_LETTER = re.compile(r"[A-Za-z]")


def _unmix(match: re.Match[str]) -> str:
    word = match.group(0)
    if not _LATIN_LETTER.search(word):
        return word
    return word.translate(_LOOKALIKES)


def _mostly_latin(text: str) -> bool:
    letters = sum(1 for ch in text if ch.isalpha())
    return 2 * len(_LATIN_LETTER.findall(text)) >= letters


def canonical_command(command: str) -> str:
    """The command as a person reads it (see the module docstring for the three steps).

    Args:
        command: the command as sent.

    Returns:
        The canonical text; equal to `command` for plain ASCII.
    """
    if command.isascii():
        return command
    text = unicodedata.normalize("NFKC", command)
    text = "".join(ch for ch in text if unicodedata.category(ch) != "Cf")
    if _mostly_latin(text):
        return text.translate(_LOOKALIKES)
    return _WORD.sub(_unmix, text)


def for_analysis(request: GateRequest) -> GateRequest:
    """The request the analyzer should see: its command canonicalized (the rest as sent)."""
    command = canonical_command(request.command)
    if command == request.command:
        return request
    return request.model_copy(update={"command": command or request.command})
