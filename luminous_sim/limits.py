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
MAX_AGENT_MEMORY_MB = 1024 * 1024
"""The largest memory limit (MiB of address space) `luminous eval --agent-memory` takes: 1 TiB."""
MAX_STEP_TIMEOUT_S = 24 * 3600.0
"""The longest `luminous eval --step-timeout` (seconds one agent call may take): a day."""
MAX_SCENE_OBJECTS = 2_000
"""Objects one scene (`scene.json`, a `Scene`) may hold. Measured: the largest generated house (the five-room
`two_bedroom_flat`, seeds 0-7) holds at most 137 objects, a generated kitchen about 50 and ALFRED's largest room
under 150, so this is about 14 times the largest, and above what the largest CDF (`MAX_CDF_INSTANCES`) adds to a
room's furniture; 100,000 objects kept `luminous view` busy past 240 s and 2.9 GB."""
MAX_SCENE_SIDE_M = 100.0
"""Longest side (m) of the bounding box of a scene's floor outline (a CDF house or an imported room spans at most
`MAX_LAYOUT_SIDE_M`, 30 m; the generated houses about 10 m)."""
MAX_SCENE_YAW_RAD = 25.0
"""Largest |yaw| (radians) of a scene object: about four turns either way (generated scenes keep within -pi..3pi)."""
MIN_SCENE_SCALE, MAX_SCENE_SCALE = 0.001, 100.0
"""The range of a scene object's uniform asset scale (CSSG keeps within 0.3..3, a layout within 0..100)."""
MAX_SCENE_ID_CHARS = 256
"""Longest object id, name, type, asset or region a scene may give (generated ids hold under 60 characters)."""
MAX_EPISODE_ACTIONS = 10_000
"""Low-level actions (and frames) one episode folder read by `luminous view --trajectory` may hold; ALFRED's
longest expert plans hold a few hundred."""
MAX_FRAME_BYTES = 64 * 1024 * 1024
"""Largest frame image (an episode's frames/*.png) the viewer reads; an agent's 300x300 frame is about 100 kB."""
MAX_FRAME_PIXELS = 4096 * 4096
"""Most pixels a frame image the viewer reads may hold (an agent's frame holds 300x300)."""
MAX_CHECKPOINT_BYTES = 1024 * 1024 * 1024
"""Largest model checkpoint read (a learned speaker: `speaker describe/evaluate`, `dataset build --speaker`; a
behaviour-cloning policy: `bc eval`); the project's are a few MB. A trajectory or vocabulary file the speaker reads
is held to `MAX_INPUT_BYTES`."""
