"""ALFRED's own code (../shared/alfred/code, unmodified) laid out so that it runs as published.

The shared copy stores `gen/layouts` as a one-line pointer file (`../../layouts`), not a link, and ALFRED's
navigation graph opens `gen/graph/../layouts/FloorPlanN-layout.npy`. `mirror` builds a folder of symbolic
links to ALFRED's files (nothing copied, nothing edited) whose `gen/layouts` is the layouts folder.
"""

from __future__ import annotations

import os
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
ALFRED = REPO.parent / "shared" / "alfred"
CODE = ALFRED / "code"
LAYOUTS = ALFRED / "layouts"


def missing() -> str | None:
    """Why ALFRED's code cannot be used here, or None."""
    for path in (CODE / "env" / "thor_env.py", CODE / "models" / "eval" / "eval_task.py", LAYOUTS):
        if not path.exists():
            return f"ALFRED's code or layouts not found ({path} is missing)"
    return None


def mirror(dest: Path) -> Path:
    """ALFRED's code folder under `dest`: links to its files, `gen/` and `gen/graph/` real folders (the graph
    reaches `../layouts` from its own folder), `gen/layouts` a link to the layouts folder."""
    dest.mkdir(parents=True, exist_ok=True)
    for item in CODE.iterdir():
        if item.name != "gen":
            os.symlink(item, dest / item.name)
    (dest / "gen" / "graph").mkdir(parents=True)
    for item in (CODE / "gen").iterdir():
        if item.name == "graph":
            for f in item.iterdir():
                os.symlink(f, dest / "gen" / "graph" / f.name)
        elif item.name != "layouts":
            os.symlink(item, dest / "gen" / item.name)
    os.symlink(LAYOUTS, dest / "gen" / "layouts")
    return dest
