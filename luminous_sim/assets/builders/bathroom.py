"""Bathroom fixtures: toilet, bathtub, shower parts, towel holders, mirror."""

from __future__ import annotations
