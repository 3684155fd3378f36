#include "kresling/model/merlin2_rest_angle.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/model/octave_arithmetic.hpp"

namespace kresling::model {

namespace {

// Three-term dot product summed left to right, as the reference BLAS does.
double dot3(const Vector3& x, const Vector3& y) {
  double s = x[0] * y[0];
  s += x[1] * y[1];
  s += x[2] * y[2];
  return s;
}

Vector3 cross3(const Vector3& x, const Vector3& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

}  // namespace

double merlin2_rest_angle(const Vector3& a, const Vector3& b, const Vector3& c,
                          const Vector3& d) {
  const Vector3 rkj = b - a, rij = c - a, rkl = b - d;
  const Vector3 m = cross3(rij, rkj), n = cross3(rkj, rkl);
  const double side = dot3(n, rij);
  const double sign = std::abs(side) > 1e-8 ? (side > 0.0 ? 1.0 : (side < 0.0 ? -1.0 : 0.0)) : 1.0;
  const double cosine = dot3(m, n) / (octave_norm(m) * octave_norm(n));
  // The real part of the arccosine, as MATLAB's real(acos(.)) gives outside [-1, 1].
  const double angle = cosine >= 1.0 ? 0.0 : (cosine <= -1.0 ? M_PI : std::acos(cosine));
  const double he = sign * angle;
  if (!(he < 0.0)) return he;
  // 2 pi + he rounds to 2 pi for |he| below ~4e-16 (a hinge folded flat): stay in [0, 2 pi).
  const double wrapped = 2.0 * M_PI + he;
  return wrapped < 2.0 * M_PI ? wrapped : std::nextafter(2.0 * M_PI, 0.0);
}

std::vector<double> merlin2_rest_angles(const NodeMatrix& nodes,
                                        const std::vector<std::array<Index, 4>>& hinges) {
  std::vector<double> out;
  out.reserve(hinges.size());
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    const auto& h = hinges[i];
    for (Index v : h) {
      if (v < 0 || v >= nodes.rows()) {
        throw std::invalid_argument("hinge " + std::to_string(i) + ": node " +
                                    std::to_string(v) + " is out of range");
      }
    }
    out.push_back(merlin2_rest_angle(nodes.row(h[0]), nodes.row(h[1]), nodes.row(h[2]),
                                     nodes.row(h[3])));
  }
  return out;
}

}  // namespace kresling::model
