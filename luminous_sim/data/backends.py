"""Where independent jobs run: in this process, in local worker processes, or on a Ray cluster.

A backend maps a picklable module-level function over items and yields `(item, result)` pairs as they
finish (in any order), keeping at most a few jobs per worker in flight so that a long job list is never
submitted at once. Dataset builds use it; so can anything else made of independent jobs (evaluation).

Typical use::

    from luminous_sim.data import make_backend, map_jobs
    with make_backend("local", workers=4) as backend:
        for item, result in map_jobs(work, items, backend):
            ...
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any, Protocol, TypeVar

from luminous_sim.errors import LuminousError

T = TypeVar("T")
R = TypeVar("R")

BACKENDS = ("local", "ray")
"""Backend names `make_backend` knows."""
IN_FLIGHT_PER_WORKER = 2
"""Jobs submitted ahead per worker: enough to keep it busy, few enough that results stream back."""


class BackendError(LuminousError):
    """A backend that cannot be set up (unknown name, Ray not installed or not reachable, bad worker count)."""


class Backend(Protocol):
    """Runs `fn(item)` for each item; yields (item, result) as each finishes."""

    workers: int

    def imap_unordered(self, fn: Callable[[T], R], items: Iterable[T]) -> Iterator[tuple[T, R]]: ...

    def close(self) -> None: ...

    def __enter__(self) -> Backend: ...

    def __exit__(self, *exc: object) -> None: ...


class _Closing:
    def __enter__(self):
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Release the workers (nothing to release by default)."""


class LocalBackend(_Closing):
    """`workers` local processes (`spawn`: a fresh interpreter each, safe beside threads); with one worker
    the jobs run in this process, one after the other."""

    def __init__(self, workers: int = 1):
        if workers < 1:
            raise BackendError(f"local backend: workers must be at least 1, got {workers}")
        self.workers = workers
        self._pool: ProcessPoolExecutor | None = None

    def imap_unordered(self, fn: Callable[[T], R], items: Iterable[T]) -> Iterator[tuple[T, R]]:
        if self.workers == 1:
            for item in items:
                yield item, fn(item)
            return
        if self._pool is None:
            self._pool = ProcessPoolExecutor(self.workers, mp_context=multiprocessing.get_context("spawn"))
        pending: dict[Future[R], T] = {}
        source = iter(items)
        limit = self.workers * IN_FLIGHT_PER_WORKER
        while True:
            for item in source:
                pending[self._pool.submit(fn, item)] = item
                if len(pending) >= limit:
                    break
            if not pending:
                return
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for fut in done:
                yield pending.pop(fut), fut.result()

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None


class RayBackend(_Closing):
    """Jobs as Ray tasks (one CPU each) on the cluster at `address`, or on a local cluster of `workers`
    CPUs started here (and stopped on close). At most `workers * IN_FLIGHT_PER_WORKER` tasks are in
    flight; on a remote cluster the output folder must be storage every node sees.

    Worker processes inherit this process's environment (`PYTHONPATH` included) on a local cluster; on a
    remote one, `luminous_sim` must be installed on every node.
    """

    def __init__(self, workers: int = 1, address: str | None = None):
        if workers < 1:
            raise BackendError(f"ray backend: workers must be at least 1, got {workers}")
        try:
            import ray
        except ImportError:
            raise BackendError("the ray backend needs Ray: pip install 'luminous-sim[cluster]'") from None
        self.workers = workers
        self._ray = ray
        self._started = not ray.is_initialized()
        if self._started:
            try:
                if address:
                    ray.init(address=address, log_to_driver=False, include_dashboard=False)
                else:
                    ray.init(num_cpus=workers, log_to_driver=False, include_dashboard=False)
            except (ConnectionError, RuntimeError, ValueError) as exc:
                where = f"the Ray cluster at {address}" if address else "a local Ray cluster"
                raise BackendError(f"cannot start or reach {where}: {exc}") from exc

    def imap_unordered(self, fn: Callable[[T], R], items: Iterable[T]) -> Iterator[tuple[T, R]]:
        ray = self._ray
        remote = ray.remote(num_cpus=1, max_retries=0)(fn)
        pending: dict[Any, T] = {}
        source = iter(items)
        limit = self.workers * IN_FLIGHT_PER_WORKER
        while True:
            for item in source:
                pending[remote.remote(item)] = item
                if len(pending) >= limit:
                    break
            if not pending:
                return
            done, _ = ray.wait(list(pending), num_returns=1)
            for ref in done:
                yield pending.pop(ref), ray.get(ref)

    def close(self) -> None:
        if self._started and self._ray.is_initialized():
            self._ray.shutdown()
        self._started = False


def make_backend(name: str = "local", workers: int = 1, address: str | None = None) -> Backend:
    """The backend called `name` (`local` or `ray`) with `workers` workers; `address` is a Ray cluster's
    (`ray` only; None starts a local cluster).

    Raises:
        BackendError: unknown name, an address for the local backend, or Ray missing or unreachable.
    """
    if name == "local":
        if address:
            raise BackendError(f"--address {address} is for the ray backend, not local")
        return LocalBackend(workers)
    if name == "ray":
        return RayBackend(workers, address)
    raise BackendError(f"unknown backend {name!r}; expected one of {', '.join(BACKENDS)}")


def map_jobs(fn: Callable[[T], R], items: Iterable[T], backend: Backend | None = None) -> Iterator[tuple[T, R]]:
    """`(item, fn(item))` for each item as it finishes, on `backend` (default: in this process).

    `fn` must be a module-level function and items and results picklable (they cross processes).
    """
    return (backend or LocalBackend(1)).imap_unordered(fn, items)
