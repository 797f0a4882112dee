"""The ids come from envs/*.toml, register lazily (no pybullet at `import luminous_sim`), and serialise."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import gymnasium
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import EnvConfig, load_entries
from luminous_sim.env.registration import PACKAGE_SPECS, REPO_SPECS, read_spec
from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES

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
    full_size = ("Luminous-ALFRED", "Luminous-HouseALFRED", "Luminous-Text")
    small = [e for e in specs.values() if not e.id.startswith(full_size)]
    assert {e.kwargs["width"] for e in small} <= {64, 96} and len(small) >= 2


@pytest.mark.parametrize("env_id", [e.id for e in load_entries()])
def test_each_id_is_registered_by_string_entry_point_and_serialises(env_id):
    spec = gymnasium.spec(env_id)
    assert isinstance(spec.entry_point, str) and spec.entry_point.startswith("luminous_sim.env.")
    back = json.loads(spec.to_json())
    assert back["kwargs"] == spec.kwargs
    assert gymnasium.envs.registration.EnvSpec.from_json(spec.to_json()) == spec
    EnvConfig.from_kwargs(spec.kwargs)  # valid options


def test_envs_is_the_one_copy_of_the_specs():
    """envs/ is the only place the specs live in the source; the package holds no second copy."""
    assert REPO_SPECS == REPO / "envs" and sorted(REPO_SPECS.glob("*.toml")), "envs/*.toml is missing"
    copies = [str(p.relative_to(REPO)) for p in (REPO / "luminous_sim").rglob("*.toml") if "[[env]]" in p.read_text()]
    assert not (REPO / "luminous_sim" / "env" / PACKAGE_SPECS).exists() and not copies, (
        f"a second copy of the env specs in the package ({copies}): keep envs/ only; the wheel copies it at build time")
    from luminous_sim.env import registration

    assert Path(str(registration.spec_folder())) == REPO_SPECS


def test_the_build_ships_envs_as_package_data(tmp_path):
    """setup.py's build hook copies envs/*.toml into the built package, where an installed wheel reads them."""
    pytest.importorskip("setuptools")
    out = subprocess.run([sys.executable, "setup.py", "-q", "egg_info", "--egg-base", str(tmp_path), "build_py",
                          "--build-lib", str(tmp_path / "lib")], capture_output=True, text=True, cwd=REPO,
                         check=False)
    assert out.returncode == 0, out.stderr[-2000:]
    shipped = tmp_path / "lib" / "luminous_sim" / "env" / PACKAGE_SPECS
    names = sorted(p.name for p in REPO_SPECS.glob("*.toml"))
    assert sorted(p.name for p in shipped.glob("*.toml")) == names, "the built package lacks envs/*.toml"
    for name in names:
        assert (shipped / name).read_bytes() == (REPO_SPECS / name).read_bytes()


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


def test_an_installed_wheel_reads_its_package_data(monkeypatch, tmp_path):
    """Where the package holds `env/specs/` (an installed wheel), those are read, not a folder beside it."""
    from luminous_sim.env import registration

    ids = [e.id for e in load_entries()]
    shipped = tmp_path / "luminous_sim" / "env" / PACKAGE_SPECS
    shipped.mkdir(parents=True)
    for p in REPO_SPECS.glob("*.toml"):
        (shipped / p.name).write_bytes(p.read_bytes())
    monkeypatch.setattr(registration.resources, "files", lambda _package: tmp_path / "luminous_sim" / "env")
    monkeypatch.setattr(registration, "REPO_SPECS", REPO / "no-such-folder")
    assert [f.name for f in registration.spec_files()] == sorted(p.name for p in REPO_SPECS.glob("*.toml"))
    assert str(shipped) in str(registration.spec_files()[0])
    assert [e.id for e in registration.load_entries()] == ids
    shutil.rmtree(shipped)
    with pytest.raises(LuminousError, match="no environment specs"):
        registration.spec_files()
