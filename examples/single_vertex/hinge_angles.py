"""Run the single-vertex problem and print its hinges' angles, family by family.

``.venv/bin/python examples/single_vertex/hinge_angles.py``

``simulation.element_histories()`` gives each hinge's dihedral angle theta at every
increment (pi when flat) and its family ("valley", "mountain", ... from the FOLD file's
assignments). theta is measured from one wing of the hinge to the other in the hinge's own
node order, so whether a valley folds towards theta < pi or theta > pi depends on that
order, not on the assignment. The FOLD file's fold angles at rest (valley positive) fix
the sign: the signed fold angle is ``rho = s (pi - theta)`` with ``s = +1`` or ``-1``
chosen so that rho at rest has the file's sign.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from kresling.simulate import simulate

HERE = Path(__file__).resolve().parent


def signed_fold_angles(simulation):
    """Fold angles [deg] in FOLD's convention (valley positive) of every hinge.

    Returns
    -------
    angles : ndarray, shape (S + 1, H)
        Row 0 is the rest state, row k increment k.
    families : tuple of str, length H
    creases : list of (int, int)
        The vertices of each hinge's axis.
    """
    pattern = simulation.problem.pattern
    at_rest = {tuple(sorted(edge)): angle for edge, angle in
               zip(pattern.edges.tolist(), pattern.edges_fold_angle)}
    model = simulation.model
    histories = simulation.element_histories()
    theta = np.vstack([model.hinge_rest_angle, histories.hinge_angle])
    creases = [tuple(sorted(hinge[:2])) for hinge in model.hinges.tolist()]
    sign = np.array([np.sign(at_rest[crease] * (np.pi - rest))
                     for crease, rest in zip(creases, model.hinge_rest_angle)])
    return np.degrees(sign * (np.pi - theta)), histories.hinge_family, creases


def main():
    simulation = simulate(HERE / "problem.toml", progress=False)
    histories = simulation.element_histories()
    families = histories.hinge_family
    theta = np.degrees(histories.hinge_angle)
    print(f"{simulation.path.num_steps} increments, completed: {simulation.completed}")
    print("\nDihedral angle theta [deg] by family (element_histories().hinge_angle):")
    for family in sorted(set(families)):
        mask = np.array([f == family for f in families])
        rest = np.degrees(simulation.model.hinge_rest_angle[mask])
        print(f"  {family:9s} rest {np.round(rest, 1)} -> end {np.round(theta[-1, mask], 1)}")

    rho, families, creases = signed_fold_angles(simulation)
    lift = simulation.history_columns()["u_2_z"]
    print("\nSigned fold angles [deg] (valley positive) as node 2 rises:")
    header = "  ".join(f"{f[0].upper()} {a}-{b}" for f, (a, b) in zip(families, creases))
    print(f"{'u_2_z [mm]':>11s}  {'load factor':>11s}  {header}")
    rows = [0] + list(range(5, len(rho), 5)) + ([len(rho) - 1] if (len(rho) - 1) % 5 else [])
    for k in rows:
        u = 0.0 if k == 0 else lift[k - 1]
        lam = 0.0 if k == 0 else simulation.path.load_factor[k - 1]
        print(f"{u:11.3f}  {lam:11.5f}  " + "  ".join(f"{x:6.1f}" for x in rho[k]))


if __name__ == "__main__":
    main()
