"""Loading MERLIN2's golden model (n=4, Lc=30, lambda=0.7, extended) from tests/data."""

from pathlib import Path

import numpy as np
import scipy.sparse as sp

from kresling.model import Model

DIR = Path(__file__).resolve().parent / "data" / "golden_n4_Lc30_lam0.7_extended"


def table(name):
    return np.genfromtxt(DIR / name, delimiter=",", names=True)


def nodes():
    t = table("nodes.csv")
    return np.column_stack([t["x"], t["y"], t["z"]])


def fixed_mask(num_nodes):
    mask = np.zeros(3 * num_nodes, dtype=bool)
    mask[np.atleast_1d(table("fixed_dofs.csv")["dof"]).astype(int) - 1] = True
    return mask.reshape(-1, 3)


def prescribed(num_nodes):
    t = table("imposed_dofs.csv")
    p = np.zeros(3 * num_nodes)
    p[t["dof"].astype(int) - 1] = t["total_disp"]
    return p


def model():
    """The golden model exactly as MERLIN2 listed its elements (1-based -> 0-based)."""
    X = nodes()
    bars, folds = table("bars.csv"), table("folds.csv")
    return Model(
        X,
        np.column_stack([bars["n1"], bars["n2"]]).astype(int) - 1,
        np.column_stack([folds["axis1"], folds["axis2"], folds["wing3"], folds["wing4"]]).astype(int) - 1,
        bar_modulus=bars["EA"] / bars["A"], bar_area=bars["A"], bar_rest_length=bars["L0"],
        hinge_stiffness=folds["kf_per_length"], hinge_rest_angle=folds["theta0"],
        hinge_length=folds["L0"], fixed=fixed_mask(len(X)),
        # MERLIN2's arccosine angle: its flat polygon spokes' forces then agree to rounding.
        hinge_angle="merlin2")


def state(step):
    """(U, IF, K) of MERLIN2 at a step: displacement, internal force, tangent (dense)."""
    U = table(f"U_step{step}.csv")["U"]
    IF = table(f"IF_step{step}.csv")["IF"]
    k = table(f"K_step{step}.csv")
    K = sp.coo_matrix((k["K"], (k["i"].astype(int) - 1, k["j"].astype(int) - 1)),
                      shape=(U.size, U.size)).toarray()
    return U, IF, K
