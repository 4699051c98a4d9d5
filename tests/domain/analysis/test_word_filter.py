"""The word filter may only rule out phrases that the whole-word tests would not find."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from app.domain.analysis.situation_base import any_phrase, contains, load_situations
from app.domain.analysis.unknown_rules import has_phrase
from app.domain.analysis.word_filter import candidates, may_occur

_GROUPS = [group for group in load_situations().phrases.values() if group]
_PIECES = st.sampled_from(
    [w for group in _GROUPS[:40] for phrase in group for w in phrase.split()]
    + ["'s", "'", "-", ",", ".", " ", "x", "un", "s", "é", "_", "2"])


def _whole_word(group: tuple[str, ...]) -> re.Pattern[str]:
    alternatives = "|".join(re.escape(p) for p in sorted(group, key=len, reverse=True))
    return re.compile(rf"(?<![\w'])(?:{alternatives})(?![\w'])")


@settings(max_examples=400, deadline=None)
@given(group=st.sampled_from(_GROUPS), pieces=st.lists(_PIECES, max_size=12),
       glue=st.sampled_from(["", " "]))
def test_a_group_ruled_out_is_never_found(group: tuple[str, ...], pieces: list[str],
                                          glue: str) -> None:
    text = glue.join(pieces)
    if not may_occur(text, group):
        assert _whole_word(group).search(text) is None
        assert any_phrase(text, group) is None


@settings(max_examples=400, deadline=None)
@given(group=st.sampled_from(_GROUPS), pieces=st.lists(_PIECES, max_size=12),
       glue=st.sampled_from(["", " "]))
def test_candidates_keep_every_phrase_the_word_tests_find(
        group: tuple[str, ...], pieces: list[str], glue: str) -> None:
    text = glue.join(pieces)
    kept = candidates(text, group)
    assert [p for p in group if contains(text, p)] == [p for p in kept if contains(text, p)]
    assert has_phrase(text, group) == has_phrase(text, list(group))


def test_candidates_are_in_group_order() -> None:
    group = ("hot pan", "the kettle", "pan", "hot")
    assert candidates("the hot pan", group) == ("hot pan", "the kettle", "pan", "hot")
    assert candidates("a pan", group) == ("pan",)


def test_a_phrase_is_found_through_possessives_hyphens_and_punctuation() -> None:
    assert may_occur("the kid's knife", ("kid",))
    assert may_occur("an x-ray machine", ("ray machine",))
    assert may_occur("careful,the stove", ("the stove",))


def test_absent_words_rule_a_group_out() -> None:
    assert not may_occur("put the cup on the table", ("knife", "scissors", "hot pan"))
    assert not may_occur("kidney beans", ("kid",))


def test_a_phrase_opening_with_punctuation_is_never_ruled_out() -> None:
    assert may_occur("nothing here", ("knife", "-free"))
