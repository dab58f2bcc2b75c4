"""A servo motor's torque envelopes from its datasheet ratings [1, 2].

A servo is not a stepper: it has no pull-out cliff, but two envelopes. The continuous
(S1) envelope is its rated torque, which its RMS torque over the cycle must stay within
(its heating); the peak (intermittent) envelope is what it gives for the short segments
of a move. The peak envelope is modelled as the peak torque up to the rated speed, then
a straight line to the torque the maker gives at the highest speed: for an AC servo the
intermittent zone narrows towards the top speed [1]; for a brushed DC motor at its
reference voltage the envelope is the speed-torque line itself, from the stall torque at
standstill (rated speed 0) towards zero at the no-load speed [2]; the library draws it
to the speed where the line gives the continuous torque.

References
----------
1. Beckhoff, AM8100 servomotors, "Technical data": rated torque and speed, peak torque,
   S1 (continuous) operation.
2. Magmotor C21-F-300FX performance sheet (2022): 48 V, no load 3780 rpm, 38 oz in at
   3360 rpm, 60 oz in at 3117 rpm, stall 342 oz in; a brushed DC motor's line.
"""

from app.core.formulas.declare import formula


@formula(
    "T(n) = T_pk if n <= n_r else T_pk + (T_top - T_pk) (n - n_r) / (n_max - n_r)",
    "servo maker's torque-speed zones (Beckhoff AM8100; Magmotor C21-F-300FX)",
)
def peak_torque_nm(
    rpm: float, peak_nm: float, rated_rpm: float, max_rpm: float, top_nm: float
) -> float:
    """Peak (intermittent) torque [N m] at ``rpm`` [rev/min]: ``peak_nm`` [N m] up to
    ``rated_rpm``, then straight to ``top_nm`` [N m] at ``max_rpm``; zero past it.

    Valid from standstill to ``max_rpm``. The Magmotor C21-F-300FX line (stall 342 oz in,
    no load 3780 rpm) gives 38 oz in at 3360 rpm:

    >>> round(peak_torque_nm(3360.0, 342.0, 0.0, 3780.0, 0.0), 1)
    38.0
    """
    if rpm > max_rpm:
        return 0.0
    if rpm <= rated_rpm:
        return peak_nm
    share = (rpm - rated_rpm) / (max_rpm - rated_rpm)
    return peak_nm + (top_nm - peak_nm) * share


def peak_curve(
    peak_nm: float, rated_rpm: float, max_rpm: float, top_nm: float
) -> tuple[tuple[float, float], ...]:
    """The peak envelope as (rpm, N m) points: standstill, the rated speed (when above
    standstill) and the top speed; straight lines between them are the model itself.

    >>> peak_curve(0.48, 3000.0, 6000.0, 0.16)
    ((0.0, 0.48), (3000.0, 0.48), (6000.0, 0.16))
    >>> peak_curve(0.44, 0.0, 4230.0, 0.0)
    ((0.0, 0.44), (4230.0, 0.0))
    """
    knee = ((rated_rpm, peak_nm),) if rated_rpm > 0.0 else ()
    return ((0.0, peak_nm), *knee, (max_rpm, top_nm))
