"""The relation graph of a CDF: placement order, and relations oriented so anchors come first.

Edges run anchor -> subject. Support relations (on, in) and relations without an inverse (face)
keep their direction; the others may be rewritten `r(a, b) -> inverse(r)(b, a)` (paper, appendix on
CSSG: the constraints must form a DAG; "a desk in front of a chair" is resolved so the desk, placed
first, is the anchor). So a cycle is unresolvable exactly when it runs through fixed edges only;
`resolve_order` sorts the fixed graph topologically, breaking ties by layer (structure, furniture,
objects, decorations) and priority q(type), and every invertible relation is then oriented along
that order, which makes the whole graph acyclic.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import networkx as nx

from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.cdf.layers import Layer, layer_of, priority
from luminous_sim.cdf.relations import ORDER_AXES, RELATIONS, STRUCTURE_ELEMENTS, default_weight

if TYPE_CHECKING:
    from luminous_sim.cdf.schema import ChallengeDefinition


@dataclass(frozen=True)
class OrientedRelation:
    """A relation as CSSG applies it: `subject` is placed relative to the earlier-placed `anchor`.

    Attributes:
        relation: Canonical relation name (the inverse of the written one when `flipped`).
        subject: The object this relation places.
        anchor: The earlier-placed object or room element (wall, window, door); None when unary.
        weight: The CDF's weight, or the default (2.0 for room structure, 1.0 between objects).
        hard: Whether CSSG must satisfy it (reject the sample) or only prefer it.
        flipped: Whether subject and target were swapped from the CDF entry.
        index: Position of the entry in `scene.relations`.
    """

    relation: str
    subject: str
    anchor: str | None
    weight: float
    hard: bool
    flipped: bool
    index: int


def placement_layers(cdf: ChallengeDefinition) -> dict[str, Layer]:
    """Layer of each declared object (an object on/in something is at least an OBJECT)."""
    supported = {
        r.subject for r in cdf.scene.relations if RELATIONS[r.relation].category == "support"
    }
    return {o.name: layer_of(o.type, o.layer, o.name in supported) for o in cdf.scene.objects}


def _is_fixed(relation: str) -> bool:
    info = RELATIONS[relation]
    return info.arity == 2 and not info.invertible


def _object_edges(cdf: ChallengeDefinition) -> list[tuple[str, str, int, str]]:
    """(target, subject, index, relation) for every binary relation between two declared objects."""
    names = {o.name for o in cdf.scene.objects}
    return [
        (r.target, r.subject, i, r.relation)
        for i, r in enumerate(cdf.scene.relations)
        if r.target is not None
        and r.target in names
        and r.subject in names
        and r.target != r.subject
    ]


def _cycle(graph: nx.DiGraph) -> tuple[list[str], list[int]] | None:
    try:
        edges = nx.find_cycle(graph)
    except nx.NetworkXNoCycle:
        return None
    names = [u for u, _ in edges] + [edges[0][0]]
    return names, [graph.edges[u, v]["index"] for u, v in edges]


def find_fixed_cycle(cdf: ChallengeDefinition) -> tuple[list[str], list[int]] | None:
    """A cycle through relations that cannot be reversed (on, in, face): (names, indexes)."""
    graph = nx.DiGraph()
    for anchor, subject, i, rel in _object_edges(cdf):
        if _is_fixed(rel):
            graph.add_edge(anchor, subject, index=i)
    return _cycle(graph)


def find_axis_contradiction(cdf: ChallengeDefinition) -> tuple[list[str], list[int]] | None:
    """A cycle along one axis (a left_of b, b left_of a): no placement can satisfy it."""
    for forward, backward in ORDER_AXES:
        graph = nx.DiGraph()
        for target, subject, i, rel in _object_edges(cdf):
            if rel == forward:
                graph.add_edge(subject, target, index=i)
            elif rel == backward:
                graph.add_edge(target, subject, index=i)
        found = _cycle(graph)
        if found:
            return found
    return None


def resolve_order(cdf: ChallengeDefinition) -> list[str]:
    """Declared object names in placement order.

    Room structure first, then furniture, then objects, then decorations; within a layer by
    priority q(type), then declaration order; always after the anchors of their fixed relations.
    Room elements (wall, window, door) come with the room and are not listed.

    Raises:
        CDFValidationError: The fixed relations form a cycle (impossible for a validated CDF).
    """
    layers = placement_layers(cdf)
    index = {o.name: i for i, o in enumerate(cdf.scene.objects)}
    types = {o.name: o.type for o in cdf.scene.objects}
    graph = nx.DiGraph()
    graph.add_nodes_from(index)
    for anchor, subject, i, rel in _object_edges(cdf):
        if _is_fixed(rel):
            graph.add_edge(anchor, subject, index=i)
    try:
        return list(
            nx.lexicographical_topological_sort(
                graph, key=lambda n: (int(layers[n]), -priority(types[n]), index[n])
            )
        )
    except nx.NetworkXUnfeasible:
        names, idx = _cycle(graph) or ([], [0])
        raise CDFValidationError(
            "<cdf>",
            [Issue(f"scene.relations[{idx[-1]}]", "relations form a cycle: " + " -> ".join(names))],
        ) from None


def oriented_relations(cdf: ChallengeDefinition) -> list[OrientedRelation]:
    """Every relation, rewritten where needed so its anchor is placed before its subject.

    An invertible relation whose target comes later in `resolve_order` is replaced by its inverse
    with subject and target swapped (`in_front_of(desk, chair)` with the desk first becomes
    `behind(chair, desk)`); symmetric relations just swap. The list follows `scene.relations`.
    """
    pos = {n: i for i, n in enumerate(resolve_order(cdf))}
    out = []
    for i, r in enumerate(cdf.scene.relations):
        info = RELATIONS[r.relation]
        weight = r.weight if r.weight is not None else default_weight(r.relation, r.target)
        if (
            r.target is not None
            and r.target not in STRUCTURE_ELEMENTS
            and info.inverse is not None
            and pos.get(r.target, -1) > pos.get(r.subject, -1)
        ):
            out.append(OrientedRelation(info.inverse, r.target, r.subject, weight, r.hard, True, i))
        else:
            out.append(OrientedRelation(r.relation, r.subject, r.target, weight, r.hard, False, i))
    return out


def relation_graph(cdf: ChallengeDefinition) -> nx.MultiDiGraph:
    """The oriented relations as a graph: edges anchor -> subject, the OrientedRelation as `rel`.

    Nodes are declared objects (`kind="object"`, with `layer`) and the room elements that relations
    target (`kind="structure"`). Unary relations are kept on their subject node as `unary`.
    """
    graph = nx.MultiDiGraph()
    for name, layer in placement_layers(cdf).items():
        graph.add_node(name, kind="object", layer=layer, unary=[])
    for rel in oriented_relations(cdf):
        if rel.anchor is None:
            graph.nodes[rel.subject]["unary"].append(rel)
            continue
        if rel.anchor in STRUCTURE_ELEMENTS and rel.anchor not in graph:
            graph.add_node(rel.anchor, kind="structure", layer=Layer.STRUCTURE, unary=[])
        graph.add_edge(rel.anchor, rel.subject, rel=rel)
    return graph
