"""The room library: names, loading, user folders, procedural names and path-traversal safety."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.errors import RoomError
from luminous_sim.rooms.generate import generate_shell
from luminous_sim.rooms.library import (
    ENV_VAR,
    PROCEDURAL,
    SHIPPED_DIR,
    has_room,
    load_room,
    room_names,
    room_path,
    shell_for,
)
from luminous_sim.rooms.shell import load_shell, save_shell

BAD_NAMES = [
    "../x",
    "/etc/passwd",
    "a/b",
    "",
    "..",
    "FloorPlan1.json",
    "a\\b",
    "x y",
    "~root",
    "FloorPlan1\x00",
]


def test_shipped_folder_is_the_repository_cdf_rooms():
    assert SHIPPED_DIR.name == "rooms" and SHIPPED_DIR.parent.name == "cdf"
    assert (SHIPPED_DIR / "alfred").is_dir()


def test_names_list_files_then_procedural():
    names = room_names()
    assert names[:3] == ["FloorPlan1", "FloorPlan2", "FloorPlan3"]
    assert "FloorPlan430" in names and "splits" not in names
    assert {"kitchen_rect", "bedroom_L", "living_room_two_zone", "bathroom"} <= set(names)
    assert set(room_names(include_procedural=False)).isdisjoint(PROCEDURAL)


def test_load_room_round_trip():
    shell = load_room("FloorPlan1")
    assert shell.name == "FloorPlan1" and shell.room_type == "Kitchen"
    assert shell == load_shell(room_path("FloorPlan1"))
    assert room_path("FloorPlan1") == (SHIPPED_DIR / "alfred" / "FloorPlan1.json").resolve()
    assert has_room("FloorPlan1") and has_room("kitchen_L") and not has_room("FloorPlan999")


@pytest.mark.parametrize("name", BAD_NAMES)
def test_path_traversal_rejected(name):
    assert not has_room(name)
    for fn in (load_room, room_path, lambda n: shell_for(n, np.random.default_rng(0))):
        with pytest.raises(RoomError, match="invalid room name"):
            fn(name)


def test_unknown_and_procedural_names_in_load_room():
    with pytest.raises(RoomError, match="no room 'nowhere'"):
        load_room("nowhere")
    with pytest.raises(RoomError, match="procedural"):
        load_room("kitchen_L")


def test_shell_for_procedural_and_file():
    a = shell_for("bedroom_L", np.random.default_rng(5))
    assert a.shape == "L" and a.room_type == "Bedroom" and a.name == "bedroom_L"
    assert a == shell_for("bedroom_L", np.random.default_rng(5))
    assert shell_for("living_room_two_zone", np.random.default_rng(1)).shape == "two_zone"
    assert shell_for("bathroom", np.random.default_rng(1)).room_type == "Bathroom"
    assert shell_for("FloorPlan201", np.random.default_rng(0)) == load_room("FloorPlan201")


def test_user_library_folder(tmp_path, monkeypatch):
    shell = generate_shell("Kitchen", np.random.default_rng(3), "L", name="my_kitchen")
    save_shell(shell, tmp_path / "my_kitchen.json")
    (tmp_path / "broken.json").write_text('{"name": "broken"}')
    monkeypatch.setenv(ENV_VAR, str(tmp_path))
    assert "my_kitchen" in room_names() and has_room("my_kitchen")
    assert load_room("my_kitchen") == shell
    assert shell_for("my_kitchen", np.random.default_rng(99)) == shell
    with pytest.raises(RoomError, match="broken.json"):
        load_room("broken")
    monkeypatch.setenv(ENV_VAR, "")
    assert not has_room("my_kitchen")


def test_user_file_cannot_shadow_shipped_room(tmp_path, monkeypatch):
    shell = generate_shell("Kitchen", np.random.default_rng(3), name="FloorPlan1")
    save_shell(shell, tmp_path / "FloorPlan1.json")
    monkeypatch.setenv(ENV_VAR, str(tmp_path))
    assert load_room("FloorPlan1").source == "alfred:FloorPlan1"


def test_a_library_without_alfreds_floor_plans_is_an_error_not_a_shorter_list(tmp_path, monkeypatch):
    """An incomplete install (the shipped rooms missing) says so, never lists only the procedural names."""
    from luminous_sim.cdf.refs import check_room
    from luminous_sim.rooms import library

    monkeypatch.setattr(library, "SHIPPED_DIR", tmp_path / "rooms")
    for call in (library.room_names, library.room_files, lambda: library.load_room("FloorPlan1")):
        with pytest.raises(RoomError, match=r"holds none of ALFRED's floor plans .* reinstall luminous-sim"):
            call()
    with pytest.raises(ValueError, match=r"unknown room 'FloorPlan18'.*holds none of ALFRED's floor plans"):
        check_room("FloorPlan18")


def test_an_unknown_room_names_where_it_was_looked_for_and_what_provides_rooms(tmp_path, monkeypatch):
    from luminous_sim.cdf.refs import check_room

    monkeypatch.setenv("LUMINOUS_ROOM_LIBRARY", str(tmp_path))
    with pytest.raises(RoomError) as err:
        load_room("FloorPlan9999")
    text = str(err.value)
    assert str(SHIPPED_DIR) in text and str(tmp_path) in text and "luminous rooms list" in text
    with pytest.raises(ValueError, match=r"unknown room 'FloorPlan9999'.*no FloorPlan9999.json in .*luminous rooms"):
        check_room("FloorPlan9999")
