"""The cross-cutting blocks of the kernels' parameter arrays and how a fidelity composes them.

A cross-cutting option (film correction, lubrication method, capacitance, traction law) is a block: its kernel
module declares the block's layout once (a Layout, names not numbers), one function here or beside the option's
model packs the block from the scene, lubricant and bearing, and the option's "off" is the null block, with which
the kernels do none of its work. A fidelity embeds each block it composes at one offset slot of the block's size in
its parameter array, and its facade writes them all with write_blocks, one (offset, block) pair a block:

| block | layout (kernels) | packing (models) | null block |
|---|---|---|---|
| film correction | film_correction FT_* | film_table.film_table_array | film_correction 'none': FT_ON 0 |
| lubrication method | lubrication LM_* | lubrication.lubrication_block | 'flooded': LM_ON 0 |
| capacitance | capacitance CAP_* | capacitance_block (here) | capacitance off: CAP_ON 0 (CAP_OIL_GAP 0: Hertz zones) |
| traction law | ball_traction TR_* | race_contacts.traction_block | race control not 'traction': zeros |
"""

import numpy as np

from ..kernels import capacitance as cap
from ..scene import PERMITTIVITY_PRESSURES


def write_blocks(array, placed):
    """Write each (offset, block) of `placed` into array[offset : offset + block.size]: the blocks a fidelity
    composes, at the offsets its kernel module declares for them."""
    for offset, block in placed:
        array[offset : offset + block.size] = block


def capacitance_block(scene):
    """The capacitance submodel's block (kernels.capacitance CAP_* layout, float64[CAP_SIZE]): the scene's
    permittivity pressure (code), film floor (m), background capacitance (F) and oil-availability gap (m; 0 with
    capacitance_region 'hertz', the Hertz zones alone). Capacitance off is the null block, all 0: no permittivity or
    capacitance is computed."""
    block = np.zeros(cap.CAP_SIZE)
    if not scene.capacitance:
        return block
    block[cap.CAP_ON] = 1.0
    block[cap.CAP_PRESSURE] = PERMITTIVITY_PRESSURES[scene.permittivity_pressure]
    block[cap.CAP_H_FLOOR] = scene.film_floor
    block[cap.CAP_BACKGROUND] = scene.background_capacitance
    block[cap.CAP_OIL_GAP] = scene.oil_gap if scene.capacitance_region == "lubricated" else 0.0
    return block
