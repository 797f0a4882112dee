"""Moved: `python -m luminous_sim.episodes.freeze`; this path warns and forwards until 0.3.0."""

import runpy
import warnings

if __name__ == "__main__":
    warnings.warn("python -m luminous_sim.benchmark.freeze moved to python -m luminous_sim.episodes.freeze; the old "
                  "path goes in release 0.3.0", DeprecationWarning, stacklevel=1)
    runpy.run_module("luminous_sim.episodes.freeze", run_name="__main__", alter_sys=True)
