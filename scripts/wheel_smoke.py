"""The installed wheel, tried as a new user tries it: run by scripts/release_check.sh with a fresh venv's Python,
from a temporary folder outside the repository, with new empty HOME, XDG_CACHE_HOME and LUMINOUS_CACHE and no
other LUMINOUS_* variable. Standard library only (besides the installed package); each step prints its time.

Steps: the install itself (luminous_sim imported from the venv, the repository nowhere on sys.path), `luminous
demo`, `luminous cdf examples` and `generate` of every shipped example CDF, `rooms list` (every room), gym.make and
reset of every registered id, `luminous eval --policy oracle --split U+ --episodes 2` (SR 1.0, the frozen episode
keys matched), `export` to each format, `luminous view` serving its page.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

BIN = Path(sys.executable).parent
LUMINOUS = str(BIN / "luminous")
STEPS: list[tuple[str, float]] = []


def step(name: str):
    def wrap(fn):
        def run(*args, **kwargs):
            start = time.perf_counter()
            print(f"== {name}", flush=True)
            out = fn(*args, **kwargs)
            STEPS.append((name, time.perf_counter() - start))
            print(f"   ok ({STEPS[-1][1]:.1f} s)", flush=True)
            return out
        return run
    return wrap


def luminous(*args: str, timeout: float = 1200) -> str:
    done = subprocess.run([LUMINOUS, *args], capture_output=True, text=True, timeout=timeout)
    if done.returncode != 0:
        raise SystemExit(f"luminous {' '.join(args)} exited {done.returncode}\n{done.stdout[-4000:]}\n"
                         f"{done.stderr[-4000:]}")
    return done.stdout


@step("the install: luminous_sim from the venv, no repository on sys.path, empty caches")
def check_install() -> None:
    import luminous_sim

    where = Path(luminous_sim.__file__).resolve()
    assert where.is_relative_to(Path(sys.prefix).resolve()), f"luminous_sim imported from {where}, not the venv"
    for entry in sys.path:
        assert not (Path(entry or ".") / "pyproject.toml").exists(), f"a source tree is on sys.path: {entry!r}"
    extra = sorted(k for k in os.environ if k.startswith("LUMINOUS_") and k != "LUMINOUS_CACHE")
    assert not extra, f"LUMINOUS_* variables set: {extra}"
    cache = Path(os.environ["LUMINOUS_CACHE"])
    assert cache.is_dir() and not any(cache.iterdir()), f"LUMINOUS_CACHE {cache} is not a new empty folder"
    print(f"   luminous_sim {luminous_sim.__version__} at {where.parent}")


@step("luminous demo")
def demo() -> None:
    out = luminous("demo", "--out", "demo", "--seed", "0")
    print("   " + "\n   ".join(out.strip().splitlines()[:6]))
    assert "NOT" not in out, out
    for name in ("episode/trajectory.json", "episode/video.mp4", "episode/top_down.png", "episode/instructions.txt"):
        assert Path("demo", name).is_file(), f"demo wrote no {name}"
    assert any(Path("demo/episode/frames").iterdir()), "demo wrote no frames"
    for room in sorted(Path("demo").glob("[0-9]_*")):
        report = json.loads((room / "report.json").read_text())
        assert report["satisfies_cdf"], f"{room}: {report}"
        assert json.loads((room / "scene.json").read_text())["objects"], f"{room}: no objects"


@step("luminous cdf examples, generate of each example")
def examples() -> list[Path]:
    luminous("cdf", "examples", "--out", "examples")
    scenes = []
    for cdf in sorted(Path("examples").glob("*.yaml")):
        out = Path("gen", cdf.stem)
        luminous("generate", "--cdf", str(cdf), "--seed", "0", "--out", str(out))
        report = json.loads((out / "report.json").read_text())
        assert report["satisfies_cdf"] and report["physics"]["ok"], f"{cdf}: {json.dumps(report)[:2000]}"
        scenes.append(out)
    for house in sorted(Path("examples/houses").glob("*.yaml")):
        out = Path("gen", house.stem)
        luminous("generate", "--house", str(house), "--seed", "0", "--out", str(out))
        assert json.loads((out / "report.json").read_text())["satisfies_cdf"], house
    print(f"   {len(scenes)} room CDFs and {len(list(Path('examples/houses').glob('*.yaml')))} houses generated")
    return scenes


@step("luminous rooms list")
def rooms() -> None:
    rows = json.loads(luminous("rooms", "list", "--json"))
    floor_plans = [r for r in rows if r["name"].startswith("FloorPlan")]
    assert len(rows) == 136 and len(floor_plans) == 120, f"{len(rows)} rooms, {len(floor_plans)} FloorPlans"


def _reset(env_id: str) -> tuple[str, float]:
    """gym.make and reset of one id, in a worker process: (id, seconds)."""
    import warnings

    import gymnasium as gym

    warnings.filterwarnings("ignore", category=DeprecationWarning)  # gymnasium's "out of date" for older ids

    import luminous_sim.env  # noqa: F401  (registers the ids)

    start = time.perf_counter()
    env = gym.make(env_id)
    try:
        obs, _ = env.reset(seed=0)
        assert env.observation_space.contains(obs), f"{env_id}: reset's observation is outside its space"
    finally:
        env.close()
    return env_id, time.perf_counter() - start


@step("gym.make and reset of every registered id")
def envs() -> None:
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    import gymnasium as gym

    import luminous_sim.env  # noqa: F401  (registers the ids)

    ids = sorted(i for i in gym.registry if i.startswith("Luminous-"))
    assert len(ids) >= 30, ids
    workers = max(1, min(2, os.cpu_count() or 1))
    with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        for env_id, seconds in pool.map(_reset, ids):
            print(f"   {env_id:<36} {seconds:5.1f} s", flush=True)
    print(f"   {len(ids)} ids on {workers} worker processes")


@step("luminous eval --policy oracle --split U+ --episodes 2")
def evaluate() -> None:
    luminous("eval", "--policy", "oracle", "--split", "U+", "--episodes", "2", "--out", "eval")
    report = json.loads(Path("eval/report.json").read_text())
    assert report["entries"] == 2 and report["drawn"] == 2, report["unavailable"]
    assert report["overall"]["sr"] == 1.0, report["overall"]
    from luminous_sim.benchmark import benchmark_entry, canonical_build_dir

    manifest = canonical_build_dir("U+") / "manifest.jsonl"
    built = [json.loads(line) for line in manifest.read_text().splitlines() if line.strip()]
    assert len(built) == 2, built
    for record in built:
        entry = benchmark_entry("U+", record["order"])
        assert record["status"] == "built" and record["episode_key"] == entry.episode_key, record
    print(f"   SR {report['overall']['sr']}; episode keys {[r['episode_key'][:12] for r in built]} as frozen")


@step("luminous export to glb, usd and mjcf")
def export(scene: Path) -> None:
    for fmt, name in (("glb", "scene.glb"), ("usd", "scene.usdc"), ("mjcf", "scene.xml")):
        extra = ["--check"] if fmt == "mjcf" else []
        luminous("export", str(scene), "--format", fmt, "--out", f"export/{name}", *extra)
        size = Path("export", name).stat().st_size
        assert size > 10_000, f"{name}: {size} bytes"
        print(f"   {name}: {size / 1e6:.2f} MB")


@step("luminous view serves its page (the demo's episode in its scene)")
def view(scene: Path) -> None:
    proc = subprocess.Popen([LUMINOUS, "view", str(scene), "--trajectory", str(scene), "--port", "0"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        assert proc.stdout is not None
        deadline = time.monotonic() + 300
        url = None
        lines = []
        while url is None and time.monotonic() < deadline:
            line = proc.stdout.readline()
            if not line:
                break
            lines.append(line)
            found = re.search(r"http://[\w.:\[\]-]+/?", line)
            url = found.group(0) if found else None
        assert url, "luminous view printed no address:\n" + "".join(lines)
        page = urllib.request.urlopen(url, timeout=60).read().decode("utf-8", "replace")
        assert "<html" in page.lower() and "script" in page.lower(), page[:500]
        print(f"   {url}: {len(page)} bytes of page")
    finally:
        proc.terminate()
        proc.wait(timeout=30)


def main() -> int:
    start = time.perf_counter()
    check_install()
    demo()
    scenes = examples()
    rooms()
    envs()
    evaluate()
    export(next(s for s in scenes if s.name == "kitchen_apple_fridge"))
    view(Path("demo/episode"))  # the demo's episode in its own kitchen (the folder holds both)
    print("\nsmoke steps (s): " + ", ".join(f"{name.split(':')[0]} {t:.1f}" for name, t in STEPS))
    print(f"wheel smoke: all passed in {time.perf_counter() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
