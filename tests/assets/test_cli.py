"""`luminous assets list|sheet`: the catalog as JSON and a contact sheet people can look at."""

from __future__ import annotations

import json

import numpy as np
from PIL import Image

from luminous_sim.assets.catalog import Catalog
from luminous_sim.cli.main import main


def test_list_json_is_the_catalog(capsys, monkeypatch, tmp_path):
    monkeypatch.setenv("LUMINOUS_USER_ASSETS", str(tmp_path / "none"))
    assert main(["assets", "list", "--json"]) == 0
    listed = json.loads(capsys.readouterr().out)
    catalog = Catalog.load(include_user=False)
    assert [e["id"] for e in listed] == [e.id for e in catalog]
    mug = next(e for e in listed if e["type"] == "Mug")
    assert mug["abilities"]["movable_receptacle"] and mug["regions"] and mug["files"]


def test_sheet_renders_labelled_thumbnails(tmp_path):
    out = tmp_path / "sheet.png"
    assert main(["assets", "sheet", "--out", str(out), "--types", "Apple", "Chair", "--tile", "96"]) == 0
    img = np.asarray(Image.open(out).convert("RGB"))
    n = len(Catalog.load().of_type("Apple")) + len(Catalog.load().of_type("Chair"))
    assert img.shape[0] >= 96 and img.shape[1] * img.shape[0] >= n * 96 * 96
    assert img.std() > 20, "thumbnails should show something, not a blank sheet"


def test_sheet_with_no_match_is_a_clear_error(tmp_path, capsys):
    assert main(["assets", "sheet", "--out", str(tmp_path / "x.png"), "--types", "Unicorn"]) == 2
    assert "no assets match" in capsys.readouterr().err
