#include "kresling/analyses/arm_crease_switching.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kresling/analyses/crease_scan.hpp"
#include "kresling/core/check.hpp"

namespace kresling::analyses {

namespace {

// The hinges in `group` of the driven cells `first` to `last` (consecutive, of one module):
// cell hinges whose four nodes all lie on levels first .. last + 1 (a polygon edge at a
// guide belongs to the cell whose panel it holds; one holding a panel of the next cell has
// a node beyond).
std::vector<Index> driven_hinges(const model::Arm& arm, int first, int last, CreaseGroup group) {
  std::vector<Index> out;
  const Index per_level = arm.n + 1, levels = 2 * arm.modules + 1;
  for (std::size_t h = 0; h < arm.cell_hinges; ++h) {
    if (!in_crease_group(arm.hinge_family[h], group)) continue;
    bool inside = true;
    for (Index node : arm.model.hinges()[h].nodes) {
      const Index level = node / per_level;
      inside = inside && node < levels * per_level && level >= first && level <= last + 1;
    }
    if (inside) out.push_back(static_cast<Index>(h));
  }
  return out;
}

// The module's length at displacement u: the distance between its guides' centres [mm].
double module_length(const model::Arm& arm, int module, const VectorX& u) {
  auto centre = [&](int level) -> Vector3 {
    const Index node = arm.node(level, arm.n);
    return arm.model.nodes().row(node).transpose() + u.segment<3>(3 * node);
  };
  return (centre(2 * module + 2) - centre(2 * module)).norm();
}

// Module states from the cells' ('x': a module whose two cells differ).
std::string configuration_of(const std::vector<int>& cells) {
  std::string c;
  for (std::size_t i = 0; i + 1 < cells.size(); i += 2) {
    c += cells[i] == cells[i + 1] ? static_cast<char>('0' + cells[i]) : 'x';
  }
  return c;
}

}  // namespace

namespace {

// Every hinge's rest angle in the arm built with `module` in `state` (its cells stress-free
// there: the angles of that state as built).
VectorX built_angles(const geometry::Design& design, std::vector<int> states,
                     const model::ArmParameters& parameters, int module, int state,
                     const model::Arm& arm) {
  states[static_cast<std::size_t>(module)] = state;
  const model::Arm built = model::build_arm(design, states, parameters);
  VectorX angles(static_cast<Index>(built.model.hinges().size()));
  for (std::size_t h = 0; h < built.model.hinges().size(); ++h) {
    if (built.model.hinges()[h].nodes != arm.model.hinges()[h].nodes) {
      throw std::logic_error("arm_crease_switch: arms of two configurations differ in hinges");
    }
    angles[static_cast<Index>(h)] = built.model.hinges()[h].rest_angle;
  }
  return angles;
}

}  // namespace

ArmCreaseSwitchResult arm_crease_switch(const geometry::Design& design,
                                        const std::vector<int>& states,
                                        const model::ArmParameters& parameters, int module,
                                        const std::vector<int>& cells, const VectorX& start,
                                        bool extend, const ArmCreaseSwitchOptions& options) {
  check_scan_options(options.scan);
  const model::Arm arm = model::build_arm(design, states, parameters);
  if (module < 0 || module >= arm.modules) {
    throw_invalid("module", module,
                  "an integer in [0, " + std::to_string(arm.modules - 1) + "] (0: the base)");
  }
  for (int c : cells) {
    if (c != 2 * module && c != 2 * module + 1) {
      throw_invalid("cells", c, "a cell of module " + std::to_string(module) + " (" +
                                    std::to_string(2 * module) + " or " +
                                    std::to_string(2 * module + 1) + ")");
    }
  }
  if (cells.empty()) throw std::invalid_argument("cells: give at least one cell to drive");
  const int first = *std::min_element(cells.begin(), cells.end());
  const int last = *std::max_element(cells.begin(), cells.end());
  const VectorX u0 = start.size() ? start : VectorX::Zero(arm.model.num_dofs());
  if (u0.size() != arm.model.num_dofs() || !u0.allFinite()) {
    throw std::invalid_argument("start: must be " + std::to_string(arm.model.num_dofs()) +
                                " finite displacements (3 per node of the arm) [mm]");
  }
  const double travel = arm.cell_extended - arm.cell_contracted;
  const double let_out = std::isnan(options.let_out) ? 3.0 * travel : options.let_out;
  require_finite("let_out", let_out);
  if (!(let_out >= 0.0)) throw_invalid("let_out", let_out, ">= 0 [mm]");

  const VectorX from = built_angles(design, states, parameters, module, extend ? 0 : 1, arm);
  const VectorX to = built_angles(design, states, parameters, module, extend ? 1 : 0, arm);
  const CreaseDrive drive =
      make_crease_drive(arm.model, driven_hinges(arm, first, last, options.group), from, to);

  ArmCreaseSwitchResult out;
  out.module = module;
  out.forward = !extend;
  out.let_out = let_out;
  out.hinges = drive.hinges;
  const Pulls pulls{-let_out, -let_out, -let_out};
  std::vector<double> rest(3);
  for (int t = 0; t < 3; ++t) rest[static_cast<std::size_t>(t)] = arm.slack_length[t] + let_out;
  const model::Model slack = arm.model.with_cable_rest_lengths(rest);
  // The descents as the arm's release takes them (ArmSolver::release): steps of up to 2 mm,
  // a snapping module travels up to 2 (Le - Lc).
  solvers::EnergyMinimumOptions descent;
  descent.max_step = 2.0;
  descent.max_iterations = 5000;
  descent.tolerance = options.scan.newton.tolerance;
  CreaseScan scan(slack, options.scan, 0.05 * travel,
                  [&](const VectorX& u) { return module_length(arm, module, u); }, descent);
  VectorX snap = u0, landing;
  out.scan = scan.run(options.group, drive, 1.0, u0, &snap, &landing);
  out.scan.forward = out.forward;

  ArmSolver solver(arm);
  out.start = solver.evaluate(u0, pulls);
  out.start.energy = out.scan.start_energy;
  out.snap = solver.evaluate(snap, pulls);
  // The snap is actuated: its energy is the scan's (the arm's own rest angles would give
  // another), and the scan kept it only with a positive-definite tangent.
  out.snap.energy = out.scan.snap_energy;
  out.snap.negative_eigenvalues = std::isnan(out.scan.snap_change) ? -1 : 0;
  out.configuration_before = configuration_of(out.start.cell_states);
  out.configuration_after = out.configuration_before;
  if (!std::isnan(out.scan.landing_height)) {
    out.after = solver.evaluate(landing, pulls);
    out.after.negative_eigenvalues = out.scan.landing_negative_eigenvalues;
    out.configuration_after = configuration_of(out.after.cell_states);
  }
  return out;
}

}  // namespace kresling::analyses
