"""The oracle tests run in the world tests' generated kitchen."""

from tests.world.conftest import kitchen_scene, world  # noqa: F401
