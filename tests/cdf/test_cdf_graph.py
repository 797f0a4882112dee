from __future__ import annotations

from pathlib import Path

import networkx as nx
import pytest

from luminous_sim.cdf import (
    Layer,
    from_document,
    load,
    oriented_relations,
    placement_layers,
    relation_graph,
    resolve_order,
)
from luminous_sim.cdf.relations import RELATIONS, STRUCTURE_ELEMENTS
from tests.cdf.helpers import EXAMPLES, base, rel


def _cdf(objects: list[tuple[str, str]], relations: list[dict], room_type: str = "Bedroom"):
    return from_document(
        {
            "cdf_version": 2,
            "scene": {
                "room_type": room_type,
                "objects": [{"name": n, "type": t} for n, t in objects],
                "relations": relations,
            },
        }
    )


def test_paper_desk_in_front_of_chair_is_rewritten_with_the_desk_as_anchor() -> None:
    cdf = _cdf([("chair", "Chair"), ("desk", "Desk")], [rel("desk", "in_front_of", "chair")])
    assert resolve_order(cdf) == ["desk", "chair"]
    (r,) = oriented_relations(cdf)
    assert (r.relation, r.subject, r.anchor, r.flipped, r.index) == (
        "behind",
        "chair",
        "desk",
        True,
        0,
    )


def test_relations_already_anchored_on_the_earlier_object_stay() -> None:
    cdf = _cdf([("desk", "Desk"), ("chair", "Chair")], [rel("chair", "in_front_of", "desk")])
    (r,) = oriented_relations(cdf)
    assert (r.relation, r.subject, r.anchor, r.flipped) == ("in_front_of", "chair", "desk", False)


@pytest.mark.parametrize(
    ("written", "rewritten"),
    [
        ("left_of", "right_of"),
        ("under", "above"),
        ("beside", "beside"),
        ("near", "near"),
        ("aligned_with", "aligned_with"),
    ],
)
def test_inverse_table_is_used(written: str, rewritten: str) -> None:
    cdf = _cdf([("chair", "Chair"), ("bed", "Bed")], [rel("bed", written, "chair")])
    (r,) = oriented_relations(cdf)
    assert (r.relation, r.subject, r.anchor) == (rewritten, "chair", "bed")


def test_face_is_never_flipped_and_orders_its_target_first() -> None:
    cdf = _cdf([("bed", "Bed"), ("chair", "Chair")], [rel("bed", "face", "chair")])
    assert resolve_order(cdf) == ["chair", "bed"]
    (r,) = oriented_relations(cdf)
    assert (r.relation, r.subject, r.anchor, r.flipped) == ("face", "bed", "chair", False)


def test_layers_order_furniture_objects_decorations() -> None:
    cdf = _cdf(
        [
            ("painting", "Painting"),
            ("book", "Book"),
            ("lamp", "DeskLamp"),
            ("chair", "Chair"),
            ("bed", "Bed"),
            ("desk", "Desk"),
            ("window1", "Window"),
        ],
        [rel("lamp", "on", "desk"), rel("book", "on", "bed"), rel("painting", "above", "bed")],
    )
    assert resolve_order(cdf) == ["window1", "bed", "desk", "chair", "lamp", "book", "painting"]
    layers = placement_layers(cdf)
    assert layers["lamp"] is Layer.OBJECT and layers["chair"] is Layer.FURNITURE
    assert layers["painting"] is Layer.DECORATION and layers["window1"] is Layer.STRUCTURE


def test_declared_layer_wins() -> None:
    cdf = _cdf([("plant", "HousePlant"), ("bed", "Bed")], [])
    assert resolve_order(cdf) == ["bed", "plant"]
    doc = {
        "cdf_version": 2,
        "scene": {
            "room_type": "Bedroom",
            "objects": [
                {"name": "plant", "type": "HousePlant", "layer": "decoration"},
                {"name": "book", "type": "Book"},
            ],
        },
    }
    assert resolve_order(from_document(doc)) == ["book", "plant"]


def test_fixed_relations_beat_layers() -> None:
    cdf = _cdf([("painting", "Painting"), ("chair", "Chair")], [rel("chair", "face", "painting")])
    assert resolve_order(cdf) == ["painting", "chair"]


def test_structure_targets_are_anchors_and_weigh_two() -> None:
    cdf = _cdf([("bed", "Bed")], [rel("bed", "beside", "window"), rel("bed", "against_wall")])
    a, b = oriented_relations(cdf)
    assert (a.anchor, a.weight, a.flipped) == ("window", 2.0, False)
    assert (b.anchor, b.weight) == (None, 2.0)


def test_explicit_weight_and_hard_are_kept() -> None:
    doc = base()
    doc["scene"]["relations"].append(
        {"subject": "fridge", "relation": "near", "target": "chair", "weight": 0.3, "hard": False}
    )
    r = oriented_relations(from_document(doc))[-1]
    assert (r.weight, r.hard) == (0.3, False)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_examples_orient_into_a_dag_along_the_order(path: Path) -> None:
    cdf = load(path)
    order = resolve_order(cdf)
    assert sorted(order) == sorted(o.name for o in cdf.scene.objects)
    pos = {n: i for i, n in enumerate(order)}
    for r in oriented_relations(cdf):
        written = cdf.scene.relations[r.index]
        if r.anchor is not None and r.anchor not in STRUCTURE_ELEMENTS:
            assert pos[r.anchor] < pos[r.subject], r
        if r.flipped:
            assert RELATIONS[written.relation].inverse == r.relation
            assert (r.subject, r.anchor) == (written.target, written.subject)
    graph = relation_graph(cdf)
    assert nx.is_directed_acyclic_graph(graph)


def test_relation_graph_nodes() -> None:
    cdf = load(next(p for p in EXAMPLES if p.stem == "livingroom_painting_sofa"))
    graph = relation_graph(cdf)
    assert graph.nodes["window"]["kind"] == "structure"
    assert graph.nodes["sofa"]["unary"][0].relation == "against_wall"
    assert graph.has_edge("sofa", "painting")
