"""Storage: cabinets, drawers, dressers, carts, safes, hampers, garbage cans, boxes."""

from __future__ import annotations
