"""Errors of the task layer, in the project's one hierarchy."""

from __future__ import annotations

from luminous_sim.errors import LuminousError


class TaskError(LuminousError):
    """A task that is malformed or cannot be built (unknown type, bad parameters, no goal)."""


class TaskSamplingError(TaskError):
    """No task of the requested type is feasible in the scene; the message says why."""
