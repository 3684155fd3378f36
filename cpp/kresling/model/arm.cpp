#include "kresling/model/arm.hpp"

#include <cmath>
#include <stdexcept>

#include "kresling/core/check.hpp"
#include "kresling/elements/cable.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/model/self_contact_family.hpp"

namespace kresling::model {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

void check_parameters(const ArmParameters& p, const geometry::Design& design) {
  const double R = design.parameters().R;
  const int n = design.parameters().n;
  require_positive("tendon_radius", p.tendon_radius);
  require_positive("guide_radius", p.guide_radius);
  require_positive("guide_factor", p.guide_factor);
  require_positive("tendon_stiffness", p.tendon_stiffness);
  require_positive("contact_distance", p.contact_distance, /*allow_zero=*/true);
  if (p.contact_distance > 0.0) require_positive("contact_stiffness", p.contact_stiffness);
  if (p.guide_radius < R) {
    throw_invalid("guide_radius", p.guide_radius,
                  ">= the cells' circumradius R = " + format_number(R) + " mm (a guide covers the polygon)");
  }
  // Every hole inside the guide polygon: its distance along the nearest edge normal below the
  // apothem. Guide levels sit at angle 0, so the holes' angles are relative to vertex 0.
  const double sector = kTwoPi / n;
  for (int t = 0; t < 3; ++t) {
    const double psi = std::fmod(kTwoPi * t / 3.0, sector) - 0.5 * sector;
    if (!(p.tendon_radius * std::cos(psi) < p.guide_radius * std::cos(0.5 * sector))) {
      throw_invalid("tendon_radius", p.tendon_radius,
                    "inside the guide polygon (tendon " + std::to_string(t + 1) +
                        "'s hole would lie outside the n = " + std::to_string(n) +
                        " polygon of circumradius guide_radius = " +
                        format_number(p.guide_radius) + " mm)");
    }
  }
}

// The arm's panels for contact, 3 node indices each: every cell's 2n side triangles (as
// kresling_specimen.hpp splits them, by the cell's chirality), then every level's polygon
// as a fan of n triangles about its centre node.
std::vector<Index> panel_triangles(const Arm& arm) {
  const int n = arm.n;
  std::vector<Index> out;
  for (std::size_t i = 0; i < arm.chirality.size(); ++i) {
    const int level = static_cast<int>(i);
    for (int j = 0; j < n; ++j) {
      const Index b = arm.node(level, j), b1 = arm.node(level, (j + 1) % n);
      const Index t = arm.node(level + 1, j), t1 = arm.node(level + 1, (j + 1) % n);
      if (arm.chirality[i] > 0) {
        out.insert(out.end(), {b, b1, t1, b, t1, t});
      } else {
        out.insert(out.end(), {b, b1, t, b1, t1, t});
      }
    }
  }
  for (int level = 0; level <= 2 * arm.modules; ++level) {
    for (int j = 0; j < n; ++j) {
      out.insert(out.end(), {arm.node(level, j), arm.node(level, (j + 1) % n), arm.node(level, n)});
    }
  }
  return out;
}

}  // namespace

std::vector<int> parse_configuration(const std::string& configuration, int modules) {
  if (configuration.empty()) {
    throw std::invalid_argument(
        "configuration = '' is invalid: give one character per module, 0 (contracted) or 1 "
        "(extended), from the base");
  }
  std::vector<int> states;
  for (char c : configuration) {
    if (c != '0' && c != '1') {
      throw std::invalid_argument("configuration = '" + configuration +
                                  "' is invalid: only 0 (contracted) and 1 (extended) are "
                                  "allowed, one per module from the base");
    }
    states.push_back(c - '0');
  }
  if (modules > 0 && static_cast<int>(states.size()) != modules) {
    throw std::invalid_argument("configuration = '" + configuration + "' has " +
                                std::to_string(states.size()) + " characters, must have one per "
                                "module (modules = " + std::to_string(modules) + ")");
  }
  return states;
}

std::string configuration_string(const std::vector<int>& states) {
  std::string s;
  for (int v : states) s += static_cast<char>('0' + v);
  return s;
}

Arm build_arm(const geometry::Design& design, const std::vector<int>& states,
              const ArmParameters& parameters) {
  if (states.empty()) throw std::invalid_argument("states: the arm needs at least one module");
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (states[k] != 0 && states[k] != 1) {
      throw_invalid("states[" + std::to_string(k) + "]", states[k], "0 (contracted) or 1 (extended)");
    }
  }
  check_parameters(parameters, design);
  const int n = design.parameters().n;
  const double R = design.parameters().R;
  const int m = static_cast<int>(states.size());

  Arm arm(Model(NodeMatrix::Zero(1, 3), {}, {}, {0, 0, 0}));
  arm.n = n;
  arm.modules = m;
  arm.states = states;
  for (int k = 0; k < m; ++k) {
    arm.cell_states.insert(arm.cell_states.end(), {states[k], states[k]});
    arm.chirality.insert(arm.chirality.end(), {1, -1});
  }
  KreslingSpecimen cells =
      build_kresling_specimen(design, arm.cell_states, arm.chirality, parameters.specimen);
  arm.level_height = cells.level_height;
  arm.level_angle = cells.level_angle;
  arm.bar_family = cells.bar_family;
  arm.hinge_family = cells.hinge_family;
  arm.cell_extended = design.height(geometry::State::Extended);
  arm.cell_contracted = design.height(geometry::State::Contracted);

  const SpecimenParameters& sp = parameters.specimen;
  const double guide_kp = parameters.guide_factor * sp.kf;
  const Model& cm = cells.model;
  std::vector<Bar> bars = cm.bars();
  std::vector<Hinge> hinges = cm.hinges();
  arm.cell_bars = bars.size();
  arm.cell_hinges = hinges.size();
  auto level_of = [&](Index node) { return static_cast<int>(node / (n + 1)); };
  // Guide plates: their spokes are stiff.
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    if (cells.hinge_family[i] != EdgeFamily::PolygonSpoke) continue;
    const int level = level_of(hinges[i].nodes[0]);
    if (level % 2 == 0 && level == level_of(hinges[i].nodes[1])) hinges[i].stiffness = guide_kp;
  }

  // Tendon holes.
  const Index cell_nodes = cm.num_nodes();
  std::vector<Vector3> extra;
  const double sector = kTwoPi / n;
  const double d = parameters.tendon_radius;
  const elements::SpringLaw law{elements::SpringLawKind::EnhancedLinear, sp.theta1, sp.theta2};
  const elements::BarLaw bar_law{sp.bar_law, sp.modulus_factor * sp.kf};
  auto position = [&](Index node) -> Vector3 {
    return node < cell_nodes ? Vector3(cm.nodes().row(node).transpose())
                             : extra[static_cast<std::size_t>(node - cell_nodes)];
  };
  auto add_bar = [&](Index a, Index b) {
    bars.push_back({{a, b}, sp.material_area, (position(b) - position(a)).norm(), bar_law});
  };
  for (int g = 0; g <= m; ++g) {
    const int level = arm.guide_level(g);
    const double z = arm.level_height[level];
    std::array<Index, 3> holes{};
    for (int t = 0; t < 3; ++t) {
      const double phi = kTwoPi * t / 3.0;
      double psi = std::fmod(phi - arm.level_angle[level], kTwoPi);
      if (psi < 0) psi += kTwoPi;
      const int j = static_cast<int>(std::floor(psi / sector)) % n, j1 = (j + 1) % n;
      const Vector3 hole(d * std::cos(phi), d * std::sin(phi), z);
      const Index vj = arm.node(level, j), vj1 = arm.node(level, j1), centre = arm.node(level, n);
      if ((hole - position(vj)).norm() < 1e-9 * R) {
        holes[t] = vj;
        continue;
      }
      const Index h = cell_nodes + static_cast<Index>(extra.size());
      extra.push_back(hole);
      holes[t] = h;
      add_bar(h, centre);
      add_bar(h, vj);
      add_bar(h, vj1);
      // Out of the plate's plane: a stiff hinge about the spoke to the bracketing vertex
      // farther from the hole (so the hole is well off its axis), the vertex beyond it as the
      // other wing.
      const bool far_is_j1 = psi - j * sector < 0.5 * sector;
      const Index vk = far_is_j1 ? vj1 : vj;
      const Index other = far_is_j1 ? arm.node(level, (j + 2) % n) : arm.node(level, (j + n - 1) % n);
      const std::array<Index, 4> hn{centre, vk, h, other};
      const double angle = elements::dihedral_angle(position(hn[0]), position(hn[1]),
                                                    position(hn[2]), position(hn[3]),
                                                    sp.hinge_angle);
      hinges.push_back({hn, guide_kp, angle, (position(vk) - position(centre)).norm(), law,
                        sp.hinge_angle});
    }
    arm.holes.push_back(holes);
  }
  NodeMatrix X(cell_nodes + static_cast<Index>(extra.size()), 3);
  X.topRows(cell_nodes) = cm.nodes();
  for (std::size_t i = 0; i < extra.size(); ++i) X.row(cell_nodes + static_cast<Index>(i)) = extra[i];

  // The base guide, with its holes, is fixed.
  std::vector<std::uint8_t> fixed(static_cast<std::size_t>(3 * X.rows()), 0);
  auto fix = [&](Index node) { fixed[3 * node] = fixed[3 * node + 1] = fixed[3 * node + 2] = 1; };
  for (int j = 0; j <= n; ++j) fix(arm.node(0, j));
  for (Index h : arm.holes[0]) fix(h);

  // Tendons: hole t of every guide, base to tip, just taut.
  std::vector<Cable> cables;
  for (int t = 0; t < 3; ++t) {
    Cable c;
    elements::CablePoints p(m + 1, 3);
    for (int g = 0; g <= m; ++g) {
      c.nodes.push_back(arm.holes[g][t]);
      p.row(g) = X.row(arm.holes[g][t]);
    }
    c.stiffness = parameters.tendon_stiffness;
    c.rest_length = elements::cable_length(p);
    arm.slack_length[t] = c.rest_length;
    cables.push_back(std::move(c));
  }
  arm.model = Model(std::move(X), std::move(bars), std::move(hinges), std::move(fixed),
                    std::move(cables));
  if (parameters.contact_distance > 0.0) {
    // The exact tangent: the arm's paths are followed by Newton to 1e-6 mm, and their
    // stability read off the tangent's inertia; a projected one converges only linearly
    // (a ratio of 0.76 per iteration near a pulled arm's contacts) and hides instability.
    arm.model = arm.model.with_family(std::make_shared<SelfContactFamily>(
        panel_triangles(arm), parameters.contact_distance, parameters.contact_stiffness,
        SelfContactFamily::TangentForm::Exact));
  }
  return arm;
}

}  // namespace kresling::model
