"""`Speaker`: a trained model with its vocabularies, turning subgoals into instructions."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import torch

from luminous_sim.language.speaker.batching import encode_sources
from luminous_sim.language.speaker.checkpoint import load_checkpoint
from luminous_sim.language.speaker.dataset import encode_goal, encode_step
from luminous_sim.language.speaker.decode import beam_decode, greedy_decode
from luminous_sim.language.speaker.errors import SpeakerError
from luminous_sim.language.speaker.model import SpeakerConfig, SpeakerModel
from luminous_sim.language.speaker.records import LowAction, Subgoal, Trajectory, load_trajectory
from luminous_sim.language.speaker.runtime import torch_threads
from luminous_sim.language.speaker.text import detokenize
from luminous_sim.language.speaker.vocab import Vocab

SubgoalLike = Subgoal | Mapping[str, Any] | Sequence[Any]
"""A :class:`Subgoal`, an ALFRED ``high_pddl`` entry, or ``(action, [args])``."""
LowActionLike = LowAction | Mapping[str, Any] | str
"""A :class:`LowAction`, an ALFRED ``low_actions`` entry, or a bare action token."""
FeaturesLike = torch.Tensor | np.ndarray | None
NO_REPEAT_NGRAM = 3
"""Default n-gram repeat block while decoding."""


def as_subgoal(item: SubgoalLike) -> Subgoal:
    """Normalise a subgoal given in any accepted form."""
    try:
        if isinstance(item, Subgoal):
            return item
        if isinstance(item, Mapping):
            return Subgoal.from_alfred(dict(item))
        action, args = item[0], item[1] if len(item) > 1 else ()
        return Subgoal(str(action), tuple(str(a).lower() for a in args))
    except (KeyError, TypeError, IndexError) as exc:
        raise SpeakerError(f"not a subgoal: {item!r} ({exc!r})") from None


def as_low_action(item: LowActionLike) -> LowAction:
    """Normalise a low-level action given in any accepted form."""
    try:
        if isinstance(item, LowAction):
            return item
        if isinstance(item, str):
            return LowAction(item)
        return LowAction.from_alfred(dict(item))
    except (KeyError, TypeError) as exc:
        raise SpeakerError(f"not a low-level action: {item!r} ({exc!r})") from None


class Speaker:
    """A trained speaker.

    Args:
        model: The network (put in eval mode).
        src_vocab: Source-token vocabulary.
        tgt_vocab: Word vocabulary.
        beam_width: Default beam width (1 = greedy).
        max_len: Longest instruction generated, in tokens.
        no_repeat_ngram: Block repeating any n-gram of this length (0: off).
        threads: Torch intra-op threads while decoding (1 is fastest for this small model).
    """

    def __init__(
        self,
        model: SpeakerModel,
        src_vocab: Vocab,
        tgt_vocab: Vocab,
        beam_width: int = 3,
        max_len: int = 40,
        no_repeat_ngram: int = NO_REPEAT_NGRAM,
        threads: int = 1,
    ) -> None:
        self.model = model.eval()
        self.src_vocab = src_vocab
        self.tgt_vocab = tgt_vocab
        self.beam_width = beam_width
        self.max_len = max_len
        self.no_repeat_ngram = no_repeat_ngram
        self.threads = threads

    @classmethod
    def load(
        cls,
        path: str | Path,
        beam_width: int = 3,
        max_len: int = 40,
        no_repeat_ngram: int = NO_REPEAT_NGRAM,
    ) -> Speaker:
        """Load a checkpoint written by training (decoding options as in the constructor).

        Raises:
            SpeakerError: The file is missing or not a speaker checkpoint.
        """
        data = load_checkpoint(path)
        try:
            model = SpeakerModel(SpeakerConfig.from_dict(dict(data["config"])))
            model.load_state_dict(data["model"])
        except (RuntimeError, TypeError) as exc:
            raise SpeakerError(
                f"{path}: checkpoint weights do not fit its config ({exc})"
            ) from None
        return cls(
            model,
            Vocab.from_json(data["src_vocab"], f"{path} src_vocab"),
            Vocab.from_json(data["tgt_vocab"], f"{path} tgt_vocab"),
            beam_width,
            max_len,
            no_repeat_ngram,
        )

    @property
    def feat_dim(self) -> int:
        """Visual feature size the model expects (0: trained without features)."""
        return self.model.config.feat_dim

    def generate_tokens(
        self,
        sources: Sequence[Sequence[str]],
        features: Sequence[np.ndarray | None] | None = None,
        beam_width: int | None = None,
    ) -> list[list[str]]:
        """Decode word tokens for encoded sources (see :func:`encode_step`, :func:`encode_goal`).

        Args:
            sources: Source token lists.
            features: Per-source aligned ``[len(src), D]`` features (or None entries).
            beam_width: Overrides the default; 1 decodes the whole list greedily as one batch.
        """
        width = self.beam_width if beam_width is None else beam_width
        feats = list(features) if features is not None else [None] * len(sources)
        if not sources:
            return []
        with torch.no_grad(), torch_threads(self.threads):
            if width <= 1:
                src, lengths, f = encode_sources(sources, feats, self.src_vocab, self.feat_dim)
                ids = greedy_decode(self.model, src, lengths, f, self.max_len, self.no_repeat_ngram)
            else:
                ids = []
                for tokens, feat in zip(sources, feats):
                    src, lengths, f = encode_sources(
                        [tokens], [feat], self.src_vocab, self.feat_dim
                    )
                    best = beam_decode(
                        self.model,
                        src,
                        lengths,
                        f,
                        width,
                        self.max_len,
                        no_repeat_ngram=self.no_repeat_ngram,
                    )
                    ids.append(best)
        return [self.tgt_vocab.decode(row) for row in ids]

    def _step_features(self, features: FeaturesLike, n_low: int) -> np.ndarray | None:
        if features is None:
            return None
        if self.feat_dim == 0:
            raise SpeakerError(
                "this speaker was trained without visual features; pass features=None"
            )
        arr = (
            features.detach().cpu().numpy()
            if isinstance(features, torch.Tensor)
            else np.asarray(features)
        )
        if arr.ndim != 2 or arr.shape[1] != self.feat_dim:
            raise SpeakerError(
                f"features must have shape [T, {self.feat_dim}], got {list(arr.shape)}"
            )
        if arr.shape[0] != n_low:
            raise SpeakerError(
                f"features has {arr.shape[0]} rows but there are {n_low} low-level actions"
            )
        return arr.astype(np.float32)

    def describe(
        self,
        subgoal: SubgoalLike,
        low_actions: Sequence[LowActionLike],
        features: FeaturesLike = None,
        beam_width: int | None = None,
    ) -> str:
        """The step-by-step instruction for one subgoal.

        Args:
            subgoal: The subgoal, e.g. ``Subgoal("GotoLocation", ("countertop",))``.
            low_actions: Its low-level actions, e.g. ``["RotateLeft_90", "MoveAhead_25"]``.
            features: ``[T, D]`` per-step visual features (T = number of low actions), or None.
            beam_width: Overrides the default beam width.

        Returns:
            A sentence such as ``"Turn left and walk to the counter."``.
        """
        lows = [as_low_action(a) for a in low_actions]
        src, feats = encode_step(
            as_subgoal(subgoal), lows, self._step_features(features, len(lows))
        )
        return detokenize(self.generate_tokens([src], [feats], beam_width)[0])

    def describe_goal(self, subgoals: Sequence[SubgoalLike], beam_width: int | None = None) -> str:
        """The goal directive for a trajectory's subgoal sequence (End entries are skipped)."""
        src = encode_goal([as_subgoal(s) for s in subgoals])
        return detokenize(self.generate_tokens([src], None, beam_width)[0])

    def describe_trajectory(
        self, trajectory: Trajectory | str | Path, beam_width: int | None = None
    ) -> tuple[str, list[str]]:
        """Goal directive and one instruction per subgoal of a traj_data.json."""
        traj = (
            trajectory
            if isinstance(trajectory, Trajectory)
            else load_trajectory(trajectory, features=self.feat_dim > 0, require_annotations=False)
        )
        feats = traj.features if (traj.features is not None and self.feat_dim > 0) else None
        steps = [
            self.describe(sg, seg, None if feats is None else feats[i], beam_width)
            for i, (sg, seg) in enumerate(zip(traj.subgoals, traj.segments))
        ]
        return self.describe_goal(traj.subgoals, beam_width), steps
