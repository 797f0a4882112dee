"""`python -m luminous_sim.thor [--data DIR] SCRIPT [ARGS...]`: run SCRIPT (e.g. ALFRED's
`models/eval/eval_seq2seq.py`) as `__main__` with `import ai2thor.controller` resolving to
`luminous_sim.thor`, in this process and in the processes it spawns."""

from __future__ import annotations

import argparse
import os
import runpy
import shutil
import sys
from pathlib import Path

from luminous_sim.thor.scenes import DATA_VAR, ThorSceneError
from luminous_sim.thor.shim import activate, write_shim


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m luminous_sim.thor",
        description="Run a script written for ai2thor 2.1.0 (ALFRED's evaluation, replay checks, ...) on "
                    "Luminous-Sim: `import ai2thor.controller` gives luminous_sim.thor's Controller. Scenes come "
                    f"from the dataset folder in ${DATA_VAR} (or --data).")
    p.add_argument("--data", action="append", default=None,
                   help=f"a dataset folder built by `luminous dataset build` (repeatable; sets ${DATA_VAR})")
    p.add_argument("--keep-shim", default=None, metavar="DIR",
                   help="write the generated ai2thor package into DIR and keep it (default: a temporary folder)")
    p.add_argument("script", help="the Python script to run as __main__")
    p.add_argument("args", nargs=argparse.REMAINDER, help="its arguments")
    return p


def main(argv: list[str] | None = None) -> int:
    ns = build_parser().parse_args(argv)
    script = Path(ns.script)
    if not script.is_file():
        print(f"python -m luminous_sim.thor: error: no such script: {script}", file=sys.stderr)
        return 2
    if ns.data:
        os.environ[DATA_VAR] = os.pathsep.join(str(Path(d).resolve()) for d in ns.data)
    folder = write_shim(ns.keep_shim)
    activate(folder)
    script_dir = str(script.resolve().parent)
    if script_dir not in sys.path:
        sys.path.insert(0, script_dir)  # as `python SCRIPT` does
    sys.argv = [str(script), *ns.args]
    try:
        runpy.run_path(str(script), run_name="__main__")
    except ThorSceneError as exc:
        print(f"python -m luminous_sim.thor: error: {exc}", file=sys.stderr)
        return 1
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        if ns.keep_shim is None:
            shutil.rmtree(folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
