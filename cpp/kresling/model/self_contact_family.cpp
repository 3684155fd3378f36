#include "kresling/model/self_contact_family.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/contact/contact_candidate_cache.hpp"
#include "kresling/contact/contact_ccd.hpp"
#include "kresling/contact/contact_closest_points.hpp"
#include "kresling/contact/contact_mollifier.hpp"

namespace kresling::model {

namespace {

using contact::ContactCandidates;

NodeMatrix deformed(const NodeMatrix& X, const VectorX& u) {
  return X + Eigen::Map<const NodeMatrix>(u.data(), X.rows(), 3);
}

Vector3 row(const NodeMatrix& x, Index i) { return x.row(i).transpose(); }

// The 4 nodes of a candidate pair: (p, t0, t1, t2) or (ea0, ea1, eb0, eb1).
std::array<Index, 4> point_triangle_nodes(const contact::TriangleMatrix& t,
                                          const std::array<Index, 2>& pair) {
  return {pair[0], t(pair[1], 0), t(pair[1], 1), t(pair[1], 2)};
}
std::array<Index, 4> edge_edge_nodes(const contact::EdgeMatrix& e,
                                     const std::array<Index, 2>& pair) {
  return {e(pair[0], 0), e(pair[0], 1), e(pair[1], 0), e(pair[1], 1)};
}

// The squared distance of a pair of the given kind at positions x, from its closest points
// (no derivatives: the kernels' value to rounding, at a fraction of their cost).
double squared_distance(const NodeMatrix& x, const std::array<Index, 4>& n, bool edge_edge) {
  const Vector3 a = row(x, n[0]), b = row(x, n[1]), c = row(x, n[2]), d = row(x, n[3]);
  if (edge_edge) {
    const auto [p, q] = contact::closest_points_of_edges(a, b, c, d);
    return (p - q).squaredNorm();
  }
  return (a - contact::closest_point_on_triangle(a, b, c, d)).squaredNorm();
}

// A lower bound on a pair's distance: the gap between the boxes of its two primitives
// (the first 1 or 2 nodes, the other 3 or 2), far cheaper than the distance itself.
double box_gap(const NodeMatrix& x, const std::array<Index, 4>& n, bool edge_edge) {
  const int split = edge_edge ? 2 : 1;
  Vector3 lo_a = row(x, n[0]), hi_a = lo_a, lo_b = row(x, n[split]), hi_b = lo_b;
  for (int i = 1; i < 4; ++i) {
    const Vector3 p = row(x, n[i]);
    Vector3& lo = i < split ? lo_a : lo_b;
    Vector3& hi = i < split ? hi_a : hi_b;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vector3 gap = (lo_b - hi_a).cwiseMax(lo_a - hi_b).cwiseMax(0.0);
  return gap.norm();
}

// ACCD's bound on the rate at which a pair's gap closes along a step dx: the largest node
// displacement on each side, the pair's mean displacement taken off (contact_ccd.cpp).
double closing_rate(const NodeMatrix& dx, const std::array<Index, 4>& n, bool edge_edge) {
  Vector3 mean = Vector3::Zero();
  for (Index i : n) mean += row(dx, i) / 4.0;
  double a = 0.0, b = 0.0;
  for (int i = 0; i < 4; ++i) {
    double& side = i < (edge_edge ? 2 : 1) ? a : b;
    side = std::max(side, (row(dx, n[i]) - mean).norm());
  }
  return a + b;
}

// Visit every candidate pair of `c` as (nodes, is edge-edge).
template <typename Visit>
void for_each_pair(const ContactCandidates& c, const contact::TriangleMatrix& t,
                   const contact::EdgeMatrix& e, Visit&& visit) {
  for (const auto& pair : c.point_triangle) visit(point_triangle_nodes(t, pair), false);
  for (const auto& pair : c.edge_edge) visit(edge_edge_nodes(e, pair), true);
}

// Visit, in the list's order, every pair of the kept list `view` that may be closer than
// `distance` at the positions it is served at (KeptView::may_be_within): the others are
// passed over at a comparison each.
template <typename Visit>
void for_each_kept_within(const contact::KeptView& view, double distance,
                          const contact::TriangleMatrix& t, const contact::EdgeMatrix& e,
                          Visit&& visit) {
  const contact::KeptCandidates& kept = *view.list;
  for (std::size_t i = 0; i < kept.pairs.point_triangle.size(); ++i) {
    if (view.may_be_within(kept.point_triangle_distance[i], distance)) {
      visit(point_triangle_nodes(t, kept.pairs.point_triangle[i]), false);
    }
  }
  for (std::size_t i = 0; i < kept.pairs.edge_edge.size(); ++i) {
    if (view.may_be_within(kept.edge_edge_distance[i], distance)) {
      visit(edge_edge_nodes(e, kept.pairs.edge_edge[i]), true);
    }
  }
}

}  // namespace

SelfContactFamily::SelfContactFamily(std::vector<Index> triangles, double d_hat,
                                     double stiffness, TangentForm tangent,
                                     contact::JoinedNodes joined, double thickness)
    : triangles_(Eigen::Map<const contact::TriangleMatrix>(
          triangles.data(), static_cast<Index>(triangles.size() / 3), 3)),
      edges_(contact::triangle_edges(triangles_)),
      d_hat_(d_hat),
      stiffness_(stiffness),
      thickness_(thickness),
      reach_(thickness + d_hat),
      tangent_(tangent),
      joined_(std::move(joined)),
      // A skin of d_hat: the list holds while no node moves d_hat / 2 (Newton's iterates
      // near contact move far less), at the cost of the pairs within t + 2 d_hat.
      cache_(std::make_unique<contact::ContactCandidateCache>(reach_, d_hat, joined_)) {}

void SelfContactFamily::check(const NodeMatrix& X, double) const {
  require_positive("self_contact: distance", d_hat_);
  require_positive("self_contact: stiffness", stiffness_);
  require_positive("self_contact: thickness", thickness_, true);
  try {
    contact::check_contact_mesh(X, triangles_, edges_, d_hat_);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("self_contact: ") + error.what());
  }
  if (!joined_.empty() && static_cast<Index>(joined_.size()) != X.rows()) {
    throw std::invalid_argument("self_contact: joined has " + std::to_string(joined_.size()) +
                                " entries: must have one per node (" +
                                std::to_string(X.rows()) + ")");
  }
  for (std::size_t i = 0; i < joined_.size(); ++i) {
    if (joined_[i] < 0 || joined_[i] >= X.rows()) {
      throw std::invalid_argument("self_contact: joined[" + std::to_string(i) + "] = " +
                                  std::to_string(joined_[i]) + " is invalid: must be a node " +
                                  "index in [0, " + std::to_string(X.rows()) + ")");
    }
  }
  NearestPair nearest;
  const double gap = nearest_pair(X, &nearest);
  if (!(gap < reach_)) return;
  // A pair within t + d_hat at rest: the barrier would push the model before anything
  // moves (or, within t, the panels would overlap from the start).
  std::string nodes;
  for (int k = 0; k < 4; ++k) nodes += (k ? ", " : "") + std::to_string(nearest.nodes[k]);
  const std::string pair = std::string(nearest.edge_edge ? "edge and edge" : "node and triangle") +
                           ", nodes " + nodes;
  if (thickness_ > 0) throw_thick_at_rest(gap, pair);
  throw std::invalid_argument(
      "self_contact: distance = " + format_number(d_hat_) + " mm is invalid: two panels are " +
      format_number(gap) + " mm apart at rest (" +
      pair + "), and the barrier would act before anything moves; must be below " +
      format_number(gap) + " mm");
}

void SelfContactFamily::throw_thick_at_rest(double gap, const std::string& pair) const {
  const std::string apart = format_number(gap) + " mm apart at rest (" + pair + ")";
  if (!(gap > thickness_)) {
    throw std::invalid_argument(
        "self_contact: thickness = " + format_number(thickness_) + " mm is invalid: the " +
        "mid-surfaces of two panels are " + apart + ", so panels this thick would overlap " +
        "before anything moves; must be below " + format_number(gap) + " mm");
  }
  throw std::invalid_argument(
      "self_contact: thickness = " + format_number(thickness_) + " mm with distance = " +
      format_number(d_hat_) + " mm is invalid: the mid-surfaces of two panels are " + apart +
      ", and the barrier, acting below thickness + distance, would act before anything " +
      "moves; thickness + distance must be below " + format_number(gap) + " mm");
}

void SelfContactFamily::find_active(const NodeMatrix& x, ActiveElements& out) const {
  out = ActiveElements{};
  out.width = 4;
  const double s_reach = reach_ * reach_;
  // Only pairs that may be within t + d_hat: the others would fail the tests below.
  const contact::KeptView view = cache_->candidates(x, triangles_, edges_);
  for_each_kept_within(view, reach_, triangles_, edges_,
                       [&](const std::array<Index, 4>& n, bool edge_edge) {
    if (box_gap(x, n, edge_edge) >= reach_) return;  // the list holds pairs to t + 2 d_hat
    if (squared_distance(x, n, edge_edge) >= s_reach) return;  // beyond: no energy
    out.nodes.insert(out.nodes.end(), n.begin(), n.end());
    out.kinds.push_back(edge_edge ? EdgeEdge : PointTriangle);
  });
}

void SelfContactFamily::active_elements(const NodeMatrix& X, const VectorX& u,
                                        ActiveElements& out) const {
  find_active(deformed(X, u), out);
}

contact::ScalarDerivatives<12> SelfContactFamily::pair_energy(
    const NodeMatrix& X, const NodeMatrix& x, const ActiveElements& active, std::size_t e,
    contact::BarrierHessian hessian) const {
  const Index* n = active.nodes.data() + 4 * e;
  const Vector3 a = row(x, n[0]), b = row(x, n[1]), c = row(x, n[2]), d = row(x, n[3]);
  if (active.kinds[e] == PointTriangle) {
    return contact::point_triangle_barrier(a, b, c, d, d_hat_, stiffness_, hessian, thickness_);
  }
  // The mollifier's threshold from the edges as built, as IPC takes it.
  const double eps_x = contact::edge_edge_mollifier_threshold(row(X, n[0]), row(X, n[1]),
                                                               row(X, n[2]), row(X, n[3]));
  return contact::edge_edge_barrier(a, b, c, d, eps_x, d_hat_, stiffness_, hessian,
                                    thickness_);
}

double SelfContactFamily::assemble(const NodeMatrix& X, const VectorX& u,
                                   AssemblyTarget& target) const {
  const NodeMatrix x = deformed(X, u);
  ActiveElements own;
  if (target.active == nullptr) find_active(x, own);
  const ActiveElements& active = target.active ? *target.active : own;
  const bool exact = tangent_ == TangentForm::Exact ||
                     (tangent_ == TangentForm::Adaptive && !target.definite);
  const auto hessian = !target.values ? contact::BarrierHessian::None
                       : exact        ? contact::BarrierHessian::Exact
                                      : contact::BarrierHessian::Projected;
  double energy = 0.0;
  const double s_reach = reach_ * reach_;
  for (std::size_t e = 0; e < active.size(); ++e) {
    // The workspace's pattern may keep pairs that have parted: no energy, no entries.
    const Index* n = active.nodes.data() + 4 * e;
    if (squared_distance(x, {n[0], n[1], n[2], n[3]}, active.kinds[e] == EdgeEdge) >= s_reach) {
      continue;
    }
    const auto b = pair_energy(X, x, active, e, hessian);
    energy += b.value;
    const std::vector<Index> dofs = active.dofs(e);
    add_local_force(b.gradient, dofs, target.force);
    if (target.values) scatter_local_tangent(b.hessian, *target.slots, e, target.values);
  }
  return energy;
}

double SelfContactFamily::min_gap(const NodeMatrix& x) const {
  return nearest_pair(x, nullptr) - thickness_;
}

double SelfContactFamily::nearest_pair(const NodeMatrix& x, NearestPair* pair) const {
  // Candidates within r hold every pair closer than r: grow r until the nearest candidate
  // lies within it (then it is the nearest pair of all), at most past the mesh's extent.
  const double extent = (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  double best = std::numeric_limits<double>::infinity();
  for (double r = d_hat_;; r *= 4.0) {
    const ContactCandidates c = contact::contact_candidates(x, triangles_, edges_, r, joined_);
    for_each_pair(c, triangles_, edges_, [&](const std::array<Index, 4>& n, bool edge_edge) {
      const double d = std::sqrt(squared_distance(x, n, edge_edge));
      if (!(d < best)) return;
      best = d;
      if (pair) *pair = {n, edge_edge};
    });
    if (best <= r || r > extent) return best;
  }
}

void SelfContactFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  ActiveElements active;
  find_active(x, active);
  VectorX segments(6 * static_cast<Index>(active.size()));
  for (std::size_t e = 0; e < active.size(); ++e) {
    const Index* n = active.nodes.data() + 4 * e;
    const Vector3 a = row(x, n[0]), b = row(x, n[1]), c = row(x, n[2]), d = row(x, n[3]);
    const auto [p, q] = active.kinds[e] == EdgeEdge
                            ? contact::closest_points_of_edges(a, b, c, d)
                            : std::make_pair(a, contact::closest_point_on_triangle(a, b, c, d));
    segments.segment<3>(6 * static_cast<Index>(e)) = p;
    segments.segment<3>(6 * static_cast<Index>(e) + 3) = q;
  }
  const double gap = min_gap(x);  // inf for a mesh without a pair: then no value
  state.add("self_contact_gap", std::isfinite(gap) ? VectorX::Constant(1, gap) : VectorX());
  state.add("self_contact_segments", segments);
}

double SelfContactFamily::step_limit(const NodeMatrix& X, const VectorX& u,
                                     const VectorX& du) const {
  const NodeMatrix x0 = deformed(X, u);
  const NodeMatrix dx = Eigen::Map<const NodeMatrix>(du.data(), X.rows(), 3);
  contact::CcdOptions options;
  options.min_distance = thickness_;  // the mid-surfaces stay t apart
  const double eta = options.conservative_rescaling;
  // ACCD (contact_ccd.cpp) finds no impact for a pair whose first advance, eta (d - t) / l_p
  // from its distance d at x0 (t the thickness, ACCD's minimum separation), already covers
  // the step: it returns t_max without a second distance.
  // Its rate l_p is the largest move on each side after the pair's mean move is taken off;
  // a node's move less the mean of four is at most (3/4 + 3/4) max |dx|, so l_p <= 3 max
  // |dx|. Pairs farther than t plus twice 3 max |dx| / eta at x0 (the factor 2 absorbs the
  // rounding of the distances and of l_p) thus cannot shorten the step.
  const double largest = dx.rows() ? dx.rowwise().norm().maxCoeff() : 0.0;
  const double far = thickness_ + 2.0 * 3.0 * largest / eta;
  // The kept candidates cover the step when it is short beside the list's skin; otherwise
  // those of the swept boxes, which hold every pair that may meet along it.
  const contact::KeptView view = cache_->candidates(x0, triangles_, edges_, &dx);
  // Every pair that is not excluded is farther than the list's clearance: when that is
  // beyond `far`, no check would shorten the step, and it is taken as it is (the same 1
  // the checks would give, at the cost of a pass over the nodes). Converged Newton
  // corrections, far shorter than the gaps, take this way.
  if (view.list && far <= view.clearance()) return 1.0;
  const NodeMatrix x1 = x0 + dx;
  double fraction = 1.0;
  auto check = [&](const std::array<Index, 4>& n, bool edge_edge) {
    const auto ccd = edge_edge ? contact::edge_edge_ccd
                               : contact::point_triangle_ccd;
    options.t_max = fraction;  // only an earlier impact can shorten the step further
    // ACCD's first advance, eta gap / rate, from a lower bound of the gap: when it already
    // reaches t_max, ACCD would find no impact (most candidates, at a fraction of its cost).
    const double gap = box_gap(x0, n, edge_edge) - thickness_;
    const double rate = closing_rate(dx, n, edge_edge);
    if (gap > 0 && options.conservative_rescaling * gap >= options.t_max * rate) return;
    const auto toi = ccd(row(x0, n[0]), row(x0, n[1]), row(x0, n[2]), row(x0, n[3]),
                         row(x1, n[0]), row(x1, n[1]), row(x1, n[2]), row(x1, n[3]), options);
    if (toi.impact) fraction = std::min(fraction, toi.toi);
  };
  if (view.list) {
    // Only the kept pairs that may be within `far` of each other at x0.
    for_each_kept_within(view, far, triangles_, edges_, check);
  } else {
    // (Those that may come within t of each other along the step.)
    for_each_pair(contact::contact_candidates(x0, triangles_, edges_, thickness_, dx, joined_),
                  triangles_, edges_, check);
  }
  return fraction;
}

Table SelfContactFamily::table() const {
  std::vector<Index> t(triangles_.data(), triangles_.data() + triangles_.size());
  Table out{{"triangles", index_column(t, 3)}, {"distance", real_column({d_hat_})},
            {"stiffness", real_column({stiffness_})}};
  if (tangent_ != TangentForm::Adaptive) {
    out.emplace("tangent", real_column({static_cast<double>(tangent_)}));
  }
  if (!joined_.empty()) out.emplace("joined", index_column(joined_));
  if (thickness_ != 0.0) out.emplace("thickness", real_column({thickness_}));
  return out;
}

FamilyPtr SelfContactFamily::from_table(const Table& t) {
  require_known_columns(t, "self_contact",
                        {"triangles", "distance", "stiffness", "tangent", "joined",
                         "thickness"});
  const auto& triangles = require_column(t, "self_contact", "triangles", true, 3);
  const auto& d_hat = require_column(t, "self_contact", "distance", false, 1, 1).reals;
  const auto& kappa = require_column(t, "self_contact", "stiffness", false, 1, 1).reals;
  auto tangent = TangentForm::Adaptive;
  if (t.count("tangent")) {
    const double code = require_column(t, "self_contact", "tangent", false, 1, 1).reals[0];
    if (code != 0.0 && code != 1.0 && code != 2.0) {
      throw std::invalid_argument("self_contact: tangent = " + format_number(code) +
                                  " is invalid: must be 0 (projected), 1 (exact) or 2 "
                                  "(adaptive)");
    }
    tangent = static_cast<TangentForm>(static_cast<int>(code));
  }
  contact::JoinedNodes joined;
  if (t.count("joined")) joined = require_column(t, "self_contact", "joined", true, 1).indices;
  const double thickness =
      t.count("thickness")
          ? require_column(t, "self_contact", "thickness", false, 1, 1).reals[0]
          : 0.0;
  return std::make_shared<SelfContactFamily>(triangles.indices, d_hat[0], kappa[0], tangent,
                                             std::move(joined), thickness);
}

}  // namespace kresling::model
