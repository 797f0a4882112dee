"""Train PPO (stable-baselines3) on a small Luminous-Sim id: save the model, the learning curve (CSV and PNG),
evaluate the trained policy, two random ones and the oracle on the same held-out seeds.

    pip install -e '.[learn]'
    python examples/train_ppo.py --env Luminous-NavToObject-64-v1 --steps 20000 --out out/ppo
    python examples/train_ppo.py --out out/ppo --steps 40000 --resume      # go on from the last save
    python examples/train_ppo.py --out out/ppo --steps 1000000 --cpu-minutes 60 --n-envs 2

It writes to `--out`: `model.zip` (`PPO.load` reads it back), `curve.csv` (one row per finished training
episode: timesteps, return, length, success, the training's CPU seconds so far), `curve.png`, `config.json`
(what was run), `progress.json` (timesteps and CPU seconds), `vecnormalize.pkl` (the reward scale) and
`eval.json` (success rate with a 95% Wilson interval, mean return and length, how episodes ended, per
policy). Everything is saved together every `--save-every` steps, so an interrupted run resumes with
`--resume`; `--cpu-minutes` bounds the training's CPU time (trainer and env workers, resumed runs included).

The policy is SB3's `MultiInputPolicy`: a CNN over `rgb`, a one-hot encoding of the instruction's token ids
(`luminous_sim.env.InstructionTokens`), so the agent knows which object the episode asks for, and feedback
(`ActionFeedback`): the last 8 actions with whether each failed, as ALFRED's agents see `lastActionSuccess`,
and the episode's failed actions so far (a policy without memory then knows it just hit a wall, that it has
turned a full circle, and how close the failure limit is). `--actions navigation` restricts the agent to the
five navigation actions (`ActionSubset`), all that `goto_object` needs. Training envs are the id as
registered but with a failed action costing 0.5 (`TRAIN_KWARGS`; ALFRED's 0.05 is far below what the 10th
failure costs: the episode and the goal's reward), changed with `--env-kwarg name=value` (a TOML value, on top
of that default), and three training-side wrappers: the failure limit ends an episode as a
termination (`FailureLimitEnds`: SB3 would otherwise bootstrap it as if the episode went on), each scene
serves 4 episodes with new goals (`SceneRepeat`: a reset in a built world costs about a third of a new
scene's), and rewards are normalised (`VecNormalize`). Evaluation uses the id as registered (`--eval-kwarg`
on top), whose episodes the oracle solves.

`--net goal-depth` swaps the feature extractor for a small CNN over `goal_mask` and `depth` (`nets.py`;
`--net rgb-depth-goal` the same over `rgb` and `depth`, told the goal by the instruction alone), and
`--bc-steps N` first makes the policy imitate the oracle with DAgger (`dagger.py`; `--critic-warmup T` then trains
only the critic for PPO's first T steps): PIRLNav's recipe, what reaches a held-out SR of 0.33-0.36 on
`Luminous-ObjectNav-64-v2` with `goal_mask=true` (docs/benchmarks.md). Such a run also writes
`warm_start.json` (a row per imitation round) and `model_warm.zip` (the imitated policy).

This is an example to read and change (policy, hyperparameters, wrappers) rather than a command of the
`luminous` CLI: stable-baselines3 and torch are optional extras, and a fixed set of flags would hide what a
user of SB3 wants to edit.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import os
import sys
import time
import tomllib
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import gymnasium
import numpy as np

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import (
    ActionFeedback,
    ActionSubset,
    FailureLimitEnds,
    InstructionTokens,
    NewPlaceBonus,
    SceneRepeat,
)
from luminous_sim.env.actions import NAVIGATION, STOP
from luminous_sim.fileio import write_atomic

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the examples' own modules, when imported from elsewhere
from dagger import WarmStart, critic_first, warm_start

DEFAULT_ENV = "Luminous-NavToObject-64-v1"
TRAIN_KWARGS: dict[str, Any] = {"depth": True, "reward": {"failure": -0.2}}
"""Env options for training by default: the id as registered with a `depth` observation (evaluation adds it
too: `observation_kwargs`), and a failed action costing 0.2 rather than ALFRED's 0.05, nearer what it costs
in the end, as the 10th failure ends the episode and loses the goal's 9 (see the module docstring)."""
OBSERVATION_OPTIONS = ("depth", "segmentation", "goal_mask", "pose", "inventory", "targets", "grid", "object_slots",
                       "step_instructions", "width", "height")
"""Env options that change what a policy sees or does: a trained policy is evaluated with the same ones."""
PPO_DEFAULTS: dict[str, Any] = {"n_steps": 128, "batch_size": 64, "n_epochs": 4, "learning_rate": 3e-4,
                                "gamma": 0.99, "gae_lambda": 0.95, "ent_coef": 0.03, "clip_range": 0.2}
CURVE_FIELDS = ("timesteps", "episode_return", "episode_length", "success", "cpu_seconds")
NEW_PLACE_BONUS = 0.2
"""Training reward for each grid position first stood on in an episode (`NewPlaceBonus`), as much as a path step
gained toward the goal earns."""
FEEDBACK_HISTORY = 8
"""Past steps in the `feedback` observation (`ActionFeedback`): enough to see a full turn (4 rotations) and what
came before it, a short memory for a policy that has none."""
ACTION_SETS: dict[str, tuple[str, ...] | None] = {"all": None, "navigation": NAVIGATION,
                                                   "objectnav": (*NAVIGATION, STOP)}
"""`--actions` choices: the env's whole space, the five navigation actions (`goto_object` needs no more), or
those and Stop (ObjectNav v2 succeeds only on Stop)."""
EVAL_SEED0 = 1_000_000
"""Evaluation seeds start here, far from the training env's seeds (the training env is reset with `--seed`,
then draws its later episodes from its own generator)."""

Policy = Callable[[dict[str, Any]], Any]
"""Observation -> action (an index, or the ALFRED dict form the oracle may give)."""


def observation_kwargs(env_kwargs: dict[str, Any]) -> dict[str, Any]:
    """The options among `env_kwargs` that a trained policy must be evaluated with (`OBSERVATION_OPTIONS`)."""
    return {k: v for k, v in env_kwargs.items() if k in OBSERVATION_OPTIONS}


def make_env(env_id: str, env_kwargs: dict[str, Any] | None = None, *, feedback: bool = False,
             actions: Sequence[str] | None = None, training: bool = False, scene_repeats: int = 1,
             new_place_bonus: float = NEW_PLACE_BONUS) -> gymnasium.Env:
    """The registered id with its instruction as token ids (what SB3's `MultiInputPolicy` takes); with
    `feedback`, the previous action and whether it failed as an observation (`ActionFeedback`); with `actions`
    (names), the agent acts over those actions only (`ActionSubset`); with `training`,
    the failure limit ends an episode as a termination (`FailureLimitEnds`), each scene serves
    `scene_repeats` episodes (`SceneRepeat`) and each grid position first stood on earns `new_place_bonus`
    (`NewPlaceBonus`; 0: none)."""
    env: gymnasium.Env = gymnasium.make(env_id, **(env_kwargs or {}))
    if training:
        env = FailureLimitEnds(SceneRepeat(env, scene_repeats))
        if new_place_bonus:
            env = NewPlaceBonus(env, new_place_bonus)
    env = InstructionTokens(env)
    if actions:
        env = ActionSubset(env, actions)
    limit = int(env.unwrapped.config.max_failures)  # type: ignore[attr-defined]
    return ActionFeedback(env, FEEDBACK_HISTORY, failures=min(limit, 100)) if feedback else env


def _monitored(env_id: str, env_kwargs: dict[str, Any], feedback: bool, actions: Sequence[str] | None,
               scene_repeats: int, new_place_bonus: float) -> gymnasium.Env:
    from stable_baselines3.common.monitor import Monitor

    env = make_env(env_id, env_kwargs, feedback=feedback, actions=actions, training=True, scene_repeats=scene_repeats,
                   new_place_bonus=new_place_bonus)
    return Monitor(env, info_keywords=("success",))


def make_vec_env(env_id: str, env_kwargs: dict[str, Any], n_envs: int, seed: int, *, feedback: bool = False,
                 actions: Sequence[str] | None = None, scene_repeats: int = 1, processes: bool = True,
                 new_place_bonus: float = NEW_PLACE_BONUS) -> Any:
    """`n_envs` monitored training envs, in worker processes (`processes` and more than one env) or in this one."""
    from functools import partial

    from stable_baselines3.common.vec_env import DummyVecEnv, SubprocVecEnv

    makers = [partial(_monitored, env_id, env_kwargs, feedback, actions, scene_repeats, new_place_bonus)
              for _ in range(n_envs)]
    vec = SubprocVecEnv(makers, start_method="fork") if processes and n_envs > 1 else DummyVecEnv(makers)
    vec.seed(seed)
    return vec


def cpu_seconds(pids: Sequence[int] = ()) -> float:
    """CPU time (user + system) of this process and of the live processes `pids` (e.g. a `SubprocVecEnv`'s
    workers), read from `/proc` (Linux; elsewhere, this process only)."""
    total = time.process_time()
    ticks = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100
    for pid in pids:
        try:
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        total += (int(fields[11]) + int(fields[12])) / ticks  # utime, stime (the 14th and 15th fields)
    return total


def worker_pids(vec: Any) -> list[int]:
    """The pids of a (possibly wrapped) `SubprocVecEnv`'s workers; [] for envs in this process."""
    while hasattr(vec, "venv"):
        vec = vec.venv
    return [p.pid for p in getattr(vec, "processes", [])]


def _callback_class() -> type:
    from stable_baselines3.common.callbacks import BaseCallback

    class EpisodeLog(BaseCallback):
        """Collects a curve row per finished episode (with the training's CPU seconds so far, `cpu()`); every
        `save_every` steps saves the model and the curve; stops training once `deadline` (a `time.monotonic()`
        value) has passed or `cpu()` has reached `cpu_budget` (checked every 16 calls)."""

        def __init__(self, rows: list[dict[str, Any]], save: Callable[[], None], save_every: int,
                     deadline: float | None, cpu: Callable[[], float], cpu_budget: float | None = None):
            super().__init__()
            self.rows, self.save, self.save_every, self.deadline = rows, save, save_every, deadline
            self.cpu, self.cpu_budget = cpu, cpu_budget
            self._next_save = save_every
            self._calls = 0

        def _on_step(self) -> bool:
            for info in self.locals["infos"]:
                episode = info.get("episode")
                if episode is not None:
                    self.rows.append({"timesteps": self.num_timesteps, "episode_return": round(float(episode["r"]), 6),
                                      "episode_length": int(episode["l"]), "success": int(bool(episode["success"])),
                                      "cpu_seconds": round(self.cpu(), 1)})
            if self.num_timesteps >= self._next_save:
                self.save()
                self._next_save = self.num_timesteps + self.save_every
            self._calls += 1
            if self.cpu_budget is not None and self._calls % 16 == 0 and self.cpu() >= self.cpu_budget:
                return False
            return self.deadline is None or time.monotonic() < self.deadline

    return EpisodeLog


def write_curve(rows: Sequence[dict[str, Any]], path: Path) -> None:
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=CURVE_FIELDS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    write_atomic(path, buf.getvalue())


def read_curve(path: Path) -> list[dict[str, Any]]:
    with path.open(newline="") as fh:
        return [{"timesteps": int(r["timesteps"]), "episode_return": float(r["episode_return"]),
                 "episode_length": int(r["episode_length"]), "success": int(r["success"]),
                 "cpu_seconds": float(r.get("cpu_seconds") or 0.0)} for r in csv.DictReader(fh)]


def save_model(model: Any, path: Path) -> None:
    """`model.save`, atomically (a reader or a resume never sees half a zip)."""
    buf = io.BytesIO()
    model.save(buf)
    write_atomic(path, buf.getvalue())


def train(env_id: str, out: Path, steps: int, *, seed: int = 0, env_kwargs: dict[str, Any] | None = None,
          ppo_kwargs: dict[str, Any] | None = None, n_envs: int = 1, save_every: int = 5000, resume: bool = False,
          time_budget_s: float | None = None, cpu_budget_s: float | None = None, feedback: bool = True,
          actions: Sequence[str] | None = None,
          normalize_reward: bool = True, scene_repeats: int = 4, processes: bool = True, torch_threads: int | None = 1,
          new_place_bonus: float = NEW_PLACE_BONUS, net: str = "default", warm: WarmStart | None = None,
          critic_warmup: int = 0, verbose: int = 0) -> Any:
    """Train (or go on training) PPO with `MultiInputPolicy` until `steps` timesteps in all, until
    `time_budget_s` seconds of this call have passed, or until the training's CPU time (this process and its env
    workers, every call on this `out` together) reaches `cpu_budget_s`; the model.

    `feedback` adds the previous action and whether it failed to the observation (`ActionFeedback`; evaluate
    with `make_env(..., feedback=True)`); `actions` (names, e.g. `NAVIGATION`) restricts the agent to those
    actions (`ActionSubset`; evaluate with the same); `normalize_reward` scales rewards by a running estimate of the
    return's spread (SB3's `VecNormalize`, rewards only; saved as `vecnormalize.pkl`). Training episodes end
    at the failure limit as terminations (`FailureLimitEnds`), and each training scene serves `scene_repeats`
    episodes with new goals (`SceneRepeat`: a reset in a built world costs about a third of a new scene's).

    `torch_threads` (None: torch's default) is 1 by default: the networks are small and the env's steps take
    most of the time, and on a busy machine torch's intra-op threads spin (PPO took 111 s for 256 steps with
    2 threads against 13 s with 1 on our 2 shared cores).

    `net` names the policy's feature extractor (`nets.NETS`: SB3's default, `goal-depth` or `rgb-depth-goal`).
    With `warm`, the policy first imitates the oracle (`dagger.warm_start`, in this process, its CPU time counted
    in the budget; once per `out`: a resumed run does not repeat it), and for the first `critic_warmup` PPO
    timesteps only the critic learns (the actor and the shared features frozen), so that PPO's first updates do
    not undo the imitation with advantages from an untrained critic.

    Writes `model.zip`, `curve.csv`, `progress.json` (timesteps and CPU seconds so far) and `config.json` under
    `out` (and saves them every `save_every` steps); with `warm`, `warm_start.json` (a row per imitation round)
    and `model_warm.zip` (the policy as imitation left it).
    """
    import stable_baselines3
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.vec_env import VecNormalize

    if torch_threads is not None:
        torch.set_num_threads(torch_threads)
    env_kwargs = dict(TRAIN_KWARGS if env_kwargs is None else env_kwargs)
    ppo_kwargs = {**PPO_DEFAULTS, **(ppo_kwargs or {})}
    out.mkdir(parents=True, exist_ok=True)
    model_path, curve_path, norm_path = out / "model.zip", out / "curve.csv", out / "vecnormalize.pkl"
    progress_path = out / "progress.json"
    resuming = resume and model_path.exists()
    vec = make_vec_env(env_id, env_kwargs, n_envs, seed, feedback=feedback, actions=actions,
                       scene_repeats=scene_repeats, processes=processes, new_place_bonus=new_place_bonus)
    pids = worker_pids(vec)
    if normalize_reward:
        vec = (VecNormalize.load(str(norm_path), vec) if resuming and norm_path.exists()
               else VecNormalize(vec, norm_obs=False, norm_reward=True, gamma=ppo_kwargs["gamma"]))
    if resuming:
        model = PPO.load(model_path, env=vec, device="cpu")
        rows = read_curve(curve_path) if curve_path.exists() else []
        cpu_before = json.loads(progress_path.read_text())["cpu_seconds"] if progress_path.exists() else 0.0
    else:
        from nets import NETS

        extractor = NETS[net]
        policy_kwargs = {} if extractor is None else {"features_extractor_class": extractor}
        model = PPO("MultiInputPolicy", vec, seed=seed, device="cpu", verbose=verbose, policy_kwargs=policy_kwargs,
                    **ppo_kwargs)
        rows, cpu_before = [], 0.0
    config = {"env_id": env_id, "env_kwargs": env_kwargs, "ppo": ppo_kwargs, "policy": "MultiInputPolicy",
              "net": net, "warm_start": asdict(warm) if warm else None, "critic_warmup": critic_warmup,
              "feedback": feedback, "feedback_history": FEEDBACK_HISTORY if feedback else 0,
              "new_place_bonus": new_place_bonus,
              "actions": list(actions) if actions else None,
              "normalize_reward": normalize_reward, "failure_limit_ends": True,
              "scene_repeats": scene_repeats,
              "steps": steps, "seed": seed, "n_envs": n_envs, "processes": bool(pids),
              "stable_baselines3": stable_baselines3.__version__, "torch": torch.__version__,
              "torch_threads": torch.get_num_threads()}
    write_atomic(out / "config.json", json.dumps(config, indent=2) + "\n")
    cpu_start = cpu_seconds(pids)

    def cpu() -> float:
        return cpu_before + cpu_seconds(pids) - cpu_start

    def save() -> None:
        save_model(model, model_path)
        write_curve(rows, curve_path)
        if isinstance(vec, VecNormalize):
            vec.save(str(norm_path))
        write_atomic(progress_path, json.dumps({"timesteps": int(model.num_timesteps),
                                                "cpu_seconds": round(cpu(), 1)}) + "\n")

    warm_path = out / "warm_start.json"
    if warm is not None and not warm_path.exists():
        imitation_env = make_env(env_id, env_kwargs, feedback=feedback, actions=actions, training=True,
                                 scene_repeats=scene_repeats, new_place_bonus=0.0)
        try:
            warm_rows = warm_start(model, imitation_env, warm, seed, cpu)
        finally:
            imitation_env.close()
        save()
        save_model(model, out / "model_warm.zip")  # the imitation alone, to compare PPO's fine-tuning with
        write_atomic(warm_path, json.dumps(warm_rows, indent=2) + "\n")
    remaining = steps - model.num_timesteps
    deadline = None if time_budget_s is None else time.monotonic() + time_budget_s
    if remaining > 0 and (cpu_budget_s is None or cpu() < cpu_budget_s):
        log = _callback_class()(rows, save, save_every, deadline, cpu, cpu_budget_s)
        callbacks = [log] if critic_warmup <= model.num_timesteps else [critic_first(critic_warmup), log]
        model.learn(remaining, callback=callbacks, reset_num_timesteps=False)
    save()
    vec.close()
    return model


@dataclass(frozen=True)
class Outcome:
    """One evaluation episode."""

    seed: int
    success: bool
    episode_return: float
    length: int
    end: str = ""
    """How it ended: `success`, `stop` (Stop before success), `failures` (the failure limit) or `steps`."""


def run_episodes(policy_for: Callable[[gymnasium.Env], Policy], env_id: str, seeds: Sequence[int],
                 env_kwargs: dict[str, Any] | None = None, *, feedback: bool = False,
                 actions: Sequence[str] | None = None) -> list[Outcome]:
    """One episode per seed with the policy `policy_for(env)` gives (observations and actions as `make_env`
    makes them)."""
    env = make_env(env_id, env_kwargs, feedback=feedback, actions=actions)
    limit = env.unwrapped.config.max_failures  # type: ignore[attr-defined]
    policy = policy_for(env)
    out = []
    try:
        for seed in seeds:
            obs, info = env.reset(seed=seed)
            total, n, done = 0.0, 0, False
            while not done:
                obs, reward, terminated, truncated, info = env.step(policy(obs))
                total, n, done = total + float(reward), n + 1, terminated or truncated
            end = ("success" if info["success"] else "stop" if terminated
                   else "failures" if info["failures"] >= limit else "steps")
            out.append(Outcome(seed, bool(info["success"]), round(total, 6), n, end))
    finally:
        env.close()
    return out


def model_policy(model: Any, seed: int = 0, deterministic: bool = False) -> Callable[[gymnasium.Env], Policy]:
    """A trained SB3 model as a policy (sampling from its action distribution, seeded, unless `deterministic`)."""
    def policy_for(env: gymnasium.Env) -> Policy:
        model.set_random_seed(seed)
        return lambda obs: int(model.predict(obs, deterministic=deterministic)[0])
    return policy_for


def random_nav_policy(seed: int) -> Callable[[gymnasium.Env], Policy]:
    """Uniform over the five navigation actions (MoveAhead, RotateLeft, RotateRight, LookUp, LookDown), from a
    seeded generator: a random walk, what wandering alone achieves."""
    from luminous_sim.env.actions import NAVIGATION

    def policy_for(env: gymnasium.Env) -> Policy:
        rng = np.random.default_rng(seed)
        return lambda obs: int(rng.integers(len(NAVIGATION)))
    return policy_for


def oracle_policy() -> Callable[[gymnasium.Env], Policy]:
    """The expert (`OraclePolicy`): what the episode allows at best."""
    from luminous_sim.env import OraclePolicy

    return lambda env: OraclePolicy(env)


def random_policy(seed: int) -> Callable[[gymnasium.Env], Policy]:
    """Uniform over the env's whole action space, from a seeded generator."""
    def policy_for(env: gymnasium.Env) -> Policy:
        rng = np.random.default_rng(seed)
        n = int(env.action_space.n)  # type: ignore[attr-defined]
        return lambda obs: int(rng.integers(n))
    return policy_for


def success_summary(outcomes: Sequence[Outcome]) -> dict[str, Any]:
    """Success rate with its 95% Wilson interval, mean return and length."""
    from scipy.stats import binomtest

    k, n = sum(o.success for o in outcomes), len(outcomes)
    ci = binomtest(k, n).proportion_ci(confidence_level=0.95, method="wilson")
    return {"episodes": n, "successes": k, "success_rate": k / n, "ci95": [round(ci.low, 4), round(ci.high, 4)],
            "mean_return": round(float(np.mean([o.episode_return for o in outcomes])), 4),
            "mean_length": round(float(np.mean([o.length for o in outcomes])), 2),
            "ends": {e: sum(o.end == e for o in outcomes) for e in sorted({o.end for o in outcomes})}}


def plot_curve(rows: Sequence[dict[str, Any]], path: Path, *, window: int = 50,
               references: dict[str, float] | None = None, title: str = "") -> None:
    """Training success rate and return (moving averages over `window` episodes) against timesteps; dashed lines
    for `references` (name -> success rate, e.g. the evaluated random and trained policies)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = np.array([r["timesteps"] for r in rows], float)
    success = np.array([r["success"] for r in rows], float)
    ret = np.array([r["episode_return"] for r in rows], float)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4))
    if len(rows):
        w = max(1, min(window, len(rows) // 5))  # at most a fifth of the episodes, so the curve shows a trend
        kernel = np.ones(w) / w
        ax1.plot(t[w - 1:], np.convolve(success, kernel, "valid"), label=f"training episodes ({w}-episode mean)")
        ax2.plot(t[w - 1:], np.convolve(ret, kernel, "valid"))
    for i, (name, value) in enumerate((references or {}).items()):
        ax1.axhline(value, ls="--", color=f"C{i + 1}", label=name)
    ax1.set(xlabel="timesteps", ylabel="success rate", ylim=(-0.02, 1.02), title="success")
    ax2.set(xlabel="timesteps", ylabel="episode return", title="return")
    ax1.legend(fontsize=8, loc="upper left")
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110)
    plt.close(fig)
    write_atomic(path, buf.getvalue())


def _kwargs(items: Sequence[str]) -> dict[str, Any]:
    out = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise SystemExit(f"env option {item!r}: expected name=value (a TOML value, e.g. max_steps=100)")
        try:
            out[name] = tomllib.loads(f"v = {value}")["v"]
        except tomllib.TOMLDecodeError:
            out[name] = value
    return out


def add_recipe_arguments(p: argparse.ArgumentParser) -> None:
    """The flags of `train`'s network and warm start (shared with `benchmarks/bench_ppo.py`)."""
    p.add_argument("--net", default="default", choices=("default", "goal-depth", "rgb-depth-goal"),
                   help="the policy's feature extractor: SB3's default for a Dict observation, a small CNN over "
                        "goal_mask and depth (`nets.GoalDepthCNN`; needs goal_mask=true), or one over rgb and depth "
                        "told the goal by the instruction (`nets.RgbDepthGoalCNN`; needs depth=true)")
    p.add_argument("--bc-steps", type=int, default=0,
                   help="imitate the oracle for this many labelled steps before PPO (DAgger; 0: no warm start)")
    p.add_argument("--bc-rounds", type=int, default=WarmStart.rounds,
                   help="DAgger rounds (the first follows the expert)")
    p.add_argument("--bc-expert-share", type=float, default=WarmStart.expert_share,
                   help="share of the expert's actions taken in DAgger rounds after the first")
    p.add_argument("--bc-epochs", type=int, default=WarmStart.epochs, help="passes over the labels after each round")
    p.add_argument("--critic-warmup", type=int, default=0,
                   help="PPO timesteps with the actor frozen, only the critic learning (after a warm start)")


def recipe_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """`train`'s keyword arguments from the flags `add_recipe_arguments` adds."""
    warm = WarmStart(args.bc_steps, args.bc_rounds, args.bc_expert_share, args.bc_epochs) if args.bc_steps else None
    return {"net": args.net, "warm": warm, "critic_warmup": args.critic_warmup}


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--env", default=DEFAULT_ENV, help=f"a registered id (default {DEFAULT_ENV})")
    p.add_argument("--steps", type=int, default=20_000, help="training timesteps in all (default 20000)")
    p.add_argument("--out", type=Path, required=True, help="output folder")
    p.add_argument("--seed", type=int, default=0, help="seed of the model and the training env (default 0)")
    p.add_argument("--n-envs", type=int, default=1, help="training envs (more than 1: worker processes)")
    p.add_argument("--env-kwarg", action="append", default=[], metavar="NAME=VALUE",
                   help=f"training env option (repeatable; default {TRAIN_KWARGS})")
    p.add_argument("--eval-kwarg", action="append", default=[], metavar="NAME=VALUE",
                   help="evaluation env option (repeatable; default none: the id as registered)")
    p.add_argument("--ppo", action="append", default=[], metavar="NAME=VALUE", help=f"PPO option ({PPO_DEFAULTS})")
    p.add_argument("--eval-episodes", type=int, default=50, help="held-out episodes per policy (default 50)")
    p.add_argument("--save-every", type=int, default=5000, help="save model and curve every N steps")
    p.add_argument("--resume", action="store_true", help="go on from the model and curve in --out")
    p.add_argument("--cpu-minutes", type=float, default=None,
                   help="stop training when it has used this much CPU time (all its processes, all resumed runs)")
    p.add_argument("--no-feedback", action="store_true", help="leave out the previous action's feedback observation")
    p.add_argument("--actions", default="all", choices=tuple(ACTION_SETS),
                   help="the agent's actions: the env's whole space (default), its five navigation actions, or "
                        "those and Stop (objectnav)")
    p.add_argument("--no-normalize-reward", action="store_true", help="train on the raw rewards")
    p.add_argument("--new-place-bonus", type=float, default=NEW_PLACE_BONUS,
                   help=f"training reward per grid position first stood on (default {NEW_PLACE_BONUS}; 0: none)")
    add_recipe_arguments(p)
    args = p.parse_args(argv)
    if args.steps < 1 or args.eval_episodes < 0 or args.n_envs < 1 or args.save_every < 1:
        p.error("--steps, --n-envs and --save-every must be positive, --eval-episodes >= 0")

    env_kwargs = {**TRAIN_KWARGS, **_kwargs(args.env_kwarg)}
    eval_kwargs = _kwargs(args.eval_kwarg)
    started = time.perf_counter()
    feedback = not args.no_feedback
    actions = ACTION_SETS[args.actions]
    model = train(args.env, args.out, args.steps, seed=args.seed, env_kwargs=env_kwargs,
                  ppo_kwargs=_kwargs(args.ppo), n_envs=args.n_envs, save_every=args.save_every, resume=args.resume,
                  cpu_budget_s=None if args.cpu_minutes is None else args.cpu_minutes * 60, feedback=feedback,
                  normalize_reward=not args.no_normalize_reward, actions=actions, new_place_bonus=args.new_place_bonus,
                  **recipe_kwargs(args))
    train_s = time.perf_counter() - started
    report: dict[str, Any] = {"env_id": args.env, "eval_kwargs": eval_kwargs, "train_seconds": round(train_s, 1),
                              "timesteps": int(model.num_timesteps)}
    if args.eval_episodes:
        seeds = list(range(EVAL_SEED0, EVAL_SEED0 + args.eval_episodes))
        runs = {"random": run_episodes(random_policy(args.seed), args.env, seeds, eval_kwargs),
                "random-nav": run_episodes(random_nav_policy(args.seed), args.env, seeds, eval_kwargs),
                "ppo": run_episodes(model_policy(model, args.seed), args.env, seeds,
                                    {**observation_kwargs(env_kwargs), **eval_kwargs}, feedback=feedback,
                                    actions=actions)}
        report["seeds"] = [seeds[0], seeds[-1]]
        report |= {name: success_summary(o) for name, o in runs.items()}
        report["episodes"] = {name: [asdict(x) for x in o] for name, o in runs.items()}
    write_atomic(args.out / "eval.json", json.dumps(report, indent=2) + "\n")
    refs = {f"{name} (eval)": report[name]["success_rate"] for name in ("random", "random-nav", "ppo")
            if name in report}
    plot_curve(read_curve(args.out / "curve.csv"), args.out / "curve.png", references=refs,
               title=f"PPO MultiInputPolicy on {args.env}")
    print(json.dumps({k: v for k, v in report.items() if k != "episodes"}, indent=2))
    print(f"wrote {args.out}/ (model.zip, curve.csv, curve.png, config.json, eval.json)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    sys.exit(main())
