#pragma once
/// \file calibration.hpp
/// Bar areas and hinge stiffnesses of a thin sheet from its material (docs/model.md,
/// 'Material calibration'): the formulas of Filipov, Liu, Tachi, Schenk and Paulino (2017),
/// "Bar and hinge models for scalable analysis of origami", as MERLIN2 v1.1 applies them to
/// an N5B8 model.
///
/// With D = E t^3 / (12 (1 - nu^2)) the plate's bending rigidity:
/// - fold hinge of length Lf: per unit length 1 / (Ls / D + 1 / (0.55 D (Lf / t)^(1/3))) / Lf;
/// - bend hinge on spoke k of a panel: per unit length D (Dsl / t)^(1/3) / Dsl, where Dsl is
///   the spoke's length plus that of the spoke opposite (a quad: spoke k + 2; larger panels:
///   the spoke whose direction is most nearly opposite);
/// - bar areas: every panel adds a share to the bars on its sides and spokes (triangles:
///   t 2 S / (P (1 - nu)); quads: by their mean width W and height H; larger panels:
///   t 2 S / ((P + sum of spokes) (1 - nu))).

#include <vector>

#include "kresling/model/panel_elements.hpp"

namespace kresling::model {

struct SheetMaterial {
  double youngs_modulus = 1e9;  ///< E [N/mm^2 in the model's units]
  double poisson_ratio = 0.33;  ///< nu, in (-1, 0.5]
  double thickness = 1.5e-3;    ///< t [mm]
  /// Ls [mm] in the fold stiffness; 0 = MERLIN2's default, twice the mean fold length.
  double length_scale = 0.0;
};

struct SheetStiffness {
  std::vector<double> bar_area;        ///< per bar, in PanelElements::bars() order
  std::vector<double> fold_stiffness;  ///< per fold hinge, per unit length
  std::vector<double> bend_stiffness;  ///< per bend hinge, per unit length
  double length_scale = 0.0;           ///< the Ls used
};

/// Calibrate an N5B8 model. `merlin2_compat` reproduces MERLIN2 v1.1's pairing of values with
/// elements, which differs from the formulas where a panel's vertices are not listed in
/// increasing order: spoke values go to spokes ranked by vertex index instead of to their
/// own spoke, and a quad whose four sides are all folds gives its side areas to its sides
/// ranked by (lower vertex, higher vertex) instead of to their own side.
/// Throws std::invalid_argument for a bad material or an N4B5 model (a panel of more than 3
/// vertices without a centre node).
SheetStiffness calibrate_sheet(const PanelElements& elements,
                               const std::vector<std::vector<Index>>& panels,
                               const SheetMaterial& material, bool merlin2_compat);

}  // namespace kresling::model
