"""Where an evaluation's episodes run: this process, a pool of local worker processes, or any backend of
the data layer (`data.make_backend`: local processes or a Ray cluster).

`map_local(fn, items, workers)` and `map_ordered(fn, items, backend)` have one contract: `fn` a picklable
top-level function, results in the order of `items`, whichever worker finished first.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from typing import TypeVar

from luminous_sim.data.backends import Backend
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


def map_ordered(fn: Callable[[T], R], items: Sequence[T], backend: Backend) -> Iterator[R]:
    """`fn` over `items` on `backend`, yielding results in the order of `items` (each as soon as it and every
    earlier one have finished; later results wait in memory). A job's `LuminousError` is raised as it is, not
    wrapped in the backend's error (Ray's `RayTaskError`)."""
    waiting: dict[int, R] = {}
    following = 0
    try:
        for (i, _, _), result in backend.imap_unordered(_apply, [(i, fn, item) for i, item in enumerate(items)]):
            waiting[i] = result
            while following in waiting:
                yield waiting.pop(following)
                following += 1
    except Exception as exc:
        cause = getattr(exc, "cause", None)  # Ray wraps a task's error (RayTaskError); ours carries the message
        if isinstance(cause, LuminousError) and cause is not exc:
            raise cause from None
        raise


def _apply(job: tuple[int, Callable[[T], R], T]) -> R:
    """`fn(item)` for an `(index, fn, item)` job (a module-level function: Ray remotes only functions, and
    `fn`, itself top-level, travels by name)."""
    _, fn, item = job
    return fn(item)
