"""kresling: stiffness-switching generalized Kresling origami, from crease pattern to manipulator.

The package reproduces, as software, the thesis *Bistable generalized Kresling origami as a
stiffness-switching joint for a tendon-driven soft manipulator*. Data flows one way::

    geometry -> model -> elements -> assembly -> solvers -> analyses -> sweeps

with the manipulator's kinematics, experimental fits and fabrication as leaves beside that
line, and the reproduction report (``kresling.report``) on top of everything: the layers and
what each may import are in docs/architecture.md. Units are mm, N and rad throughout unless
a name says otherwise (bending stiffness is reported in N*m/rad).

Examples
--------
>>> import kresling
>>> d = kresling.Design(n=10, lam=0.9, Lc=15.0, R=30.0)
>>> round(d.Le, 10)
55.8194667798
"""

import logging

from kresling._lazy import lazy_names

# Imported when first used: ``kresling design`` needs the geometry, not the model (nor the
# pattern readers the model package brings).
__getattr__, __dir__ = lazy_names(__name__, {"Design": "geometry",
                                             "design_quantities": "geometry", "Model": "model"})

__version__ = "0.2.0"
__all__ = ["Design", "Model", "design_quantities", "__version__"]

logging.getLogger(__name__).addHandler(logging.NullHandler())
