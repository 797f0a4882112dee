"""Layer L3: evaluation splits as data. LUMINOUS's S+ and U+ (ALFRED's seen and unseen room structures
with new layouts, paper section 4.3): which structure, layout, task type and seeds each episode index
means, and ALFRED's `oct21.json` split-file layout for what a build produced.

Typical use::

    from luminous_sim.splits import plus_split
    print(plus_split("U+").structures)       # entry i of a split: luminous_sim.benchmark.benchmark_entry
"""

from luminous_sim.splits.plus import (
    PLUS_SPLITS,
    PlusSplit,
    SplitError,
    oct21_document,
    plus_split,
)

__all__ = [
    "PLUS_SPLITS",
    "PlusSplit",
    "SplitError",
    "oct21_document",
    "plus_split",
]
