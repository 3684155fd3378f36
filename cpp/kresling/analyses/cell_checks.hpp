#pragma once
/// \file cell_checks.hpp
/// What the analyses of a built cell (bending, snap-through) require of a design: that the
/// state they test is not folded flat. The model's hinge angles come from MERLIN2's
/// arccosine, whose error near a flat fold is ~1e-16 / theta rad (~1e-8 rad at theta =
/// 1e-8): a facet angle Psi below kMinFacetAngle is not resolved, and the enhanced linear
/// law turns that error into forces of any size (1e11 N spikes, 1e13 N "snap forces").

#include <string>

#include "kresling/core/check.hpp"
#include "kresling/geometry/design.hpp"

namespace kresling::analyses {

/// Smallest facet angle Psi [rad] of a state an analysis runs in: its hinge angles are then
/// known to ~1e-10 relative (the error ~1e-16 / Psi^2 of the arccosine).
inline constexpr double kMinFacetAngle = 1e-6;

/// Throw std::invalid_argument unless the cell of `design` in `state` (0 contracted, 1
/// extended) has a facet angle of at least kMinFacetAngle; `test` names the analysis. The
/// message names Lc for the contracted state (Lc = 0 folds it flat) and lam for the extended
/// one (lam -> 0.5 flattens it).
inline void check_not_flat(const geometry::Design& design, int state, const std::string& test) {
  const auto& p = design.parameters();
  const auto& d = design.derived();
  const double psi = state == 0 ? d.psi_con : d.psi_ext;
  if (psi >= kMinFacetAngle) return;
  const std::string resolution =
      " to within the model's resolution: Psi_" + std::string(state == 0 ? "con" : "ext") +
      " = " + format_number(psi) + " rad, must be >= " + format_number(kMinFacetAngle) +
      " rad (hinge angles near a flat fold carry errors up to ~1e-8 rad)";
  if (state == 0) {
    throw_invalid("Lc", p.Lc,
                  "> 0 for " + test + ", and large enough that the contracted cell is not flat" +
                      resolution);
  }
  throw_invalid("lam", p.lam,
                "further from 0.5 for " + test + ": the extended cell is flat" + resolution);
}

}  // namespace kresling::analyses
