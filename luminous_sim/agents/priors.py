"""Where things are: for each object type, the share of its instances each receptacle type holds, counted in
generated scenes that are in no split (`scripts/learn_search_priors.py` makes the shipped file). The search
opens the closed receptacles likeliest to hold what it looks for first."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from luminous_sim.errors import LuminousError

PRIORS_FILE = Path(__file__).parent / "data" / "search_priors.json"


@dataclass(frozen=True)
class SearchPriors:
    """P(receptacle type | object type), from counts."""

    counts: dict[str, dict[str, int]]

    def chance(self, object_type: str, receptacle_type: str) -> float:
        row = self.counts.get(object_type) or {}
        total = sum(row.values())
        return row.get(receptacle_type, 0) / total if total else 0.0

    def to_json(self) -> str:
        return json.dumps({"counts": {o: dict(sorted(r.items())) for o, r in sorted(self.counts.items())}},
                          indent=1) + "\n"

    @classmethod
    def load(cls, path: Path) -> SearchPriors:
        try:
            data = json.loads(Path(path).read_text())
            counts = {str(o): {str(r): int(n) for r, n in row.items()} for o, row in data["counts"].items()}
        except (OSError, ValueError, KeyError, TypeError, AttributeError) as exc:
            raise LuminousError(f"{path}: not a search priors file ({type(exc).__name__}: {exc})") from None
        return cls(counts)


_DEFAULT: SearchPriors | None = None


def default_priors() -> SearchPriors:
    """The shipped priors (loaded once)."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = SearchPriors.load(PRIORS_FILE) if PRIORS_FILE.exists() else SearchPriors({})
    return _DEFAULT
