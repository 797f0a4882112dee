"""ALFRED's object vocabulary, abilities, receptacle compatibility and room-type lists, as data (layer L0)."""

from luminous_sim.vocab.alfred import (
    ALL_TYPES,
    OBJECTS,
    ROOM_TYPES,
    SLICED_TYPES,
    Abilities,
    abilities,
    can_contain,
    check_type,
    object_class_id,
    parent_type,
    receptacle_objects,
    room_objects,
    vocab_data,
)

__all__ = [
    "ALL_TYPES",
    "OBJECTS",
    "ROOM_TYPES",
    "SLICED_TYPES",
    "Abilities",
    "abilities",
    "can_contain",
    "check_type",
    "object_class_id",
    "parent_type",
    "receptacle_objects",
    "room_objects",
    "vocab_data",
]
