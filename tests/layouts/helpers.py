from __future__ import annotations

from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
FIXTURES = Path(__file__).resolve().parent / "fixtures"
FRONT = FIXTURES / "front_kitchen.json"
MODEL_INFO = FIXTURES / "front_model_info.json"
ATISS = FIXTURES / "atiss_bedroom.json"
