"""BLEU (Papineni et al. 2002) with multiple references, written with collections.Counter."""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence


def ngrams(tokens: Sequence[str], n: int) -> Counter[tuple[str, ...]]:
    """Counts of the n-grams of ``tokens``."""
    return Counter(tuple(tokens[i : i + n]) for i in range(len(tokens) - n + 1))


def _closest_ref_length(hyp_len: int, refs: Sequence[Sequence[str]]) -> int:
    return min((abs(len(r) - hyp_len), len(r)) for r in refs)[1]


def corpus_bleu(
    hypotheses: Sequence[Sequence[str]],
    references: Sequence[Sequence[Sequence[str]]],
    max_n: int = 4,
    smooth: bool = False,
) -> float:
    """Corpus-level BLEU-``max_n`` with uniform weights.

    Args:
        hypotheses: One token list per segment.
        references: For each segment, one or more reference token lists.
        max_n: Highest n-gram order (4 for BLEU-4).
        smooth: Add one to the numerator and denominator of orders > 1 (Lin & Och 2004), so a
            missing 4-gram does not zero the score; off for the standard corpus score.

    Returns:
        BLEU in [0, 1].

    Raises:
        ValueError: The lists differ in length or a segment has no reference.
    """
    if len(hypotheses) != len(references):
        raise ValueError(f"{len(hypotheses)} hypotheses but {len(references)} reference sets")
    matches = [0] * max_n
    totals = [0] * max_n
    hyp_len = ref_len = 0
    for hyp, refs in zip(hypotheses, references):
        if not refs:
            raise ValueError("every hypothesis needs at least one reference")
        hyp_len += len(hyp)
        ref_len += _closest_ref_length(len(hyp), refs)
        for n in range(1, max_n + 1):
            counts = ngrams(hyp, n)
            best: Counter[tuple[str, ...]] = Counter()
            for ref in refs:
                best |= ngrams(ref, n)
            matches[n - 1] += sum((counts & best).values())
            totals[n - 1] += max(len(hyp) - n + 1, 0)
    if hyp_len == 0:
        return 0.0
    log_p = 0.0
    for n in range(max_n):
        num, den = matches[n], totals[n]
        if smooth and n > 0:
            num, den = num + 1, den + 1
        if num == 0 or den == 0:
            return 0.0
        log_p += math.log(num / den) / max_n
    brevity = 1.0 if hyp_len > ref_len else math.exp(1.0 - ref_len / hyp_len)
    return brevity * math.exp(log_p)


def sentence_bleu(
    hypothesis: Sequence[str],
    references: Sequence[Sequence[str]],
    max_n: int = 4,
    smooth: bool = True,
) -> float:
    """BLEU of a single sentence (smoothed by default, since short sentences often lack 4-grams)."""
    return corpus_bleu([hypothesis], [references], max_n=max_n, smooth=smooth)
