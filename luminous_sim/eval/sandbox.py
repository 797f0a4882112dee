"""A user's agent (`MODULE:CALLABLE`) in a child process, behind the agent interface, with limits.

`AgentProcess(spec, context, limits)` starts a child (a `forkserver` context: a clean process that has
imported the simulator once, so a child starts in a fraction of a second and inherits no simulator state).
The child imports MODULE, calls the factory with a copy of the `AgentContext` (the spaces, the action table,
the env's configuration: plain data) and then answers calls: `reset(instruction, info)` and
`act(observation, info)`, sent as plain numpy arrays and dicts, never the env or its world. The evaluation
process never imports the user's module and never unpickles anything the child sends: a reply is JSON of at
most `MAX_REPLY_BYTES` (an action: an index, or a dict of lists, strings and numbers; numpy arrays travel as
dtype, shape and bytes), so a hostile agent can only choose its actions.

Limits (`AgentLimits`; `luminous eval --step-timeout SECONDS --agent-memory MB`):

* each `reset()` or `act()` call must return within `step_timeout` seconds, else the child is killed and the
  call raises `AgentTimeout` (the evaluation ends that episode as `agent_timeout`, a failure, and the next
  episode gets a fresh child); starting (the import and the factory) has `start_timeout`;
* the child's address space is capped at `memory_mb` (`RLIMIT_AS`, set in the child before the user's module
  is imported): an allocation beyond it raises `MemoryError` there, reported as such.

Anything else that ends the agent (an exception, `sys.exit`, `os._exit`, a signal, the memory limit, a reply
that breaks the protocol) raises `AgentCrashed` with the cause named; the evaluation stops (episodes already
finished stay written) and `luminous eval` exits 1. The default limits are at least 10x what the project's
reference agents measure (`benchmarks/bench_agent_limits.py`, figures in docs/benchmarks.md).
"""

from __future__ import annotations

import base64
import contextlib
import json
import math
import multiprocessing
import multiprocessing.util
import os
import pickle
import resource
import signal
import sys
import threading
import time
import traceback
import types
import weakref
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from typing import Any

import numpy as np

from luminous_sim.eval.policies import AgentContext, PolicyError, TextAgentContext, build_agent, resolve_factory

DEFAULT_STEP_TIMEOUT = 10.0
"""Seconds one `reset()` or `act()` call may take (the reference agents' p99 is far below: docs/benchmarks.md)."""
DEFAULT_AGENT_MEMORY_MB = 16384
"""The agent process's address space, in MiB (`RLIMIT_AS`; at least 10x the reference agents' peak)."""
DEFAULT_START_TIMEOUT = 300.0
"""Seconds to import the agent's module and call its factory (a model's weights may take a while to load)."""
MIN_AGENT_MEMORY_MB = 1024
"""The least memory limit accepted: the child's interpreter and the simulator's modules need about this much
address space before the agent's own code runs."""
MAX_REPLY_BYTES = 16 * 2**20
"""The largest reply the evaluation reads from the agent process (an action with a mask is far smaller)."""
MAX_DEPTH = 16
"""The deepest nesting of lists and dicts an action may have."""
_TEXT = 2000
"""Characters kept of a message the child sends (an exception's text)."""
_ORPHAN_CHECK_S = 1.0


class AgentTimeout(PolicyError):
    """A `reset()` or `act()` call that did not return within the step limit; the child was killed."""

    def __init__(self, call: str, seconds: float):
        super().__init__(f"{call} did not return within {_seconds(seconds)} (the step limit, --step-timeout)")
        self.call, self.seconds = call, seconds

    def __reduce__(self) -> tuple[Any, ...]:
        return type(self), (self.call, self.seconds)


class AgentCrashed(PolicyError):
    """The agent process ended or broke the interface: `cause` says how (`CRASH_CAUSES`)."""

    def __init__(self, message: str, cause: str = "raised"):
        super().__init__(message)
        self.message, self.cause = message, cause

    def __reduce__(self) -> tuple[Any, ...]:
        return type(self), (self.message, self.cause)

    def on(self, split: str, index: int, step: int | None = None) -> AgentCrashed:
        """The same crash, its message naming the episode (and the step of an `act()` call)."""
        at = "" if step is None else f" at step {step}"
        return AgentCrashed(f"{self.message} on {split} episode {index}{at}", self.cause)


CRASH_CAUSES: tuple[str, ...] = ("raised", "exit", "signal", "memory", "start_timeout", "protocol")
"""How an agent process can crash: its code raised, it exited (`sys.exit`, `os._exit`), a signal killed it,
it went past its memory limit, it did not start in time, or it sent what the protocol does not allow."""


@dataclass(frozen=True)
class AgentLimits:
    """The limits of a user's agent process (see the module docstring)."""

    step_timeout: float = DEFAULT_STEP_TIMEOUT
    memory_mb: int = DEFAULT_AGENT_MEMORY_MB
    start_timeout: float = DEFAULT_START_TIMEOUT

    def __post_init__(self) -> None:
        for name in ("step_timeout", "start_timeout"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value) or value <= 0:
                raise PolicyError(f"agent limits: {name} must be a positive number of seconds, got {value!r}")
        if isinstance(self.memory_mb, bool) or not isinstance(self.memory_mb, int) or \
                self.memory_mb < MIN_AGENT_MEMORY_MB:
            raise PolicyError(f"agent limits: memory_mb must be a whole number of MiB, at least "
                              f"{MIN_AGENT_MEMORY_MB} (MIN_AGENT_MEMORY_MB), got {self.memory_mb!r}")


class AgentProcess:
    """A user's agent in a child process (see the module docstring); `reset` and `act` as an `Agent`'s.

    Raises (from the constructor, `reset` and `act`):
        PolicyError: the spec names no usable factory, or the factory raised or returned no agent.
        AgentTimeout: a call over the step limit (the child is killed; the next `reset` starts a new one).
        AgentCrashed: the agent raised, exited, was killed, went past its memory limit or broke the protocol.
    """

    def __init__(self, spec: str, context: AgentContext | TextAgentContext | None,
                 limits: AgentLimits | None = None):
        self.spec, self.context, self.limits = spec, context, limits or AgentLimits()
        self.starts = 0
        """Children started so far (one, plus one after each timeout or crash)."""
        self._process: Any = None
        self._conn: Connection | None = None
        self._start()

    @property
    def pid(self) -> int | None:
        """The running child's process id (None between a timeout or crash and the next `reset`)."""
        return None if self._process is None else self._process.pid

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        if self._process is None:
            self._start()
        self._call(("reset", instruction, info), "reset()", self.limits.step_timeout)

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> Any:
        if self._process is None:
            self._start()
        return _decode(self._call(("act", observation, info), "act()", self.limits.step_timeout))

    def close(self) -> None:
        """Stop the child (asked first, then killed); idempotent."""
        process, conn = self._process, self._conn
        self._process = self._conn = None
        if process is None:
            return
        with contextlib.suppress(OSError, ValueError):
            if conn is not None:
                conn.send(("close",))
        process.join(1.0)
        _kill(process)
        if conn is not None:
            conn.close()

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self.close()

    # ------------------------------------------------------------------ the child's lifetime

    def _start(self) -> None:
        context = _mp_context()
        mine, theirs = context.Pipe(duplex=True)
        process = context.Process(target=_child_main, name="luminous-agent", daemon=False,
                                  args=(theirs, self.spec, self.context, self.limits.memory_mb, dict(os.environ)))
        with _without_main():
            process.start()
        theirs.close()
        self._process, self._conn = process, mine
        self.starts += 1
        _LIVE.add(process)
        self._call(None, "start", self.limits.start_timeout)

    def _call(self, message: tuple[Any, ...] | None, name: str, timeout: float) -> Any:
        """Send `message` for the call `name` (None: only wait for the child's first reply, to the call "start")
        and return the reply's value."""
        process, conn = self._process, self._conn
        module = self.spec.partition(":")[0]
        call = (f"while starting (importing {module} and calling its factory)" if name == "start" else
                f"during {name}")
        assert process is not None and conn is not None
        writer: threading.Thread | None = None
        sent: list[BaseException] = []
        if message is not None:
            payload = pickle.dumps(message, protocol=pickle.HIGHEST_PROTOCOL)
            # A thread writes, so that a child that stops reading (stopped, or a thread of its own replying
            # early) cannot block this process beyond the deadline: the pipe holds only 64 KiB.
            writer = threading.Thread(target=_send, args=(conn, payload, sent), daemon=True)
            writer.start()
        ready = wait([conn, process.sentinel], timeout)
        if not ready:
            self._kill()
            if name == "start":
                raise AgentCrashed(f"the agent did not start within {_seconds(timeout)} (importing {module} and "
                                   "calling its factory)", "start_timeout")
            raise AgentTimeout(name, timeout)
        if conn not in ready:
            raise self._ended(call)
        try:
            data = conn.recv_bytes(MAX_REPLY_BYTES)
        except EOFError:
            raise self._ended(call) from None
        except OSError:  # a message over the limit ("bad message length") or a broken connection
            if not process.is_alive():
                raise self._ended(call) from None
            self._kill()
            raise AgentCrashed(f"the agent sent a reply of over {MAX_REPLY_BYTES} bytes {call}", "protocol") from None
        if writer is not None:
            writer.join(1.0)
            if writer.is_alive():
                self._kill()
                raise AgentCrashed(f"the agent process replied before reading the call {call}", "protocol")
        return self._reply(data, call)

    def _reply(self, data: bytes, call: str) -> Any:
        try:
            reply = json.loads(data)
        except (ValueError, RecursionError):
            reply = None
        if not isinstance(reply, dict) or not (("ok" in reply) ^ ("error" in reply)):
            self._kill()
            raise AgentCrashed(f"the agent process sent a malformed reply {call}", "protocol")
        if "ok" in reply:
            return reply["ok"]
        kind, text = reply.get("error"), _text(reply.get("message"))
        if kind == "policy":
            self.close()
            raise PolicyError(text)
        self._kill()
        if kind == "exit":
            raise AgentCrashed(f"the agent called sys.exit({text}) {call}", "exit")
        if kind == "memory":
            raise AgentCrashed(f"the agent exceeded its memory limit of {self.limits.memory_mb} MB (--agent-memory; "
                               f"{text}) {call}", "memory")
        if kind == "raised":
            raise AgentCrashed(f"the agent raised {text} {call}", "raised")
        raise AgentCrashed(f"the agent process sent a malformed reply {call}", "protocol")

    def _ended(self, call: str) -> AgentCrashed:
        """The crash of a child that exited, was killed or closed its end of the connection."""
        process = self._process
        assert process is not None
        process.join(5.0)
        code = process.exitcode
        self._kill()
        if code is None:
            return AgentCrashed(f"the agent process closed its connection to the evaluation {call}", "protocol")
        if code < 0:
            try:
                name = signal.Signals(-code).name
            except ValueError:
                name = f"signal {-code}"
            hint = (" (sent by itself, another process, or the system's out-of-memory killer)"
                    if -code == signal.SIGKILL else "")
            return AgentCrashed(f"the agent process was killed by {name}{hint} {call}", "signal")
        return AgentCrashed(f"the agent exited with status {code} {call}", "exit")

    def _kill(self) -> None:
        process, conn = self._process, self._conn
        self._process = self._conn = None
        if process is not None:
            _kill(process)
        if conn is not None:
            conn.close()


_LIVE: weakref.WeakSet[Any] = weakref.WeakSet()
"""This process's agent children, killed at exit (an interrupted evaluation leaves none behind)."""


def _kill_live() -> None:
    for process in list(_LIVE):
        with contextlib.suppress(Exception):
            _kill(process)


# Before multiprocessing joins a process's children at its exit (a pool worker's, or this process's at
# interpreter exit), which would wait forever on an idle agent: finalizers of priority >= 0 run first.
multiprocessing.util.Finalize(None, _kill_live, exitpriority=100)


def _kill(process: Any) -> None:
    """Kill a child and its process group (what it started), and reap it."""
    if process.exitcode is None:
        with contextlib.suppress(OSError):
            os.killpg(process.pid, signal.SIGKILL)  # the child leads its own group (`_child_main`)
        with contextlib.suppress(OSError, ValueError):
            process.kill()
    with contextlib.suppress(OSError, ValueError, AssertionError):
        process.join(5.0)
    _LIVE.discard(process)


def _send(conn: Connection, payload: bytes, errors: list[BaseException]) -> None:
    try:
        conn.send_bytes(payload)
    except (OSError, ValueError) as exc:  # the child is gone: the sentinel says how
        errors.append(exc)


_CONTEXT: Any = None


def _mp_context() -> Any:
    """The `forkserver` context (its server imports this module once: children fork from a clean process that
    has the simulator's modules loaded, none of its state); `spawn` where there is no forkserver."""
    global _CONTEXT
    if _CONTEXT is None:
        if "forkserver" in multiprocessing.get_all_start_methods():
            _CONTEXT = multiprocessing.get_context("forkserver")
            _CONTEXT.set_forkserver_preload([__name__])
        else:
            _CONTEXT = multiprocessing.get_context("spawn")
    return _CONTEXT


@contextlib.contextmanager
def _without_main() -> Iterator[None]:
    """Start a child without this process's `__main__`: multiprocessing would run the main script again in the
    child (a user's unguarded script, Ray's worker), and the child needs nothing of it."""
    main = sys.modules.get("__main__")
    sys.modules["__main__"] = types.ModuleType("__main__")
    try:
        yield
    finally:
        if main is not None:
            sys.modules["__main__"] = main


def _seconds(value: float) -> str:
    return f"{value:g} s"


def _text(value: Any) -> str:
    text = str(value) if value is not None else ""
    return text if len(text) <= _TEXT else text[: _TEXT - 3] + "..."


# ---------------------------------------------------------------------- what crosses from the child

class Unsent:
    """An action the child could not send as data (an object of its own): `repr` is the agent's, so the
    evaluation names it when it ends the episode as `invalid_action`."""

    def __init__(self, text: str):
        self.text = text

    def __repr__(self) -> str:
        return self.text


_ARRAY_KINDS = "biuf"


def encode(value: Any, depth: int = 0) -> Any:
    """`value` as JSON data (numpy scalars as numbers, arrays tagged with dtype, shape and base64 bytes,
    tuples as lists); an object that is none of these becomes `{"__unsent__": repr}`."""
    if value is None or isinstance(value, bool | str):
        return value
    if isinstance(value, int):
        return value if abs(value) < 2**63 else {"__unsent__": _text(repr(value))}
    if isinstance(value, float):
        return value
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return float(value)
    if depth < MAX_DEPTH:
        if isinstance(value, np.ndarray) and value.dtype.kind in _ARRAY_KINDS and value.nbytes <= MAX_REPLY_BYTES // 2:
            data = base64.b64encode(np.ascontiguousarray(value).tobytes()).decode()
            return {"__ndarray__": [value.dtype.str, list(value.shape), data]}
        if isinstance(value, list | tuple):
            return [encode(v, depth + 1) for v in value]
        if isinstance(value, dict) and all(isinstance(k, str) for k in value):
            return {k: encode(v, depth + 1) for k, v in value.items()}
    return {"__unsent__": _text(repr(value))}


def _decode(value: Any, depth: int = 0) -> Any:
    """The action `encode` made; anything it cannot be is an `Unsent`, which the env refuses."""
    if value is None or isinstance(value, bool | int | float | str):
        return value
    if depth >= MAX_DEPTH:
        return Unsent("(an action nested too deeply)")
    if isinstance(value, list):
        return [_decode(v, depth + 1) for v in value]
    if not isinstance(value, dict):
        return Unsent(_text(repr(value)))
    if set(value) == {"__unsent__"}:
        return Unsent(_text(value["__unsent__"]))
    if set(value) == {"__ndarray__"}:
        try:
            dtype_text, shape, data = value["__ndarray__"]
            dtype = np.dtype(str(dtype_text))
            if dtype.kind not in _ARRAY_KINDS or not all(isinstance(n, int) and n >= 0 for n in shape):
                raise ValueError(dtype_text)
            return np.frombuffer(base64.b64decode(str(data), validate=True), dtype).reshape(shape).copy()
        except (ValueError, TypeError):
            return Unsent("(a malformed array)")
    return {str(k): _decode(v, depth + 1) for k, v in value.items()}


# ---------------------------------------------------------------------- the child

def probe(spec: str, limits: AgentLimits | None = None) -> None:
    """Check in a child process that `spec` names a callable (the module imports); this process never imports
    it. Raises as `AgentProcess` does while starting."""
    AgentProcess(spec, None, limits).close()


def _child_main(conn: Connection, spec: str, context: AgentContext | TextAgentContext | None, memory_mb: int,
                environ: dict[str, str]) -> None:
    """The agent process: limits first, then the user's module, then calls until told to close (with no
    `context`: only check that the spec names a callable). `environ` is the evaluation's environment now (a
    forkserver's child would otherwise see the one the server started with)."""
    os.environ.clear()
    os.environ.update(environ)
    with contextlib.suppress(OSError):
        os.setpgid(0, 0)  # its own process group: a kill reaches what the agent starts
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the evaluation's to handle
    _watch_parent(os.getppid())
    limit = memory_mb * 2**20
    _, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard != resource.RLIM_INFINITY:
        limit = min(limit, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    made: list[Any] = []

    def start() -> None:
        factory = resolve_factory(spec)
        if context is not None:
            made.append(build_agent(spec, factory, context))

    if not _answer(conn, start) or not made:
        return
    agent = made[0]
    while True:
        try:
            message = conn.recv()
        except (EOFError, OSError):
            return  # the evaluation is gone
        if message[0] == "reset":
            ok = _answer(conn, agent.reset, *message[1:3])
        elif message[0] == "act":
            ok = _answer(conn, lambda observation, info: encode(agent.act(observation, info)), *message[1:3])
        else:
            return
        if not ok:
            return


def _answer(conn: Connection, call: Callable[..., Any], *args: Any) -> bool:
    """Run `call(*args)` and send its value or why it failed; whether the child goes on."""
    try:
        reply: dict[str, Any] = {"ok": call(*args)}
    except PolicyError as exc:
        reply = {"error": "policy", "message": str(exc)}
    except MemoryError as exc:
        reply = {"error": "memory", "message": f"MemoryError: {exc}" if str(exc) else "MemoryError"}
    except SystemExit as exc:
        reply = {"error": "exit", "message": repr(exc.code) if exc.code is not None else ""}
    except BaseException as exc:
        traceback.print_exc()  # the agent's own traceback, on the evaluation's stderr
        reply = {"error": "raised", "message": f"{type(exc).__name__}: {exc}"}
    try:
        data = json.dumps(reply, allow_nan=True).encode()
    except (ValueError, TypeError, RecursionError) as exc:
        data = json.dumps({"error": "raised", "message": f"an unsendable reply ({type(exc).__name__})"}).encode()
    if len(data) > MAX_REPLY_BYTES and "ok" in reply:
        data = json.dumps({"ok": {"__unsent__": f"(an action of {len(data)} bytes)"}}).encode()
    try:
        conn.send_bytes(data)
    except (OSError, ValueError):
        return False
    return "ok" in reply


def _watch_parent(parent: int) -> None:
    """End this process when the evaluation's process is gone (an agent busy in `act` reads no EOF)."""

    def watch() -> None:
        while True:
            time.sleep(_ORPHAN_CHECK_S)
            if os.getppid() != parent:
                os._exit(70)

    threading.Thread(target=watch, name="luminous-agent-watch", daemon=True).start()
