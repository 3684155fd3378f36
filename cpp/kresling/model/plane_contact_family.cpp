#include "kresling/model/plane_contact_family.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/contact/contact_barrier.hpp"
#include "kresling/contact/contact_ccd.hpp"
#include "kresling/contact/contact_distance.hpp"

namespace kresling::model {

PlaneContactFamily::PlaneContactFamily(std::vector<Index> nodes, std::vector<ContactPlane> planes,
                                       double d_hat, double stiffness, double thickness)
    : nodes_(std::move(nodes)),
      planes_(std::move(planes)),
      d_hat_(d_hat),
      stiffness_(stiffness),
      offset_(thickness / 2.0) {}

std::vector<Index> PlaneContactFamily::element_dofs(std::size_t e) const {
  const Index n = nodes_[e / planes_.size()];
  return {3 * n, 3 * n + 1, 3 * n + 2};
}

void PlaneContactFamily::check(const NodeMatrix& X, double) const {
  require_positive("contact: distance", d_hat_);
  require_positive("contact: stiffness", stiffness_);
  require_positive("contact: thickness", 2.0 * offset_, true);
  for (std::size_t p = 0; p < planes_.size(); ++p) {
    const auto& plane = planes_[p];
    if (!plane.origin.allFinite() || !plane.normal.allFinite() || !(plane.normal.norm() > 0.0)) {
      throw std::invalid_argument("contact: plane " + std::to_string(p) +
                                  " needs a finite point and a finite, non-zero normal");
    }
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i] < 0 || nodes_[i] >= X.rows()) {
      throw std::invalid_argument("contact: node " + std::to_string(nodes_[i]) +
                                  " is out of range [0, " + std::to_string(X.rows()) + ")");
    }
    for (std::size_t p = 0; p < planes_.size(); ++p) {
      const double d = contact::point_plane_signed_distance(X.row(nodes_[i]).transpose(),
                                                             planes_[p].origin, planes_[p].normal);
      if (!(std::abs(d) > 0.0)) {
        throw std::invalid_argument("contact: node " + std::to_string(nodes_[i]) +
                                    " lies on plane " + std::to_string(p) +
                                    " at the start: a node must start clear of every plane");
      }
      if (!(std::abs(d) > offset_)) {
        throw std::invalid_argument(
            "contact: thickness = " + format_number(2.0 * offset_) + " mm is invalid: node " +
            std::to_string(nodes_[i]) + " starts " + format_number(std::abs(d)) +
            " mm from plane " + std::to_string(p) + ", within half the thickness; must be " +
            "below " + format_number(2.0 * std::abs(d)) + " mm");
      }
    }
  }
}

double PlaneContactFamily::assemble(const NodeMatrix& X, const VectorX& u,
                                    AssemblyTarget& target) const {
  double energy = 0.0;
  for (std::size_t e = 0; e < size(); ++e) {
    const Index node = nodes_[e / planes_.size()];
    const ContactPlane& plane = planes_[e % planes_.size()];
    const Vector3 p = position(X, u, node);
    const double gap =
        std::abs(contact::point_plane_signed_distance(p, plane.origin, plane.normal)) - offset_;
    if (gap >= d_hat_) continue;  // beyond d_hat the barrier is zero, with its derivatives
    const auto b = contact::point_plane_barrier(
        p, plane.origin, plane.normal, d_hat_, stiffness_,
        target.values ? contact::BarrierHessian::Projected : contact::BarrierHessian::None,
        offset_);
    energy += b.value;
    add_local_force(b.gradient, element_dofs(e), target.force);
    if (target.values) scatter_local_tangent(b.hessian, *target.slots, e, target.values);
  }
  return energy;
}

void PlaneContactFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  VectorX gap(static_cast<Index>(size())), energy(static_cast<Index>(size()));
  // The force each plane exerts on its node, minus the barrier's gradient (3 per pair): a
  // floor's reaction on a model is their sum (zero beyond d_hat).
  VectorX force = VectorX::Zero(3 * static_cast<Index>(size()));
  for (std::size_t e = 0; e < size(); ++e) {
    const Index node = nodes_[e / planes_.size()];
    const ContactPlane& plane = planes_[e % planes_.size()];
    const Vector3 p = x.row(node).transpose();
    const Index i = static_cast<Index>(e);
    gap[i] = std::abs(contact::point_plane_signed_distance(p, plane.origin, plane.normal)) -
             offset_;
    energy[i] = 0.0;
    if (gap[i] < d_hat_) {
      const auto b = contact::point_plane_barrier(p, plane.origin, plane.normal, d_hat_,
                                                   stiffness_, contact::BarrierHessian::None,
                                                   offset_);
      energy[i] = b.value;
      force.segment<3>(3 * i) = -b.gradient;
    }
  }
  state.add("contact_gap", gap);
  state.add("contact_energy", energy);
  state.add("contact_force", force);
}

double PlaneContactFamily::step_limit(const NodeMatrix& X, const VectorX& u,
                                      const VectorX& du) const {
  contact::CcdOptions options;
  options.min_distance = offset_;  // a node stays t/2 off the plane
  double fraction = 1.0;
  for (std::size_t e = 0; e < size(); ++e) {
    const Index node = nodes_[e / planes_.size()];
    const ContactPlane& plane = planes_[e % planes_.size()];
    const Vector3 start = position(X, u, node);
    const Vector3 end = start + du.segment<3>(3 * node);
    const auto toi = contact::point_plane_ccd(start, end, plane.origin, plane.normal, options);
    if (toi.impact) fraction = std::min(fraction, toi.toi);
  }
  return fraction;
}

Table PlaneContactFamily::table() const {
  std::vector<double> origin, normal;
  for (const auto& p : planes_) {
    origin.insert(origin.end(), p.origin.data(), p.origin.data() + 3);
    normal.insert(normal.end(), p.normal.data(), p.normal.data() + 3);
  }
  Table out{{"nodes", index_column(nodes_)}, {"origin", real_column(origin, 3)},
            {"normal", real_column(normal, 3)}, {"distance", real_column({d_hat_})},
            {"stiffness", real_column({stiffness_})}};
  if (offset_ != 0.0) out.emplace("thickness", real_column({2.0 * offset_}));
  return out;
}

FamilyPtr PlaneContactFamily::from_table(const Table& t) {
  require_known_columns(t, "contact",
                        {"nodes", "origin", "normal", "distance", "stiffness", "thickness"});
  const auto& nodes = require_column(t, "contact", "nodes", true, 1).indices;
  const Index planes = column_rows(t, "contact", "origin", false, 3);
  const auto& origin = require_column(t, "contact", "origin", false, 3).reals;
  const auto& normal = require_column(t, "contact", "normal", false, 3, planes).reals;
  const auto& d_hat = require_column(t, "contact", "distance", false, 1, 1).reals;
  const auto& kappa = require_column(t, "contact", "stiffness", false, 1, 1).reals;
  std::vector<ContactPlane> list(static_cast<std::size_t>(planes));
  for (Index p = 0; p < planes; ++p) {
    list[p].origin = Vector3(origin[3 * p], origin[3 * p + 1], origin[3 * p + 2]);
    list[p].normal = Vector3(normal[3 * p], normal[3 * p + 1], normal[3 * p + 2]);
  }
  const double thickness =
      t.count("thickness") ? require_column(t, "contact", "thickness", false, 1, 1).reals[0]
                           : 0.0;
  return std::make_shared<PlaneContactFamily>(nodes, std::move(list), d_hat[0], kappa[0],
                                              thickness);
}

}  // namespace kresling::model
