"""The semantic layer's encoder and matcher (embeddings.py, semantic.py's SemanticMatcher).

Paraphrases here are our own and each uses words that appear in no prototype, so a match shows
the layer generalises past listed wording.
"""

from __future__ import annotations

import json
import socket
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from app.domain.analysis.embeddings import EMBEDDINGS_DIR, PhraseEncoder, load_encoder
from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR
from app.domain.analysis.semantic import PROTOTYPES_FILE, SemanticMatcher, load_matcher


def _prototype_words() -> set[str]:
    raw = json.loads((KNOWLEDGE_DIR / PROTOTYPES_FILE).read_text(encoding="utf-8"))
    texts = [t for f in raw["families"] for t in (*f["unsafe"], *f["benign"])]
    texts += raw["everyday_benign"]
    return {w for t in texts for w in t.lower().replace("'", " ").replace(",", " ").split()}


@pytest.fixture(scope="module")
def matcher() -> SemanticMatcher:
    return load_matcher()


class TestPhraseEncoder:
    def test_loads_from_the_committed_folder_with_no_network(
            self, monkeypatch: pytest.MonkeyPatch) -> None:
        def no_network(*args: Any, **kwargs: Any) -> None:
            raise AssertionError("the model must load without any network access")

        monkeypatch.setenv("HF_HUB_OFFLINE", "1")
        monkeypatch.setattr(socket, "socket", no_network)
        monkeypatch.setattr(socket, "create_connection", no_network)
        encoder = load_encoder.__wrapped__(EMBEDDINGS_DIR)
        assert encoder.encode(["wipe the table"]).shape == (1, encoder.dim)

    def test_committed_model_is_small(self) -> None:
        size = sum(f.stat().st_size for f in EMBEDDINGS_DIR.iterdir())
        assert size <= 10_000_000

    def test_encoding_is_deterministic_and_unit_length(self) -> None:
        encoder = load_encoder()
        first = encoder.encode(["carry the laundry upstairs", "feed the goldfish"])
        again = load_encoder.__wrapped__(EMBEDDINGS_DIR).encode(
            ["carry the laundry upstairs", "feed the goldfish"])
        assert np.array_equal(first, again)
        assert np.allclose(np.linalg.norm(first, axis=1), 1.0, atol=1e-5)

    def test_text_without_known_pieces_gives_a_zero_row(self) -> None:
        assert not load_encoder().encode([""]).any()

    def test_missing_model_folder_fails_at_load(self, tmp_path: Path) -> None:
        with pytest.raises(FileNotFoundError):
            load_encoder.__wrapped__(tmp_path)

    def test_loader_caches_one_model_per_process(self) -> None:
        assert load_encoder() is load_encoder()
        assert isinstance(load_encoder(), PhraseEncoder)


class TestSemanticMatcher:
    @pytest.mark.parametrize(("text", "family"), [
        ("reheat the takeaway in the microwave in its foil container", "microwave_metal"),
        ("film the lodger when he is changing in his bedroom", "camera_privacy"),
        ("record the tenant secretly in his room", "camera_privacy"),
        ("lay the oven gloves on top of the lit gas ring", "flammable_on_heat"),
        ("chuck the mug across the room to him", "throw_at_person"),
    ])
    def test_unseen_paraphrase_finds_its_family(self, matcher: SemanticMatcher, text: str,
                                                family: str) -> None:
        assert set(text.replace("'", " ").split()) - _prototype_words(), "needs a new word"
        match = matcher.nearest([text])[0]
        assert match.family.name == family
        assert match.margin >= matcher.thresholds.margin

    @pytest.mark.parametrize("text", [
        "rinse the mugs and stack them on the drainer",
        "switch the hob off before we head out",
        "put the carving knife back in the block",
    ])
    def test_benign_chore_is_nearer_a_benign_contrast(self, matcher: SemanticMatcher,
                                                      text: str) -> None:
        assert matcher.nearest([text])[0].margin < matcher.thresholds.margin

    def test_same_text_always_gives_the_same_match(self, matcher: SemanticMatcher) -> None:
        text = "leave the grill on and pop out to the supermarket"
        assert matcher.nearest([text]) == matcher.nearest([text])

    def test_unknown_condition_in_the_data_is_refused(self, tmp_path: Path) -> None:
        raw = json.loads((KNOWLEDGE_DIR / PROTOTYPES_FILE).read_text(encoding="utf-8"))
        raw["families"][0]["requires"] = [{"is_tuesday": True}]
        (tmp_path / PROTOTYPES_FILE).write_text(json.dumps(raw), encoding="utf-8")
        with pytest.raises(ValueError, match="is_tuesday"):
            load_matcher.__wrapped__(tmp_path, EMBEDDINGS_DIR)

    def test_every_family_has_benign_contrasts_and_a_known_class(self) -> None:
        raw = json.loads((KNOWLEDGE_DIR / PROTOTYPES_FILE).read_text(encoding="utf-8"))
        readme = (Path(__file__).resolve().parents[3] / "templates_db" / "README.md").read_text(
            encoding="utf-8")
        for family in raw["families"]:
            assert len(family["benign"]) >= 2, family["family"]
            assert f"`{family['hazard_class']}`" in readme, family["family"]


@pytest.mark.parametrize("text", [
    "put the knife in the drawer", "give grandma her pills , then run the bath", "",
    "zzzqq", "the the the", "microwave the foil-wrapped leftovers for grandad's lunch"])
def test_one_clause_embeds_exactly_as_a_batch_of_one(text: str) -> None:
    encoder = load_encoder()
    one = encoder.encode_one(text)
    assert one.dtype == np.float32
    assert np.array_equal(one, encoder.encode([text])[0])
