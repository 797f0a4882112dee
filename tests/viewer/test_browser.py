"""`luminous view` end to end in a real browser: Debian's chromium driven by Playwright, WebGL through
SwiftShader. The page loads and shows the scene's object count, a click on an object in the 3D canvas shows
its id, the canvas's own pixels vary (it drew the scene), the episode steps, and no request leaves localhost.

Where chromium or Playwright is missing the test skips, except where LUMINOUS_REQUIRE_BROWSER is set (CI,
`.ci/run`): there it fails."""

from __future__ import annotations

import io
import os
import re
import shutil
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import urlparse

import numpy as np
import pytest

from luminous_sim.scene import Scene
from tests.viewer.conftest import REPO

CHROMIUM = os.environ.get("LUMINOUS_CHROMIUM", "/usr/bin/chromium")
FLAGS = ("--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
         "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
         "--disable-default-apps", "--disable-domain-reliability", "--metrics-recording-only")
SHOT = Path(os.environ.get("LUMINOUS_VIEW_SHOT", "/tmp/luminous_view_test.png"))
"""Where the test leaves a screenshot of the page as it ended (to look at when it fails)."""
LOCAL = ("127.0.0.1", "localhost", "::1", "[::1]")


def _need(what: str) -> None:
    if os.environ.get("LUMINOUS_REQUIRE_BROWSER"):
        pytest.fail(f"{what} (LUMINOUS_REQUIRE_BROWSER is set: the browser test must run here)")
    pytest.skip(what)


@pytest.fixture(scope="module")
def browser() -> Iterator:
    try:
        import viser  # noqa: F401
        from playwright.sync_api import sync_playwright
    except ImportError:
        _need("viser or playwright is not installed (the `view` extra)")
    if not (Path(CHROMIUM).is_file() or shutil.which(CHROMIUM)):
        _need(f"no chromium at {CHROMIUM} (Debian: apt-get install chromium)")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=list(FLAGS))
        yield b
        b.close()


@pytest.fixture(scope="module")
def served(scene_dir: Path, episode_dir: Path) -> Iterator[str]:
    """`luminous view SCENE --trajectory EPISODE --port 0` in its own process; its address."""
    proc = subprocess.Popen([sys.executable, "-m", "luminous_sim.cli.main", "view", str(scene_dir), "--trajectory",
                             str(episode_dir), "--port", "0"], cwd=REPO, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    lines: list[str] = []
    found = threading.Event()

    def read() -> None:
        assert proc.stdout is not None
        for line in proc.stdout:
            lines.append(line)
            if " at http://" in line:
                found.set()

    threading.Thread(target=read, daemon=True).start()
    try:
        if not found.wait(180):
            pytest.fail("luminous view did not start:\n" + "".join(lines))
        url = re.search(r" at (http://\S+)", "".join(lines))
        assert url is not None
        yield url.group(1)
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()


def _target(scene: Scene, scene_dir: Path) -> tuple[str, np.ndarray, np.ndarray]:
    """An object a camera straight above sees first: standing on the floor, holding nothing, and with no other
    body's box over the middle of its own; its id and its box (as the world has it)."""
    from luminous_sim.export import build_world
    from luminous_sim.world.posed import posed_scene

    with build_world(scene) as world:
        boxes = {o.object_id: (np.array(o.aabb[0]), np.array(o.aabb[1])) for o in posed_scene(world).objects}
    holds = {o.parent for o in scene.objects}
    best = None
    for o in scene.objects:
        if o.parent is not None or o.id in holds or o.layer not in ("furniture", "fixture"):
            continue
        lo, hi = boxes[o.id]
        mid = (lo + hi) / 2
        covered = any(b_lo[0] <= mid[0] <= b_hi[0] and b_lo[1] <= mid[1] <= b_hi[1] and b_hi[2] > lo[2] + 0.02
                      for oid, (b_lo, b_hi) in boxes.items() if oid != o.id)
        area = float(np.prod(hi[:2] - lo[:2]))
        if not covered and (best is None or area > best[0]):
            best = (area, o.id, lo, hi)
    assert best is not None, "no object in the kitchen that a camera above sees first"
    return best[1], best[2], best[3]


def test_the_page_shows_the_scene_and_a_click_names_the_object(browser, served: str, kitchen: Scene,
                                                               scene_dir: Path):
    from PIL import Image

    object_id, lo, hi = _target(kitchen, scene_dir)
    mid = (lo + hi) / 2
    eye = (mid[0], mid[1] - 0.3, hi[2] + 1.8)
    # viser's URL parameters place the camera (world coordinates, z up): above the object, looking at its middle
    url = (f"{served}?initialCameraPosition={eye[0]:.3f},{eye[1]:.3f},{eye[2]:.3f}"
           f"&initialCameraLookAt={mid[0]:.3f},{mid[1]:.3f},{mid[2]:.3f}")
    requests: list[str] = []
    outside: list[str] = []
    page = browser.new_page(viewport={"width": 1280, "height": 800})

    def route(r) -> None:
        requests.append(r.request.url)
        if urlparse(r.request.url).hostname not in LOCAL:
            outside.append(r.request.url)
            r.abort()
        else:
            r.continue_()

    page.route("**/*", route)
    page.on("websocket", lambda ws: requests.append(ws.url) or (
        urlparse(ws.url).hostname not in LOCAL and outside.append(ws.url)))
    try:
        t0 = time.perf_counter()
        page.goto(url)
        page.get_by_text(f"{len(kitchen.objects)} objects").wait_for(timeout=60_000)
        loaded = time.perf_counter() - t0
        canvas = max(page.locator("canvas").all(), key=lambda c: (c.bounding_box() or {"width": 0})["width"])
        box = canvas.bounding_box()
        assert box is not None and box["width"] > 300
        # the canvas's middle half (no HTML over it there); the meshes arrive after the panel, so wait
        # until its pixels vary
        middle = {"x": box["x"] + box["width"] / 4, "y": box["y"] + box["height"] / 4, "width": box["width"] / 2,
                  "height": box["height"] / 2}
        std, deadline = 0.0, time.perf_counter() + 45
        while std < 10 and time.perf_counter() < deadline:
            shot = np.asarray(Image.open(io.BytesIO(page.screenshot(clip=middle))).convert("RGB"), dtype=float)
            std = float(shot.std())
            time.sleep(0.5)
        drawn = time.perf_counter() - t0
        print(f"\nviewer load: panel with the object count {loaded:.2f} s, scene drawn {drawn:.2f} s "
              f"({len(kitchen.objects)} objects; canvas pixel std {std:.1f})")
        assert std >= 10, f"the canvas looks blank (pixel std {std:.1f})"
        assert len(np.unique(shot.reshape(-1, 3), axis=0)) > 50
        time.sleep(1.0)
        page.mouse.click(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        page.get_by_text(object_id, exact=True).first.wait_for(timeout=20_000)
        # the episode: a step forward shows the next action and its instruction
        page.get_by_role("button", name="Next").click()
        page.get_by_text("MoveAhead").first.wait_for(timeout=10_000)
        page.get_by_text("step 1").first.wait_for(timeout=10_000)
    finally:
        page.screenshot(path=str(SHOT))
        page.close()
    assert outside == [], f"requests left localhost: {outside}"
    assert any(urlparse(u).scheme == "ws" for u in requests)
