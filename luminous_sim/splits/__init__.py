"""Layer L3: evaluation splits as data. LUMINOUS's S+ and U+ (ALFRED's seen and unseen room structures
with new layouts, paper section 4.3): which structure, layout, task type and seeds each episode index
means, and ALFRED's `oct21.json` split-file layout for what a build produced.

Typical use::

    from luminous_sim.splits import split_entries
    for entry in split_entries("U+", 14):
        print(entry.floor_plan, entry.layout_seed, entry.task_type, entry.task_seed)
"""

from luminous_sim.splits.plus import (
    PLUS_SPLITS,
    PlusSplit,
    SplitEntry,
    SplitError,
    oct21_document,
    plus_split,
    split_entries,
    split_entry,
)

__all__ = [
    "PLUS_SPLITS",
    "PlusSplit",
    "SplitEntry",
    "SplitError",
    "oct21_document",
    "plus_split",
    "split_entries",
    "split_entry",
]
