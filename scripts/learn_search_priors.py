"""Learn the modular agent's search priors (`luminous_sim/agents/data/search_priors.json`): for each object type,
how many of its instances each receptacle type holds, counted in the initial states of ALFRED episodes the env
generates on the fly (seeds from `--seed` on), which belong to no split: they are laid out in CSSG's own room
shapes, and every split (S, U, S+, U+) is in one of ALFRED's floor plans, which the count refuses.

    python scripts/learn_search_priors.py --episodes 60 --seed 1000000 --out luminous_sim/agents/data/search_priors.json
"""

from __future__ import annotations

import argparse
from collections import Counter, defaultdict
from pathlib import Path

from luminous_sim.agents.priors import SearchPriors
from luminous_sim.env import LuminousEnv
from luminous_sim.fileio import write_atomic
from luminous_sim.scene import Scene


def check_outside_splits(scene: Scene) -> None:
    """Raise ValueError where `scene` is laid out in one of ALFRED's floor plans, the rooms of every split."""
    if scene.room.name.startswith("FloorPlan"):
        raise ValueError(f"a priors episode is in {scene.room.name}, an ALFRED floor plan that splits use")


def count_parents(episodes: int, seed: int) -> dict[str, dict[str, int]]:
    """Receptacle type counts per object type over `episodes` generated episodes' initial states."""
    counts: dict[str, Counter[str]] = defaultdict(Counter)
    env = LuminousEnv(width=32, height=32, verify_expert=False)
    for k in range(episodes):
        env.reset(seed=seed + k)
        assert env.world is not None and env.episode is not None
        check_outside_splits(env.episode.scene)
        state = env.world.view().state
        for obj in state.objects.values():
            if obj.parent in state.objects:
                counts[obj.object_type][state.objects[obj.parent].object_type] += 1
        env.close()
    return {o: dict(c) for o, c in counts.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--episodes", type=int, default=60)
    parser.add_argument("--seed", type=int, default=1_000_000)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    priors = SearchPriors(count_parents(args.episodes, args.seed))
    write_atomic(args.out, priors.to_json())
    print(f"wrote {args.out}: {len(priors.counts)} object types from {args.episodes} episodes")


if __name__ == "__main__":
    main()
