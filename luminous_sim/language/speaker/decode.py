"""Greedy (batched) and beam-search decoding for :class:`SpeakerModel`.

Both can block repeated n-grams (``no_repeat_ngram``): a word that would complete an n-gram
already in the sentence gets probability 0, which stops small models from looping.
"""

from __future__ import annotations

import torch

from luminous_sim.language.speaker.model import SpeakerModel
from luminous_sim.language.speaker.vocab import Vocab

BANNED = (Vocab.pad_id, Vocab.bos_id, Vocab.unk_id)
"""Ids never generated."""


def repeat_banned(seq: list[int], n: int) -> list[int]:
    """Words that would complete an n-gram already in ``seq`` (none when ``n`` < 1)."""
    if n < 1 or len(seq) < n - 1:
        return []
    prefix = seq[len(seq) - n + 1 :] if n > 1 else []
    return [seq[i + n - 1] for i in range(len(seq) - n + 1) if seq[i : i + n - 1] == prefix]


def _log_probs(logits: torch.Tensor, seqs: list[list[int]], no_repeat_ngram: int) -> torch.Tensor:
    logits = logits.clone()
    logits[:, list(BANNED)] = float("-inf")
    for row, seq in enumerate(seqs):
        banned = repeat_banned(seq, no_repeat_ngram)
        if banned:
            logits[row, banned] = float("-inf")
    return torch.log_softmax(logits, dim=-1)


@torch.no_grad()
def greedy_decode(
    model: SpeakerModel,
    src: torch.Tensor,
    lengths: torch.Tensor,
    features: torch.Tensor | None,
    max_len: int = 40,
    no_repeat_ngram: int = 0,
) -> list[list[int]]:
    """Most likely word at each step, for a whole batch at once.

    Returns:
        One id list per batch row, without ``<eos>``.
    """
    memory, mask, state = model.encode(src, lengths, features)
    feed = torch.zeros_like(state)
    prev = torch.full((src.size(0),), Vocab.bos_id, dtype=torch.long)
    done = [False] * src.size(0)
    out: list[list[int]] = [[] for _ in range(src.size(0))]
    for _ in range(max_len):
        logits, state, feed = model.decode_step(prev, state, feed, memory, mask)
        prev = _log_probs(logits, out, no_repeat_ngram).argmax(dim=-1)
        for b, word in enumerate(prev.tolist()):
            if done[b]:
                continue
            if word == Vocab.eos_id:
                done[b] = True
            else:
                out[b].append(word)
        if all(done):
            break
    return out


@torch.no_grad()
def beam_decode(
    model: SpeakerModel,
    src: torch.Tensor,
    lengths: torch.Tensor,
    features: torch.Tensor | None,
    width: int = 3,
    max_len: int = 40,
    alpha: float = 0.7,
    no_repeat_ngram: int = 0,
) -> list[int]:
    """Beam search for one source (batch of 1).

    Finished hypotheses are ranked by ``log p / (length + 1) ** alpha`` (``+1`` counts ``<eos>``).

    Returns:
        The best id list, without ``<eos>``.
    """
    memory, mask, state = model.encode(src, lengths, features)
    feed = torch.zeros_like(state)
    prev = torch.tensor([Vocab.bos_id])
    beams: list[tuple[list[int], float]] = [([], 0.0)]
    finished: list[tuple[list[int], float]] = []
    for _ in range(max_len):
        k = len(beams)
        logits, state, feed = model.decode_step(
            prev, state, feed, memory.expand(k, -1, -1), mask.expand(k, -1)
        )
        log_p = _log_probs(logits, [seq for seq, _ in beams], no_repeat_ngram)
        total = torch.tensor([s for _, s in beams])[:, None] + log_p
        vocab = total.size(1)
        top = torch.topk(total.flatten(), min(2 * width, total.numel()))
        keep: list[tuple[int, int, float]] = []
        for score, idx in zip(top.values.tolist(), top.indices.tolist()):
            if score == float("-inf"):
                break
            beam, word = divmod(idx, vocab)
            if word == Vocab.eos_id:
                finished.append((beams[beam][0], score))
            else:
                keep.append((beam, word, score))
            if len(keep) == width:
                break
        if len(finished) >= width or not keep:
            break
        rows = torch.tensor([b for b, _, _ in keep])
        state, feed = state[rows], feed[rows]
        prev = torch.tensor([w for _, w, _ in keep])
        beams = [(beams[b][0] + [w], s) for b, w, s in keep]
    pool = finished or beams
    return max(pool, key=lambda hyp: hyp[1] / (len(hyp[0]) + 1) ** alpha)[0]
