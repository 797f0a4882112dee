"""The freeze that drew the splits: a layout whose oracle keeps failing gives up and passes its share on, the
counts are met, and an interrupted freeze goes on from its checkpoint."""

from __future__ import annotations

from typing import Any

import pytest

from luminous_sim.benchmark import type_counts
from luminous_sim.benchmark.counts import type_layouts
from luminous_sim.episodes import freeze as freeze_module
from luminous_sim.episodes.freeze import ORACLE_FAILURES_IN_A_ROW, Capacity, Stream, freeze, run_stream
from luminous_sim.vocab import ALFRED_TASK_TYPES


def test_a_layout_whose_oracle_keeps_failing_gives_up(monkeypatch):
    monkeypatch.setattr(freeze_module, "oracle_cause", lambda scene, drawn: "not_visible")
    layout = type_layouts("U+", "pick_and_place_simple")[0]
    out = run_stream("U+", "pick_and_place_simple", layout, 3)
    assert out.gave_up and out.exhausted and not out.entries
    assert out.rejected["oracle"] >= ORACLE_FAILURES_IN_A_ROW


def _fake_stream(calls: list[tuple[str, str]], broken: str = ""):
    def run(split: str, task_type: str, layout: Any, need: int) -> Stream:
        calls.append((task_type, layout.name))
        if task_type == broken:
            raise RuntimeError("killed")
        out = Stream(task_type, layout, need)
        first = type_layouts(split, task_type)[0]
        if layout == first:   # this layout gives up at once: its share goes to the others
            out.gave_up = True
            return out
        out.entries = [{"task_type": task_type, "floor_plan": layout.floor_plan, "room_type": layout.room_type,
                        "layout": layout.layout, "layout_seed": layout.layout_seed, "draw": k, "task_seed": k,
                        "pddl_params": {}, "start": [0.0, 0.0, 0, 30], "repeat": False,
                        "episode_key": f"{task_type}-{layout.name}-{k}"} for k in range(need)]
        return out
    return run


def test_shortfalls_pass_on_and_an_interrupted_freeze_resumes(monkeypatch, tmp_path):
    monkeypatch.setattr(freeze_module, "capacity", lambda t, lay: Capacity(t, lay, 50))
    calls: list[tuple[str, str]] = []
    checkpoint = tmp_path / "U+.jsonl.partial"
    monkeypatch.setattr(freeze_module, "run_stream", _fake_stream(calls, broken=ALFRED_TASK_TYPES[2]))
    with pytest.raises(RuntimeError, match="killed"):
        freeze("U+", checkpoint=checkpoint, log=lambda m: None)
    assert checkpoint.is_file()
    calls.clear()
    monkeypatch.setattr(freeze_module, "run_stream", _fake_stream(calls))
    said: list[str] = []
    manifest = freeze("U+", checkpoint=checkpoint, log=said.append)
    assert {t for t, _ in calls} == set(ALFRED_TASK_TYPES[2:]), "the two finished types come from the checkpoint"
    assert sum("from the checkpoint" in m for m in said) == 2
    header = manifest["header"]
    assert header["counts"] == type_counts("U+") and header["entries"] == 435
    assert all(s["layouts_given_up"] for t, s in header["stats"].items() if t not in ALFRED_TASK_TYPES[:2])
    assert [e["index"] for e in manifest["entries"]] == list(range(435))
