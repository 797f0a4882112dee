"""BLEU-4 of a speaker on held-out trajectories, with every annotator's sentence as a reference."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from luminous_sim.language.speaker.bleu import corpus_bleu
from luminous_sim.language.speaker.dataset import Example, build_examples
from luminous_sim.language.speaker.generate import Speaker
from luminous_sim.language.speaker.records import Trajectory


@dataclass
class EvalReport:
    """Scores on a set of trajectories.

    Attributes:
        bleu_steps: Corpus BLEU-4 of step instructions (one hypothesis per subgoal, all annotators'
            ``high_descs[i]`` as references).
        bleu_goals: Corpus BLEU-4 of goal directives (all ``task_desc`` as references).
        n_steps: Subgoals scored.
        n_goals: Trajectories scored.
        beam_width: Decoding used.
        samples: A few ``(kind, hypothesis, first reference)`` triples, space-joined tokens.
    """

    bleu_steps: float
    bleu_goals: float
    n_steps: int
    n_goals: int
    beam_width: int
    samples: list[tuple[str, str, str]] = field(default_factory=list)


@dataclass
class _Item:
    src: tuple[str, ...]
    features: np.ndarray | None
    refs: list[list[str]]


def group_references(examples: Sequence[Example]) -> dict[str, list[_Item]]:
    """Group examples of the same (trajectory, subgoal) into one item with several references."""
    items: dict[tuple[str, int], _Item] = {}
    kinds: dict[tuple[str, int], str] = {}
    for ex in examples:
        if ex.key not in items:
            items[ex.key] = _Item(ex.src, ex.features, [])
            kinds[ex.key] = ex.kind
        items[ex.key].refs.append(list(ex.tgt))
    out: dict[str, list[_Item]] = {"step": [], "goal": []}
    for key, item in items.items():
        out[kinds[key]].append(item)
    return out


def evaluate(
    speaker: Speaker, trajectories: Sequence[Trajectory], beam_width: int = 1, n_samples: int = 5
) -> EvalReport:
    """Corpus BLEU-4 of ``speaker`` on ``trajectories``.

    Args:
        speaker: The trained speaker.
        trajectories: Annotated trajectories not used in training.
        beam_width: 1 = greedy (batched, fast); 3 = beam search.
        n_samples: How many examples to keep in the report.
    """
    groups = group_references(build_examples(trajectories))
    scores: dict[str, float] = {}
    samples: list[tuple[str, str, str]] = []
    for kind, items in groups.items():
        hyps = speaker.generate_tokens(
            [i.src for i in items], [i.features for i in items], beam_width
        )
        scores[kind] = corpus_bleu(hyps, [i.refs for i in items]) if items else 0.0
        samples += [
            (kind, " ".join(h), " ".join(i.refs[0])) for h, i in zip(hyps[:n_samples], items)
        ]
    return EvalReport(
        scores["step"],
        scores["goal"],
        len(groups["step"]),
        len(groups["goal"]),
        beam_width,
        samples,
    )
