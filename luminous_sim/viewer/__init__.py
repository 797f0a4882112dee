"""Layer L5: a scene, and an expert episode in it, in the browser (`luminous view`).

    from luminous_sim.viewer import serve
    viewer = serve("out/demo/1_kitchen", trajectory="out/demo/episode", port=8080)
    print(viewer.url)          # http://127.0.0.1:8080/ : orbit, walk, click objects, play the episode
    viewer.close()

The page is viser's web client (three.js, shipped inside viser's wheel and served by this process, so the
page fetches nothing from anywhere else); each object is one mesh node named by its objectId, made from
`luminous_sim.export`'s meshes. `episode` and `scene_info` are pure (no viser), `app` holds the server.
"""

from __future__ import annotations

from luminous_sim.lazy import lazy_getattr
from luminous_sim.viewer.episode import Episode, EpisodeStep, ViewerError, load_episode
from luminous_sim.viewer.scene_info import ObjectInfo, RoomLabel, object_infos, reachable_points, room_labels

__all__ = ["Episode", "EpisodeStep", "ObjectInfo", "RoomLabel", "Viewer", "ViewerError", "load_episode",
           "object_infos", "reachable_points", "room_labels", "serve"]


# the server (viser) loads only when asked for
__getattr__ = lazy_getattr(__name__, {"Viewer": "app", "serve": "app"})
