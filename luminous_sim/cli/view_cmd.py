"""`luminous view`: a scene (and an episode in it) in the browser, served on localhost until stopped."""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cli.args import int_range

EPILOG = (
    "example: luminous view out/demo/1_kitchen --trajectory out/demo/episode   (then open the printed address; "
    "drag to orbit, click an object for its id, type, state and support; Ctrl-C stops it)"
)


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("view", help="look around a scene (and play an episode) in the browser", epilog=EPILOG)
    parser.add_argument("scene_dir", type=Path, metavar="SCENE_DIR",
                        help="a scene folder written by `luminous generate` (or its scene.json)")
    parser.add_argument("--trajectory", type=Path, default=None, metavar="DIR",
                        help="an episode folder to play (trajectory.json, frames/, instructions.txt), e.g. "
                        "`luminous demo`'s episode/")
    parser.add_argument("--port", type=int_range(0, 65535), default=8080,
                        help="port to serve on (default 8080; a busy one: the next free one, up to 65535; 0: any "
                        "free one)")
    parser.add_argument("--host", default="127.0.0.1",
                        help="interface to listen on (default 127.0.0.1, this machine only)")
    parser.set_defaults(func=_run)


def wait_for_interrupt() -> None:
    """Wait until Ctrl-C (a seam: the CLI's tests replace it)."""
    import contextlib
    import threading

    with contextlib.suppress(KeyboardInterrupt):
        threading.Event().wait()


def _run(args: argparse.Namespace) -> int:
    from luminous_sim.viewer import serve

    # serve refuses a busy port range, a host it cannot listen on, a scene or an episode that is not valid and an
    # episode of another scene, each in one line (exit 2), before any server thread starts
    viewer = serve(args.scene_dir, args.trajectory, port=args.port, host=args.host)
    print(f"serving {args.scene_dir} ({len(viewer.scene.objects)} objects"
          f"{', episode ' + str(args.trajectory) if args.trajectory else ''}) at {viewer.url}  (Ctrl-C stops it)",
          flush=True)
    try:
        wait_for_interrupt()
    finally:
        viewer.close()
    return 0
