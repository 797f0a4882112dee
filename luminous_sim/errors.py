"""The one error hierarchy, and the codes of failed actions and plans.

A user's bad input raises a subclass whose message names what is wrong and where. An action or a plan
that fails does not raise: it reports a `Failure`, a `FailureCode` for programs beside a message for
people (the table of codes is in docs/failure_codes.md).
"""

from __future__ import annotations

import os
import stat
from dataclasses import dataclass
from enum import StrEnum
from typing import Any


class FailureCode(StrEnum):
    """Why an action or a plan failed, for programs to branch on (the message is for people).

    Values are stable lower-case strings, so they serialise as they are (an environment's `info`).
    """

    # the action itself
    UNKNOWN_ACTION = "unknown_action"
    """No such low-level action (or a planner-only action sent as a low-level one)."""
    INVALID_ARGUMENT = "invalid_argument"
    """An argument the action does not take or that ALFRED's discrete agent cannot honour: an unknown key, a
    value of the wrong type or not finite, a moveMagnitude other than 0.25, a turn other than 90 degrees, a
    teleport off the 0.25 m grid (docs/failure_codes.md, "Action arguments")."""
    NO_TARGET = "no_target"
    """The action names no object: no id given, or its mask or point hits nothing to interact with."""
    UNKNOWN_OBJECT = "unknown_object"
    """The object id is not in the scene."""
    # navigation
    BLOCKED = "blocked"
    """The agent cannot go there (off the navigable grid), or an opening door would hit it."""
    HORIZON_LIMIT = "horizon_limit"
    """The camera may not tilt beyond -30..60 degrees."""
    # reach
    NOT_VISIBLE = "not_visible"
    """The object is within reach but not in view."""
    OUT_OF_REACH = "out_of_reach"
    """The object is farther than the visibility distance (1.5 m)."""
    # the object-state rules
    NOT_PICKUPABLE = "not_pickupable"
    NOT_OPENABLE = "not_openable"
    NOT_TOGGLEABLE = "not_toggleable"
    NOT_SLICEABLE = "not_sliceable"
    NOT_A_RECEPTACLE = "not_a_receptacle"
    HANDS_FULL = "hands_full"
    """PickupObject while something is held."""
    NOT_HOLDING = "not_holding"
    """Nothing is held, or not the object the action names."""
    CLOSED = "closed"
    """The receptacle is closed (open it first)."""
    SHUT_IN = "shut_in"
    """The object is inside a closed receptacle."""
    INCOMPATIBLE = "incompatible"
    """The receptacle cannot take the object (compatibility table, itself, or inside what is held)."""
    ALREADY_DONE = "already_done"
    """The object is already open, closed, on, off or sliced."""
    MUST_BE_CLOSED = "must_be_closed"
    """A microwave is switched on only when closed."""
    NEEDS_TOOL = "needs_tool"
    """SliceObject needs a knife in hand."""
    # placement
    NO_SPOT_IN_REACH = "no_spot_in_reach"
    """The receptacle has no open region within reach of the agent."""
    RECEPTACLE_FULL = "receptacle_full"
    """No free, stable spot for the object in the receptacle's regions within reach."""
    # planning (the oracle)
    GOAL_UNREACHABLE = "goal_unreachable"
    """The planner proved the goal impossible in this state (a missing object, a forbidden place)."""
    PLAN_BUDGET = "plan_budget"
    """The planner found no plan within its time or node budget."""
    NO_PLAN = "no_plan"
    """The planner found no plan (search exhausted, or a plan failed its check)."""
    NO_POSE = "no_pose"
    """No standing pose sees the object within reach."""
    NO_PATH = "no_path"
    """No path on the navigation graph to the chosen pose."""


@dataclass(frozen=True)
class Failure:
    """A failure's code and its message."""

    code: FailureCode
    message: str

    def __str__(self) -> str:
        return self.message


class LuminousError(Exception):
    """Base class for every error Luminous-Sim raises on purpose."""


class VocabularyError(LuminousError, KeyError):
    """An object type, room type or ability that the vocabulary does not know."""

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return str(self.args[0]) if self.args else ""


class AssetError(LuminousError):
    """An asset that cannot be built, found, imported or loaded."""


class CDFError(LuminousError):
    """A malformed or inconsistent Challenge Definition Format document."""


class InfeasibleSceneError(LuminousError):
    """CSSG could not satisfy a CDF within its sampling budget.

    Args:
        message: what failed how often, for people.
        unplaced: the CDF's object names that some sample could not place, for programs (a caller may
            ask for the scene without them).
    """

    def __init__(self, message: str, unplaced: tuple[str, ...] = ()):
        super().__init__(message)
        self.unplaced = unplaced


class PlanningError(LuminousError):
    """The oracle planner found no plan, or execution diverged beyond repair.

    Args:
        message: what went wrong, for people.
        code: why, for programs (`FailureCode.NO_PLAN` unless said otherwise).
    """

    def __init__(self, message: str, code: FailureCode = FailureCode.NO_PLAN):
        super().__init__(message)
        self.code = code


class RoomError(LuminousError):
    """A room structure that is malformed, cannot be generated, converted or found in the library."""


def mode_kind(mode: int) -> str:
    """What a file of `os.stat` mode `mode` is, in words for a message: "a regular file", "a folder",
    "a FIFO (named pipe)", "a device", "a socket", or "not a regular file"."""
    if stat.S_ISREG(mode):
        return "a regular file"
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def path_kind(path: str | os.PathLike[str]) -> str:
    """What `path` is (following links), in words for a message: `mode_kind`'s words, "no such file or folder",
    or "cannot read (<reason>)". Never opens the path (opening a FIFO would block)."""
    try:
        return mode_kind(os.stat(path).st_mode)
    except FileNotFoundError:
        return "no such file or folder"
    except OSError as exc:
        return f"cannot read ({exc.strerror or exc})"


def link_or_kind(path: str | os.PathLike[str]) -> str:
    """`path_kind`'s words, or "a symbolic link" for a link (which builds and evaluations never follow)."""
    return "a symbolic link" if os.path.islink(path) else path_kind(path)


def read_file_bytes(path: str | os.PathLike[str], limit: int, what: str,
                    error: type[LuminousError] = LuminousError, follow_links: bool = False) -> bytes:
    """The bytes of the regular file `path` (never followed through a link, unless `follow_links`) of at most
    `limit` bytes.

    What `path` is, is checked before it is opened (`os.lstat`, or `os.stat` with `follow_links`: a FIFO would
    block, a device could be endless), and again on the open descriptor (opened without blocking, and without
    following a link unless asked), so that a file swapped in between is refused too; at most `limit` + 1 bytes
    are read.

    Raises:
        error: missing, a link (unless `follow_links`), not a regular file (a folder, a FIFO, a device, a socket)
            or over `limit` bytes; the message names the file and says it was expected to be `what`.
    """
    import errno

    def refused(kind: str) -> LuminousError:
        return error(f"{path}: {kind}; expected {what}")

    def not_a_file(mode: int) -> LuminousError | None:
        if stat.S_ISLNK(mode):
            return refused("a symbolic link")
        return None if stat.S_ISREG(mode) else refused(mode_kind(mode))

    def too_big() -> LuminousError:
        return error(f"{path}: over {limit} bytes; expected {what}")

    try:
        before = os.stat(path) if follow_links else os.lstat(path)
    except FileNotFoundError:
        raise refused("no such file or folder") from None
    except OSError as exc:
        raise refused(f"cannot read ({exc.strerror or exc})") from None
    problem = not_a_file(before.st_mode) or (too_big() if before.st_size > limit else None)
    if problem is not None:
        raise problem
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    if not follow_links:
        flags |= getattr(os, "O_NOFOLLOW", 0)
    try:
        fd = os.open(path, flags)
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            raise refused("a symbolic link") from None
        raise refused("no such file or folder" if isinstance(exc, FileNotFoundError)
                      else f"cannot read ({exc.strerror or exc})") from None
    with os.fdopen(fd, "rb") as fh:
        opened = os.fstat(fh.fileno())
        problem = not_a_file(opened.st_mode) or (too_big() if opened.st_size > limit else None)
        if problem is not None:
            raise problem
        try:
            raw = fh.read(limit + 1)
        except OSError as exc:
            raise refused(f"cannot read ({exc.strerror or exc})") from None
    if len(raw) > limit:  # it grew after the checks
        raise too_big()
    return raw


def json_field(data: Any, where: str | os.PathLike[str], *names: str,
               error: type[LuminousError] = LuminousError) -> Any:
    """`data[names[0]][names[1]]...` of a parsed JSON document; `error` naming the file and the dotted field
    that is missing (or whose parent is not an object)."""
    value = data
    for k, name in enumerate(names):
        if not isinstance(value, dict) or name not in value:
            raise error(f"{os.fspath(where)}: field {'.'.join(names[:k + 1])!r} is missing")
        value = value[name]
    return value


def read_json_file(path: str | os.PathLike[str], limit: int, what: str,
                   error: type[LuminousError] = LuminousError) -> Any:
    """The JSON value of the regular file `path` (read by `read_file_bytes`: never through a link, never a FIFO or
    a device, at most `limit` bytes). Standard JSON only: `NaN` and `Infinity` are refused, and so is a document
    nested too deeply for the parser.

    Raises:
        error: see `read_file_bytes`; not JSON or nested too deeply; the message names the file and says it was
            expected to be `what` (e.g. "an episode outcome file (luminous_sim.limits.MAX_EPISODE_FILE_BYTES)").
    """
    import json

    raw = read_file_bytes(path, limit, what, error)
    try:
        return json.loads(raw, parse_constant=_not_a_json_number)
    except RecursionError:
        raise error(f"{path}: not JSON (nested too deeply for the parser); expected {what}") from None
    except ValueError as exc:
        raise error(f"{path}: not JSON ({exc}); expected {what}") from None


def _not_a_json_number(name: str) -> Any:
    raise ValueError(f"{name} is not a JSON number")
