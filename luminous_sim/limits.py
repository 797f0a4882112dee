"""The stated limits on what users give the `luminous` command and the library: counts, sizes and files.

Each is checked before any work starts, and a value beyond it is refused with a one-line message that
names the option or the file and field, and the limit. They are generous for real use (the paper's
splits hold 1,405 and 435 trajectories; ALFRED's largest room holds under 150 objects) and small enough
that the job lists, layouts and scenes they allow fit in memory and finish in reasonable time.
"""

from __future__ import annotations

MAX_BUILD_JOBS = 100_000
"""Episodes (or ALFRED designs) one `dataset build` call asks for (`--count`)."""
MAX_EVAL_EPISODES = 100_000
"""Episodes one evaluation plays (`luminous eval --episodes`)."""
MAX_LAYOUT_OBJECTS = 1_000
"""Objects (furniture and small objects) in one imported or read layout."""
MAX_CDF_INSTANCES = 1_000
"""Object instances one CDF may ask for (the sum of every object's count)."""
MAX_INPUT_BYTES = 64 * 1024 * 1024
"""Largest JSON file read as a layout, a layout-importer input or an evaluation's episode file."""
MAX_CDF_BYTES = 1_000_000
"""Largest CDF file (or CDF text) read (`cdf.load`, `cdf.loads`); checked before it is parsed."""
MAX_EPISODE_FILE_BYTES = 1024 * 1024
"""Largest evaluation outcome file (`episodes/<split>-<index>.json`) read back on resume."""
MAX_CDF_RELATIONS = 5_000
"""Relations one CDF may state (`scene.relations`)."""
MAX_CDF_STEPS = 5_000
"""Execution steps one CDF may hold (`execution`); ALFRED's longest expert plans hold a few hundred."""
MAX_LAYOUT_SIDE_M = 30.0
"""Longest side (m) of an object's box in a layout or an importer's input (the longest side of a CDF house)."""
MAX_LAYOUT_COORDINATE_M = 1_000.0
"""Largest |coordinate| (m) of a point in a layout or an importer's input (a 3D-FRONT house keeps its rooms in
one frame, tens of metres across)."""
MAX_LAYOUT_ROOM_SIDE_M = 30.0
"""Longest side (m) of the bounding box of a layout's room outline."""
MAX_MINARI_EPISODES = 100_000
"""Episodes one Minari export writes (`luminous dataset minari --episodes`)."""
MAX_MINARI_SEEDS = 10 * MAX_MINARI_EPISODES + 10
"""Seeds one Minari export may try (`--max-seeds`; its default for N episodes is 10 * N + 10)."""
MAX_WORKERS = 256
"""Worker processes (or Ray CPUs of a local cluster) one `dataset build` or `eval` starts (`--workers`), and
those one `assets build` starts (`--jobs`)."""
MAX_THREADS = 256
"""Torch threads one training uses (`bc train --threads`)."""
MAX_EPOCHS = 10_000
"""Passes over the data one training makes (`speaker train`, `bc train`, `train-layouts`: `--epochs`)."""
MAX_BATCH_SIZE = 65_536
"""Examples in one training batch (`speaker train`, `bc train`: `--batch-size`)."""
MAX_TRAIN_EXAMPLES = 10_000_000
"""Examples one speaker training may be capped at (`speaker train --max-examples`)."""
MAX_TRAJECTORIES = 1_000_000
"""Trajectories one speaker training may be capped at (`speaker train --max-trajectories`); ALFRED holds
about 8,000."""
MAX_LAYOUT_ROOMS = 10_000
"""Rooms of CSSG layouts one `train-layouts` call learns from (`--rooms`)."""
MAX_EPISODE_INDEX = 1_000_000_000
"""First episode index of a split one `bc collect` or `bc eval` may start at (`--start`)."""
MAX_FLOOR_PLAN = 10_000
"""Largest AI2-THOR floor-plan number `rooms convert --scene` takes (ALFRED's run 1 to 430)."""
MAX_INSTRUCTION_TOKENS = 1_000
"""Instruction tokens an observation may hold (`InstructionTokens(length=...)`, `dataset minari --token-length`)."""
MAX_NGRAM = 100
"""Longest n-gram a speaker's decoding may forbid repeating (`--no-repeat-ngram`)."""
MAX_GENERATE_SCENES = 100_000
"""Scenes one `luminous generate` call writes (`--count`)."""
MAX_CHECKPOINT_BYTES = 1024 * 1024 * 1024
"""Largest model checkpoint read (a learned speaker: `speaker describe/evaluate`, `dataset build --speaker`; a
behaviour-cloning policy: `bc eval`); the project's are a few MB. A trajectory or vocabulary file the speaker reads
is held to `MAX_INPUT_BYTES`."""
