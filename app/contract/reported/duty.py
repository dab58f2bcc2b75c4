"""The output table's rows of life and duty: the nut's life, and the energy of one
cycle (the motor's work, braking, the work on the load, the losses)."""

from app.contract.reported.row import Formula, Reported
from app.contract.source import From
from app.core import cycle_energy
from app.core.formulas import energy, life
from app.core.formulas.declare import SEED

ROWS: tuple[Reported, ...] = (
    Reported(
        "life.years",
        "Life",
        "Expected wear life: years at your stroke and cycles per day, else the travel.",
        unit="years",
        better="higher",
        cell="life",
        column=True,
        note="years or travel",
        unit_heading=False,
        css="life",
        ranks=("life",),
        csv=True,
        compare=True,
        formula=Formula(
            life.life_years,
            "years = travel / (2 stroke x cycles/day x 365), the travel the seed's rated "
            "travel (at most the nut's wear life), else the wear life, else a ball nut's "
            "L10 revolutions x lead",
            SEED + " (Anti-Backlash Life); Archard's law (nut wear); ISO 3408-5 (ball nut L10)",
        ),
        views=("summary",),
    ),
    Reported(
        "life.hours",
        "Life in hours",
        "Hours of operation until the nut's life is done: its cycles times the cycle's time.",
        unit="h",
        formula=Formula(life.operating_hours),
    ),
    Reported(
        "life.travel_km",
        "Life as travel",
        "The nut's life as travel: the seed's rating (cut to the nut's wear life where it "
        "wears sooner), else its wear life by Archard's law, or a ball nut's L10.",
        quantity="travel",
        better="higher",
        cell="band",
        csv=True,
        compare=True,
    ),
    *(
        Reported(
            key,
            label,
            help,
            quantity="energy",
            better="lower" if key != "cycle_regen_j" else None,
            csv=True,
            compare=True,
            formula=Formula(function, text, source) if text else Formula(function),
            source=From("quantities.energy." + key, "energy"),
        )
        for key, label, help, function, text, source in (
            (
                "cycle_motor_work_j",
                "Motor work per cycle",
                "Given a move: the work the motor gives at its shaft in one cycle, summed over "
                "the segments where it drives (torque times the turns).",
                energy.shaft_energy,
                "E = sum max(0, T_i 2 pi x_i / lead) over the segments",
                "work of a constant torque over the turns",
            ),
            (
                "cycle_regen_j",
                "Braking energy per cycle",
                "Given a move: the energy braking gives back to the drive in one cycle, where "
                "the motor holds back a decelerating mass or a descending load, before the "
                "drive's own losses (a drive without a regenerative path burns it in a "
                "resistor).",
                energy.shaft_energy,
                "E = sum max(0, -T_i 2 pi x_i / lead) over the segments",
                "work of a constant torque over the turns",
            ),
            (
                "cycle_load_work_j",
                "Work on the load per cycle",
                "Given a move: the work done on the load in one cycle, sum F x over the "
                "segments: the external loads and the weight raised less the weight lowered "
                "(the moving mass's kinetic energy cancels over each move).",
                cycle_energy.cycle_energy,
                "W = sum F_i x_i over the moving segments",
                "work of a force",
            ),
            (
                "cycle_thread_loss_j",
                "Thread friction loss per cycle",
                "Given a move: the energy the thread's friction turns into heat in one cycle, "
                "F x (1/eta - 1) where the motor drives and |F| x (1 - eta_b) where the load "
                "does (at the friction the segment's torque is worked at: a ball screw's "
                "low end where that brakes hardest).",
                energy.thread_loss,
                "",
                "",
            ),
            (
                "cycle_drag_loss_j",
                "Drag loss per cycle",
                "Given a move: the nut's drag torque times the turns of one cycle (the top of "
                "the series' drag range; the bottom over a segment the load drives, where "
                "that brakes hardest).",
                energy.shaft_energy,
                "E = T_drag 2 pi sum x_i / lead",
                "work of a constant torque over the turns",
            ),
            (
                "cycle_copper_loss_j",
                "Copper loss per cycle",
                "Given a move and a stepper's phase current and winding resistance: the heat "
                "of its two windings over the whole cycle, 2 I_rms² R t, the drive holding "
                "the current at rest too: I_rms is the current's amplitude over √2 when "
                "microstepping (a sine), the amplitude itself at full steps (both phases on, "
                "twice the heat). Empty for a servo, whose torque constant is not an input.",
                energy.stepper_copper_loss,
                "",
                "",
            ),
        )
    ),
)
