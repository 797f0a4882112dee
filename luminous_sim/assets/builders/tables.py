"""Tables, desks, TV stands and shelves (furniture)."""

from __future__ import annotations
