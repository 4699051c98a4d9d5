"""What the analyzer reads (app/services/text_hygiene.py): look-alike text reads as it looks,
while a plain command, and a word wholly in another script, are left alone."""

from __future__ import annotations

import pytest

from app.domain.models import GateRequest
from app.services.text_hygiene import canonical_command, for_analysis


class TestCanonicalCommand:
    @pytest.mark.parametrize(("sent", "read"), [
        ("hand me the \uff2bnife", "hand me the Knife"),          # fullwidth K (NFKC)
        ("hand me the k\u200bnife", "hand me the knife"),         # zero-width space (Cf)
        ("hand me the kn\u0456fe", "hand me the knife"),          # Cyrillic i in a Latin word
        ("pour the ble\u0430ch \u0430way", "pour the bleach away"),  # Cyrillic a, also alone
        ("hand me the \u00adknife", "hand me the knife"),         # soft hyphen
    ])
    def test_look_alike_text_reads_as_it_looks(self, sent: str, read: str) -> None:
        assert canonical_command(sent) == read

    def test_a_command_in_another_script_is_left_alone(self) -> None:
        command = "\u043f\u0440\u0438\u043d\u0435\u0441\u0438 \u043d\u043e\u0436"  # Russian
        assert canonical_command(command) == command

    def test_plain_ascii_is_unchanged(self) -> None:
        assert canonical_command("put the mug away") == "put the mug away"


class TestForAnalysis:
    def test_only_the_command_changes(self) -> None:
        request = GateRequest(command="hand me the kn\u0456fe", user={"age_group": "child"})
        seen = for_analysis(request)
        assert seen.command == "hand me the knife"
        assert seen.model_dump(exclude={"command"}) == request.model_dump(exclude={"command"})
        assert request.command == "hand me the kn\u0456fe"  # the audit keeps what was sent

    def test_a_clean_request_is_passed_through_as_is(self) -> None:
        request = GateRequest(command="put the mug away")
        assert for_analysis(request) is request
