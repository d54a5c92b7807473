"""Slot numbers of the kernels' structure-of-arrays arrays, counted from their declarations, not written by hand.

A kernel module declares the slots of one array in order, each with its width:

    _B_SLOTS = Layout()
    B_X = _B_SLOTS.slot(3)  # centre position x, y, z (m)
    B_VX = _B_SLOTS.slot(3)  # centre velocity (m/s)
    B_SIZE = _B_SLOTS.size

Each name is a plain int fixed when the module is imported, which numba compiles as a constant: the kernels'
machine code is that of literal numbers, while a slot inserted or widened renumbers the ones after it.
"""


class Layout:
    """The slots of one array, handed out in declaration order."""

    def __init__(self):
        self.size = 0  # slots declared so far: the array's length once the last one is declared

    def slot(self, width=1):
        """The index of a new slot of `width` consecutive entries (a 3-vector: 3)."""
        if int(width) != width or width < 1:
            raise ValueError(f"a slot's width is a positive whole number, not {width!r}")
        start = self.size
        self.size += int(width)
        return start
