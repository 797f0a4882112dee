"""Material palettes: each visual part names a material slot; colours are drawn from its palette at load
time (the paper's object material randomisation). The first entry is the asset's default colour."""

from __future__ import annotations

RGBA = tuple[float, float, float, float]


def _hex(*codes: str, alpha: float = 1.0) -> tuple[RGBA, ...]:
    out = []
    for c in codes:
        c = c.lstrip("#")
        out.append((int(c[0:2], 16) / 255, int(c[2:4], 16) / 255, int(c[4:6], 16) / 255, alpha))
    return tuple((round(r, 4), round(g, 4), round(b, 4), a) for r, g, b, a in out)


PALETTES: dict[str, tuple[RGBA, ...]] = {
    "wood": _hex("a0703c", "c49a6c", "7b5230", "d8b98a", "5c3a21", "b5835a"),
    "dark_wood": _hex("4a2f1b", "3b2616", "5e3b22", "2e1e12"),
    "painted": _hex("f2f0eb", "dfe5e8", "6f8fa6", "9fb59a", "e8d9b5", "40464d"),
    "metal": _hex("b8bcc2", "9aa0a6", "d0d3d6", "7d838a"),
    "dark_metal": _hex("3a3d41", "2b2d30", "505459"),
    "brass": _hex("b5a642", "c9ae5d", "a8894a"),
    "appliance": _hex("eeeeee", "d6d8da", "2f3235", "b0b4b8"),
    "fabric": _hex("6b7a8f", "9e4a3c", "c8b99c", "3f5e4a", "8a8f94", "d4c5b0", "2f3b52"),
    "leather": _hex("5b3a29", "2d2420", "8b5a3c", "1f1f1f"),
    "cushion": _hex("e6ddd0", "b8c4d6", "d9a6a0", "9fb6a2", "f0e6c8"),
    "ceramic": _hex("f4f4f0", "e9e2d6", "bcd4e6", "c94c4c", "3d5a80", "f2c14e"),
    "porcelain": _hex("fbfbf8", "f1f1ec", "e8eef2"),
    "plastic": _hex("d94f4f", "3f88c5", "f2c14e", "5aa469", "eeeeee", "2d2d2d", "9b5de5"),
    "dark_plastic": _hex("1e1e1e", "2d2d2d", "3a3a3a"),
    "glass": _hex("b9d9e6", "9cc7d6", "cfe8ef", alpha=1.0),
    "mirror": _hex("cfdde6", "d8e4ea"),
    "screen": _hex("101418", "0b0d10"),
    "paper": _hex("f5f1e6", "ebe5d5", "fafafa"),
    "book_cover": _hex("8c2f39", "1d3557", "2a9d8f", "e9c46a", "6d597a", "264653"),
    "rubber": _hex("222222", "333333"),
    "stone": _hex("d9d4cc", "8c8c8c", "f0ece4", "4a4a4a", "c2b8a3"),
    "tile": _hex("f3f3f3", "dce3e6", "e8e0d0"),
    "wall": _hex("f1ede4", "e6e9ea", "efe3d0", "dfe7dc"),
    "floor": _hex("b08a5e", "9c7a54", "c8ad88", "8f8f8f"),
    "plant": _hex("3f7d3a", "4f8f45", "2f6b2f", "5e9e4c"),
    "soil": _hex("4a3526", "3b2a1f"),
    "water": _hex("7fb8e6", "8cc4ec", alpha=1.0),
    "glow": _hex("fff3b0", "ffe58a", "fff8d6"),
    "hot": _hex("ff5a1f", "e63e12"),
    "led_off": _hex("2a2a2a"),
    "led_on": _hex("3ddc84", "5ad1ff"),
    "dirt": _hex("6b5032", "5a4128", "7a6a45"),
    # food: the default is the ripe colour
    "apple": _hex("c0392b", "d64541", "7dbb3c", "e8c547"),
    "apple_flesh": _hex("f3e6b3", "efe0a8"),
    "bread": _hex("c68642", "b5732f", "d9a05b"),
    "bread_crumb": _hex("f2dfb4", "ead3a0"),
    "egg": _hex("f3e5cf", "e9d2b0", "fafafa"),
    "lettuce": _hex("7cb342", "8bc34a", "689f38"),
    "potato": _hex("b9935a", "a67c47", "c9a56b"),
    "potato_flesh": _hex("f1e3b0", "ead9a0"),
    "tomato": _hex("d62828", "e63946", "c1121f"),
    "tomato_flesh": _hex("e5383b", "f25c54"),
    "stem": _hex("5a3d1e", "3f6b22"),
    "imported": _hex("b4b4b4", "8c9aa8", "c8b496", "a0a0a0"),
    # shared by the small-object families (household, electronics, textiles, toiletries)
    "hh_art": _hex("e76f51", "2a9d8f", "264653", "e9c46a", "6d597a"),
    "hh_button": _hex("5a5a5a", "7d7d7d", "9a9a9a"),
    "hh_dark": _hex("141414"),
    "hh_face": _hex("fbfbf8", "f5f1e6", "fafafa"),
    "hh_ink": _hex("1b1b1b", "262626"),
    "hh_print": _hex("9a978f", "8c8980"),
    "hh_red": _hex("d62828", "c1121f"),
    "hh_remote": _hex("1e1e1e", "2d2d2d", "e6e6e6", "3a3a3a"),
}


def add_palettes(**palettes: tuple[RGBA, ...]) -> None:
    """Register palettes a builder module needs (at import time); redefining one differently is an error."""
    for name, colours in palettes.items():
        if name in PALETTES and PALETTES[name] != tuple(colours):
            raise ValueError(f"palette {name!r} is already defined differently")
        PALETTES[name] = tuple(colours)


def hex_colours(*codes: str, alpha: float = 1.0) -> tuple[RGBA, ...]:
    """Palette entries from hex codes such as "a0703c"."""
    return _hex(*codes, alpha=alpha)


def palette(slot: str) -> tuple[RGBA, ...]:
    """The palette of a material slot; an unknown slot is a programming error in a builder."""
    try:
        return PALETTES[slot]
    except KeyError:
        raise KeyError(f"unknown material slot {slot!r}; known: {', '.join(sorted(PALETTES))}") from None
