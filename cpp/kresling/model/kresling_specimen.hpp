#pragma once
/// \file kresling_specimen.hpp
/// Bar-and-hinge model of a stack of generalized Kresling cells (a reconstruction of the
/// thesis's generator: docs/thesis_equations.md, 'Bending test').
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

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "kresling/elements/dihedral.hpp"
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

/// Stiffness assignment; defaults are the thesis's (Appendix B; docs/model.md,
/// 'Material calibration').
/// Largest specimen a builder makes: (cells + 1) (n + 1) nodes at most (and so n at most).
inline constexpr long long kMaxSpecimenNodes = 1000000;

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
  /// The hinges' angle: MERLIN2's arccosine, as the thesis's runs computed it, so that the
  /// cells reproduce them to rounding (their polygon spokes rest flat, where the two forms
  /// differ by ~1e-8 rad); Exact for atan2's.
  elements::DihedralForm hinge_angle = elements::DihedralForm::Merlin2;
};

/// The factor of kf that gives the stiffness of a hinge on an edge of family `f`.
double hinge_factor(EdgeFamily f, const SpecimenParameters& p);

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

/// Builds specimens of one polygon size and chirality pattern. The topology and element
/// families depend only on those (and on the node numbering), so a builder computes them
/// once and each build only places the nodes and sets rest lengths and angles: what a
/// parametric sweep over (lambda, Lc) needs.
class KreslingSpecimenBuilder {
 public:
  /// `chirality` has one entry (+1/-1) per cell, base first. Throws std::invalid_argument
  /// for n < 3, an empty list, bad entries or parameters.
  KreslingSpecimenBuilder(int n, std::vector<int> chirality, SpecimenParameters parameters = {});

  /// Build for `design` (its n must be the builder's) with one state (0 contracted,
  /// 1 extended) per cell. `fixed` is empty (no supports) or one entry per DOF.
  KreslingSpecimen build(const geometry::Design& design, const std::vector<int>& states,
                         std::vector<std::uint8_t> fixed = {}) const;

  int n() const { return n_; }
  int cells() const { return static_cast<int>(chirality_.size()); }

 private:
  NodeMatrix place_nodes(const geometry::Design& design, const std::vector<int>& states,
                         std::vector<double>& heights, std::vector<double>& angles) const;
  void build_topology_for(const NodeMatrix& X, std::vector<std::array<Index, 2>>& bars,
                          std::vector<EdgeFamily>& bar_family,
                          std::vector<std::array<Index, 4>>& hinges,
                          std::vector<EdgeFamily>& hinge_family) const;

  int n_;
  std::vector<int> chirality_;
  SpecimenParameters parameters_;
  std::vector<std::vector<Index>> panels_;
  std::vector<std::pair<std::pair<Index, Index>, EdgeFamily>> families_;  // sorted by edge
  // Cached topology (MERLIN2's duplicated topology depends on node numbers only).
  bool cached_ = false;
  std::vector<std::array<Index, 2>> bars_;
  std::vector<EdgeFamily> bar_family_;
  std::vector<std::array<Index, 4>> hinges_;
  std::vector<EdgeFamily> hinge_family_;
};

/// Build the stack in one call (see KreslingSpecimenBuilder). `states` and `chirality`
/// have one entry per cell, base first. Throws std::invalid_argument for empty or
/// mismatched lists, bad entries or parameters.
KreslingSpecimen build_kresling_specimen(const geometry::Design& design,
                                         const std::vector<int>& states,
                                         const std::vector<int>& chirality,
                                         const SpecimenParameters& parameters = {},
                                         std::vector<std::uint8_t> fixed = {});

}  // namespace kresling::model
