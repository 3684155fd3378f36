"""Where a fold with a material of its own stalls, would Origami Simulator's go on?

Stiff bars (MERLIN2's examples use 1e5 N/mm^2) leave a pattern whose panels cannot follow
the creases exactly no way to stretch a little, and the fold's path ends at a limit point.
The question is answered by folding the same problem again with the preset material, up to
one increment past where the first fold stopped, so the advice in the message is a result,
not a guess.
"""

from __future__ import annotations

import logging

from kresling.model.material_presets import preset_material

__all__ = ["preset_goes_past"]

PRESET = "origami_simulator"


def preset_goes_past(problem, load_factor: float, simulate) -> float | None:
    """Fold ``problem`` again with Origami Simulator's material to one increment past
    ``load_factor`` (where the first fold stopped).

    Parameters
    ----------
    problem : Problem
        A fold (``method = "fold"``) with a material of its own.
    load_factor : float
        Where its path stopped (stages count 1 each).
    simulate : callable
        The run (:func:`kresling.simulate.simulate`; passed in by the run that asks, which
        this module does not import).

    Returns
    -------
    float or None
        The load factor the preset's fold reached, if past ``load_factor``; None if it
        stopped at or before it too.
    """
    beyond = load_factor + 1.0 / problem.analysis.steps
    trial = problem.replace(material=preset_material(PRESET, problem.pattern.vertices),
                            preset=PRESET, merlin2_compat=False)
    quiet = logging.getLogger("kresling.simulate.run")
    level = quiet.level
    quiet.setLevel(logging.ERROR)  # the trial's own lines would read as the run's
    try:
        sim = simulate(trial, stop=lambda state: state.load_factor >= beyond, progress=False)
    except ValueError:
        return None
    finally:
        quiet.setLevel(level)
    reached = float(sim.path.load_factor[-1]) if sim.path.num_steps else 0.0
    return reached if reached > load_factor else None
