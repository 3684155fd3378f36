#include "kresling/analyses/arm_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kresling/core/check.hpp"
#include "kresling/elements/cable.hpp"
#include "kresling/solvers/cable_pull_control.hpp"
#include "kresling/solvers/energy_minimum.hpp"
#include "kresling/solvers/halving_steps.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"

namespace kresling::analyses {

void check_pulls(const Pulls& pulls, const model::Arm& arm, const std::string& name) {
  for (int t = 0; t < 3; ++t) {
    const std::string item = name + "[" + std::to_string(t) + "]";
    require_finite(item, pulls[t]);
    if (pulls[t] < 0.0) {
      throw std::invalid_argument(
          item + " = " + format_number(pulls[t]) + " mm makes tendon " + std::to_string(t + 1) +
          " longer than its slack length (" + format_number(arm.slack_length[t]) +
          " mm, its path as built): a pull must be >= 0 (a tendon cannot push)");
    }
    if (!(pulls[t] < arm.slack_length[t])) {
      throw_invalid(item, pulls[t],
                    "below tendon " + std::to_string(t + 1) + "'s slack length " +
                        format_number(arm.slack_length[t]) + " mm (its rest length must stay positive)");
    }
  }
}

struct ArmSolver::Impl {
  std::vector<Index> rows;
  std::unique_ptr<model::Model> current;     // the arm with the pulls being solved
  Pulls current_pulls{-1.0, -1.0, -1.0};
  std::unique_ptr<assembly::Assembler> assembler;
  solvers::TangentSolver solver;
  std::unique_ptr<assembly::Assembler> full;  // full storage, no shift: energy descent

  // Bind the assemblers to the arm with these pulls (tendon rest lengths).
  void set_pulls(const model::Arm& arm, const Pulls& pulls) {
    if (pulls == current_pulls) return;
    std::vector<double> rest(3);
    for (int t = 0; t < 3; ++t) rest[t] = arm.slack_length[t] - pulls[t];
    auto next = std::make_unique<model::Model>(arm.model.with_cable_rest_lengths(rest));
    assembler->rebind(*next);
    if (full) full->rebind(*next);
    current = std::move(next);
    current_pulls = pulls;
  }
  // Factorise the tangent just assembled, its pattern first told to the solver (contact
  // pairs change it between solves).
  solvers::FactorizeInfo factorize_tangent() {
    solvers::follow_pattern(*assembler, solver);
    return solver.factorize(assembler->matrix());
  }
  // Bind the assemblers to a model of their own again (after a path follower bound them
  // to its control's), with the pulls they had.
  void rebind(const model::Arm& arm) {
    const Pulls pulls = current_pulls;
    current_pulls = {-1.0, -1.0, -1.0};
    set_pulls(arm, pulls);
  }
};

ArmSolver::ArmSolver(const model::Arm& arm, ArmOptions options)
    : arm_(&arm), options_(options), impl_(std::make_unique<Impl>()) {
  if (options_.steps < 1) throw_invalid("steps", options_.steps, "an integer >= 1");
  if (options_.max_bisections < 0 || options_.max_bisections > 30) {
    throw_invalid("max_bisections", options_.max_bisections, "an integer in [0, 30]");
  }
  require_positive("tolerance", options_.newton.tolerance);
  if (options_.newton.max_iterations < 1) {
    throw_invalid("max_iterations", options_.newton.max_iterations, "an integer >= 1");
  }
  require_positive("shift", options_.shift, true);
  impl_->rows = assembly::unmasked_dofs(arm.model.fixed());
  impl_->current = std::make_unique<model::Model>(arm.model);
  impl_->current_pulls = {0.0, 0.0, 0.0};
  impl_->assembler = std::make_unique<assembly::Assembler>(*impl_->current, impl_->rows,
                                                           options_.shift, assembly::Storage::Lower);
}

ArmSolver::~ArmSolver() = default;

namespace {

VectorX tip_force(const model::Arm& arm, const Vector3& load) {
  VectorX f = VectorX::Zero(arm.model.num_dofs());
  f.segment<3>(3 * arm.tip_node()) = load;
  return f;
}

Pulls lerp(const Pulls& a, const Pulls& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// The state at u of `model`, the arm with these pulls (its tendons' rest lengths) and tip
// load (no solve).
ArmState state_at(const model::Arm& arm, const model::Model& model, const VectorX& u,
                  const Pulls& pulls, const Vector3& load) {
  ArmState s;
  s.displacement = u;
  s.pulls = pulls;
  s.load = load;
  const NodeMatrix x = arm.model.deformed(u);
  s.tip_position = x.row(arm.tip_node()).transpose();
  s.tip_displacement = u.segment<3>(3 * arm.tip_node());
  const auto es = assembly::element_state(model, u);
  for (int t = 0; t < 3; ++t) {
    s.tension[t] = es["cable_tension"][t];
    s.tendon_length[t] = es["cable_length"][t];
  }
  s.energy = es["bar_energy"].sum() + es["hinge_energy"].sum() + es["cable_energy"].sum();
  const int n = arm.n;
  std::vector<Vector3> centroid(static_cast<std::size_t>(2 * arm.modules + 1));
  for (int k = 0; k <= 2 * arm.modules; ++k) {
    Vector3 c = Vector3::Zero();
    for (int j = 0; j < n; ++j) c += x.row(arm.node(k, j)).transpose();
    centroid[k] = c / n;
  }
  const double threshold = 0.5 * (arm.cell_extended + arm.cell_contracted);
  for (int i = 0; i < 2 * arm.modules; ++i) {
    const double h = (centroid[i + 1] - centroid[i]).norm();
    s.cell_height.push_back(h);
    s.cell_states.push_back(h > threshold ? 1 : 0);
  }
  for (int k = 0; k < arm.modules; ++k) {
    s.module_length.push_back(
        (x.row(arm.node(2 * k + 2, n)) - x.row(arm.node(2 * k, n))).norm());
  }
  return s;
}


}  // namespace

ArmState ArmSolver::evaluate(const VectorX& u, const Pulls& pulls, const Vector3& load) {
  impl_->set_pulls(*arm_, pulls);
  return state_at(*arm_, *impl_->current, u, pulls, load);
}

ArmState ArmSolver::built() {
  ArmState s = evaluate(VectorX::Zero(arm_->model.num_dofs()), {0.0, 0.0, 0.0});
  VectorX force;
  impl_->assembler->assemble(s.displacement, force, true);
  s.negative_eigenvalues = impl_->factorize_tangent().negative_eigenvalues;
  return s;
}

void check_rest_lengths(const Pulls& pulls, const model::Arm& arm, const std::string& name) {
  for (int t = 0; t < 3; ++t) {
    const std::string item = name + "[" + std::to_string(t) + "]";
    require_finite(item, pulls[t]);
    if (!(pulls[t] < arm.slack_length[t])) {
      throw_invalid(item, pulls[t],
                    "below tendon " + std::to_string(t + 1) + "'s slack length " +
                        format_number(arm.slack_length[t]) + " mm (its rest length must stay positive)");
    }
  }
}

ArmPath ArmSolver::ramp(const ArmState& start, const Pulls& pulls_to, const Vector3& load_to,
                        const ArmEvent& event) {
  const model::Arm& arm = *arm_;
  check_rest_lengths(pulls_to, arm);
  if (!load_to.allFinite()) throw std::invalid_argument("load: contains NaN or inf");
  ArmPath path;
  path.parameter.push_back(0.0);
  path.states.push_back(start);
  // The path follower under the tendons' pulls and the tip load, in increments halved on
  // failure and doubled back on success, each started from the secant of the last two
  // equilibria.
  auto as_vector = [](const Pulls& p) { return std::vector<double>(p.begin(), p.end()); };
  solvers::CablePullControl control(
      arm.model, std::vector<double>(arm.slack_length.begin(), arm.slack_length.end()),
      as_vector(start.pulls), as_vector(pulls_to), tip_force(arm, start.load),
      tip_force(arm, load_to));
  solvers::HalvingSteps policy(options_.steps, options_.max_bisections);
  solvers::FollowOptions follow;
  follow.newton = options_.newton;
  follow.secant_start = true;
  // An increment is accepted only at a stable equilibrium with every cell in its state and
  // the caller's event not reached; the last check's findings name the end of the path.
  ArmState pending;
  int checked = -1;  // the attempt the findings below belong to
  bool is_event = false;
  int jumped = -1;
  solvers::PathResult result;
  follow.check = [&](const solvers::Increment& increment, const VectorX& u,
                     const solvers::NewtonOutcome& out) -> std::string {
    const std::vector<double> pulls = control.pulls_at(increment.to);
    const Pulls p{pulls[0], pulls[1], pulls[2]};
    const Vector3 load = start.load + increment.to * (load_to - start.load);
    checked = result.attempted_increments;
    is_event = false;
    jumped = -1;
    // The follower has bound the assembler to the control's model at increment.to.
    pending = state_at(arm, impl_->assembler->model(), u, p, load);
    pending.negative_eigenvalues = out.negative_eigenvalues;
    pending.iterations = out.iterations;
    if (out.negative_eigenvalues != 0) {
      return out.negative_eigenvalues < 0
                 ? "the tangent is singular (stability unknown)"
                 : "the equilibrium is unstable (" + std::to_string(out.negative_eigenvalues) +
                       " negative eigenvalue" + (out.negative_eigenvalues > 1 ? "s" : "") + ")";
    }
    const std::vector<int>& before = path.states.back().cell_states;
    for (std::size_t i = 0; i < pending.cell_states.size(); ++i) {
      if (pending.cell_states[i] != before[i]) {
        jumped = static_cast<int>(i);
        return "cell " + std::to_string(i) + " (module " + std::to_string(i / 2) +
               ") jumped to its " + (pending.cell_states[i] ? "extended" : "contracted") + " state";
      }
    }
    if (event && !(event(pending) > 0.0)) {
      is_event = true;
      return "the event was reached";
    }
    return "";
  };
  follow.stop = [&](const solvers::PathStep& step) {
    path.parameter.push_back(step.load_factor);
    path.states.push_back(std::move(pending));
    return false;
  };
  VectorX u = start.displacement;
  solvers::follow_path(control, *impl_->assembler, impl_->solver, u, policy, follow, result);
  impl_->rebind(arm);  // off the control's models, which end here
  path.attempted_increments = result.attempted_increments;
  if (result.completed) {
    path.completed = true;
    return path;
  }
  // Findings of a check belong to the failed attempt only if it was the last one.
  if (checked != result.attempted_increments) is_event = false, jumped = -1;
  std::string reason = policy.reason();
  const double t = path.parameter.back(), tn = policy.failed_at();
  // Newton may stall where a tendon is about to go slack (its stiffness switches off at
  // zero tension). If the event, extrapolated from the last two equilibria, is reached
  // within this last increment, or the last equilibrium is within 1 % of it (of its value
  // at the start), that is what happened.
  const std::size_t k = path.states.size();
  if (!is_event && event && k >= 2) {
    const double e1 = event(path.states[k - 1]), e0 = event(path.states[k - 2]);
    const double t1 = path.parameter[k - 1], t0 = path.parameter[k - 2];
    if (e1 + (e1 - e0) / (t1 - t0) * (tn - t1) <= 0.0 || e1 <= 0.01 * event(path.states[0])) {
      reason += " (at the event: the last equilibrium is within 1 % of it)";
      is_event = true;
    }
  }
  path.end_parameter = tn;
  path.event = is_event;
  path.lost = !is_event;
  if (path.lost) {
    path.critical_cell = jumped;
    if (jumped < 0) {
      const std::vector<double> dh = softest_mode_heights(path.states.back());
      double largest = 0.0;
      for (std::size_t i = 0; i < dh.size(); ++i) {
        if (std::abs(dh[i]) > largest) largest = std::abs(dh[i]), path.critical_cell = static_cast<int>(i);
      }
    }
  }
  path.message = (is_event ? std::string("event") : std::string("equilibrium lost")) +
                 " between t = " + format_number(t) + " and " + format_number(tn) + ": " + reason;
  return path;
}

ArmRelease ArmSolver::release(const ArmState& from, const Pulls& pulls) {
  check_rest_lengths(pulls, *arm_);
  if (!impl_->full) {
    impl_->full = std::make_unique<assembly::Assembler>(*impl_->current, impl_->rows, 0.0,
                                                        assembly::Storage::Full);
  }
  impl_->set_pulls(*arm_, pulls);
  VectorX u = from.displacement;
  solvers::EnergyMinimumOptions o;
  o.max_step = 2.0;
  o.max_iterations = 2000;
  o.tolerance = options_.newton.tolerance;
  const solvers::EnergyMinimum r = solvers::minimize_energy(*impl_->full, u, o);
  ArmRelease out;
  out.converged = r.converged;
  out.message = r.failure;
  out.state = evaluate(u, pulls);
  out.state.negative_eigenvalues = r.negative_eigenvalues;
  out.state.iterations = r.iterations;
  return out;
}

Eigen::Matrix3d ArmSolver::tip_compliance(const ArmState& state) {
  impl_->set_pulls(*arm_, state.pulls);
  VectorX force;
  impl_->assembler->assemble(state.displacement, force, true);
  const auto info = impl_->factorize_tangent();
  Eigen::Matrix3d C = Eigen::Matrix3d::Constant(ArmState::kNaN);
  if (!info.ok) return C;
  const Index tip = arm_->tip_node();
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(impl_->assembler->size(), 3);
  for (int k = 0; k < 3; ++k) B(impl_->rows[3 * tip + k], k) = 1.0;
  const Eigen::MatrixXd X = impl_->solver.solve(B);
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) C(k, l) = X(impl_->rows[3 * tip + k], l);
  }
  return C;
}

std::vector<double> ArmSolver::softest_mode_heights(const ArmState& state) {
  impl_->set_pulls(*arm_, state.pulls);
  VectorX force;
  impl_->assembler->assemble(state.displacement, force, true);
  std::vector<double> out;
  if (!impl_->factorize_tangent().ok) return out;
  // Inverse iteration: converges to the eigenvector of the smallest eigenvalue, fast where
  // that one is far below the next (near a limit point).
  VectorX x = VectorX::Ones(impl_->assembler->size());
  for (int k = 0; k < 40; ++k) {
    x = impl_->solver.solve(x);
    x /= x.norm();
  }
  VectorX mode = VectorX::Zero(arm_->model.num_dofs());
  solvers::scatter_add_rows(*impl_->assembler, x, mode);
  mode /= mode.cwiseAbs().maxCoeff();
  const ArmState a = evaluate(state.displacement + 1e-3 * mode, state.pulls, state.load);
  const ArmState b = evaluate(state.displacement - 1e-3 * mode, state.pulls, state.load);
  for (std::size_t i = 0; i < a.cell_height.size(); ++i) {
    out.push_back((a.cell_height[i] - b.cell_height[i]) / 2e-3);
  }
  return out;
}

Eigen::Matrix3d ArmSolver::tension_sensitivity(const ArmState& state) {
  const model::Arm& arm = *arm_;
  impl_->set_pulls(arm, state.pulls);
  VectorX force;
  impl_->assembler->assemble(state.displacement, force, true);
  const auto info = impl_->factorize_tangent();
  Eigen::Matrix3d S = Eigen::Matrix3d::Constant(ArmState::kNaN);
  if (!info.ok) return S;
  const NodeMatrix x = arm.model.deformed(state.displacement);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(impl_->assembler->size(), 3);
  double a[3], b[3];
  for (int t = 0; t < 3; ++t) {
    const auto& c = impl_->current->cables()[t];
    elements::CablePoints p(static_cast<Index>(c.nodes.size()), 3);
    for (std::size_t i = 0; i < c.nodes.size(); ++i) p.row(static_cast<Index>(i)) = x.row(c.nodes[i]);
    const auto r = elements::cable_response(p, c.stiffness, c.rest_length, false);
    const double l = r.length, L = c.rest_length;
    a[t] = r.taut ? c.stiffness * (3 * l * l - L * L) / (2 * L * L * L) : 0.0;  // dT/dl
    b[t] = -a[t] * l / L;                                                        // dT/dL
    const VectorX g = elements::cable_length_gradient(p);
    for (std::size_t i = 0; i < c.nodes.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        const Index row = impl_->rows[3 * c.nodes[i] + k];
        if (row >= 0) G(row, t) += g[3 * static_cast<Index>(i) + k];
      }
    }
  }
  const Eigen::MatrixXd KG = impl_->solver.solve(G);
  const Eigen::Matrix3d GKG = G.transpose() * KG;
  // dT_i/dL_j = b_i delta_ij - a_i b_j g_i^T K^-1 g_j; a pull shortens L: dT/dpull = -dT/dL.
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) S(i, j) = -((i == j ? b[i] : 0.0) - a[i] * b[j] * GKG(i, j));
  }
  return S;
}

ArmPath ArmSolver::pretension(const ArmState& start, double tension, double tolerance) {
  require_positive("pretension", tension);
  ArmPath path;
  path.parameter.push_back(0.0);
  path.states.push_back(start);
  ArmState s = start;
  for (int iteration = 0; iteration < 40; ++iteration) {
    Eigen::Vector3d residual;
    for (int t = 0; t < 3; ++t) residual[t] = tension - s.tension[t];
    if (residual.cwiseAbs().maxCoeff() <= tolerance * tension + 1e-9) {
      path.completed = true;
      return path;
    }
    Eigen::Matrix3d S = tension_sensitivity(s);
    for (int t = 0; t < 3; ++t) {
      // A slack tendon: take its own stiffness EA / L (the pull that would tension it alone).
      if (s.tension[t] == 0.0) {
        S.row(t).setZero();
        S(t, t) = arm_->model.cables()[t].stiffness / (arm_->slack_length[t] - s.pulls[t]);
      }
    }
    const Eigen::Vector3d step = S.fullPivLu().solve(residual);
    if (!step.allFinite()) {
      // Tendons so soft (EA = 1e-310 N) that the pull reaching the tension overflows: the
      // pretension cannot be reached, which is the caller's to report, not a bad pull.
      path.message =
          "pretension: the pulls that would reach it are not finite (the tendons' stiffness "
          "EA is too small)";
      return path;
    }
    Pulls next = s.pulls;
    for (int t = 0; t < 3; ++t) next[t] = std::max(0.0, s.pulls[t] + step[t]);
    ArmPath leg = ramp(s, next, s.load);
    path.attempted_increments += leg.attempted_increments;
    if (!leg.completed) {
      path.lost = leg.lost;
      path.message = "pretension: " + leg.message;
      path.end_parameter = ArmState::kNaN;
      return path;
    }
    s = leg.states.back();
    path.parameter.push_back(static_cast<double>(iteration + 1));
    path.states.push_back(s);
  }
  path.message = "pretension: no convergence in 40 iterations";
  return path;
}

// ---------------------------------------------------------------------------------------

ArmLoadResult arm_tip_load(ArmSolver& solver, const Vector3& load, const Pulls& pulls,
                           double pretension) {
  check_pulls(pulls, solver.arm());
  if (!load.allFinite()) throw std::invalid_argument("load: contains NaN or inf");
  require_positive("pretension", pretension, /*allow_zero=*/true);
  ArmLoadResult r;
  ArmState start = solver.built();
  if (pretension > 0.0) {
    const ArmPath p = solver.pretension(start, pretension);
    if (!p.completed) {
      r.message = p.message;
      r.pretensioned = p.states.back();
      return r;
    }
    start = p.states.back();
  }
  r.pretensioned = start;
  r.pretension_pulls = start.pulls;
  Pulls to = start.pulls;
  for (int t = 0; t < 3; ++t) to[t] += pulls[t];
  r.path = solver.ramp(start, to, load);
  r.completed = r.path.completed;
  r.message = r.path.message;
  return r;
}

ArmSnapResult arm_pull_until_snap(ArmSolver& solver, const ArmState& start, const Pulls& direction,
                                  double max_pull) {
  const model::Arm& arm = solver.arm();
  require_positive("max_pull", max_pull);
  double largest = 0.0;
  for (int t = 0; t < 3; ++t) {
    require_finite("direction[" + std::to_string(t) + "]", direction[t]);
    if (direction[t] < 0.0) {
      throw_invalid("direction[" + std::to_string(t) + "]", direction[t],
                    ">= 0 (a pull shortens a tendon; it cannot lengthen it beyond its slack length)");
    }
    largest = std::max(largest, direction[t]);
  }
  if (!(largest > 0.0)) throw std::invalid_argument("direction: pull at least one tendon");
  Pulls to = start.pulls;
  for (int t = 0; t < 3; ++t) to[t] += max_pull * direction[t] / largest;
  check_pulls(to, arm, "pulls");
  ArmSnapResult r;
  r.path = solver.ramp(start, to, start.load);
  if (r.path.completed) {
    r.message = "no module snapped up to a pull of " + format_number(max_pull) + " mm";
    return r;
  }
  if (!r.path.lost) {
    r.message = r.path.message;
    return r;
  }
  const ArmState& last = r.path.states.back();
  r.snapped = true;
  r.pulls = last.pulls;
  r.pull = std::max({last.pulls[0] - start.pulls[0], last.pulls[1] - start.pulls[1],
                     last.pulls[2] - start.pulls[2]});
  r.tension = last.tension;
  r.tension_sum = last.tension[0] + last.tension[1] + last.tension[2];
  r.message = r.path.message;
  if (start.load.norm() != 0.0) {
    r.message += "; not released (the release holds no tip load)";
    return r;
  }
  const Pulls past = lerp(start.pulls, to, r.path.end_parameter);
  const ArmRelease rel = solver.release(last, past);
  r.release_converged = rel.converged;
  r.after = rel.state;
  r.cell_states_after = rel.state.cell_states;
  for (std::size_t i = 0; i < last.cell_states.size(); ++i) {
    if (rel.state.cell_states[i] != last.cell_states[i]) r.snapped_cells.push_back(static_cast<int>(i));
  }
  if (!r.snapped_cells.empty()) r.snapped_module = r.snapped_cells.front() / 2;
  for (int k = 0; k < arm.modules; ++k) {
    const int a = rel.state.cell_states[2 * k], b = rel.state.cell_states[2 * k + 1];
    r.configuration_after += a == b ? static_cast<char>('0' + a) : 'x';
  }
  if (!rel.converged) r.message += "; release: " + rel.message;
  return r;
}

ArmCapacityResult arm_load_capacity(ArmSolver& solver, const ArmState& pretensioned,
                                    const Vector3& direction, double max_load) {
  require_positive("max_load", max_load);
  if (!direction.allFinite() || !(direction.norm() > 0.0)) {
    throw std::invalid_argument("direction: must be a finite, non-zero vector");
  }
  const Vector3 e = direction.normalized();
  std::vector<int> taut;
  for (int t = 0; t < 3; ++t) {
    if (pretensioned.tension[t] > 0.0) taut.push_back(t);
  }
  ArmEvent event;
  if (!taut.empty()) {
    event = [taut](const ArmState& s) {
      double smallest = INFINITY;
      for (int t : taut) smallest = std::min(smallest, s.tension[t]);
      return smallest;
    };
  }
  ArmCapacityResult r;
  r.path = solver.ramp(pretensioned, pretensioned.pulls, pretensioned.load + max_load * e, event);
  const ArmState& last = r.path.states.back();
  const double reached = (last.load - pretensioned.load).norm();
  r.message = r.path.message;
  if (r.path.completed) {
    r.limit = "none";
    r.load = max_load;
  } else if (r.path.event) {
    r.limit = "slack";
    r.load = reached;
    double smallest = INFINITY;
    for (int t : taut) {
      if (last.tension[t] < smallest) smallest = last.tension[t], r.tendon = t;
    }
  } else {
    r.limit = "snap";
    r.load = reached;
    if (r.path.critical_cell >= 0) r.module = r.path.critical_cell / 2;
  }
  return r;
}

}  // namespace kresling::analyses
