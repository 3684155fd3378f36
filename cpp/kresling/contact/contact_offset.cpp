// The squared distance between offset surfaces (contact_offset.hpp).

#include "kresling/contact/contact_offset.hpp"

#include <cmath>

namespace kresling::contact {

template <int N>
ScalarDerivatives<N> offset_squared_distance(const ScalarDerivatives<N>& distance, double offset,
                                             bool with_hessian) {
  if (offset == 0.0) return distance;  // no thickness: the barrier as without one
  ScalarDerivatives<N> out;
  const double d = std::sqrt(distance.value);
  const double gap = d - offset;
  if (!(gap > 0)) return out;  // faces touching or overlapping: not admissible
  const double first = gap / d;                        // ds_o/ds = 1 - offset / d
  out.value = gap * gap;
  out.gradient = first * distance.gradient;
  if (!with_hessian) return out;
  const double second = offset / (2.0 * d * d * d);    // d^2 s_o / ds^2
  out.hessian = first * distance.hessian +
                second * distance.gradient * distance.gradient.transpose();
  return out;
}

template ScalarDerivatives<3> offset_squared_distance<3>(const ScalarDerivatives<3>&, double,
                                                         bool);
template ScalarDerivatives<12> offset_squared_distance<12>(const ScalarDerivatives<12>&, double,
                                                           bool);

}  // namespace kresling::contact
