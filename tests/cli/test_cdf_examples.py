"""`luminous cdf examples --out DIR`: the example CDFs that ship inside the package, copied out for a user of the
wheel (who has no repository checkout), never over a file of theirs."""

from __future__ import annotations

from luminous_sim import cdf
from luminous_sim.cli.main import main
from luminous_sim.resources import examples_dir


def test_examples_are_copied_out_and_each_loads(tmp_path, capsys):
    out = tmp_path / "mine"
    assert main(["cdf", "examples", "--out", str(out)]) == 0
    shipped = sorted(p.relative_to(examples_dir()) for p in examples_dir().rglob("*.yaml"))
    copied = sorted(p.relative_to(out) for p in out.rglob("*.yaml"))
    assert copied == shipped and len(copied) >= 9
    assert f"copied {len(copied)} example CDFs" in capsys.readouterr().out
    for path in out.rglob("*.yaml"):
        assert path.read_bytes() == (examples_dir() / path.relative_to(out)).read_bytes()
    assert cdf.load(out / "kitchen_apple_fridge.yaml").scene is not None


def test_a_folder_with_files_in_it_is_refused_and_left_alone(tmp_path, capsys):
    (tmp_path / "kitchen_apple_fridge.yaml").write_text("mine")
    assert main(["cdf", "examples", "--out", str(tmp_path)]) == 2
    assert "expected a new or empty folder" in capsys.readouterr().err
    assert (tmp_path / "kitchen_apple_fridge.yaml").read_text() == "mine"
