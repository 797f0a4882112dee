"""Preview some asset types (all their variants) as one picture: `python3 scripts/asset_preview.py [--open] T...`.

With --open every joint is at its upper limit and every "on"/"dirty" state visual is shown.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.assets.catalog import Catalog
from luminous_sim.world.asset_sheet import render_sheet


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("types", nargs="*")
    ap.add_argument("--open", action="store_true")
    ap.add_argument("--out", default="/tmp/asset_preview.png")
    args = ap.parse_args()
    cat = Catalog.load(include_user=False)
    entries = [e for e in cat if not args.types or e.type in args.types]
    render_sheet(entries, Path(args.out), tile=220, states_on=args.open)
    print(args.out)


if __name__ == "__main__":
    main()
