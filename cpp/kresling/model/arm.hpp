#pragma once
/// \file arm.hpp
/// The tendon-driven manipulator as one structure (thesis chapter 4, as a bar-and-hinge
/// model): m modules of two Kresling cells of opposite chirality, joined at stiff guide
/// plates, the base plate fixed, three sliding cables from the base to the tip guide.
///
///      tip guide (level 2m)   o===o=====o===o   <- tendon ends (anchors)
///                              |  cell  -  |
///      mid level (2k + 1)     o---o-----o---o   (a polygon of the stack, not a guide)
///                              |  cell  +  |
///      guide (level 2k)       o===o=====o===o   <- tendons slide through its holes
///                              :           :
///      base guide (level 0)   ###############   fixed (and the tendons' start)
///
/// Module k (base first) is cells 2k (chirality +1) and 2k+1 (chirality -1), both in the
/// module's state (0 contracted, 1 extended); their twists cancel, so every guide level sits
/// at angle 0. The cells are the Kresling specimen's (model/kresling_specimen.hpp: same
/// nodes, bars, hinges and thesis stiffnesses). A guide is a stiff plate: its polygon's spoke
/// hinges get guide_factor * kf, and it carries three tendon holes at radius d, angles
/// 0, 120 and 240 degrees (tendon 1 on +x, as in the kinematics). Each hole is a node tied to
/// the plate by bars to the centre and the two perimeter vertices around it, and by a stiff
/// hinge that keeps it in the plate's plane (a hole on a perimeter vertex is that vertex).
/// Tendon t is a cable through hole t of guides 0, 1, ..., m: anchored at the (fixed) base
/// and at the tip guide, sliding without friction through the others. Its rest length is the
/// path length as built, so the unloaded arm is stress-free in every configuration.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "kresling/geometry/design.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/model/model.hpp"

namespace kresling::model {

struct ArmParameters {
  SpecimenParameters specimen;     ///< the cells' stiffnesses (the thesis's by default)
  double tendon_radius = 32.0;     ///< d: radius of the tendon holes [mm] (thesis 4.2)
  /// Circumradius of the guide plates (regular n-gons aligned with the cells' polygons)
  /// [mm]. Only bounds where holes may sit; the thesis gives no plate size (an assumption).
  double guide_radius = 40.0;
  double guide_factor = 1e4;       ///< hinges inside a guide plate: factor * kf
  /// Axial rigidity EA of each tendon [N]. The thesis does not give its tendons' material;
  /// 500 N is a nylon line of about 0.4 mm (E ~ 4 GPa), an assumption.
  double tendon_stiffness = 500.0;
  /// Contact between the panels (the cells' side triangles and the levels' polygons, within
  /// a module and between modules; self_contact_family.hpp): the barrier's distance d_hat
  /// [mm] (0: no contact) and its stiffness kappa [N/mm^3] (> 0 with contact).
  double contact_distance = 0.0;
  double contact_stiffness = 0.0;
};

/// The arm's model and where its parts are.
struct Arm {
  explicit Arm(Model m) : model(std::move(m)) {}

  Model model;
  int n = 0;
  int modules = 0;
  std::vector<int> states;           ///< per module (0 contracted, 1 extended), base first
  std::vector<int> cell_states;      ///< per cell (two per module)
  std::vector<int> chirality;        ///< per cell: +1, -1, +1, -1, ...
  std::vector<double> level_height;  ///< z of each level as built [mm]
  std::vector<double> level_angle;   ///< angle of each level's vertex 0 [rad]
  std::vector<EdgeFamily> bar_family;    ///< the cells' bars (the first ones)
  std::vector<EdgeFamily> hinge_family;  ///< the cells' hinges (the first ones)
  std::size_t cell_bars = 0;         ///< bars [0, cell_bars) are the specimen's, then guides'
  std::size_t cell_hinges = 0;       ///< likewise for hinges
  std::vector<std::array<Index, 3>> holes;  ///< per guide g = 0..m: node of tendon t's hole
  std::array<double, 3> slack_length{};     ///< each tendon's path length as built [mm]
  double cell_extended = 0.0;        ///< Le [mm]
  double cell_contracted = 0.0;      ///< Lc [mm]

  /// Node of perimeter vertex j of `level` (its centre for j = n).
  Index node(int level, int j) const { return static_cast<Index>(level) * (n + 1) + j; }
  /// Level of guide g (0 = base, modules = tip).
  int guide_level(int g) const { return 2 * g; }
  /// The tip guide's centre: where tip loads act and the tip position is read.
  Index tip_node() const { return node(2 * modules, n); }
};

/// Parse a configuration such as "010" (one character per module, base first; 0
/// contracted, 1 extended). Throws std::invalid_argument naming `configuration` for an empty
/// string, other characters, or (if `modules` > 0) a different length.
std::vector<int> parse_configuration(const std::string& configuration, int modules = 0);

/// The configuration string of module states (inverse of parse_configuration).
std::string configuration_string(const std::vector<int>& states);

/// Build the arm of `design` with one state per module, base first. Throws
/// std::invalid_argument naming the parameter for no modules, states other than 0/1, a
/// tendon radius that is not positive or puts a hole outside the guide polygon, a guide
/// radius below the cells' R, or non-positive factors and stiffnesses.
Arm build_arm(const geometry::Design& design, const std::vector<int>& states,
              const ArmParameters& parameters = {});

}  // namespace kresling::model
