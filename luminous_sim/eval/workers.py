"""Where an evaluation's episodes run: this process, or a pool of local worker processes.

`map_local(fn, items, workers)` is the evaluator's one call into a backend; swapping it for another
backend's map (e.g. Ray) with the same contract changes that one call: `fn` a picklable top-level
function, results in the order of `items`.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from typing import TypeVar

from luminous_sim.errors import LuminousError

T = TypeVar("T")
R = TypeVar("R")


def map_local(fn: Callable[[T], R], items: Sequence[T], workers: int = 1) -> Iterator[R]:
    """`fn` over `items`, yielding results in order; `workers` > 1 runs them in that many processes.

    Processes are started with `spawn` (each imports afresh: no simulator state is shared through fork).
    """
    if workers < 1:
        raise LuminousError(f"workers: expected at least 1, got {workers}")
    if workers == 1 or len(items) <= 1:
        yield from map(fn, items)
        return
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=min(workers, len(items)), mp_context=context) as pool:
        yield from pool.map(fn, items)
