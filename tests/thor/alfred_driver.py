"""Plays built trials with ALFRED's own, unmodified code (`env/thor_env.py`, `env/tasks.py`,
`models/eval/eval_task.py`) on `luminous_sim.thor`. Run it under the shim:

    python -m luminous_sim.thor --data BUILD tests/thor/alfred_driver.py --alfred MIRROR --mode eval --out R.jsonl

MIRROR is ALFRED's code folder as `alfred_code.mirror` lays it out. One JSON line per trial and mode goes to
`--out`: what ALFRED's code judged (`satisfied`, `alfred_gc`), what our own judge says of the same final
state (`our_gc`), the failed actions, steps and seconds.

Modes:
- `eval`: ALFRED's `EvalTask.evaluate` with a stand-in model that replays the trial's low-level actions
  (masks decompressed, as a model's predicted masks) and a stand-in feature extractor.
- `va`: `reset`, `restore_scene`, `step(init_action)`, `set_task(traj, args, reward_type='dense')`, then each
  low-level action through `va_interact(action, interact_mask=mask)`, the reward taken after each.
- `api`: the same set-up, then each recorded `api_action` through `env.step` (ALFRED's data-tool replay).
- `smooth`: as `va` with `smooth_nav=True` (va_interact's default).
- `negatives`: the first trial of `--negatives-type` (else the first): its actions up to its last
  interaction (judged: `cut`), then that interaction with its mask moved onto another interactable object
  in view (judged: `moved`).
- `spawn`: a process started with the `spawn` method imports `ai2thor.controller`; reports its module.
"""

from __future__ import annotations

import argparse
import glob
import json
import multiprocessing as mp
import os
import sys
import threading
import time
import types
from typing import Any

import numpy as np


def _child(queue: Any) -> None:
    import ai2thor.controller

    queue.put(ai2thor.controller.Controller.__module__)


def _setup(env: Any, traj: dict[str, Any], args: Any) -> None:
    scene = traj["scene"]
    env.reset(f"FloorPlan{scene['scene_num']}")
    env.restore_scene(scene["object_poses"], scene["object_toggles"], scene["dirty_and_empty"])
    env.step(dict(scene["init_action"]))
    env.set_task(traj, args, reward_type="dense")


def _mask(env: Any, action: dict[str, Any]) -> np.ndarray | None:
    args = action["discrete_action"]["args"]
    return env.decompress_mask(args["mask"]) if "mask" in args else None


def _our_gc(env: Any, trial: str) -> list[int]:
    from luminous_sim.tasks import TaskInstance

    with open(os.path.join(trial, "luminous.json")) as fh:
        task = TaskInstance.from_dict(json.load(fh)["task"])
    world = env.world
    done, total = task.conditions().alfred_counts(world.view().state, set(world.visible_objects()))
    return [int(done), int(total)]


class ReplayModel:
    """A stand-in for a trained model in ALFRED's evaluation: it predicts the trial's own actions and masks."""

    def __init__(self, traj: dict[str, Any], decompress: Any):
        self.actions = traj["plan"]["low_actions"]
        self.decompress = decompress
        self.t = 0

    def reset(self) -> None:
        self.t = 0

    def featurize(self, batch: list[Any], load_mask: bool = False) -> dict[str, Any]:
        return {}

    def step(self, feat: dict[str, Any]) -> int:
        self.t += 1
        return self.t - 1

    def extract_preds(self, out: int, batch: list[Any], feat: dict[str, Any],
                      clean_special_tokens: bool = False) -> dict[str, Any]:
        if out >= len(self.actions):
            return {"pred": {"action_low": "<<stop>>", "action_low_mask": [None]}}
        a = self.actions[out]
        args = a["discrete_action"]["args"]
        mask = self.decompress(args["mask"])[None] if "mask" in args else np.zeros((1, 300, 300))
        return {"pred": {"action_low": a["discrete_action"]["action"], "action_low_mask": [mask]}}

    def has_interaction(self, action: str) -> bool:
        return action not in ("MoveAhead_25", "RotateLeft_90", "RotateRight_90", "LookUp_15", "LookDown_15",
                              "<<stop>>", "<<pad>>", "<<seg>>")


class FeatureStandIn:
    """A stand-in for ALFRED's ResNet feature extractor (the replaying model ignores the features)."""

    def featurize(self, images: list[Any], batch: int = 32) -> Any:
        import torch

        return torch.zeros(len(images), 512, 7, 7)


def _eval_task() -> Any:
    """ALFRED's EvalTask, its two uninstallable imports stood in: `models.nn.resnet` (needs torchvision) and
    `data.preprocess` (needs revtok, progressbar, vocab and ALFRED's models/model/seq2seq.py, not shipped).
    Both are used only by `Eval.__init__` (loading a checkpoint), which the loop below does not call."""
    for name, attr in (("models.nn.resnet", "Resnet"), ("data.preprocess", "Dataset")):
        stand_in = types.ModuleType(name)
        setattr(stand_in, attr, None)
        sys.modules[name] = stand_in
    from eval_task import EvalTask  # models/eval on sys.path

    return EvalTask


def run_trial(env: Any, mode: str, trial: str, args: Any) -> dict[str, Any]:
    with open(os.path.join(trial, "traj_data.json")) as fh:
        traj = json.load(fh)
    failures: list[str] = []
    start = time.perf_counter()
    steps = len(traj["plan"]["low_actions"])
    row: dict[str, Any] = {"trial": trial, "task_type": traj["task_type"], "mode": mode, "steps": steps}
    if mode == "eval":
        evaluate = _eval_task().evaluate
        traj = {**traj, "root": trial, "repeat_idx": 0}
        successes: list[dict[str, Any]] = []
        failed: list[dict[str, Any]] = []
        results: dict[str, Any] = {}
        evaluate(env, ReplayModel(traj, env.decompress_mask), 0, FeatureStandIn(), traj, args, threading.Lock(),
                 successes, failed, results)
        entry = (successes or failed)[0]
        row.update(satisfied=bool(successes), alfred_gc=[entry["completed_goal_conditions"],
                                                         entry["total_goal_conditions"]],
                   our_gc=_our_gc(env, trial), entry=entry)
    elif mode in ("va", "api", "smooth"):
        _setup(env, traj, args)
        for a in traj["plan"]["low_actions"]:
            if mode == "api":
                event = env.step(dict(a["api_action"]))
                ok, err = event.metadata["lastActionSuccess"], event.metadata["errorMessage"]
            else:
                ok, _, _, err, _ = env.va_interact(a["discrete_action"]["action"], interact_mask=_mask(env, a),
                                                   smooth_nav=mode == "smooth")
            if not ok:
                failures.append(f"{a['discrete_action']['action']}: {err}")
            env.get_transition_reward()
        done, total = env.get_goal_conditions_met()
        row.update(satisfied=bool(env.get_goal_satisfied()), alfred_gc=[int(done), int(total)],
                   our_gc=_our_gc(env, trial))
    elif mode == "negatives":
        _setup(env, traj, args)
        low = traj["plan"]["low_actions"]
        last = max(i for i, a in enumerate(low) if "mask" in a["discrete_action"]["args"])
        for a in low[:last]:
            ok, _, _, err, _ = env.va_interact(a["discrete_action"]["action"], interact_mask=_mask(env, a),
                                               smooth_nav=False)
            if not ok:
                failures.append(f"{a['discrete_action']['action']}: {err}")
        row["cut"] = {"satisfied": bool(env.get_goal_satisfied()),
                      "alfred_gc": [int(v) for v in env.get_goal_conditions_met()]}
        action = low[last]
        target = action["api_action"].get("receptacleObjectId") or action["api_action"]["objectId"]
        event = env.last_event
        held = [o["objectId"] for o in event.metadata["inventoryObjects"]]
        interactable = {o["objectId"] for o in event.metadata["objects"]
                        if o["pickupable"] or o["receptacle"] or o["openable"] or o["toggleable"] or o["sliceable"]}
        others = sorted((int(m.sum()), oid) for oid, m in event.instance_masks.items()
                        if oid in interactable and oid != target and oid not in held)
        if others:  # the largest other interactable object in view
            moved_to = others[-1][1]
            moved = event.instance_masks[moved_to].astype(int)
        else:  # nothing else to interact with in view: every pixel but the target's
            moved_to = "(no other object in view: every pixel off the target)"
            moved = (~event.instance_masks[target]).astype(int)
        ok, _, hit, err, _ = env.va_interact(action["discrete_action"]["action"], interact_mask=moved,
                                             smooth_nav=False)
        row["moved"] = {"to": moved_to, "target": target, "hit": hit, "action_success": bool(ok), "error": str(err),
                        "satisfied": bool(env.get_goal_satisfied()),
                        "alfred_gc": [int(v) for v in env.get_goal_conditions_met()]}
    elif mode == "spawn":
        ctx = mp.get_context("spawn")
        queue = ctx.Queue()
        proc = ctx.Process(target=_child, args=(queue,))
        proc.start()
        row["child_module"] = queue.get(timeout=120)
        proc.join()
    row.update(failures=failures, seconds=round(time.perf_counter() - start, 3))
    return row


def _first_of(trials: list[str], task_type: str) -> list[str]:
    typed = [t for t in trials if os.path.basename(os.path.dirname(t)).startswith(task_type + "-")]
    return (typed or trials)[:1]


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--alfred", required=True, help="ALFRED's code folder (alfred_code.mirror's layout)")
    p.add_argument("--mode", action="append", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--negatives-type", default="pick_and_place_simple",
                   help="the negative controls use the first trial of this task type (else the first trial)")
    p.add_argument("--trials", nargs="*", default=None, help="trial folders (default: every one in the data)")
    ns = p.parse_args()
    sys.path[:0] = [ns.alfred, os.path.join(ns.alfred, "gen"), os.path.join(ns.alfred, "models", "eval")]
    from env.thor_env import ThorEnv

    args = types.SimpleNamespace(reward_config=os.path.join(ns.alfred, "models", "config", "rewards.json"),
                                 max_steps=1000, max_fails=10, smooth_nav=False, debug=False)
    trials = ns.trials
    if trials is None:
        roots = os.environ["LUMINOUS_ALFRED_DATA"].split(os.pathsep)
        trials = sorted(os.path.dirname(t) for r in roots for t in glob.glob(os.path.join(r, "*", "*", "*",
                                                                                       "traj_data.json")))
    env = ThorEnv()
    with open(ns.out, "a") as out:
        for mode in ns.mode:
            for trial in _first_of(trials, ns.negatives_type) if mode in ("negatives", "spawn") else trials:
                try:
                    row = run_trial(env, mode, trial, args)
                except Exception as exc:  # a crash is a finding: recorded with its cause, the sweep goes on
                    row = {"trial": trial, "mode": mode, "crash": f"{type(exc).__name__}: {exc}"}
                out.write(json.dumps(row, default=str) + "\n")
                out.flush()
    env.stop()


if __name__ == "__main__":
    main()
