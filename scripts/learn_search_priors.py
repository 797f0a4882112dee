"""Learn the modular agent's search priors (`luminous_sim/agents/data/search_priors.json`): for each object type,
how many of its instances each receptacle type holds, counted in the initial states of ALFRED episodes the env
generates on the fly (seeds from `--seed` on), which belong to no split.

    python scripts/learn_search_priors.py --episodes 60 --seed 1000000 --out luminous_sim/agents/data/search_priors.json
"""

from __future__ import annotations

import argparse
from collections import Counter, defaultdict
from pathlib import Path

from luminous_sim.agents.priors import SearchPriors
from luminous_sim.assets.objio import write_atomic
from luminous_sim.env import LuminousEnv


def count_parents(episodes: int, seed: int) -> dict[str, dict[str, int]]:
    """Receptacle type counts per object type over `episodes` generated episodes' initial states."""
    counts: dict[str, Counter[str]] = defaultdict(Counter)
    env = LuminousEnv(width=32, height=32, verify_expert=False)
    for k in range(episodes):
        env.reset(seed=seed + k)
        assert env.world is not None
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
