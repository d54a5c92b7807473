"""Root finding shared by the kernels: the bracket update of the Illinois false position (Dowell & Jarratt 1971,
BIT 11, 168-174), which kernels.lubrication (the inlet meniscus) and kernels.capacitance (where the oil bound cuts
the gap) iterate on their own functions."""

from bearing_fmu_common.jit import kernel


@kernel
def illinois_update(x, f, lo, f_lo, hi, f_hi, side):
    """The bracket [lo, hi] with its function values (f_lo < 0 <= f_hi) after the estimate x with value f: x replaces
    the upper end where f >= 0, else the lower one; side (1 upper, -1 lower, 0 at the start) is the end replaced last.
    When one end is replaced twice in a row, the other end's value is halved, so that the next estimate
    (lo f_hi - hi f_lo) / (f_hi - f_lo) moves past an end that would otherwise stall (plain regula falsi).
    Returns (lo, f_lo, hi, f_hi, side)."""
    if f >= 0.0:
        if side == 1:
            f_lo *= 0.5
        return lo, f_lo, x, f, 1
    if side == -1:
        f_hi *= 0.5
    return x, f, hi, f_hi, -1
