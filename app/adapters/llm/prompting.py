"""Prompts as versioned files: `prompts/<version>/<name>.md`, filled in by `{{placeholder}}`.

In: a version directory name (default `v1`) and, per render, the placeholder values. Out:
`PromptSet.render(name, **values)` -> the text, and `PromptSet.identity`, the version plus a
digest of every file in it, so that editing a prompt invalidates cached analyses.
Fails: `PromptError` for a missing version or file, a placeholder without a value, or a value
without a placeholder (a silent typo would change what the model is asked).
"""

from __future__ import annotations

import hashlib
import re
from functools import cached_property
from pathlib import Path

PROMPTS_DIR = Path(__file__).resolve().parent / "prompts"
DEFAULT_PROMPT_VERSION = "v1"
_PLACEHOLDER = re.compile(r"\{\{([a-z_]+)\}\}")


class PromptError(ValueError):
    """A prompt file that is missing or does not fit the values given to it."""


class PromptSet:
    """One version of the prompt files."""

    def __init__(self, version: str = DEFAULT_PROMPT_VERSION, root: Path = PROMPTS_DIR) -> None:
        self.version = version
        self._directory = root / version
        if not self._directory.is_dir():
            raise PromptError(f"no prompt version {version!r} under {root}")

    def text(self, name: str) -> str:
        """The raw text of one prompt file, without its final newline.

        Args:
            name: the file's stem, e.g. `analysis_system`.

        Returns:
            The file's content.

        Raises:
            PromptError: the file does not exist.
        """
        path = self._directory / f"{name}.md"
        if not path.is_file():
            raise PromptError(f"prompt {self.version}/{name}.md does not exist")
        return path.read_text(encoding="utf-8").rstrip("\n")

    def render(self, name: str, **values: str) -> str:
        """Fill a prompt file's `{{placeholders}}`.

        Args:
            name: the file's stem.
            **values: one value per placeholder of the file.

        Returns:
            The filled prompt.

        Raises:
            PromptError: a placeholder has no value or a value has no placeholder.
        """
        template = self.text(name)
        wanted = set(_PLACEHOLDER.findall(template))
        missing = wanted - values.keys()
        unused = values.keys() - wanted
        if missing or unused:
            raise PromptError(
                f"prompt {self.version}/{name}.md: missing {sorted(missing)}, "
                f"unused {sorted(unused)}"
            )
        return _PLACEHOLDER.sub(lambda match: values[match.group(1)], template)

    @cached_property
    def identity(self) -> str:
        """`<version>-<digest>`: changes whenever any file of this version changes."""
        digest = hashlib.sha256()
        for path in sorted(self._directory.glob("*.md")):
            digest.update(path.name.encode())
            digest.update(path.read_bytes())
        return f"{self.version}-{digest.hexdigest()[:12]}"
