#include "kresling/solvers/time_control.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "kresling/core/check.hpp"
#include "kresling/model/hinge_family.hpp"

namespace kresling::solvers {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}  // namespace

DrivenRestAngles::DrivenRestAngles(const model::Model& model, const RestAngleSchedule& schedule)
    : base_(model), schedule_(schedule) {
  if (schedule.empty()) return;
  scratch_ = model.hinges();
  const auto num_hinges = static_cast<Index>(scratch_.size());
  for (std::size_t k = 0; k < schedule.terms.size(); ++k) {
    const auto& term = schedule.terms[k];
    const std::string name = "actuation[" + std::to_string(k) + "]";
    const auto n = static_cast<Index>(term.hinges.size());
    if (n == 0) throw std::invalid_argument(name + ": drives no hinge");
    if (term.start.size() != n || term.delta.size() != n) {
      throw std::invalid_argument(name + ": needs one start and one delta per hinge (" +
                                  std::to_string(n) + ")");
    }
    for (Index i = 0; i < n; ++i) {
      const Index h = term.hinges[static_cast<std::size_t>(i)];
      if (h < 0 || h >= num_hinges) {
        throw std::invalid_argument(name + ": hinge " + std::to_string(h) +
                                    " is not a hinge of the model (" +
                                    std::to_string(num_hinges) + " hinges)");
      }
      require_finite(name + ": start", term.start[i]);
      require_finite(name + ": delta", term.delta[i]);
    }
  }
}

void DrivenRestAngles::set_rest_angles(double t) {
  for (std::size_t n = 0; n < schedule_.terms.size(); ++n) {
    const auto& term = schedule_.terms[n];
    const double f = term.factor ? term.factor(t) : 1.0;
    if (!std::isfinite(f)) {
      throw std::invalid_argument("actuation[" + std::to_string(n) +
                                  "]: factor not finite at t = " + format_number(t) + " s");
    }
    for (std::size_t i = 0; i < term.hinges.size(); ++i) {
      const auto k = static_cast<Index>(i);
      const double rest = term.start[k] + f * term.delta[k];
      if (!(rest >= 0.0 && rest < kTwoPi)) {  // a fold beyond flat
        throw std::invalid_argument(
            "actuation[" + std::to_string(n) + "]: hinge " + std::to_string(term.hinges[i]) +
            " at t = " + format_number(t) + " s: rest angle = " + format_number(rest) +
            " is invalid: must be in [0, 2 pi) rad");
      }
      scratch_[static_cast<std::size_t>(term.hinges[i])].rest_angle = rest;
    }
  }
}

const model::Model& DrivenRestAngles::model_at(double t) {
  if (!driven()) return base_;
  set_rest_angles(t);
  current_.emplace(base_.with_family(std::make_shared<model::HingeFamily>(scratch_)));
  return *current_;
}

double DrivenRestAngles::hinge_energy(double t, const VectorX& u) {
  if (!driven()) return 0.0;
  set_rest_angles(t);
  force_.setZero(u.size());
  model::AssemblyTarget target{force_};
  return model::HingeFamily(scratch_).assemble(base_.nodes(), u, target);
}

const RestAngleSchedule TimeControl::kNoActuation{};

TimeControl::TimeControl(const model::Model& model, const TimeLoad& load,
                         const RestAngleSchedule& actuation)
    : model_(model), load_(load), supported_(supported_dofs(model)), driven_(model, actuation) {}

std::string TimeControl::failure_message(int, int, double t, int max_bisections,
                                         const std::string& reason) const {
  return "time step at t = " + format_rounded(t) + " s failed after " +
         std::to_string(max_bisections) + " halvings: " + reason;
}

void TimeControl::record_motion(const VectorX& velocity, double kinetic, double strain,
                                double dissipated, double work, double actuation_work) {
  history.velocity.push_back(velocity);
  history.kinetic.push_back(kinetic);
  history.strain.push_back(strain);
  history.dissipated.push_back(dissipated);
  history.work.push_back(work);
  history.actuation_work.push_back(actuation_work);
}

}  // namespace kresling::solvers
