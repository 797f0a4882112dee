"""ALFWorld's own code (`alfworld==0.4.2`, the test extra: a client, never imported by the package) on a
build's `initial_state.pddl`: its generator makes and solves the games, its `AlfredTWEnv` loads them and its
hand-coded expert wins each one there, as its planner expert does on a sample (`benchmarks/bench_alfworld.py`);
its demangler names every object as `text.names_of` does; a goal no room can meet is found unsolvable (the
negative control)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from tests.conftest import UPLUS_BUILT, load_script

alfworld = pytest.importorskip("alfworld", reason="ALFWorld is in the test extra (make test installs it)")


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_alfworld.py")


@pytest.fixture(scope="module")
def played(bench, uplus_build, tmp_path_factory):
    games = tmp_path_factory.mktemp("games")
    return bench.measure(uplus_build, games, ["U+"], planner_sample=3, jobs=2), games  # two generator ranges


def test_every_playable_trial_is_solved_and_won_in_alfworlds_own_env(played):
    result, _ = played
    got = result["splits"]["U+"]
    entries = sum(row["entries"] for row in got["types"].values())
    assert entries == UPLUS_BUILT
    causes = {cause for per in got["causes"].values() for cause in per}
    # the shared build has one trial of each type; ALFWorld skips the sliced and movable ones, nothing else
    assert causes <= {"skipped by ALFWorld (sliced object)", "skipped by ALFWorld (movable)"}, got["causes"]
    skipped = sum(n for per in got["causes"].values() for n in per.values())
    assert got["games_played"] == UPLUS_BUILT - skipped >= 4
    assert sum(row["won"] for row in got["types"].values()) == got["games_played"]
    assert got["planner_sample"] == {"games": 3, "won": 3}  # ALFWorld's planner expert (Fast Downward) too


def test_alfworlds_demangler_names_every_object_as_ours(played, uplus_build):
    import textworld
    from alfworld.agents.environment.alfred_tw_env import AlfredDemangler
    from textworld.envs import PddlEnv

    from luminous_sim.text import names_of

    _, games = played
    checked = 0
    for sidecar in sorted((uplus_build / "U+").glob("*/*/luminous.json")):
        game = games / "U+" / sidecar.parent.relative_to(uplus_build / "U+") / "game.tw-pddl"
        if not game.is_file():
            continue
        env = AlfredDemangler(PddlEnv(textworld.EnvInfos(facts=True)), shuffle=False)
        env.load(str(game))
        theirs = {info.id: info.name for info in env._entity_infos.values()}
        ids = json.loads(sidecar.read_text())["alfworld"]["ids"]
        problem = (sidecar.parent / "initial_state.pddl").read_text()
        locations = {p.split(" - ")[0].strip() for p in problem.splitlines() if p.endswith(" - location")}
        ours = names_of({**ids, **{lo: lo for lo in locations}})
        for oid, pddl in ids.items():
            assert theirs[pddl.lower()].strip() == ours[oid], (oid, theirs[pddl.lower()], ours[oid])
            checked += 1
    assert checked > 100


def test_a_goal_no_room_meets_is_unsolvable(bench, uplus_build, tmp_path):
    trial = next(p.parent for p in sorted((uplus_build / "U+").glob("pick_cool*/*/initial_state.pddl")))
    build = tmp_path / "build"
    copy = build / "U+" / trial.parent.name / trial.name
    shutil.copytree(trial, copy)
    problem = (copy / "initial_state.pddl").read_text()
    goal = problem.split("(:goal")[1]
    parent = goal.split("(receptacleType ?r ")[1].split(")")[0]
    (copy / "initial_state.pddl").write_text(problem.replace(f"(receptacleType ?r {parent})",
                                                             "(receptacleType ?r SafeType)"))
    games = tmp_path / "games"
    bench.generate(build, games, "U+")
    made = json.loads((games / "U+" / trial.parent.name / trial.name / "game.tw-pddl").read_text())
    assert made["solvable"] is False
    assert bench.play(games / "U+") == {}  # AlfredTWEnv loads only solvable games


def test_the_games_carry_the_trials_own_goal_text(played):
    _, games = played
    grammars = [json.loads(p.read_text())["grammar"] for p in Path(games).rglob("game.tw-pddl")]
    assert grammars and all("UNKNOWN GOAL" not in g for g in grammars)
