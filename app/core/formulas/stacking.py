"""Stacked axes: the thrust an axis passes to the nut of a parallel axis that carries it."""

from collections.abc import Sequence

from app.core.formulas.declare import formula


@formula(
    "E = max_i |F_nut,i - W_i|",
    "Newton's second and third laws: the upper nut's force on its moving mass reacts on "
    "the upper frame, which the lower carriage carries; along a parallel axis it reaches "
    "the lower nut",
)
def parallel_reaction(thrusts_n: Sequence[float], weights_n: Sequence[float]) -> float:
    """The largest thrust [N] an upper axis's nut exerts beyond the weight of the mass it
    moves, E = max_i |F_nut,i - W_i| over its moving segments i: its m x'' and its load.
    ``thrusts_n``: the upper nut's force on its moving mass in each segment [N];
    ``weights_n``: the weight of that segment's moving mass [N] (0 on a horizontal axis).
    The reaction of F_nut pushes the upper frame; on a lower axis parallel to it (a
    vertical axis on a vertical one) the weight W is already carried as mass, and the
    rest, E, reaches the lower nut whenever the upper axis moves while the lower one does.

    A 2 kg vertical axis at 2 m/s^2 with no load: F_nut = 2 (9.80665 + 2) = 23.6133 N
    accelerating up, W = 19.6133 N, E = 4 N:

    >>> round(parallel_reaction([23.6133, 19.6133, 15.6133], [19.6133] * 3), 6)
    4.0
    """
    return max((abs(f - w) for f, w in zip(thrusts_n, weights_n, strict=True)), default=0.0)
