"""The ALFRED agent's body and senses, shared by scene generation (which keeps things within its
reach and sight) and the simulator (which enforces them)."""

CAMERA_HEIGHT = 1.576
"""Eye height above the floor used for ALFRED by HLSM (spec 2.1); AI2-THOR's agent y + 0.675."""
AGENT_RADIUS = 0.2
"""The agent's body, a cylinder from the floor to its camera, as wide as its navigation allows."""
VISIBILITY_DISTANCE = 1.5
"""ALFRED's reach: an object can be interacted with within this distance of the camera."""
HORIZON_MIN, HORIZON_MAX = -30, 60
"""Camera pitch range in degrees (positive looks down)."""
