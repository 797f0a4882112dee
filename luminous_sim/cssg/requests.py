"""What CSSG has to place: the CDF's objects and relations, completed with room-type defaults and the
implicit rule table, in placement order (a DAG over relations, ties broken by type priority)."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cache
from importlib import resources

import networkx as nx
import numpy as np

from luminous_sim.cdf.graph import oriented_relations, resolve_order
from luminous_sim.cdf.predicates import atoms, is_variable
from luminous_sim.cdf.relations import STRUCTURE_ELEMENTS
from luminous_sim.cdf.schema import ChallengeDefinition
from luminous_sim.cssg.tables import generation_layer, needs, object_hosts, placement, room_defaults, supports_for
from luminous_sim.scene import can_hold
from luminous_sim.scene.model import auto_name
from luminous_sim.vocab import HANGERS, room_objects


@cache
def implicit_table() -> dict:
    return json.loads(resources.files("luminous_sim.cssg").joinpath("data/implicit_rules.json").read_text())


@dataclass(frozen=True)
class Rel:
    """`relation` of the request to `anchor` (a request name, a room element, or None when unary)."""

    relation: str
    anchor: str | None
    weight: float
    hard: bool
    explicit: bool
    source: str  # "cdf:scene.relations[i]" or "implicit:<Type> <relation> <Target>"


@dataclass
class Request:
    """One object instance to place."""

    name: str
    type: str
    layer: str
    explicit: bool
    asset: str | None = None
    states: dict[str, bool] = field(default_factory=dict)
    rels: list[Rel] = field(default_factory=list)
    attributes: dict = field(default_factory=dict)
    """colour, material and size from the CDF (size: a factor or {width, depth, height})."""
    clear_above: float = 0.0
    """Half-width (m) of a wall piece the CDF hangs above this one (0: none): no window behind it there."""
    tag: str | None = None
    """The variant tag a rule asks for (a chair at a counter: "bar_stool"); None: only untagged-by-rule variants."""
    holds: dict[str, int] = field(default_factory=dict)
    """Object type -> how many the CDF puts in or on this receptacle at once (`put_holds`)."""
    goal_puts: dict[str, int] = field(default_factory=dict)
    """Object type -> how many the CDF's goal puts in or on this receptacle at once (`goal_holds`): room
    kept for them before the room's default objects are placed."""

    def variants(self, catalog) -> list:
        """The asset variants this request may use, filtered and scaled by its attributes: those with the rule's
        variant tag it asks for, else those without any rule's tag (no bar stool at a dining table); and, of a
        receptacle the goal puts things in, those that can hold them (`can_hold`): every variant of each
        thing where some such host variant exists, else some variant of it, else any host variant (the
        feasibility checks after generation then say no)."""
        from luminous_sim.cssg.attributes import candidates

        pool = catalog.of_type(self.type)
        if self.asset:
            pool = [e for e in pool if e.id == self.asset]
        elif self.tag:
            pool = [e for e in pool if self.tag in e.tags] or pool
        else:
            pool = [e for e in pool if not set(e.tags) & rule_tags()] or pool
        pool = candidates(pool, self.attributes)
        if not self.holds or self.type in HANGERS:
            return pool
        things = {t: catalog.of_type(t) for t in self.holds}
        for every in (all, any):
            kept = [e for e in pool if all(every(can_hold(e, v, n) for v in things[t])
                                           for t, n in self.holds.items() if things[t])]
            if kept:
                return kept
        return pool

    def colour(self, where: str = "") -> tuple[float, float, float] | None:
        from luminous_sim.cssg.attributes import parse_colour

        name = self.attributes.get("colour")
        return parse_colour(name, f"{where or self.name}: attributes.colour") if name else None


def _instances(cdf: ChallengeDefinition) -> dict[str, list[str]]:
    """CDF name -> instance names (`mug`, or `pillow`, `pillow#2`, ... for count > 1)."""
    return {o.name: [o.name] + [f"{o.name}#{i}" for i in range(2, o.count + 1)] for o in cdf.scene.objects}


DEFAULT_ABOVE_WIDTH = 1.2
"""Width (m) assumed for a wall piece hung above something when the CDF gives no size (a large painting)."""


FIXTURE_ANCHOR = "@"
"""Prefix of the anchor name an implicit rule gives a fixture type of the room (`@CounterTop`: any counter run)."""


@cache
def rule_tags() -> frozenset[str]:
    """Variant tags that implicit rules ask for (drawn only by the requests those rules apply to)."""
    return frozenset(r["variant_tag"] for r in implicit_table()["rules"] if "variant_tag" in r)


def _rule_tag(subject: str, relation: str, target: str) -> str | None:
    return next((r["variant_tag"] for r in implicit_table()["rules"] if "variant_tag" in r and r["subject"] == subject
                 and r["relation"] == relation and r.get("target") == target), None)


def requests_from_cdf(cdf: ChallengeDefinition, room_type: str, rng: np.random.Generator,
                      defaults: bool = True, area: float = 20.0, fixtures: frozenset[str] = frozenset()
                      ) -> list[Request]:
    """Every object instance to place, with its relations, in placement order; `fixtures`: the types of the
    fixtures the room already has (a kitchen's counter runs), which defaults may need and implicit rules
    may target."""
    inst = _instances(cdf)
    specs = {o.name: o for o in cdf.scene.objects}
    reqs: dict[str, Request] = {}
    for name in resolve_order(cdf):
        spec = specs[name]
        states = {k: v for k, v in (spec.state.model_dump() if spec.state else {}).items() if v is not None}
        attrs = spec.attributes.model_dump(exclude_none=True) if spec.attributes else {}
        for iname in inst[name]:
            reqs[iname] = Request(iname, spec.type, _layer(spec.type, spec.layer, room_type), True, spec.asset,
                                  dict(states), attributes=attrs)
    for o in oriented_relations(cdf):
        rel = o.relation
        if o.flipped and cdf.scene.relations[o.index].relation == "in_front_of":
            rel = "face"  # "desk in front of chair" with the desk first: the chair faces the desk
        anchors = [o.anchor] if o.anchor is None or o.anchor in STRUCTURE_ELEMENTS else inst[o.anchor]
        tag = _rule_tag(specs[o.subject].type, rel, specs[o.anchor].type) if o.anchor in specs else None
        for sub in inst[o.subject]:
            anchor = anchors[min(inst[o.subject].index(sub), len(anchors) - 1)] if anchors != [None] else None
            reqs[sub].rels.append(Rel(rel, anchor, o.weight, o.hard, True, f"cdf:scene.relations[{o.index}]"))
            reqs[sub].tag = reqs[sub].tag or tag  # the CDF's chair facing a counter is a bar stool too
    for r in list(reqs.values()):
        size = r.attributes.get("size")
        width = size.get("width", DEFAULT_ABOVE_WIDTH) if isinstance(size, dict) else DEFAULT_ABOVE_WIDTH
        for rel in r.rels:
            if rel.relation == "above" and rel.anchor in reqs:
                reqs[rel.anchor].clear_above = max(reqs[rel.anchor].clear_above, width / 2)
    for name, holds in put_holds(cdf).items():
        for iname in inst[name]:
            reqs[iname].holds = dict(holds)
    for name, holds in goal_holds(cdf).items():
        for iname in inst[name]:
            reqs[iname].goal_puts = dict(holds)
    if defaults:
        _add_defaults(reqs, room_type, rng, area, fixtures)
    _add_implicit(reqs, room_type, fixtures)
    return _ordered(reqs)


PUT_PREDICATES = ("inReceptacle",)
"""Goal predicates that put their first argument in or on their second (a receptacle of the room)."""


def goal_holds(cdf: ChallengeDefinition) -> dict[str, dict[str, int]]:
    """CDF object name -> {object type: count} that the CDF's task goal puts in or on it at once: the
    receptacle must leave room for the task's put. A goal variable of a receptacle type stands for every
    CDF object of that type; two distinct variables put in one receptacle count two (ALFRED's
    pick_two_obj_and_place)."""
    if cdf.task is None:
        return {}
    specs = {o.name: o for o in cdf.scene.objects}
    puts: dict[str, dict[str, set[str]]] = {}
    for atom, scope in atoms(cdf.task.goal):
        if atom.pred not in PUT_PREDICATES or len(atom.args) != 2:
            continue
        what, where = atom.args
        thing = scope.get(what) if is_variable(what) else (specs[what].type if what in specs else None)
        if not thing:
            continue
        if is_variable(where):
            hosts = [o.name for o in cdf.scene.objects if o.type == scope.get(where)]
        else:
            hosts = [where] if where in specs else []
        for host in hosts:
            puts.setdefault(host, {}).setdefault(thing, set()).add(what)
    return {host: {t: len(args) for t, args in things.items()} for host, things in puts.items()}


def put_holds(cdf: ChallengeDefinition) -> dict[str, dict[str, int]]:
    """CDF object name -> {object type: count} that must fit in or on it at once: what the CDF's `on`
    and `in` relations put there (two boxes on one table), or what its goal puts there (`goal_holds`),
    whichever is more."""
    specs = {o.name: o for o in cdf.scene.objects}
    out: dict[str, dict[str, int]] = {}
    for r in cdf.scene.relations:
        if r.relation in ("on", "in") and r.subject in specs and r.target in specs:
            held = out.setdefault(r.target, {})
            held[specs[r.subject].type] = held.get(specs[r.subject].type, 0) + specs[r.subject].count
    for host, things in goal_holds(cdf).items():
        held = out.setdefault(host, {})
        for t, n in things.items():
            held[t] = max(held.get(t, 0), n)
    return out


def _layer(object_type: str, declared: str | None, room_type: str) -> str:
    if object_type in placement().get("wall_mounted_in", {}).get(room_type, []):
        return "wall"
    own = generation_layer(object_type)
    if declared == "decoration" and own != "wall":
        return own
    return own if declared is None or own in ("fixture", "wall") else {"furniture": "furniture",
                                                                      "object": "object"}.get(declared, own)


ROOMY = 20.0
"""m^2 from which a room gets its full share of optional furniture; smaller rooms get proportionally less."""


def _add_defaults(reqs: dict[str, Request], room_type: str, rng: np.random.Generator, area: float,
                  fixtures: frozenset[str] = frozenset()) -> None:
    """Room-type furniture and ALFRED-frequency objects that the CDF did not ask for."""
    have = {r.type for r in reqs.values()}
    room_share = min(1.0, area / ROOMY)
    for t, (lo, hi) in sorted(room_defaults(room_type)["furniture"].items()):
        n = lo + int(rng.binomial(hi - lo, room_share * 0.6))
        for i in range(n if t not in have else 0):
            name = auto_name(t, i)
            reqs[name] = Request(name, t, _layer(t, None, room_type), False)
    for t, n in sorted(room_objects(room_type).items()):
        if t in have or generation_layer(t) not in ("object", "wall") or rng.random() >= n / 30:
            continue
        if generation_layer(t) == "object" and not supports_for(t):
            continue
        name = auto_name(t, 0)
        reqs[name] = Request(name, t, generation_layer(t), False)
    have = {r.type for r in reqs.values()} | fixtures
    for name in [n for n, r in reqs.items() if not r.explicit and needs(r.type)]:
        if not have & set(needs(reqs[name].type)):
            del reqs[name]  # a chair with no table to sit at


REPEATABLE = frozenset({"away_from", "far"})
"""Relations that one piece may have to several anchors at once (away from the walls and from the sofa)."""


def _add_implicit(reqs: dict[str, Request], room_type: str, fixtures: frozenset[str] = frozenset()) -> None:
    by_type: dict[str, list[str]] = {}
    for r in reqs.values():
        by_type.setdefault(r.type, []).append(r.name)
    for rule in implicit_table()["rules"]:
        if any(t in by_type for t in rule.get("unless", ())) or room_type not in rule.get("rooms", (room_type,)):
            continue
        for name in by_type.get(rule["subject"], []):
            req = reqs[name]
            same = [x for x in req.rels if x.relation == rule["relation"]]
            if same and (rule["relation"] not in REPEATABLE or any(x.explicit for x in same)):
                continue  # the CDF (or an earlier rule) already says how this one relates
            target = rule.get("target")
            if target is None or target in STRUCTURE_ELEMENTS:
                anchor = target
            elif target in by_type:
                anchor = by_type[target][0]
            elif target in fixtures:
                anchor = FIXTURE_ANCHOR + target
            else:
                continue
            if anchor is not None and any(x.explicit and x.anchor == anchor for x in req.rels):
                continue  # the CDF already says how these two relate ("coffee table beside the sofa")
            src = f"implicit:{rule['subject']} {rule['relation']} {target or ''}".strip()
            req.rels.append(Rel(rule["relation"], anchor, float(rule["weight"]), False, False, src))
            req.tag = req.tag or rule.get("variant_tag")


def _ordered(reqs: dict[str, Request]) -> list[Request]:
    """Topological order over anchors, ties by layer, then (for small objects) the CDF's own before the
    room's defaults, then the priority table, then name. Furniture keeps the priority order whoever asked
    for it: a default bed still goes in before a required chair."""
    prio = {t: i for i, t in enumerate(implicit_table()["priority"])}
    layer_rank = {"fixture": 0, "furniture": 1, "object": 2, "wall": 3}
    g = nx.DiGraph()
    g.add_nodes_from(reqs)
    for r in reqs.values():
        for rel in r.rels:
            if rel.anchor in reqs and rel.anchor != r.name:
                g.add_edge(rel.anchor, r.name)
    if not nx.is_directed_acyclic_graph(g):  # implicit rules never override the CDF's order
        for r in reqs.values():
            for rel in list(r.rels):
                if not rel.explicit and rel.anchor in reqs and g.has_edge(r.name, rel.anchor):
                    r.rels.remove(rel)
                    g.remove_edge(rel.anchor, r.name)
    def rank(r: Request) -> float:
        # a default object that ALFRED hangs (a hand towel on its holder) waits for the wall things
        hung = r.layer == "object" and not r.explicit and any(
            generation_layer(h) == "wall" for h in object_hosts().get(r.type, ()))
        return layer_rank["wall"] + 0.5 if hung else layer_rank[r.layer]

    order = nx.lexicographical_topological_sort(
        g, key=lambda n: (rank(reqs[n]), reqs[n].layer == "object" and not reqs[n].explicit,
                          prio.get(reqs[n].type, 99), not reqs[n].explicit, n))
    return [reqs[n] for n in order]
