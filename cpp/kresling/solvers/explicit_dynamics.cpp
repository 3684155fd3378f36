#include "kresling/solvers/explicit_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/stable_time_step.hpp"

namespace kresling::solvers {

namespace {

// Steps of the run: the duration in whole steps of at most time_step.
long long step_count(const ExplicitOptions& o) {
  require_positive("time_step", o.time_step);
  require_positive("duration", o.duration);
  const double steps = std::ceil(o.duration / o.time_step * (1.0 - 1e-12));
  if (!(steps <= static_cast<double>(kMaxExplicitSteps))) {
    throw std::invalid_argument("duration / time_step = " + format_number(o.duration / o.time_step) +
                                " steps: at most " + std::to_string(kMaxExplicitSteps));
  }
  require_integer_in("record_every", o.record_every, 1, kMaxExplicitSteps);
  const long long n = std::max(1LL, static_cast<long long>(steps));
  if ((n + o.record_every - 1) / o.record_every > kMaxSteps) {
    throw std::invalid_argument("record_every = " + std::to_string(o.record_every) + " keeps " +
                                std::to_string((n + o.record_every - 1) / o.record_every) +
                                " of the " + std::to_string(n) + " steps: at most " +
                                std::to_string(kMaxSteps) + " (raise record_every)");
  }
  return n;
}

void refuse_unstable(const ExplicitOptions& o, const StableStep& stable) {
  if (o.time_step <= stable.time_step) return;
  throw std::invalid_argument(
      "time_step = " + format_number(o.time_step) + " s is above the explicit scheme's stable " +
      "step " + format_number(stable.time_step) + " s (the highest natural frequency is " +
      format_number(stable.omega_max) + " rad/s at the start): must be at most the stable " +
      "step, or use an implicit scheme");
}

}  // namespace

TimeHistory integrate_explicit(const model::Model& model, const VectorX& masses,
                               const TimeLoad& time_load, const ExplicitOptions& o, const VectorX& u0, const VectorX& v0) {
  const long long steps = step_count(o);
  require_positive("mass_damping", o.mass_damping, /*allow_zero=*/true);
  require_positive("stiffness_damping", o.stiffness_damping, /*allow_zero=*/true);
  check_motion_input(model, masses, time_load, u0, v0);
  for (const auto& family : model.families()) {
    if (family->limits_steps()) {
      throw std::invalid_argument(std::string("the model's ") + family->name() + " elements " +
                                  "limit each step (a barrier): explicit integration cannot " +
                                  "keep them; use an implicit scheme");
    }
  }
  const Index n = model.num_dofs();
  VectorX u = u0.size() ? u0 : VectorX::Zero(n), v = v0.size() ? v0 : VectorX::Zero(n);
  VectorX inverse_mass = VectorX::Zero(n);
  std::vector<Index> supported;
  for (Index i = 0; i < n; ++i) {
    if (model.fixed()[i]) {
      u[i] = v[i] = 0.0;
      supported.push_back(i);
    } else {
      inverse_mass[i] = 1.0 / masses[i];
    }
  }
  StableStep stable;
  try {
    stable = stable_time_step(model, masses, u, o.mass_damping, o.stiffness_damping);
  } catch (const std::invalid_argument& error) {  // name the start, as the caller gave it
    throw std::invalid_argument(std::string("initial displacement: ") + error.what());
  }
  refuse_unstable(o, stable);
  const double dt = o.duration / static_cast<double>(steps);

  // Every DOF assembled (the supports' reactions are recorded); the tangent only once, for
  // the stiffness-proportional damping K0.
  assembly::Workspace workspace(model, assembly::all_dofs(n), 0.0, assembly::Storage::Lower);
  assembly::Assembler assembler(model, workspace);
  VectorX force;
  assembly::Energies energies = assembler.assemble(u, force, o.stiffness_damping != 0.0);
  const assembly::SparseMatrix k0 = o.stiffness_damping != 0.0 ? assembler.matrix()
                                                               : assembly::SparseMatrix();
  VectorX cv(n), kv(n);
  auto damping = [&](const VectorX& velocity) {
    cv.noalias() = o.mass_damping * masses.cwiseProduct(velocity);
    if (o.stiffness_damping != 0.0) {
      kv.noalias() = k0.selfadjointView<Eigen::Lower>() * velocity;
      cv += o.stiffness_damping * kv;
    }
  };

  TimeHistory h;
  h.stable_time_step = stable.time_step;
  h.time_step = dt;
  h.path.constraint_dofs = supported;
  h.path.families = family_names(model);
  VectorX load = time_load.at(0.0, n), next_load(n);
  damping(v);
  VectorX a = inverse_mass.cwiseProduct(load - force - cv);
  VectorX half = v + 0.5 * dt * a;  // v_{1/2}
  const double start_energy = 0.5 * v.dot(masses.cwiseProduct(v)) + energies.total();
  double work = 0.0, dissipated = 0.0, put_in = std::abs(start_energy);
  for (long long k = 1; k <= steps; ++k) {
    if ((k & 63) == 0) check_interrupt();
    const double t = (k == steps) ? o.duration : static_cast<double>(k) * dt;
    u.noalias() += dt * half;
    energies = assembler.assemble(u, force, false);
    next_load = time_load.at(t, n);
    const double dw = 0.5 * dt * half.dot(load + next_load);
    work += dw;
    put_in += std::abs(dw);
    damping(half);
    dissipated += dt * half.dot(cv);
    a = inverse_mass.cwiseProduct(next_load - force - cv);
    v = half + 0.5 * dt * a;
    half = v + 0.5 * dt * a;
    load.swap(next_load);
    const double kinetic = 0.5 * v.dot(masses.cwiseProduct(v)), strain = energies.total();
    const bool finite = std::isfinite(kinetic) && std::isfinite(strain) && u.allFinite();
    // The energy at a whole step is half a step ahead of the work summed so far (v_n holds
    // dt a_n / 2 of the current load): that half step's work is in play too.
    const double ahead = 0.5 * dt * std::abs(v.dot(load));
    const bool grown = kinetic + strain > kEnergyGrowthLimit * (put_in + ahead);
    const bool last = k == steps || !finite || grown;
    if (last || k % o.record_every == 0) {
      PathStep step;
      step.load_factor = t;
      step.displacement = u;
      step.constraint_force.resize(static_cast<Index>(supported.size()));
      for (std::size_t i = 0; i < supported.size(); ++i) {
        step.constraint_force[static_cast<Index>(i)] = force[supported[i]];
      }
      step.energies = energies.vector();
      h.path.steps.push_back(std::move(step));
      h.velocity.push_back(v);
      h.kinetic.push_back(kinetic);
      h.strain.push_back(strain);
      h.dissipated.push_back(dissipated);
      h.work.push_back(work);
    }
    h.path.attempted_increments = static_cast<int>(std::min<long long>(k, 2147483647LL));
    if (!finite || grown) {
      h.path.failed_increment = h.path.attempted_increments;
      h.path.message = "unstable at t = " + format_number(t) + " s: " +
                       (finite ? "the energy grew to " + format_number(kinetic + strain) +
                                     " N mm, over " + format_number(kEnergyGrowthLimit) +
                                     " times the " + format_number(put_in + ahead) +
                                     " N mm put in (the tangent stiffened beyond the start's "
                                     "stable step: take a smaller time_step)"
                              : std::string("the state is not finite"));
      return h;
    }
    if (o.stop && (last || k % o.record_every == 0) && o.stop(h.path.steps.back())) break;
  }
  h.path.completed = true;
  return h;
}

}  // namespace kresling::solvers
