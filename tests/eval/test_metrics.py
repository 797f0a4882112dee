"""ALFRED's metrics (spec section 5.1) on a hand-made set of episodes, each value worked out by hand, and
the Table 4-style table over them."""

from __future__ import annotations

import pytest

from luminous_sim.errors import LuminousError
from luminous_sim.eval import EpisodeOutcome, metrics, metrics_by_type, type_average
from luminous_sim.eval.report import markdown_table

PICK, HEAT = "pick_and_place_simple", "pick_heat_then_place_in_recep"


def outcome(index: int, task_type: str, end: str, gc: tuple[int, int], steps: int, expert: int,
            **extra) -> EpisodeOutcome:
    return EpisodeOutcome("U+", index, task_type, "FloorPlan10", 0, end, success=end == "success",
                          goal_conditions=gc, steps=steps, expert_length=expert, **extra)


EPISODES = [
    outcome(0, PICK, "success", (1, 1), steps=10, expert=10),      # w = 1
    outcome(1, PICK, "max_failures", (0, 1), steps=20, expert=5),  # w = 5/20
    outcome(2, HEAT, "success", (3, 3), steps=40, expert=20),      # w = 20/40
    outcome(3, HEAT, "stop", (2, 3), steps=5, expert=30),          # w = min(1, 30/5) = 1
    EpisodeOutcome("U+", 4, HEAT, "FloorPlan10", 1, "unavailable", cause="no_task", detail="no Microwave"),
]


def alfred_form(episodes):
    """ALFRED's eval_task.py, line by line: s_spl = s * min(1, L/t), pc_spl = gc * min(1, L/t), weighted by L."""
    drawn = [e for e in episodes if e.drawn]
    plw_s = sum((1 if e.success else 0) * min(1.0, e.expert_length / float(e.steps)) * e.expert_length
                for e in drawn)
    plw_pc = sum(e.goal_conditions[0] / float(e.goal_conditions[1]) * min(1.0, e.expert_length / float(e.steps))
                 * e.expert_length for e in drawn)
    total = sum(e.expert_length for e in drawn)
    return plw_s / total, plw_pc / total


def test_overall_metrics_by_hand():
    m = metrics(EPISODES)
    assert (m.entries, m.episodes, m.successes) == (5, 4, 2)
    assert m.sr == pytest.approx(2 / 4)
    assert m.gc == pytest.approx((1 + 0 + 3 + 2) / (1 + 1 + 3 + 3))   # micro-average: 6/8, not mean(1, 0, 1, 2/3)
    assert m.plw_sr == pytest.approx((1 * 10 + 0 + 0.5 * 20 + 0) / (10 + 5 + 20 + 30))
    assert m.plw_gc == pytest.approx((1 * 1 * 10 + 0 + 1 * 0.5 * 20 + (2 / 3) * 1 * 30) / 65)   # 40/65
    assert m.sr_all == pytest.approx(2 / 5)   # the undrawn entry counts as a failure of the population
    assert (m.plw_sr, m.plw_gc) == pytest.approx(alfred_form(EPISODES))


def test_per_type_metrics_by_hand():
    per = metrics_by_type(EPISODES)
    assert list(per) == [PICK, HEAT]   # ALFRED's order, types present only
    pick, heat = per[PICK], per[HEAT]
    assert (pick.sr, pick.gc, pick.plw_sr, pick.plw_gc, pick.sr_all) == pytest.approx((0.5, 0.5, 10 / 15, 10 / 15, 0.5))
    assert (heat.entries, heat.episodes) == (3, 2)
    assert (heat.sr, heat.gc) == pytest.approx((0.5, 5 / 6))
    assert (heat.plw_sr, heat.plw_gc) == pytest.approx((10 / 50, 30 / 50))
    assert heat.sr_all == pytest.approx(1 / 3)
    assert type_average(per, "sr") == pytest.approx(0.5) and type_average(per, "gc") == pytest.approx((0.5 + 5 / 6) / 2)


def test_no_drawn_episode_gives_no_metric_rather_than_zero():
    m = metrics([EPISODES[-1]])
    assert (m.sr, m.gc, m.plw_sr, m.plw_gc) == (None, None, None, None) and m.sr_all == 0.0
    assert metrics([]).sr_all is None


def test_a_stop_at_the_start_is_weighted_like_the_papers_form():
    stopped = outcome(9, PICK, "stop", (0, 1), steps=0, expert=7)
    assert stopped.path_weight == 1.0 and metrics([stopped]).plw_gc == 0.0


@pytest.mark.parametrize("bad", [
    {"end": "finished"},
    {"goal_conditions": (2, 1)},
    {"goal_conditions": (0, 0)},
    {"expert_length": 0},
])
def test_inconsistent_outcomes_are_refused(bad):
    fields = {"end": "stop", "goal_conditions": (0, 1), "steps": 3, "expert_length": 4, **bad}
    with pytest.raises(LuminousError):
        EpisodeOutcome("U+", 0, PICK, "FloorPlan10", 0, **fields)


def test_outcomes_round_trip_through_json_data():
    for e in EPISODES:
        assert EpisodeOutcome.from_dict(e.to_dict()) == e


def test_table_has_table4_rows_and_notes_undrawn_entries():
    from luminous_sim.eval import EvalReport

    report = EvalReport("oracle", "U+", 0, {}, tuple(EPISODES))
    table = markdown_table([report])
    rows = [ln.split("|")[1].strip() for ln in table.splitlines() if ln.startswith("| ") and "---" not in ln]
    assert rows == ["Task", "Pick", "Cool", "Stack", "Heat", "Clean", "Examine", "Pick Two", "Average", "**All**"]
    heat = next(ln for ln in table.splitlines() if ln.startswith("| Heat "))
    assert heat.split("|")[2:8] == [" 2/3 ", " .500 ", " .833 ", " .200 ", " .600 ", " .333 "]
    assert "1 of 5 entries had no episode (no_task: 1)" in table
