#include "kresling/elements/anchor_spring.hpp"

namespace kresling::elements {

AnchorSpringResponse anchor_spring_response(const Vector3& x, const Vector3& anchor,
                                            const Vector3& k) {
  AnchorSpringResponse r;
  const Vector3 d = x - anchor;
  r.force = k.cwiseProduct(d);
  r.energy = 0.5 * d.dot(r.force);
  r.stiffness = k.asDiagonal();
  return r;
}

}  // namespace kresling::elements
