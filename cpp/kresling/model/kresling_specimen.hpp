#pragma once
/// \file kresling_specimen.hpp
/// Bar-and-hinge model of a stack of generalized Kresling cells (MODEL.md's reconstruction
/// of the thesis's generator).
///
/// Level k (k = 0..cells) has n perimeter nodes at radius R and angles
/// theta_k + 2 pi j / n, then one centre node: node k (n+1) + j, centre k (n+1) + n. Cell i
/// joins levels i and i+1; it rises by Le (extended) or Lc (contracted) and twists by
/// chirality_i * alpha_e or alpha0: theta_{k+1} = theta_k + chirality_i alpha. Every level's
/// polygon is a fan of triangles around its centre, intermediate levels included.
///
///   chirality +1: triangles [b_j, b_j+1, t_j+1], [b_j, t_j+1, t_j];  valley b_j - t_j+1
///   chirality -1: triangles [b_j, b_j+1, t_j],   [b_j+1, t_j+1, t_j]; valley b_j+1 - t_j
///   both:         mountain b_j - t_j (cut through in the specimens: a weak bar, no hinge)
///
/// Element families set the stiffness (thesis Appendix B): valley and polygon-edge hinges
/// kf, polygon-spoke hinges 10 kf, mountain hinges 0; bars C0 = 1e5 kf with area 1, mountain
/// bars area 0.01. Each cell is stress-free in its own state.

#include <cstdint>
#include <vector>

#include "kresling/geometry/design.hpp"
#include "kresling/model/model.hpp"

namespace kresling::model {

/// What an edge of the specimen is; bars and hinges take the family of their (axis) edge.
enum class EdgeFamily : std::uint8_t {
  Valley = 0,
  Mountain = 1,
  PolygonEdge = 2,
  PolygonSpoke = 3,
};

/// Stiffness assignment; defaults are the thesis's (Appendix B, MODEL.md).
struct SpecimenParameters {
  double kf = 0.047;                   ///< crease stiffness per unit length [N/rad]
  double valley_factor = 1.0;          ///< valley hinges: factor * kf
  double polygon_edge_factor = 1.0;    ///< hinges on polygon edges: factor * kf
  double spoke_factor = 10.0;          ///< hinges on polygon spokes (flat facets): factor * kf
  double mountain_factor = 0.0;        ///< hinges on the cut mountain creases: factor * kf
  double modulus_factor = 1e5;         ///< bar modulus C0 = factor * kf
  double material_area = 1.0;          ///< area of bars on material
  double mountain_area = 0.01;         ///< area of the cut mountain bars
  double theta1 = 5.0 * 3.14159265358979323846 / 180.0;    ///< enhanced linear limits [rad]
  double theta2 = 355.0 * 3.14159265358979323846 / 180.0;
  elements::BarLawKind bar_law = elements::BarLawKind::Ogden;
  bool duplicate_shared_edges = true;  ///< MERLIN2's topology (see topology.hpp)
};

struct KreslingSpecimen {
  Model model;
  std::vector<EdgeFamily> bar_family;    ///< per bar
  std::vector<EdgeFamily> hinge_family;  ///< per hinge (family of its axis)
  std::vector<double> level_height;      ///< z of each level [mm]
  std::vector<double> level_angle;       ///< theta of each level [rad]
  int n = 0;
  int cells = 0;

  /// Node index of perimeter vertex j of level k, or its centre for j = n.
  Index node(int level, int j) const { return static_cast<Index>(level) * (n + 1) + j; }
};

/// Build the stack. `states` (0 contracted, 1 extended) and `chirality` (+1/-1) have one
/// entry per cell, base first. `fixed` is empty (no supports) or one entry per DOF.
/// Throws std::invalid_argument for empty or mismatched lists, bad entries or parameters.
KreslingSpecimen build_kresling_specimen(const geometry::Design& design,
                                         const std::vector<int>& states,
                                         const std::vector<int>& chirality,
                                         const SpecimenParameters& parameters = {},
                                         std::vector<std::uint8_t> fixed = {});

}  // namespace kresling::model
