"""The viewer itself: a viser server (https://viser.studio) holding the scene as one mesh node per object
(named by its objectId, so that a click names the object), the structure, the reachable grid, room labels
and, with an episode, the agent's path, its pose and its frames. viser's web client ships inside its
wheel and is served from this process: the page fetches nothing from anywhere else."""

from __future__ import annotations

import contextlib
import errno
import io
import math
import socket
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.viewer.episode import Episode, ViewerError, load_episode
from luminous_sim.viewer.scene_info import ObjectInfo, bounds, object_infos, reachable_points, room_labels

if TYPE_CHECKING:
    import viser

    from luminous_sim.scene import Scene
    from luminous_sim.world.posed import PosedScene

EYE_HEIGHT = 1.5
"""Where the walk buttons hold the camera (about the agent's camera height)."""
WALK_STEP = 0.25
TURN_STEP = 30.0
PLAY_INTERVAL = 0.35
"""Seconds per step when an episode plays."""
AMBIENT = 1.6
"""The ambient light's intensity (with viser's default lights and no environment map)."""
AGENT_FOV = math.radians(90.0)
"""The agent camera's field of view (ALFRED's)."""


def _wxyz(xyzw: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
    return (xyzw[3], xyzw[0], xyzw[1], xyzw[2])


def _rgb(rgba: tuple[float, ...]) -> tuple[int, int, int]:
    return (round(255 * min(max(rgba[0], 0.0), 1.0)), round(255 * min(max(rgba[1], 0.0), 1.0)),
            round(255 * min(max(rgba[2], 0.0), 1.0)))


def _object_glb(obj: Any) -> bytes:
    """The body's visual meshes, in its own frame and with their colours, as one glTF binary."""
    import trimesh

    from luminous_sim.export.glb import coloured_mesh, material_name
    from luminous_sim.export.meshes import visual_parts

    scene = trimesh.Scene()
    for part in visual_parts(obj):
        scene.add_geometry(coloured_mesh(part.mesh, part.rgba, material_name(part.rgba)), node_name=part.name,
                           geom_name=part.name)
    return bytes(scene.export(file_type="glb"))


def _look_rotation(forward: np.ndarray) -> np.ndarray:
    """wxyz of a camera frame (OpenCV: x right, y down, z forward) looking along `forward`."""
    from viser import transforms

    f = forward / np.linalg.norm(forward)
    right = np.cross(f, [0.0, 0.0, 1.0])
    right = right / np.linalg.norm(right) if np.linalg.norm(right) > 1e-9 else np.array([1.0, 0.0, 0.0])
    down = np.cross(f, right)
    return transforms.SO3.from_matrix(np.stack([right, down, f], axis=1)).wxyz


class Viewer:
    """A scene (and optionally an episode) served on localhost; `url` is the page.

    Build it with `serve`; `close()` stops the server. Callbacks run on viser's threads."""

    def __init__(self, scene: Scene, posed: PosedScene, episode: Episode | None, host: str, port: int) -> None:
        import viser

        self.scene = scene
        self.episode = episode
        self.infos: dict[str, ObjectInfo] = object_infos(
            scene, {o.object_id: dict(o.states) for o in posed.objects},
            {o.object_id: o.object_type for o in posed.objects})
        self.aabbs = {o.object_id: o.aabb for o in posed.objects}
        self.selected: str | None = None
        self._playing = threading.Event()
        self._stop = threading.Event()
        with contextlib.redirect_stdout(io.StringIO()):  # viser's banner: `luminous view` prints its own line
            self.server = viser.ViserServer(host=host, port=port, label="Luminous-Sim", verbose=False)
        t0 = time.perf_counter()
        self._add_scene(posed)
        self._add_gui()
        if episode is not None:
            self._add_episode(episode)
        self.build_seconds = time.perf_counter() - t0
        self._player = threading.Thread(target=self._play_loop, name="luminous-view-play", daemon=True)
        self._player.start()

    @property
    def host(self) -> str:
        return self.server.get_host()

    @property
    def port(self) -> int:
        return self.server.get_port()

    @property
    def url(self) -> str:
        host = self.host
        return f"http://{'127.0.0.1' if host in ('0.0.0.0', '') else host}:{self.port}/"

    # the 3D scene

    def _add_scene(self, posed: PosedScene) -> None:
        s = self.server.scene
        s.set_up_direction("+z")
        # no shadows and no environment map: in a browser without a GPU (software WebGL) each costs more than
        # the rest of the page (the map: seconds of filtering before the first frame); an ambient light fills in
        s.configure_default_lights(enabled=True, cast_shadow=False)
        s.configure_environment_map(hdri=None)
        s.add_light_ambient("/lights/ambient", intensity=AMBIENT)
        (x0, y0), (x1, y1) = bounds(self.scene)
        cx, cy, extent = (x0 + x1) / 2, (y0 + y1) / 2, max(x1 - x0, y1 - y0, 2.0)
        self.centre = (cx, cy)
        self.server.initial_camera.position = (cx, cy - 0.4 * extent, 1.1 * extent + 1.0)
        self.server.initial_camera.look_at = (cx, cy, 0.0)
        self.walls: list[Any] = []
        for box in posed.structure:
            if not box.visible or box.kind in ("ceiling", "light"):
                continue
            h = s.add_box(f"/structure/{box.name.replace('#', '_')}", color=_rgb(box.rgba), dimensions=box.size,
                          wxyz=_wxyz(box.orientation), position=box.center, cast_shadow=False)
            if box.kind == "wall":
                self.walls.append(h)
        self.nodes: dict[str, Any] = {}
        for obj in posed.objects:
            base = obj.links[0]
            handle = s.add_glb(f"/objects/{obj.object_id}", _object_glb(obj), position=base.position,
                               wxyz=_wxyz(base.orientation), cast_shadow=False)
            handle.on_click(self._clicked(obj.object_id))
            self.nodes[obj.object_id] = handle
        pts = reachable_points(self.scene)
        self.grid = s.add_point_cloud("/reachable_grid", np.column_stack([pts, np.full(len(pts), 0.03)]),
                                      colors=(40, 180, 90), point_size=0.09, point_shape="circle", visible=False)
        self.labels = [s.add_label(f"/rooms/{i}", label.text, position=(*label.position, 0.2),
                                   anchor="center-center", font_screen_scale=1.2)
                       for i, label in enumerate(room_labels(self.scene))]

    def _clicked(self, object_id: str) -> Callable[[Any], None]:
        def on_click(_event: Any) -> None:
            self.select(object_id)
        return on_click

    def select(self, object_id: str | None) -> None:
        """Show an object's id, type, state and support in the panel and box it in the 3D view."""
        self.selected = object_id
        if object_id is None or object_id not in self.infos:
            self.selection_md.content = "Click an object to see its id, type, state and support."
            self.server.scene.add_box("/selection", dimensions=(0.01, 0.01, 0.01), visible=False)
            return
        self.selection_md.content = self.infos[object_id].markdown()
        lo, hi = (np.asarray(v) for v in self.aabbs[object_id])
        self.server.scene.add_box("/selection", color=(255, 200, 0), dimensions=tuple(hi - lo + 0.02),
                                  position=tuple((lo + hi) / 2), wireframe=True, cast_shadow=False)

    # the panel

    def _add_gui(self) -> None:
        gui = self.server.gui
        gui.configure_theme(control_layout="fixed", control_width="large", show_share_button=False)
        room = self.scene.room
        kind = f"house of {len(room.house.rooms)} rooms" if room.house is not None else room.room_type
        self.count_md = gui.add_markdown(f"**{room.name}** ({kind}), seed {self.scene.seed}  \n"
                                         f"**{len(self.scene.objects)} objects**")
        with gui.add_folder("Selected object"):
            self.selection_md = gui.add_markdown("Click an object to see its id, type, state and support.")
        with gui.add_folder("Show"):
            grid = gui.add_checkbox("Reachable grid (0.25 m)", initial_value=False)
            labels = gui.add_checkbox("Room labels", initial_value=True)
            walls = gui.add_checkbox("Walls", initial_value=True)

        @grid.on_update
        def _(_: Any) -> None:
            self.grid.visible = grid.value

        @labels.on_update
        def _(_: Any) -> None:
            for h in self.labels:
                h.visible = labels.value

        @walls.on_update
        def _(_: Any) -> None:
            for h in self.walls:
                h.visible = walls.value

        with gui.add_folder("Walk (or drag to orbit)"):
            row = gui.add_button_group("Move", ("Forward", "Back", "Left", "Right"))
            stand = gui.add_button("Stand in the room")
            overview = gui.add_button("Overview")

        @row.on_click
        def _(event: Any) -> None:
            if event.client is not None:
                self.walk(event.client, row.value)

        @stand.on_click
        def _(event: Any) -> None:
            if event.client is not None:
                self.stand(event.client)

        @overview.on_click
        def _(event: Any) -> None:
            if event.client is not None:
                cam = event.client.camera
                cam.position = tuple(self.server.initial_camera.position)
                cam.look_at = tuple(self.server.initial_camera.look_at)

    def stand(self, client: viser.ClientHandle, x: float | None = None, y: float | None = None,
              heading: tuple[float, float] = (0.0, 1.0)) -> None:
        """Put a client's camera at eye height, looking along `heading` (default: the room's middle, north)."""
        x = self.centre[0] if x is None else x
        y = self.centre[1] if y is None else y
        with client.atomic():
            client.camera.position = (x, y, EYE_HEIGHT)
            client.camera.look_at = (x + heading[0], y + heading[1], EYE_HEIGHT - 0.1)

    def walk(self, client: viser.ClientHandle, move: str) -> None:
        """Walk a client's camera: Forward/Back a step along the floor, Left/Right a turn, at eye height."""
        pos = np.asarray(client.camera.position, dtype=float)
        target = np.asarray(client.camera.look_at, dtype=float)
        d = target[:2] - pos[:2]
        if np.linalg.norm(d) < 1e-6:
            d = np.array([0.0, 1.0])
        d = d / np.linalg.norm(d)
        if move in ("Left", "Right"):
            a = math.radians(TURN_STEP if move == "Left" else -TURN_STEP)
            d = np.array([d[0] * math.cos(a) - d[1] * math.sin(a), d[0] * math.sin(a) + d[1] * math.cos(a)])
        elif move in ("Forward", "Back"):
            pos[:2] += d * WALK_STEP * (1 if move == "Forward" else -1)
        self.stand(client, float(pos[0]), float(pos[1]), (float(d[0]), float(d[1])))

    # the episode

    def _add_episode(self, episode: Episode) -> None:
        gui, s = self.server.gui, self.server.scene
        path = np.array([[x, y, 0.05] for x, y in episode.path()])
        if len(path) > 1:
            seg = np.stack([path[:-1], path[1:]], axis=1)
            seg = seg[np.linalg.norm(seg[:, 1] - seg[:, 0], axis=1) > 1e-6]
            if len(seg):
                s.add_line_segments("/episode/path", seg, colors=(220, 60, 40), thickness=0.03)
        last = len(episode.steps) - 1
        with gui.add_folder("Episode"):
            gui.add_markdown(f"**task** {episode.task_desc}  \n{episode.task_type}: "
                             f"{'solved' if episode.success else 'not solved'}, {last} actions")
            # Any: viser's `value` has a setter that mypy cannot see (an asymmetric property)
            self.step_slider: Any = gui.add_slider("Step", min=0, max=max(last, 1), step=1, initial_value=0,
                                              disabled=last == 0)
            buttons = gui.add_button_group("Play", ("Prev", "Play", "Pause", "Next"))
            self.follow = gui.add_checkbox("See through the agent's eyes", initial_value=False)
            self.step_md = gui.add_markdown("")
            self.frame_image = gui.add_image(np.zeros((300, 300, 3), dtype=np.uint8), label="agent's view",
                                             format="jpeg")

        @self.step_slider.on_update
        def _(_: Any) -> None:
            self.show_step(int(self.step_slider.value))

        @buttons.on_click
        def _(_: Any) -> None:
            value = buttons.value
            if value == "Play":
                if int(self.step_slider.value) >= last:
                    self.step_slider.value = 0
                self._playing.set()
            elif value == "Pause":
                self._playing.clear()
            else:
                self._playing.clear()
                k = int(self.step_slider.value) + (1 if value == "Next" else -1)
                self.step_slider.value = min(max(k, 0), last)

        self.show_step(0)

    def show_step(self, k: int) -> None:
        """Show the episode after `k` actions: the agent's pose, its frame, the action and instruction."""
        if self.episode is None:
            return
        step = self.episode.steps[min(max(k, 0), len(self.episode.steps) - 1)]
        pose = step.pose
        forward = np.array(pose.view_direction())
        eye = np.array(pose.eye())
        self.server.scene.add_camera_frustum("/episode/agent", fov=AGENT_FOV, aspect=1.0, scale=0.25,
                                             color=(220, 60, 40), wxyz=_look_rotation(forward), position=eye)
        self.server.scene.add_icosphere("/episode/agent_body", radius=0.12, color=(220, 60, 40),
                                        position=(pose.x, pose.y, 0.12))
        self.step_md.content = (f"**step {step.index}** of {len(self.episode.steps) - 1}: `{step.action}`  \n"
                                f"**instruction** {step.instruction or '-'}")
        if step.frame is not None:
            self.frame_image.image = _frame_pixels(step.frame)
        if self.follow.value:
            for client in self.server.get_clients().values():
                with client.atomic():
                    client.camera.fov = AGENT_FOV
                    client.camera.position = tuple(eye)
                    client.camera.look_at = tuple(eye + forward)

    def _play_loop(self) -> None:
        while not self._stop.is_set():
            if self._playing.wait(0.2) and self.episode is not None:
                k = int(self.step_slider.value)
                if k >= len(self.episode.steps) - 1:
                    self._playing.clear()
                else:
                    self.step_slider.value = k + 1
                time.sleep(PLAY_INTERVAL)

    def close(self) -> None:
        """Stop playing and stop the server."""
        self._stop.set()
        self._playing.clear()
        self.server.stop()


def _frame_pixels(path: Path) -> np.ndarray:
    """A frame's pixels (checked when the episode was read; read again here without blocking and within the
    limits, so that a file swapped since shows black instead of raising in viser's thread)."""
    from PIL import Image

    from luminous_sim.errors import read_file_bytes
    from luminous_sim.limits import MAX_FRAME_BYTES, MAX_FRAME_PIXELS

    try:
        raw = read_file_bytes(path, MAX_FRAME_BYTES, "a frame image", ViewerError, follow_links=True)
        with Image.open(io.BytesIO(raw)) as im:
            if im.size[0] * im.size[1] > MAX_FRAME_PIXELS:
                raise ViewerError(f"{path}: too many pixels")
            return np.asarray(im.convert("RGB"))
    except (ViewerError, OSError, ValueError, Image.DecompressionBombError):
        return np.zeros((300, 300, 3), dtype=np.uint8)


PORT_TRIES = 1000
"""Ports tried from the one asked for (as viser does) before `serve` gives up."""


def free_port(host: str, port: int) -> int:
    """The first port from `port` (at most PORT_TRIES, none beyond 65535) that `host` can listen on; `port` 0
    stays 0 (the system picks one) once the host is known to be one to listen on.

    Tried here, before the server's thread starts: viser's own search runs in that thread and, past 65535 or
    with a host it cannot listen on, prints a traceback there and leaves its caller waiting for ever.

    Raises:
        ViewerError: `host` is not an address of this machine, or every port tried is taken.
    """
    try:
        infos = socket.getaddrinfo(host, None, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE)
    except (OSError, UnicodeError, ValueError) as exc:
        raise ViewerError(f"--host {host}: cannot listen there ({exc}); expected an address of this machine, "
                          "e.g. 127.0.0.1") from None
    family, _, _, _, address = infos[0]
    last = min(port + PORT_TRIES - 1, 65535) if port else 0
    for p in range(port, last + 1):
        with socket.socket(family, socket.SOCK_STREAM) as s:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as the server will bind it
            try:
                s.bind((address[0], p, *address[2:]))
            except OSError as exc:
                if exc.errno in (errno.EADDRINUSE, errno.EACCES):
                    continue
                raise ViewerError(f"--host {host}: cannot listen there ({exc.strerror or exc}); expected an address "
                                  "of this machine, e.g. 127.0.0.1") from None
            return p
    raise ViewerError(f"--port {port}: ports {port}..{last} on {host} are all in use; give another --port (or 0 "
                      "for any free one)")


def load_scene_for_view(scene_dir: Path) -> tuple[Scene, PosedScene]:
    """The scene of a scene folder and its bodies as PyBullet settles them (initial states applied)."""
    from luminous_sim.export import load_scene

    scene = load_scene(Path(scene_dir))
    return scene, posed_of(scene)


def posed_of(scene: Scene) -> PosedScene:
    """A scene's bodies as PyBullet settles them (initial states applied)."""
    from luminous_sim.export import build_world
    from luminous_sim.world.posed import posed_scene

    with build_world(scene) as world:
        return posed_scene(world)


def serve(scene_dir: Path | str, trajectory: Path | str | None = None, port: int = 8080,
          host: str = "127.0.0.1") -> Viewer:
    """Serve a scene folder (and an episode folder) on `host:port`; returns at once with the server running.

    Args:
        scene_dir: a scene folder written by `luminous generate` (or its scene.json).
        trajectory: an episode folder (trajectory.json, frames/, instructions.txt) to play, or None.
        port: the port to listen on (0: any free one; a busy one: the next free one). `Viewer.url` says which.
        host: the interface to listen on (default: this machine only).

    Raises:
        ViewerError: no scene or no episode where named, an episode of another scene or with a malformed field,
            `host` not one to listen on or no free port from `port` (`free_port`), or viser is not installed
            (the `view` extra).
        ExportError: the scene folder holds no valid scene (`export.load_scene`).
    """
    try:
        import viser  # noqa: F401
    except ImportError:
        raise ViewerError("luminous view needs viser: pip install 'luminous-sim[view]'") from None
    if isinstance(port, bool) or not isinstance(port, int) or not 0 <= port <= 65535:
        raise ViewerError(f"port {port!r}: expected a whole number in 0..65535")
    free_port(host, port)  # before the scene is built: a busy port or a bad host is said at once
    from luminous_sim.export import load_scene

    scene = load_scene(Path(scene_dir))
    episode = load_episode(Path(trajectory), scene) if trajectory is not None else None
    posed = posed_of(scene)
    return Viewer(scene, posed, episode, host, free_port(host, port))
