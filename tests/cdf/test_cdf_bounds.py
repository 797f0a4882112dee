"""Issue 27: a CDF's sizes are bounded (limits.MAX_CDF_INSTANCES, MAX_CDF_RELATIONS, MAX_CDF_STEPS, the
longest side), checked before validation and generation, with one line naming the file and key path."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from luminous_sim.cdf import CDFValidationError, ChallengeDefinition, from_document, load
from luminous_sim.cdf.bounds import document_issues
from luminous_sim.cli.main import main
from luminous_sim.limits import MAX_CDF_INSTANCES, MAX_CDF_RELATIONS, MAX_CDF_STEPS
from tests.cdf.helpers import base


def _apples(counts: list[int]) -> dict[str, Any]:
    return {"cdf_version": 2, "scene": {"room_type": "Kitchen",
                                        "objects": [{"name": f"a{i}", "type": "Apple", "count": c}
                                                    for i, c in enumerate(counts)]}}


def _write(tmp_path: Path, doc: dict[str, Any]) -> Path:
    path = tmp_path / "big.yaml"
    path.write_text(yaml.safe_dump(doc))
    return path


def test_the_issues_100000_instances_are_refused_naming_the_file_and_count(tmp_path: Path) -> None:
    path = _write(tmp_path, _apples([50] * 2000))
    with pytest.raises(CDFValidationError) as info:
        load(path)
    first = MAX_CDF_INSTANCES // 50  # objects 0..20 hold 1,050 instances
    assert str(info.value) == (
        f"{path}: scene.objects[{first}].count: scene.objects[0..{first}] ask for {(first + 1) * 50} object "
        f"instances; a CDF may ask for at most {MAX_CDF_INSTANCES} in all (luminous_sim.limits.MAX_CDF_INSTANCES)")


def test_exactly_the_limit_is_accepted() -> None:
    cdf = from_document(_apples([50] * (MAX_CDF_INSTANCES // 50)))
    assert sum(o.count for o in cdf.scene.objects) == MAX_CDF_INSTANCES


def test_a_document_built_in_code_is_checked_too() -> None:
    """model_validate (not from_document) still meets the bound: validate.check runs it first."""
    with pytest.raises(CDFValidationError) as info:
        ChallengeDefinition.model_validate(_apples([50] * 20 + [1]), context={"source": "code.yaml"})
    assert str(info.value).startswith("code.yaml: scene.objects[20].count: scene.objects[0..20] ask for 1001")


def test_too_many_relations_and_steps_are_refused() -> None:
    doc = base()
    doc["scene"]["relations"] = [{"subject": "chair", "relation": "near", "target": "fridge"}] * (MAX_CDF_RELATIONS + 1)
    doc["execution"] = [{"action": "MoveAhead"}] * (MAX_CDF_STEPS + 1)
    with pytest.raises(CDFValidationError) as info:
        from_document(doc, "many.yaml")
    paths = [i.path for i in info.value.issues]
    assert paths == [f"scene.relations[{MAX_CDF_RELATIONS}]", f"execution[{MAX_CDF_STEPS}]"]
    assert "luminous_sim.limits.MAX_CDF_RELATIONS" in str(info.value)
    assert "luminous_sim.limits.MAX_CDF_STEPS" in str(info.value)


@pytest.mark.parametrize(("where", "value", "path"), [
    ("size", {"width": 100, "depth": 1, "height": 1}, "scene.objects[2].attributes.size.width"),
    ("size", {"width": 1, "depth": 1, "height": 1e300}, "scene.objects[2].attributes.size.height"),
    ("room", {"min_area": 1e9}, "scene.room.min_area"),
    ("room", {"max_width": 31}, "scene.room.max_width"),
])
def test_sizes_are_bounded(where: str, value: Any, path: str) -> None:
    doc = base()
    if where == "size":
        doc["scene"]["objects"][2]["attributes"] = {"size": value}
    else:
        doc["scene"]["room"] = value
    with pytest.raises(CDFValidationError) as info:
        from_document(doc, "k.yaml")
    assert str(info.value).startswith(f"k.yaml: {path}: expected less than or equal to")


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(min_value=1, max_value=50), max_size=60))
def test_the_bound_is_the_sum_of_counts(counts: list[int]) -> None:
    issues = document_issues(_apples(counts))
    over = sum(counts) > MAX_CDF_INSTANCES
    assert bool(issues) == over
    if over:
        crossing = next(i for i in range(len(counts)) if sum(counts[: i + 1]) > MAX_CDF_INSTANCES)
        assert issues[0].path == f"scene.objects[{crossing}].count"


@settings(max_examples=30, deadline=None)
@given(st.recursive(st.none() | st.integers() | st.text(max_size=3) | st.booleans(),
                    lambda kids: st.lists(kids, max_size=3) | st.dictionaries(st.sampled_from(
                        ["scene", "objects", "count", "relations", "execution"]), kids, max_size=3), max_leaves=20))
def test_document_issues_never_fails_on_any_shape(doc: Any) -> None:
    assert document_issues(doc) == [] or all(i.path for i in document_issues(doc))


@pytest.mark.parametrize("command", [["cdf", "validate"], ["generate", "--no-physics", "--out", "OUT", "--cdf"],
                                     ["run", "--out", "OUT", "--cdf"]])
def test_commands_refuse_it_in_one_line(command: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = _write(tmp_path, _apples([50] * 2000))
    argv = [str(tmp_path / "out") if a == "OUT" else a for a in command] + [str(path)]
    try:
        code = main(argv)
    except SystemExit as exc:
        code = int(exc.code or 0)
    err = capsys.readouterr().err
    assert code == 2, err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and f"{path}: scene.objects[20].count" in lines[0] and "Traceback" not in err
