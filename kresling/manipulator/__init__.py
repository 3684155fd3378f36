"""The Kresling manipulator (thesis chapter 4, Appendix E): constant-curvature kinematics of
a chain of bistable modules, tendon and motor inputs, the pseudo-linkage protocol, marker
comparison with measurements, inverse kinematics and workspace maps.

Modules are contracted (state 0, flexible: a constant-curvature arc driven by three tendons)
or extended (state 1, rigid: a link of length ``2 Le``). Units: mm and rad.

Examples
--------
>>> from kresling.manipulator import Manipulator, pseudo_linkage
>>> run = pseudo_linkage(Manipulator(), "101", steps=[10])
>>> run.markers[0, -1, [0, 2]].round(3)     # tip x and z [mm] at k = 10 (Appendix E)
array([ 75.655, 229.971])
"""

from kresling.manipulator.constant_curvature import arc_from_tendons, tendon_angles, tendons_from_arc
from kresling.manipulator.forward import (ChainState, forward_kinematics, from_plot_plane,
                                          to_plot_plane)
from kresling.manipulator.inverse import (InverseKinematicsResult, inverse_kinematics,
                                          solve_configuration)
from kresling.manipulator.joint_lengths import joint_length_table, read_table5
from kresling.manipulator.markers import (MarkerComparison, MarkerData, compare_markers,
                                          read_markers, write_markers)
from kresling.manipulator.model import (FRAMES, Manipulator, all_configurations,
                                        configuration_name, parse_configuration)
from kresling.manipulator.motors import TendonDrive
from kresling.manipulator.protocol import (THESIS_STEPS, ProtocolRun, protocol_tendon_lengths,
                                           pseudo_linkage)
from kresling.manipulator.synthetic import MarkerPerturbation, synthetic_markers
from kresling.manipulator.workspace import Workspace, workspace, workspaces

__all__ = [
    "Manipulator", "parse_configuration", "configuration_name", "all_configurations", "FRAMES",
    "arc_from_tendons", "tendons_from_arc", "tendon_angles",
    "ChainState", "forward_kinematics", "to_plot_plane", "from_plot_plane",
    "ProtocolRun", "pseudo_linkage", "protocol_tendon_lengths", "THESIS_STEPS",
    "TendonDrive",
    "MarkerData", "MarkerComparison", "read_markers", "write_markers", "compare_markers",
    "joint_length_table", "read_table5",
    "MarkerPerturbation", "synthetic_markers",
    "InverseKinematicsResult", "inverse_kinematics", "solve_configuration",
    "Workspace", "workspace", "workspaces",
]
