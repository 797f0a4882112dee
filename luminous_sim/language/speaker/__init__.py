"""A learned speaker: a small seq2seq model from ALFRED subgoals (and their low-level actions, and
optionally per-step visual features) to step-by-step instructions and goal directives.

Torch-free parts (data, vocabulary, BLEU, features) import eagerly; the model, training and
generation (which need ``torch``) are imported on first use, e.g. ``speaker.Speaker``; the
functions are ``luminous_sim.language.speaker.train.train`` and ``...evaluate.evaluate``.
"""

from __future__ import annotations

import importlib
from typing import Any

from luminous_sim.language.speaker.bleu import corpus_bleu, sentence_bleu
from luminous_sim.language.speaker.dataset import (
    Example,
    build_examples,
    encode_goal,
    encode_step,
    find_trajectory_files,
    load_trajectories,
    split_trajectories,
)
from luminous_sim.language.speaker.errors import SpeakerError
from luminous_sim.language.speaker.features import FEATURE_DIM, frame_features, load_step_features
from luminous_sim.language.speaker.records import (
    Annotation,
    LowAction,
    Subgoal,
    Trajectory,
    load_trajectory,
)
from luminous_sim.language.speaker.text import detokenize, tokenize
from luminous_sim.language.speaker.vocab import Vocab

_LAZY = {
    "Speaker": "generate",
    "SpeakerModel": "model",
    "SpeakerConfig": "model",
    "TrainReport": "train",
    "EvalReport": "evaluate",
}

__all__ = [
    "FEATURE_DIM",
    "Annotation",
    "EvalReport",
    "Example",
    "LowAction",
    "Speaker",
    "SpeakerConfig",
    "SpeakerError",
    "SpeakerModel",
    "Subgoal",
    "TrainReport",
    "Trajectory",
    "Vocab",
    "build_examples",
    "corpus_bleu",
    "detokenize",
    "encode_goal",
    "encode_step",
    "find_trajectory_files",
    "frame_features",
    "load_step_features",
    "load_trajectories",
    "load_trajectory",
    "sentence_bleu",
    "split_trajectories",
    "tokenize",
]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        try:
            module = importlib.import_module(f"luminous_sim.language.speaker.{_LAZY[name]}")
        except ModuleNotFoundError as exc:
            if exc.name == "torch":
                raise SpeakerError(
                    "the learned speaker needs PyTorch: pip install torch==2.13.0"
                ) from None
            raise
        return getattr(module, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
