"""Torch run-time settings for a small model: seeded determinism and a single intra-op thread.

The speaker's tensors are tiny, so intra-op threads only add synchronisation; on a busy machine
OpenMP spin-waiting makes multi-threaded steps hundreds of times slower. Both settings are
restored when the block ends.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import torch


@contextmanager
def torch_threads(n: int = 1) -> Iterator[None]:
    """Run the block with ``n`` intra-op threads."""
    previous = torch.get_num_threads()
    torch.set_num_threads(n)
    try:
        yield
    finally:
        torch.set_num_threads(previous)


@contextmanager
def deterministic(
    seed: int, rng_state: torch.Tensor | None = None, threads: int = 1
) -> Iterator[None]:
    """Seeded (or ``rng_state``-restored), deterministic, ``threads``-threaded torch in the block.

    The global RNG state, the deterministic-algorithms flag and the thread count are restored
    after it.
    """
    previous = torch.are_deterministic_algorithms_enabled()
    with torch.random.fork_rng(devices=[]), torch_threads(threads):
        if rng_state is not None:
            torch.set_rng_state(rng_state)
        else:
            torch.manual_seed(seed)
        torch.use_deterministic_algorithms(True)
        try:
            yield
        finally:
            torch.use_deterministic_algorithms(previous)
