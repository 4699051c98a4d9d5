"""The static phrase encoder: the small model2vec model committed under `knowledge/embeddings/`.

In: a folder holding a model2vec `StaticModel` (distilled offline from all-MiniLM-L6-v2 by
`knowledge/build/distill_embeddings.py`). Out: `PhraseEncoder.encode(texts)`, one unit-length
float32 row per text, so a dot product is a cosine similarity. The model is read from disk once
per folder and process (`load_encoder` caches it); nothing is imported or read at import time and
nothing is ever fetched from a hub. Fails: `FileNotFoundError` if the folder has no model,
`ImportError` if model2vec is not installed (both at construction, never while encoding).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cache, lru_cache
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR

EMBEDDINGS_DIR = KNOWLEDGE_DIR / "embeddings"
Vectors = npt.NDArray[np.float32]


class PhraseEncoder:
    """Turns short texts into unit vectors with a static (one vector per word-piece) model.

    A text's vector is the mean of its word-pieces' vectors, as model2vec computes it. The
    model's BERT tokenizer never joins pieces across white space, so a text's pieces are its
    words' pieces in order: words are tokenised one at a time and remembered (a bounded cache of
    vocabulary, shared by all requests), which saves the tokenizer's ~25 us per call on every
    clause of every request.
    """

    def __init__(self, model: Any) -> None:
        self._model = model
        self.dim: int = int(model.dim)
        self._tokenizer = model.tokenizer
        self._unknown: int | None = model.unk_token_id
        # Per-token means are exact only without a vocabulary mapping or token weights.
        self._direct = model.token_mapping is None and model.weights is None
        self._table: Vectors = np.asarray(model.embedding, dtype=np.float32)
        self._word_pieces = lru_cache(maxsize=32768)(self._pieces_of)

    def _pieces_of(self, word: str) -> tuple[int, ...]:
        return tuple(i for i in self._tokenizer.encode(word, add_special_tokens=False).ids
                     if i != self._unknown)

    def _piece_ids(self, text: str) -> list[int]:
        return [i for word in text.split() for i in self._word_pieces(word)]

    def encode(self, texts: Sequence[str]) -> Vectors:
        """Embed texts as unit-length rows (a text with no known word-piece gives a zero row).

        Args:
            texts: the phrases.

        Returns:
            A (len(texts), dim) float32 array.
        """
        if not texts:
            return np.zeros((0, self.dim), dtype=np.float32)
        if self._direct:
            raw = np.zeros((len(texts), self.dim), dtype=np.float32)
            for row, text in enumerate(texts):
                ids = self._piece_ids(text)
                if ids:
                    raw[row] = self._table[ids].mean(axis=0)
        else:
            raw = np.asarray(self._model.encode(list(texts), show_progress_bar=False),
                             dtype=np.float32)
        norms = np.linalg.norm(raw, axis=1, keepdims=True)
        unit: Vectors = np.divide(raw, norms, out=np.zeros_like(raw), where=norms > 0)
        return unit

    def encode_one(self, text: str) -> Vectors:
        """`encode([text])[0]` with a handful of array operations instead of a dozen: the
        analyzer embeds one clause at a time (see `SemanticMatcher._match`)."""
        if not self._direct:
            row: Vectors = self.encode([text])[0]
            return row
        ids = self._piece_ids(text)
        if not ids:
            return np.zeros(self.dim, dtype=np.float32)
        # np.mean's own steps without its Python wrapper: a float32 sum, divided by the count
        # as an intp (so the very same float32 result, bit for bit).
        raw: Vectors = np.add.reduce(self._table[ids], axis=0)
        np.true_divide(raw, np.intp(len(ids)), out=raw, casting="unsafe")
        norm = np.sqrt(np.add.reduce(raw * raw))
        if not norm > 0:
            return np.zeros(self.dim, dtype=np.float32)
        unit: Vectors = raw / norm
        return unit


@cache
def load_encoder(model_dir: Path = EMBEDDINGS_DIR) -> PhraseEncoder:
    """Load the static model from a local folder, once per folder and process.

    Args:
        model_dir: the folder with `config.json`, `model.safetensors` and `tokenizer.json`.

    Returns:
        The `PhraseEncoder`.

    Raises:
        FileNotFoundError: the folder holds no model.
    """
    if not (model_dir / "model.safetensors").is_file():
        raise FileNotFoundError(f"no static embedding model in {model_dir}")
    # Imported here, not at module level: loading model2vec (and its hub client) costs ~0.3 s,
    # which only an analyzer that is actually built should pay.
    from model2vec import StaticModel

    return PhraseEncoder(StaticModel.from_pretrained(model_dir))
