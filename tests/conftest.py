"""Shared fixtures and helpers for the test suite."""

from __future__ import annotations

from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
SHARED_ALFRED = REPO.parent / "shared" / "alfred"


@pytest.fixture(scope="session")
def shared_alfred() -> Path:
    """The real ALFRED data beside the repository; tests that need it skip with a reason when absent."""
    if not SHARED_ALFRED.exists():
        pytest.skip(f"ALFRED sample data not found at {SHARED_ALFRED}")
    return SHARED_ALFRED
