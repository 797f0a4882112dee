"""The top of report.json says whether a scene satisfies its CDF: an object the CDF names that was not placed
makes it not, and the console says so (`luminous generate`); objects the CDF does not name are listed apart."""

from __future__ import annotations

from types import SimpleNamespace

from luminous_sim.cssg import LayoutReport
from luminous_sim.scene_outputs import cdf_summary, summary_lines


def _generated(unplaced: list[str], required: list[str]) -> SimpleNamespace:
    return SimpleNamespace(report=LayoutReport(attempt=0, unplaced=unplaced, required=required, reachable_points=40))


def test_an_unplaced_object_the_cdf_names_means_the_scene_does_not_satisfy_it():
    summary = cdf_summary(_generated(["mug", "Chair_2"], ["mug"]))
    assert summary == {"satisfies_cdf": False, "unplaced_named_by_cdf": ["mug"], "unplaced_others": ["Chair_2"]}
    lines = summary_lines("out/x", summary)
    assert lines[0].startswith("warning: out/x: the scene does NOT satisfy its CDF (objects it names were not "
                               "placed: mug")
    assert lines[1] == "note: out/x: 1 other object(s) left out: Chair_2"


def test_a_scene_with_every_named_object_placed_satisfies_it():
    summary = cdf_summary(_generated(["Chair_2"], ["mug"]))
    assert summary["satisfies_cdf"] and summary["unplaced_named_by_cdf"] == []
    assert [line for line in summary_lines("x", summary) if line.startswith("warning")] == []


def test_generate_writes_the_summary_at_the_top_of_report_json(tmp_path):
    import json

    from luminous_sim.cli.main import main

    out = tmp_path / "scene"
    assert main(["generate", "--cdf", "cdf/examples/kitchen_apple_fridge.yaml", "--seed", "0", "--out", str(out),
                 "--no-physics"]) == 0
    report = json.loads((out / "report.json").read_text())
    assert list(report)[:3] == ["satisfies_cdf", "unplaced_named_by_cdf", "unplaced_others"]
    assert report["satisfies_cdf"] is True and report["unplaced_named_by_cdf"] == []
    assert "collision" not in report["measures"] and report["measures"]["walkable_rate"] > 0.9  # no physics: no meshes


def test_a_type_the_library_lacks_is_named_before_any_layout_is_drawn():
    import pytest

    from luminous_sim import cdf
    from luminous_sim.assets.catalog import Catalog, default_catalog
    from luminous_sim.cssg import generate
    from luminous_sim.errors import AssetError

    doc = cdf.load("cdf/examples/kitchen_apple_fridge.yaml")
    without_apples = Catalog([e for e in default_catalog() if e.type != "Apple"])
    want = (r"scene.objects\[\d+\] \(.*\): the asset library has no asset of type Apple \(looked in .*urdf_assets\)"
            r".*luminous assets import MESH --type Apple")
    with pytest.raises(AssetError, match=want):
        generate(doc, seed=0, catalog=without_apples)
