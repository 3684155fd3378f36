#include "kresling/solvers/time_control.hpp"

#include "kresling/core/check.hpp"

namespace kresling::solvers {

TimeControl::TimeControl(const model::Model& model, const TimeLoad& load)
    : model_(model), load_(load), supported_(supported_dofs(model)) {}

std::string TimeControl::failure_message(int, int, double t, int max_bisections,
                                         const std::string& reason) const {
  return "time step at t = " + format_rounded(t) + " s failed after " +
         std::to_string(max_bisections) + " halvings: " + reason;
}

void TimeControl::record_motion(const VectorX& velocity, double kinetic, double strain,
                                double dissipated, double work) {
  history.velocity.push_back(velocity);
  history.kinetic.push_back(kinetic);
  history.strain.push_back(strain);
  history.dissipated.push_back(dissipated);
  history.work.push_back(work);
}

}  // namespace kresling::solvers
