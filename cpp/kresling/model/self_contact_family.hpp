#pragma once
/// \file self_contact_family.hpp
/// Contact between the model's panels (its triangles, within a pattern and between the
/// modules of an arm): IPC's barrier on every point-triangle and edge-edge pair closer than
/// d_hat (kernels: contact/contact_barrier.hpp, the edge-edge pairs mollified), the pairs
/// found by the broad phase (contact/contact_broad_phase.hpp) at every evaluation.
///
///        t2              A pair acts while its distance d < d_hat, with energy
///       /  \    o p      kappa b(d^2); pairs that share a node are never pairs, so a
///      /    \   |        crease is not a contact, while the free corner of a panel meets
///    t0 ---- t1          its neighbour's face across a crease that folds shut.
///
/// Thickness t >= 0: the panels' mid-surfaces are kept at least t apart (t/2 each side),
/// the barrier acting on the gap d - t between their faces (contact_offset.hpp) while it is
/// below d_hat; t = 0 is the barrier on the mid-surfaces' distance itself.
///
/// The pairs change as the panels approach and part: the family changes_elements(), and
/// its active elements (4 nodes each: point-triangle (p, t0, t1, t2) or edge-edge (ea0,
/// ea1, eb0, eb1)) are those within t + d_hat at the state; the workspace builds the tangent's
/// pattern for them. Newton's corrections are shortened by additive CCD over the candidates
/// of the swept boxes (step_limit), so that no step makes two panels pass through each other.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "kresling/contact/contact_barrier.hpp"
#include "kresling/contact/contact_broad_phase.hpp"
#include "kresling/contact/contact_candidate_cache.hpp"
#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// Table columns: triangles (3 node indices a row), distance (d_hat [mm], one value),
/// stiffness (kappa [N/mm^3], one value), optionally tangent (one value, a TangentForm:
/// 0 projected, 1 exact, 2 adaptive; absent: adaptive) and joined (one representative node
/// per node: nodes that count as one for the exclusions, the two sides of a cut coincident
/// at rest; absent: none) and thickness (t [mm], one value; absent: 0).
class SelfContactFamily final : public ElementFamily {
 public:
  /// Kinds of active elements.
  enum Kind : std::uint8_t { PointTriangle = 0, EdgeEdge = 1 };

  /// How the pairs' Hessians enter the tangent. Projected: each onto the positive
  /// semi-definite cone (a tangent that stays definite, but not the force's Jacobian: Newton
  /// converges linearly where many pairs act). Exact: as they are (the Jacobian, so Newton
  /// converges quadratically and the tangent's inertia tells stability; indefinite in
  /// general). Adaptive: exact where the whole tangent is positive definite, projected at the
  /// iterates where it is not (adapts_tangent; the solvers ask for it by target.definite).
  enum class TangentForm : int { Projected = 0, Exact = 1, Adaptive = 2 };

  SelfContactFamily(std::vector<Index> triangles, double d_hat, double stiffness,
                    TangentForm tangent = TangentForm::Adaptive,
                    contact::JoinedNodes joined = {}, double thickness = 0.0);
  static FamilyPtr from_table(const Table& table);

  const char* name() const override { return "self_contact"; }
  std::size_t size() const override { return 0; }  // its elements are active_elements
  std::vector<Index> element_dofs(std::size_t) const override { return {}; }
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  /// Columns: self_contact_gap (one value: the smallest gap between two primitives that
  /// are not excluded, their distance less the thickness [mm]; none for a mesh without such
  /// a pair) and self_contact_segments (per pair within t + d_hat, its two closest points on
  /// the mid-surfaces: 6 coordinates [mm]).
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  bool limits_steps() const override { return true; }
  double step_limit(const NodeMatrix& X, const VectorX& u, const VectorX& du) const override;
  bool changes_elements() const override { return true; }
  bool adapts_tangent() const override { return tangent_ == TangentForm::Adaptive; }
  void active_elements(const NodeMatrix& X, const VectorX& u, ActiveElements& out) const override;

  /// The smallest gap between two primitives that are not excluded at positions x, their
  /// mid-surfaces' distance less the thickness [mm]; inf when the mesh has no such pair.
  double min_gap(const NodeMatrix& x) const;

 private:
  struct NearestPair {
    std::array<Index, 4> nodes{};
    bool edge_edge = false;
  };
  // The smallest distance of two primitives (min_gap plus the thickness), and the pair
  // that has it when `pair` is not null.
  double nearest_pair(const NodeMatrix& x, NearestPair* pair) const;
  void find_active(const NodeMatrix& x, ActiveElements& out) const;
  // check's refusal of a thickness whose pair (described by `pair`) is `gap` apart at rest.
  [[noreturn]] void throw_thick_at_rest(double gap, const std::string& pair) const;
  // The pair energy of active element e of `active` at positions x (rest positions X for
  // the edge-edge mollifier's threshold).
  contact::ScalarDerivatives<12> pair_energy(const NodeMatrix& X, const NodeMatrix& x,
                                              const ActiveElements& active, std::size_t e,
                                              contact::BarrierHessian hessian) const;

  contact::TriangleMatrix triangles_;
  contact::EdgeMatrix edges_;
  double d_hat_, stiffness_;
  double thickness_;  // t: the mid-surfaces' smallest distance
  double reach_;      // t + d_hat: the distance below which a pair acts
  TangentForm tangent_ = TangentForm::Adaptive;
  contact::JoinedNodes joined_;  // nodes that count as one (contact_broad_phase.hpp)
  // The broad phase's candidates kept across evaluations (the family's only state, a cache:
  // every result is that of a broad phase of its own).
  std::unique_ptr<contact::ContactCandidateCache> cache_;
};

}  // namespace kresling::model
