"""Household small objects: books, electronics, sports gear, textiles, toiletries, ornaments."""

from __future__ import annotations
