"""The ids come from envs/*.toml, register lazily (no pybullet at `import luminous_sim`), and serialise."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import gymnasium
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import EnvConfig, load_entries
from luminous_sim.env.config import ALFRED_TASK_TYPES
from luminous_sim.env.registration import PACKAGE_SPECS, REPO_SPECS, read_spec
from luminous_sim.errors import LuminousError

REPO = Path(__file__).resolve().parents[2]
TASK_TYPE_IDS = {
    "pick_and_place_simple": "Luminous-ALFRED-PickPlace-v0",
    "pick_two_obj_and_place": "Luminous-ALFRED-PickTwo-v0",
    "look_at_obj_in_light": "Luminous-ALFRED-LookInLight-v0",
    "pick_clean_then_place_in_recep": "Luminous-ALFRED-PickClean-v0",
    "pick_heat_then_place_in_recep": "Luminous-ALFRED-PickHeat-v0",
    "pick_cool_then_place_in_recep": "Luminous-ALFRED-PickCool-v0",
    "pick_and_place_with_movable_recep": "Luminous-ALFRED-PickMovable-v0",
}


def test_importing_the_package_registers_ids_without_pybullet():
    code = ("import sys, luminous_sim, gymnasium; assert 'pybullet' not in sys.modules, 'pybullet imported'; "
            "assert 'luminous_sim.world' not in sys.modules; print(gymnasium.spec('Luminous-ALFRED-v0').id)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "Luminous-ALFRED-v0"


def test_every_alfred_type_has_an_id_and_the_family_id_has_all_seven():
    specs = {e.id: e for e in load_entries()}
    assert specs["Luminous-ALFRED-v0"].kwargs["task_types"] == list(ALFRED_TASK_TYPES)
    assert specs["Luminous-ALFRED-v0"].kwargs["width"] == specs["Luminous-ALFRED-v0"].kwargs["height"] == 300
    for task_type, env_id in TASK_TYPE_IDS.items():
        assert specs[env_id].kwargs["task_types"] == [task_type]
    small = [e for e in specs.values() if not e.id.startswith("Luminous-ALFRED")]
    assert {e.kwargs["width"] for e in small} <= {64, 96} and len(small) >= 2


@pytest.mark.parametrize("env_id", [e.id for e in load_entries()])
def test_each_id_is_registered_by_string_entry_point_and_serialises(env_id):
    spec = gymnasium.spec(env_id)
    assert isinstance(spec.entry_point, str) and spec.entry_point.startswith("luminous_sim.env.")
    back = json.loads(spec.to_json())
    assert back["kwargs"] == spec.kwargs
    assert gymnasium.envs.registration.EnvSpec.from_json(spec.to_json()) == spec
    EnvConfig.from_kwargs(spec.kwargs)  # valid options


def test_the_shipped_copy_matches_the_repository_specs():
    shipped = REPO / "luminous_sim" / "env" / PACKAGE_SPECS
    assert REPO_SPECS == REPO / "envs"
    names = sorted(p.name for p in REPO_SPECS.glob("*.toml"))
    assert names and names == sorted(p.name for p in shipped.glob("*.toml")), \
        "copy envs/*.toml to luminous_sim/env/specs/ (what a wheel ships)"
    for name in names:
        assert (REPO_SPECS / name).read_bytes() == (shipped / name).read_bytes(), f"{name} differs from its copy"


def test_registering_twice_changes_nothing():
    from luminous_sim.env import register_envs

    before = dict(gymnasium.registry)
    register_envs()
    assert dict(gymnasium.registry) == before


@pytest.mark.parametrize(("text", "message"), [
    ("[[env]]\nid = 1\n", "env[0]: id"),
    ("[[env]]\nid = 'X-v0'\nkwargs.width = 'wide'\n", "width: expected an integer"),
    ("[[env]]\nid = 'X-v0'\nentry_point = 'm:C'\nkwargs.colour = 1\n", "unknown option(s) colour"),
    ("[[env]]\nid = 'X-v0'\nentry_point = 'm:C'\nkwargs.task_types = ['fly']\n", "task_types: ['fly']"),
    ("[[env]]\nid = 'X-v0'\nentry_point = 'm:C'\ncolour = 1\n", "unknown key(s) colour"),
    ("[[env]\n", "not valid TOML"),
    ("envs = 1\n", "unknown top-level key(s) envs"),
])
def test_a_bad_spec_names_the_file_and_the_key(text, message):
    with pytest.raises(LuminousError, match="bad.toml") as err:
        read_spec(text.replace("[[env]]\nid = 'X-v0'\n", "[family]\nentry_point = 'm:C'\n[[env]]\nid = 'X-v0'\n")
                  if "entry_point" not in text and "id = 'X-v0'" in text else text, "bad.toml")
    assert message in str(err.value)


def test_without_the_repository_folder_the_shipped_specs_are_read(monkeypatch):
    from luminous_sim.env import registration

    ids = [e.id for e in load_entries()]
    monkeypatch.setattr(registration, "REPO_SPECS", REPO / "no-such-folder")
    files = registration.spec_files()
    assert [f.name for f in files] == sorted(p.name for p in REPO_SPECS.glob("*.toml"))
    assert "luminous_sim" in str(files[0]) and "specs" in str(files[0])
    assert [e.id for e in registration.load_entries()] == ids
