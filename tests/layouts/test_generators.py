"""CSSG and the uniform baseline behind the one generator interface; realize gives back their own scenes."""

from __future__ import annotations

import numpy as np

from luminous_sim import cssg
from luminous_sim.layouts import CSSGLayouts, LayoutGenerator, UniformLayouts, realize
from luminous_sim.rooms import generate_shell


def test_generators_share_the_interface_and_realize_to_their_own_scenes():
    shell = generate_shell("Kitchen", np.random.default_rng(3))
    for gen, direct in ((CSSGLayouts(), lambda: cssg.generate(cssg.empty_cdf("Kitchen"), seed=5, room=shell).scene),
                        (UniformLayouts(), lambda: cssg.generate_uniform(shell, 5))):
        assert isinstance(gen, LayoutGenerator)
        layout = gen.layout(shell, 5)
        assert layout.provenance.generator == gen.name and layout.provenance.seed == 5
        assert realize(layout, repair=False).given.generated.scene == direct()
