"""Digests of every registered id's scripted episodes: the proof that a restructuring of the episodes or the
env changed no behaviour (issue 41).

`python scripts/episode_digests.py [--ids ID ...] [--out FILE] [--check FILE]` plays, for each id, a reset
from a fixed seed and a fixed script of steps (the expert's action, with every fourth step a fixed index of
the action space instead, so failures and recoveries are in it too), and digests, separately, what the agent
saw (observations), what it was paid (rewards, terminated, truncated), what it was told (infos) and the
expert's plan proved at reset. Beside the generated episodes, the sources of `reset(options=...)` are played
in `Luminous-ALFRED-v1`: a frozen split's entry, a given scene, a CDF file, and a built trial.

The committed digests are `tests/env/episode_digests.json`; `tests/env/test_episode_digests.py` compares a
sample against them in the fast suite and every id in the slow one. A digest that changes must be explained
in the change that changes it.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

DIGESTS = ROOT / "tests" / "env" / "episode_digests.json"
SEED = 7
STEPS = 12
"""Steps of each scripted episode (fewer when it ends first)."""
OFF_SCRIPT = 4
"""Every OFF_SCRIPT-th step sends a fixed action index instead of the expert's."""
SOURCES_ID = "Luminous-ALFRED-v1"
"""The id the reset sources beside generation are played in."""
CONFIGURED: dict[str, tuple[str, dict[str, Any]]] = {
    "every sensor": ("Luminous-PickUp-64-v2", {"depth": True, "segmentation": True, "goal_mask": True,
                                               "pose": True, "inventory": True, "expert_in_info": True}),
    "object slots": ("Luminous-ALFRED-v2", {"targets": "objects", "object_slots": 8, "inventory": True,
                                            "step_instructions": True, "reward_mode": "sparse",
                                            "expert_in_info": True}),
}
"""Settings no registered id uses (the observations, action forms and rewards off by default), as id + kwargs."""


def canonical(value: Any) -> Any:
    """Plain, order-independent data of an observation or info value (arrays by dtype, shape and bytes)."""
    if isinstance(value, np.ndarray):
        return ["ndarray", str(value.dtype), list(value.shape), hashlib.sha256(value.tobytes()).hexdigest()]
    if isinstance(value, np.generic):
        return canonical(value.item())
    if isinstance(value, dict):
        return {str(k): canonical(v) for k, v in sorted(value.items(), key=lambda kv: str(kv[0]))}
    if isinstance(value, list | tuple):
        return [canonical(v) for v in value]
    if isinstance(value, float):
        return repr(value)
    return value


def _digest(items: list[Any]) -> str:
    return hashlib.sha256(json.dumps(canonical(items), sort_keys=True).encode()).hexdigest()[:16]


def scripted(env: Any, seed: int = SEED, options: dict[str, Any] | None = None) -> dict[str, str]:
    """The digests of one scripted episode of `env` (an unwrapped `LuminousEnv`)."""
    obs, info = env.reset(seed=seed, options=options)
    observations, infos, paid = [obs], [info], []
    for k in range(STEPS):
        action = (k * 7) % env.action_space.n if k % OFF_SCRIPT == OFF_SCRIPT - 1 else env.expert_action()
        obs, reward, terminated, truncated, info = env.step(action)
        observations.append(obs)
        infos.append(info)
        paid.append([reward, terminated, truncated])
        if terminated or truncated:
            break
    plan = env.episode.expert
    expert = None if plan is None else [list(plan.actions), list(plan.steps), plan.exact]
    return {"key": env.episode.key, "observations": _digest(observations), "rewards": _digest(paid),
            "infos": _digest(infos), "expert": _digest([expert]), "steps": str(len(paid))}


def scripted_text(env: Any, seed: int = SEED) -> dict[str, str]:
    """The digests of one scripted episode of a text env (`Luminous-Text-v0`): each step sends the admissible
    command at a fixed index of the sorted list (the env has no expert action; its expert is `text.TextExpert`)."""
    obs, info = env.reset(seed=seed)
    observations, infos, paid = [obs], [info], []
    for k in range(STEPS):
        commands = sorted(info["admissible_commands"])
        obs, reward, terminated, truncated, info = env.step(commands[(k * 7) % len(commands)])
        observations.append(obs)
        infos.append(info)
        paid.append([reward, terminated, truncated])
        if terminated or truncated:
            break
    return {"key": env.episode.key, "observations": _digest(observations), "rewards": _digest(paid),
            "infos": _digest(infos), "steps": str(len(paid))}


def _trial(work: Path, frames: bool = False) -> Path:
    """A built trial of U+ entry 0."""
    from luminous_sim.benchmark import trial_folders
    from luminous_sim.data import BuildOptions, build_split

    build_split(work, "U+", 1, options=BuildOptions(frames=frames, video=False), progress=False)
    return trial_folders(work / "U+")[0][0]


def build_digest(work: Path) -> dict[str, str]:
    """The digest of every file of U+ entry 0 built with its frames (`dataset build`'s output)."""
    from luminous_sim.data.build import tree_digest

    count, digest = tree_digest(_trial(work, frames=True))
    return {"files": str(count), "tree": digest[:16]}


def source_options(name: str, work: Path) -> dict[str, Any]:
    """The reset options of a source beside generation (one of `SOURCE_NAMES`), played in `SOURCES_ID`."""
    from luminous_sim.cssg import empty_cdf, generate

    if name == "split":
        return {"split": "S+", "index": 0}
    if name == "scene":
        return {"scene": generate(empty_cdf("kitchen"), seed=3).scene}
    if name == "cdf":
        return {"cdf": str(ROOT / "cdf" / "examples" / "kitchen_apple_fridge.yaml"), "scene_seed": 1}
    return {"trial": str(_trial(work))}


def registered_ids() -> list[str]:
    from luminous_sim.env import load_entries

    return [e.id for e in load_entries()]


def id_digests(env_id: str, **kwargs: Any) -> dict[str, str]:
    import gymnasium

    import luminous_sim  # noqa: F401  (registers the ids)

    env = gymnasium.make(env_id, **kwargs).unwrapped
    try:
        return scripted_text(env) if isinstance(env.action_space, gymnasium.spaces.Text) else scripted(env)
    finally:
        env.close()


def source_digests(name: str, work: Path) -> dict[str, str]:
    import gymnasium

    import luminous_sim  # noqa: F401

    options = source_options(name, work)
    env = gymnasium.make(SOURCES_ID).unwrapped
    try:
        return scripted(env, options=options)
    finally:
        env.close()


SOURCE_NAMES = ("split", "scene", "cdf", "trial")


def all_digests(ids: list[str]) -> dict[str, dict[str, str]]:
    out: dict[str, dict[str, str]] = {}
    for env_id in ids:
        out[env_id] = id_digests(env_id)
        print(env_id, json.dumps(out[env_id]), flush=True)
    for name, (env_id, kwargs) in CONFIGURED.items():
        out[f"{env_id}:{name}"] = id_digests(env_id, **kwargs)
        print(name, json.dumps(out[f"{env_id}:{name}"]), flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name in SOURCE_NAMES:
            out[f"{SOURCES_ID}:{name}"] = source_digests(name, Path(tmp) / name)
            print(name, json.dumps(out[f"{SOURCES_ID}:{name}"]), flush=True)
        out["dataset build U+ 0"] = build_digest(Path(tmp) / "build")
        print("build", json.dumps(out["dataset build U+ 0"]), flush=True)
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ids", nargs="*", help="ids to play (default: every registered id)")
    parser.add_argument("--build-only", action="store_true", help="only the dataset build's digest")
    parser.add_argument("--configured-only", action="store_true", help="only the settings no id uses")
    parser.add_argument("--out", type=Path, help="write the digests here (JSON)")
    parser.add_argument("--check", type=Path, help="compare against these digests; exit 1 on a difference")
    args = parser.parse_args()
    if args.configured_only:
        got = {f"{i}:{n}": id_digests(i, **kw) for n, (i, kw) in CONFIGURED.items()}
        print(json.dumps(got))
    elif args.build_only:
        with tempfile.TemporaryDirectory() as tmp:
            got = {"dataset build U+ 0": build_digest(Path(tmp))}
        print(json.dumps(got))
    else:
        got = all_digests(args.ids or registered_ids())
    if args.out:
        args.out.write_text(json.dumps(got, indent=1, sort_keys=True) + "\n")
    if args.check:
        want = json.loads(args.check.read_text())
        diff = {k: (want.get(k), v) for k, v in got.items() if want.get(k) != v}
        for k, (a, b) in diff.items():
            print(f"DIFFERS {k}: committed {a}, now {b}")
        return 1 if diff else 0
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
