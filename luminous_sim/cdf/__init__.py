"""Challenge Definition Format (layer L0): schema, safe load/save, validation, relation graph.

Typical use::

    from luminous_sim import cdf
    doc = cdf.load("cdf/examples/kitchen_apple_fridge.yaml")
    for name in cdf.resolve_order(doc): ...
    for rel in cdf.oriented_relations(doc): ...
"""

from luminous_sim.cdf.export import export_schema, schema_dict, schema_filename, schema_text
from luminous_sim.cdf.graph import (
    OrientedRelation,
    oriented_relations,
    placement_layers,
    relation_graph,
    resolve_order,
)
from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.cdf.layers import Layer
from luminous_sim.cdf.loader import (
    dump,
    dumps,
    from_document,
    load,
    loads,
    read_document,
    to_document,
)
from luminous_sim.cdf.predicates import (
    PREDICATES,
    And,
    Atom,
    Exists,
    Expr,
    ExprError,
    ForAll,
    Not,
    Or,
    Param,
    expr_from_data,
    parse_expr,
    to_sexpr,
)
from luminous_sim.cdf.relations import RELATIONS, STRUCTURE_ELEMENTS, RelationInfo, relation_info
from luminous_sim.cdf.schema import (
    CDF_VERSION,
    AgentPoseSpec,
    Attributes,
    ChallengeDefinition,
    HighLevelStep,
    HouseRoomSpec,
    HouseSize,
    HouseSpec,
    LowLevelStep,
    ObjectSpec,
    ObjectStateSpec,
    Relation,
    RoomConstraints,
    SceneSpec,
    Task,
)
from luminous_sim.cdf.summary import summarize
from luminous_sim.cdf.upgrade import SUPPORTED_VERSIONS, upgrade
from luminous_sim.errors import CDFError

__all__ = [
    "CDF_VERSION",
    "PREDICATES",
    "RELATIONS",
    "STRUCTURE_ELEMENTS",
    "SUPPORTED_VERSIONS",
    "AgentPoseSpec",
    "And",
    "Atom",
    "Attributes",
    "CDFError",
    "CDFValidationError",
    "ChallengeDefinition",
    "Exists",
    "Expr",
    "ExprError",
    "ForAll",
    "HighLevelStep",
    "HouseRoomSpec",
    "HouseSize",
    "HouseSpec",
    "Issue",
    "Layer",
    "LowLevelStep",
    "Not",
    "ObjectSpec",
    "ObjectStateSpec",
    "Or",
    "OrientedRelation",
    "Param",
    "Relation",
    "RelationInfo",
    "RoomConstraints",
    "SceneSpec",
    "Task",
    "dump",
    "dumps",
    "export_schema",
    "expr_from_data",
    "from_document",
    "load",
    "loads",
    "oriented_relations",
    "parse_expr",
    "placement_layers",
    "read_document",
    "relation_graph",
    "relation_info",
    "resolve_order",
    "schema_dict",
    "schema_filename",
    "schema_text",
    "summarize",
    "to_document",
    "to_sexpr",
    "upgrade",
]
