"""What an action reports: AI2-THOR's lastActionSuccess and errorMessage, and a `FailureCode`."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from luminous_sim.errors import Failure, FailureCode


@dataclass(frozen=True)
class StepResult:
    """What AI2-THOR reports after an action, with the failure's code for programs.

    A failed result always carries a `code` (the `error` message is for people); a successful one never.
    """

    success: bool
    error: str = ""
    action: dict[str, Any] = field(default_factory=dict)
    code: FailureCode | None = None

    def __post_init__(self) -> None:
        if self.success != (self.code is None):
            raise ValueError(f"a {'successful' if self.success else 'failed'} StepResult "
                             f"{'has' if self.success else 'needs'} a failure code ({self.code!r}, {self.error!r})")

    @classmethod
    def ok(cls, action: dict[str, Any]) -> StepResult:
        return cls(True, "", action)

    @classmethod
    def fail(cls, code: FailureCode, message: str, action: dict[str, Any]) -> StepResult:
        return cls(False, message, action, code)

    @classmethod
    def of(cls, failure: Failure, action: dict[str, Any]) -> StepResult:
        """The failed result of a `Failure`."""
        return cls(False, failure.message, action, failure.code)

    @property
    def failure(self) -> Failure | None:
        """The code and message together, or None for a success."""
        return None if self.code is None else Failure(self.code, self.error)
