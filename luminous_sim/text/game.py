"""A trial as a text game in ALFWorld's command grammar and feedback (`alfred.twl2`), played on our own object
states: each command is one or more of ALFRED's interactions applied by `states.step` to the same
`WorldState` the embodied env keeps, so the text game and the embodied one are one episode (what a command
changes is what those interactions change there) and success is the task's own goal conditions.

The agent stands in the middle of the room or at one receptacle; it sees what is on or in that receptacle
(in a closed one only once opened). Commands: "go to R", "open R", "close R", "take O from R", "move O to R"
(R a receptacle, or a bowl, pot, plate... where the agent is), "use O" (a lamp), "heat O with R", "cool O
with R", "clean O with R" (ALFRED's sequences at a microwave, a fridge, a basin), "slice O with K", "examine
X", "look", "inventory", "help". Beyond ALFWorld: all seven task types (movable receptacles take things and
go where things go, carrying what is in them) and sliced objects, named as ALFRED names them ("apple slice
3"). Names and their numbers are ALFWorld's (`alfworld_names`); a thing that stands on no receptacle is
shown on the nearest one that does not close, as in ALFWorld's problem (`alfworld_problem.free_holders`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from luminous_sim.states import WorldState, enclosing_closed, step
from luminous_sim.states.tables import GATING_OPENABLE
from luminous_sim.text.alfworld_names import alfworld_id, mangle, names_of
from luminous_sim.text.alfworld_problem import fixed_holder, free_holders, is_receptacle
from luminous_sim.vocab import SLICED_TYPES, abilities

WELCOME = "-= Welcome to TextWorld, ALFRED! =-"
NOTHING = "Nothing happens."
HELP = ("\nAvailable commands:\n  look:                             look around your current location\n"
        "  inventory:                        check your current inventory\n"
        "  go to (receptacle):               move to a receptacle\n"
        "  open (receptacle):                open a receptacle\n"
        "  close (receptacle):               close a receptacle\n"
        "  take (object) from (receptacle):  take an object from a receptacle\n"
        "  move (object) to (receptacle):  place an object in or on a receptacle\n"
        "  examine (something):              examine a receptacle or an object\n"
        "  use (object):                     use an object\n"
        "  heat (object) with (receptacle):  heat an object using a receptacle\n"
        "  clean (object) with (receptacle): clean an object using a receptacle\n"
        "  cool (object) with (receptacle):  cool an object using a receptacle\n"
        "  slice (object) with (object):     slice an object using a sharp object\n")
"""ALFWorld's help text (`alfred.twl2`)."""
DEVICES = {"heat": "Microwave", "cool": "Fridge", "clean": ("SinkBasin", "BathtubBasin")}


@dataclass(frozen=True)
class TextAction:
    """What a command does in ALFRED's terms: the verb, the object it names and the receptacle (or tool)."""

    verb: str
    target: str | None = None
    receptacle: str | None = None


class TextGame:
    """One trial as a text game. `goal_met(state, visible)` says whether the task is done (the task's goal
    conditions; `visible`: what the agent sees where it stands, for a lamp that must be seen on)."""

    def __init__(self, state: WorldState, goal_text: str, goal_met: Callable[[WorldState, set[str]], bool]):
        self.state = state
        self.goal_text = goal_text
        self._goal_met = goal_met
        self.at: str | None = None
        self.won = False
        self.history: list[TextAction] = []
        """The commands carried out (those that did something), as actions on object ids."""
        self._free = free_holders(state)
        self.free: Mapping[str, str] = dict(self._free)
        """What stands on no receptacle, with the receptacle the game shows it on."""
        self._pddl = {oid: mangle(alfworld_id(oid, o.object_type)).lower() for oid, o in state.objects.items()}
        self.names: dict[str, str] = names_of(self._pddl)
        self.ids: dict[str, str] = {n: oid for oid, n in self.names.items()}
        self._slices: dict[str, int] = {}
        self.receptacles = sorted((oid for oid, o in state.objects.items() if is_receptacle(o.object_type)),
                                   key=self._pddl.__getitem__)
        self._on: dict[str, list[str]] | None = None

    # what is where

    def holder(self, oid: str) -> str | None:
        """The receptacle the game shows a thing on or in (None while held, or for one on no receptacle)."""
        if self.state.held == oid:
            return None
        h = fixed_holder(self.state, oid)
        if h is None and self.state[oid].parent is None:
            h = self._free.get(oid)
        return h

    def on(self, receptacle: str) -> list[str]:
        """What is on or in a receptacle (open or not; not what a shut box on it holds), or in a bowl or box, in
        ALFWorld's listing order."""
        if self._on is None:
            on: dict[str, list[str]] = {r: [] for r in self.receptacles}
            for oid, o in self.state.objects.items():
                if not is_receptacle(o.object_type):
                    h = self.holder(oid)
                    if h is not None and enclosing_closed(self.state, oid) in (None, h):  # not in a shut box
                        on[h].append(oid)
            for items in on.values():
                items.sort(key=self._sort_key)
            self._on = on
        if receptacle not in self._on:  # a bowl or box: what is in it
            return sorted(self.state.contents(receptacle), key=self._sort_key)
        return self._on[receptacle]

    def _sort_key(self, oid: str) -> str:
        return self._pddl.get(oid) or oid.lower()

    def _closes(self, receptacle: str) -> bool:
        """Whether a receptacle hides what it holds while closed (ALFRED's OPENABLE_CLASS_LIST; a toilet's lid
        does not)."""
        return self.state[receptacle].object_type in GATING_OPENABLE

    def _open_to_view(self, receptacle: str) -> bool:
        return not self._closes(receptacle) or self.state[receptacle].isOpen

    def visible(self) -> list[str]:
        """What the agent can act on where it stands (nothing in the middle of the room)."""
        if self.at is None or not self._open_to_view(self.at):
            return []
        return list(self.on(self.at))

    def name(self, oid: str) -> str:
        if oid not in self.names:  # a slice, named when first seen: "apple slice 3"
            kind = self.state[oid].object_type
            word = f"{SLICED_TYPES.get(kind, kind).lower()} slice"
            self._slices[word] = self._slices.get(word, 0) + 1
            self.names[oid] = f"{word} {self._slices[word]}"
            self.ids[self.names[oid]] = oid
        return self.names[oid]

    # text

    def _listing(self, oids: list[str]) -> str:
        if not oids:
            return "nothing"
        items = [f"a {self.name(o)}" for o in oids]
        return items[0] if len(items) == 1 else ", ".join(items[:-1]) + ", and " + items[-1]

    def _examine_receptacle(self, r: str) -> str:
        name = self.name(r)
        if self._closes(r):
            if self.state[r].isOpen:
                return f"The {name} is open. In it, you see {self._listing(self.on(r))}."
            return f"The {name} is closed."
        return f"On the {name}, you see {self._listing(self.on(r))}."

    def look(self) -> str:
        """ALFWorld's "look": in the middle of the room it lists nothing (only the welcome lists the receptacles)."""
        if self.at is None:
            return "You are in the middle of a room. Looking quickly around you, you see nothing."
        return f"You are facing the {self.name(self.at)}. Next to it, you see nothing."

    def intro(self) -> str:
        return (f"{WELCOME}\n\nYou are in the middle of a room. Looking quickly around you, you see "
                f"{self._listing(self.receptacles)}.\n\nYour task is to: {self.goal_text}.")

    # commands

    def admissible(self) -> list[str]:
        """Every command that does something here and now, sorted (as ALFWorld lists them)."""
        out = [f"go to {self.name(r)}" for r in self.receptacles if r != self.at] + ["help", "inventory", "look"]
        held = self.state.held
        if held is not None:
            out.append(f"examine {self.name(held)}")
        if self.at is not None:
            r = self.at
            out.append(f"examine {self.name(r)}")
            if self._closes(r):
                out.append(f"{'close' if self.state[r].isOpen else 'open'} {self.name(r)}")
            for o in self.visible():
                ab = abilities(self.state[o].object_type)
                if held is None and ab.pickupable:
                    out.append(f"take {self.name(o)} from {self.name(r)}")
                if ab.toggleable:
                    out.append(f"use {self.name(o)}")
                if self._closes(o):  # a box
                    out.append(f"{'close' if self.state[o].isOpen else 'open'} {self.name(o)}")
                if held is not None and ab.sliceable and self._tool(held):
                    out.append(f"slice {self.name(o)} with {self.name(held)}")
            if held is not None:
                for dest in [r, *(o for o in self.visible() if abilities(self.state[o].object_type).movable_receptacle
                                  and o != held)]:
                    if self._allowed("PutObject", held, dest):
                        out.append(f"move {self.name(held)} to {self.name(dest)}")
                for verb in ("heat", "cool", "clean"):
                    if self._device(verb, r) and self._run(self._sequence(verb, held, r)) is not None:
                        out.append(f"{verb} {self.name(held)} with {self.name(r)}")
        return sorted(set(out))

    def parse(self, command: str) -> TextAction | None:
        """The action a command names (None for one the grammar does not know, or naming unknown things)."""
        words = " ".join(command.lower().split())
        for verb, shape in (("go to", "go to {r}"), ("take", "take {o} from {r}"), ("move", "move {o} to {r}"),
                            ("heat", "heat {o} with {r}"), ("cool", "cool {o} with {r}"),
                            ("clean", "clean {o} with {r}"), ("slice", "slice {o} with {r}"), ("open", "open {r}"),
                            ("close", "close {r}"), ("use", "use {o}"), ("examine", "examine {o}")):
            head = shape.split(" {")[0]
            if not words.startswith(head + " "):
                continue
            rest = words[len(head) + 1:]
            if "{r}" in shape and "{o}" in shape:
                joint = shape.split("{o} ")[1].split(" {r}")[0]
                o, sep, r = rest.partition(f" {joint} ")
                if not sep or o not in self.ids or r not in self.ids:
                    return None
                return TextAction(verb, self.ids[o], self.ids[r])
            if rest not in self.ids:
                return None
            return TextAction(verb, self.ids[rest]) if "{o}" in shape else TextAction(verb, None, self.ids[rest])
        if words in ("look", "inventory", "help"):
            return TextAction(words)
        return None

    def step(self, command: str) -> str:
        """Carry a command out; its feedback ("Nothing happens." for one that does nothing)."""
        action = self.parse(command)
        if action is None or " ".join(command.lower().split()) not in self.admissible():
            feedback = NOTHING
        else:
            feedback = self._do(action)
            self.history.append(action)
        self.won = self.won or self._goal_met(self.state, set(self.visible()) | {self.state.held} - {None})
        return feedback

    def _do(self, a: TextAction) -> str:
        held = self.state.held
        if a.verb == "look":
            return self.look()
        if a.verb == "help":
            return HELP
        if a.verb == "inventory":
            return f"You are carrying: a {self.name(held)}." if held else "You are not carrying anything."
        if a.verb == "go to":
            assert a.receptacle is not None
            self.at = a.receptacle
            return f"You arrive at {self.name(a.receptacle)}. {self._examine_receptacle(a.receptacle)}"
        if a.verb == "examine":
            assert a.target is not None
            if is_receptacle(self.state[a.target].object_type):
                return self._examine_receptacle(a.target)
            return self._examine_object(a.target)
        if a.verb in ("open", "close"):
            assert a.receptacle is not None
            self._apply([("OpenObject" if a.verb == "open" else "CloseObject", a.receptacle, None)])
            if a.verb == "close":
                return f"You close the {self.name(a.receptacle)}."
            return f"You open the {self.name(a.receptacle)}. {self._examine_receptacle(a.receptacle)}"
        if a.verb == "take":
            assert a.target is not None and a.receptacle is not None
            self._apply([("PickupObject", a.target, None)])
            return f"You pick up the {self.name(a.target)} from the {self.name(a.receptacle)}."
        if a.verb == "move":
            assert a.target is not None and a.receptacle is not None
            self._apply([("PutObject", a.target, a.receptacle)])
            return f"You move the {self.name(a.target)} to the {self.name(a.receptacle)}."
        if a.verb == "use":
            assert a.target is not None
            on = not self.state[a.target].isToggled
            self._apply([("ToggleObjectOn" if on else "ToggleObjectOff", a.target, None)])
            return f"You turn {'on' if on else 'off'} the {self.name(a.target)}."
        if a.verb == "slice":
            assert a.target is not None and a.receptacle is not None
            knife, whole = self.name(a.receptacle), self.name(a.target)
            self._apply([("SliceObject", a.target, None)])
            return f"You sliced the {whole} with the {knife}."
        assert a.target is not None and a.receptacle is not None
        self._apply(self._sequence(a.verb, a.target, a.receptacle))
        past = {"heat": "heat", "cool": "cool", "clean": "clean"}[a.verb]
        return f"You {past} the {self.name(a.target)} using the {self.name(a.receptacle)}."

    def _examine_object(self, oid: str) -> str:
        s, name = self.state[oid], self.name(oid)
        if abilities(s.object_type).movable_receptacle:
            return f"This is a normal {name}. In it, you see {self._listing(self.state.contents(oid))}."
        hot, cool, clean = oid in self.state.heated, oid in self.state.cooled, oid in self.state.cleaned
        sliced = " sliced" if s.isSliced else ""
        if clean and (hot or cool):
            return f"This is a {'hot' if hot else 'cool'} and clean{sliced} {name}."
        if clean or hot or cool:
            return f"This is a {'clean' if clean else 'hot' if hot else 'cold' if not sliced else 'cool'}" \
                   f"{sliced} {name}."
        if abilities(s.object_type).toggleable:
            return f"This {name} is {'on' if s.isToggled else 'off'}."
        if s.isSliced:
            return f"This is a sliced {name}."
        return f"There's nothing special about {name}."

    # ALFRED's interactions

    def _tool(self, oid: str) -> bool:
        return self.state[oid].object_type in ("Knife", "ButterKnife")

    def _device(self, verb: str, receptacle: str) -> bool:
        kinds = DEVICES[verb]
        return self.state[receptacle].object_type in (kinds if isinstance(kinds, tuple) else (kinds,))

    def _sequence(self, verb: str, oid: str, device: str) -> list[tuple[str, str, str | None]]:
        """ALFRED's interactions for heating, cooling or cleaning a held thing at a device."""
        closed = self._closes(device) and not self.state[device].isOpen
        opened = [("OpenObject", device, None)] if closed else []
        if verb == "heat":
            return [*opened, ("PutObject", oid, device), ("CloseObject", device, None),
                    ("ToggleObjectOn", device, None), ("ToggleObjectOff", device, None), ("OpenObject", device, None),
                    ("PickupObject", oid, None), ("CloseObject", device, None)]
        if verb == "cool":
            return [*opened, ("PutObject", oid, device), ("CloseObject", device, None), ("OpenObject", device, None),
                    ("PickupObject", oid, None), ("CloseObject", device, None)]
        faucets = [f for f, basin in self.state.faucet_basin.items() if basin == device]
        if not faucets:
            return [("NoFaucet", device, None)]
        return [("PutObject", oid, device), ("ToggleObjectOn", faucets[0], None), ("ToggleObjectOff", faucets[0], None),
                ("PickupObject", oid, None)]

    def _run(self, actions: list[tuple[str, str, str | None]]) -> WorldState | None:
        state = self.state
        for action, target, receptacle in actions:
            if action == "NoFaucet":
                return None
            state, why = step(state, action, target, receptacle)
            if why is not None:
                return None
        return state

    def _allowed(self, action: str, target: str, receptacle: str | None) -> bool:
        return self._run([(action, target, receptacle)]) is not None

    def _apply(self, actions: list[tuple[str, str, str | None]]) -> None:
        state = self._run(actions)
        assert state is not None, f"an admissible command failed: {actions}"
        self.state = state
        self._on = None


def text_names(state: WorldState) -> Mapping[str, str]:
    """Each object's text name in a state, as the text game (and ALFWorld) names it."""
    return names_of({oid: mangle(alfworld_id(oid, o.object_type)).lower() for oid, o in state.objects.items()})
