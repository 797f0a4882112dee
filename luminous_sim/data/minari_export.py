"""Oracle demonstrations as a Minari dataset (offline RL), next to the ALFRED-format export.

`export_minari` rolls `OraclePolicy` out in a registered env, its instruction as token ids
(`InstructionTokens`, the observations SB3's `MultiInputPolicy` takes), and writes with Minari's own storage
(HDF5) one episode per seed: observations (`rgb`, `instruction` token ids, and whatever else the env's options
add), the discrete actions, rewards, terminations, truncations, and per-step infos (`success`,
`goal_conditions_met`, `goal_conditions_total`, `failures`, `failure_code`, `subgoal`; a code is "" where the
action succeeded). Each episode's metadata holds its seed, its instruction as text and its task type.

The oracle acts through the env's discrete space wherever an index means what it means; where its target
covers none of the k x k grid points it needs the ALFRED dict form, which a dataset over `Discrete` actions
cannot hold. Such an episode is left out and its seed listed in the dataset's metadata
(`luminous_skipped_seeds`, beside `luminous_seeds_tried`), so the share kept is on record; seeds are tried in
order from `seed` until `episodes` are kept, or `max_seeds` are spent (an error). On the 64 px pick-up id
(a 3 x 3 grid) most episodes need that form; its `targets="objects"` variant (object slots) needs it almost
never.

The dataset is built in `<out>.partial/` (a Minari datasets root), each episode appended as it is rolled out,
and moved to `out` when complete; `resume=True` goes on from a `<out>.partial/` an interrupted run left (one
stopped before its first episode, its dataset created but no run recorded, is started afresh). Read
it back with `minari.MinariDataset(minari_dataset_path(out, dataset_id))`, or with `MINARI_DATASETS_PATH=out` and
`minari.load_dataset(dataset_id)`; `dataset.recover_environment()` rebuilds the wrapped env.
"""

from __future__ import annotations

import contextlib
import json
import os
import warnings
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.errors import LuminousError
from luminous_sim.limits import MAX_MINARI_EPISODES, MAX_MINARI_SEEDS

ALGORITHM = "luminous_sim.env.OraclePolicy"
PARTIAL = ".partial"


class MinariExportError(LuminousError):
    """The Minari dataset cannot be written (minari missing, bad arguments, an existing output)."""


@dataclass(frozen=True)
class MinariExport:
    """What `export_minari` wrote."""

    path: Path
    """The dataset's folder (`<out>/<dataset_id>`); its `data/` is what `minari.MinariDataset` opens."""
    dataset_id: str
    episodes: int
    steps: int
    seeds_tried: int
    skipped_seeds: tuple[int, ...]


def default_minari_id(env_id: str) -> str:
    """`luminous/<env id without "Luminous-">/oracle-v0`, e.g. `luminous/NavToObject-64-v1/oracle-v0`."""
    return f"luminous/{env_id.removeprefix('Luminous-')}/oracle-v0"


def minari_dataset_path(out: Path, dataset_id: str) -> Path:
    """The folder `minari.MinariDataset` opens for a dataset written under `out`."""
    return Path(out) / dataset_id / "data"


@contextlib.contextmanager
def _datasets_root(root: Path) -> Iterator[None]:
    """Point Minari's datasets root (`MINARI_DATASETS_PATH`, which its creation API writes under) at `root`."""
    old = os.environ.get("MINARI_DATASETS_PATH")
    os.environ["MINARI_DATASETS_PATH"] = str(root)
    try:
        yield
    finally:
        if old is None:
            del os.environ["MINARI_DATASETS_PATH"]
        else:
            os.environ["MINARI_DATASETS_PATH"] = old


def _step_info(info: dict[str, Any]) -> dict[str, Any]:
    met, total = info["goal_conditions"]
    return {"success": bool(info["success"]), "goal_conditions_met": int(met), "goal_conditions_total": int(total),
            "failures": int(info["failures"]), "failure_code": info["failure_code"] or "",
            "subgoal": str(info["subgoal"])}


def _rollout(env: Any, seed: int, episode_id: int) -> tuple[Any, dict[str, Any]] | None:
    """The oracle's episode as a Minari `EpisodeBuffer` and its metadata, or None if the oracle needed an
    action outside the discrete space."""
    from minari.data_collector import EpisodeBuffer

    from luminous_sim.env import OraclePolicy

    policy = OraclePolicy(env)
    obs, info = env.reset(seed=seed)
    inner = env.unwrapped
    meta = {"seed": seed, "instruction": inner.episode.goal.instruction, "task_type": inner.episode.goal.task_type}
    observations: dict[str, list[Any]] = {k: [v] for k, v in obs.items()}
    infos: dict[str, list[Any]] = {k: [v] for k, v in _step_info(info).items()}
    actions: list[int] = []
    rewards: list[float] = []
    terminations: list[bool] = []
    truncations: list[bool] = []
    done = False
    while not done:
        action = policy(obs)
        if not isinstance(action, (int, np.integer)):
            return None
        obs, reward, terminated, truncated, info = env.step(action)
        for k, v in obs.items():
            observations[k].append(v)
        for k, v in _step_info(info).items():
            infos[k].append(v)
        actions.append(int(action))
        rewards.append(float(reward))
        terminations.append(bool(terminated))
        truncations.append(bool(truncated))
        done = terminated or truncated
    buffer = EpisodeBuffer(id=episode_id, seed=seed, observations=observations, actions=actions, rewards=rewards,
                           terminations=terminations, truncations=truncations, infos=infos)
    return buffer, meta


def _kept_seeds(storage: Any) -> list[int]:
    n = storage.total_episodes
    return [int(m["seed"]) for m in storage.get_episode_metadata(range(n))] if n else []


def export_minari(env_id: str, episodes: int, out: Path, *, seed: int = 0, dataset_id: str | None = None,
                  env_kwargs: dict[str, Any] | None = None, token_length: int = 32, jpeg: bool = False,
                  resume: bool = False, max_seeds: int | None = None, progress: bool = False) -> MinariExport:
    """Roll the oracle out in `env_id` and write `episodes` of its episodes as a Minari dataset under `out`.

    Args:
        env_id: a registered id (`luminous_sim.env.load_entries()`).
        episodes: episodes to keep (see the module docstring for the ones left out).
        out: a Minari datasets root to create (it must not exist, or be an empty folder).
        seed: the first episode's seed; later ones count up from it.
        dataset_id: Minari's id; default `default_minari_id(env_id)`.
        env_kwargs: env options (`EnvConfig` fields), as `gymnasium.make(env_id, **env_kwargs)`.
        token_length: tokens kept of the instruction (`InstructionTokens`).
        jpeg: store images JPEG-encoded (Minari's default: lossy, smaller) instead of raw arrays.
        resume: go on from the `<out>.partial/` of an interrupted run with the same arguments (or start
            afresh where that run stopped before writing any episode).
        max_seeds: give up after trying this many seeds (default `10 * episodes + 10`).
        progress: show a progress bar.

    Raises:
        MinariExportError: minari is not installed, `out` exists, an argument is wrong, or `max_seeds` seeds
            gave fewer than `episodes` episodes in the discrete space (the partial dataset is kept).
    """
    if isinstance(episodes, bool) or not isinstance(episodes, int) or not 1 <= episodes <= MAX_MINARI_EPISODES:
        raise MinariExportError(f"episodes: expected a whole number from 1 to {MAX_MINARI_EPISODES} "
                                f"(luminous_sim.limits.MAX_MINARI_EPISODES), got {episodes!r}")
    if max_seeds is not None and (isinstance(max_seeds, bool) or not isinstance(max_seeds, int)
                                  or not 1 <= max_seeds <= MAX_MINARI_SEEDS):
        raise MinariExportError(f"max_seeds: expected a whole number from 1 to {MAX_MINARI_SEEDS} "
                                f"(luminous_sim.limits.MAX_MINARI_SEEDS), got {max_seeds!r}")
    try:
        import minari
    except ModuleNotFoundError:
        raise MinariExportError("the Minari export needs the minari package: pip install 'luminous-sim[minari]'"
                                ) from None
    import gymnasium
    from tqdm import tqdm

    from luminous_sim.env import InstructionTokens

    # Absolute from the start: Minari joins its (relative) datasets root onto itself (MinariStorage.get_size)
    out = Path(out).resolve()
    if out.exists() and (not out.is_dir() or any(out.iterdir())):
        raise MinariExportError(f"{out}: already exists; choose a new --out (a dataset is never overwritten)")
    dataset_id = dataset_id or default_minari_id(env_id)
    try:
        minari.dataset.minari_dataset.parse_dataset_id(dataset_id)
    except ValueError as exc:
        raise MinariExportError(f"dataset id {dataset_id!r}: {exc}") from None
    if env_id not in gymnasium.registry:
        raise MinariExportError(f"env {env_id!r} is not registered; see `luminous_sim.env.load_entries()`")
    partial = out.with_name(out.name + PARTIAL)
    store = minari_dataset_path(partial, dataset_id)
    unstarted = _unstarted(store)
    if partial.exists() and not resume:
        state = ", stopped before its first episode" if unstarted else ""
        then = "start it afresh" if unstarted else "go on from it"
        raise MinariExportError(f"{partial}: an interrupted export is there{state}; pass resume (--resume) to "
                                f"{then}, or remove it")

    env = InstructionTokens(gymnasium.make(env_id, **(env_kwargs or {})), length=token_length)
    try:
        with _datasets_root(partial):
            if unstarted:
                _remove_unstarted(store)
            if store.exists():
                try:
                    dataset = minari.MinariDataset(store)
                except Exception as exc:  # a torn write: h5py/json errors of any kind
                    raise MinariExportError(f"{partial}: cannot resume ({exc}); remove it and start again"
                                            ) from None
            else:
                dataset = _new_dataset(minari, dataset_id, env, jpeg)
            storage = dataset.storage
            run = {"luminous_env_id": env_id, "luminous_env_kwargs": dict(env_kwargs or {}),
                   "luminous_first_seed": seed, "luminous_token_length": token_length}
            before = {k: storage.metadata.get(k) for k in run}
            if any(v is not None for v in before.values()) and before != run:
                raise MinariExportError(f"{partial}: was started with {before}, not {run}; resume with the same "
                                        "arguments, or remove it")
            storage.update_metadata(run)
            kept = _kept_seeds(storage)
            next_seed = max(kept) + 1 if kept else seed
            bar = tqdm(total=episodes, initial=len(kept), desc="oracle episodes", unit="ep", disable=not progress)
            limit = seed + (max_seeds if max_seeds is not None else 10 * episodes + 10)
            while len(kept) < episodes:
                if next_seed >= limit:
                    raise MinariExportError(
                        f"{env_id}: only {len(kept)} of seeds {seed}..{next_seed - 1} gave an oracle episode in the "
                        f"discrete action space (its target covered no grid point in the others); try the env "
                        f"option targets=objects, or a larger max_seeds ({partial} is kept for resume)")
                rolled = _rollout(env, next_seed, len(kept))
                if rolled is not None:
                    buffer, meta = rolled
                    storage.update_episodes([buffer])
                    storage.update_episode_metadata([meta], episode_indices=[len(kept)])
                    kept.append(next_seed)
                    bar.update()
                next_seed += 1
            bar.close()
            taken = set(kept)
            skipped = tuple(s for s in range(seed, next_seed) if s not in taken)
            storage.update_metadata({"luminous_seeds_tried": [seed, next_seed - 1],
                                     "luminous_skipped_seeds": list(skipped)})
            steps = storage.total_steps
    finally:
        env.close()
    if out.exists():
        out.rmdir()
    os.replace(partial, out)
    return MinariExport(out / dataset_id, dataset_id, len(kept), int(steps), next_seed - seed, skipped)


_STORE_FILES = frozenset({"metadata.json", "main_data.hdf5"})


def _unstarted(store: Path) -> bool:
    """Whether `store` is a dataset this export created but stopped before recording its run (no episodes).

    Only Minari's own two files in `data/` and nothing else beside it, metadata naming our algorithm, no
    episode and no `luminous_*` run: holding nothing of value, such a dataset is recreated on resume.
    """
    try:
        if {p.name for p in store.parent.iterdir()} != {"data"} or not store.is_dir():
            return False
        files = {p.name for p in store.iterdir()}
        if "metadata.json" not in files or not files <= _STORE_FILES or any(
                not (store / name).is_file() or (store / name).is_symlink() for name in files):
            return False
        metadata = json.loads((store / "metadata.json").read_text())
    except (OSError, ValueError):
        return False
    return (isinstance(metadata, dict) and metadata.get("algorithm_name") == ALGORITHM
            and metadata.get("total_episodes") == 0 and "luminous_env_id" not in metadata)


def _remove_unstarted(store: Path) -> None:
    """Remove an `_unstarted` dataset: its known files one by one, then its (now empty) folders."""
    for name in _STORE_FILES:
        (store / name).unlink(missing_ok=True)
    store.rmdir()
    store.parent.rmdir()


def _new_dataset(minari: Any, dataset_id: str, env: Any, jpeg: bool) -> Any:
    from luminous_sim import __version__

    description = (f"OraclePolicy demonstrations in {env.spec.id} (Luminous-Sim {__version__}): one episode per "
                   "seed; observations rgb and instruction token ids (luminous_sim.env.InstructionTokens); "
                   "episodes whose oracle needed an action outside the discrete space are left out (their seeds "
                   "are in luminous_skipped_seeds).")
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"`(code_permalink|author_email)` is set to None")
        warnings.filterwarnings("ignore", message=r"`eval_env` is set to None")
        return minari.create_dataset_from_buffers(
            dataset_id, [], env=env, algorithm_name=ALGORITHM, author="Luminous-Sim", description=description,
            data_format="hdf5", requirements=[f"luminous-sim=={__version__}"], jpeg_encoding=jpeg)

