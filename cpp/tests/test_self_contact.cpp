// Panel-panel contact (model/self_contact_family.hpp) through the assembly: the tangent's
// pattern follows the pairs within d_hat, the force is the energy's gradient (finite
// differences), the step limit keeps panels apart, and a solver re-analyses a new pattern.
//
// Tolerances: central differences of the energy with h = 1e-6 of the geometry's size have
// truncation and rounding errors ~1e-9 of the force's scale here (the barrier's curvature
// at the gaps used, 0.2 to 0.6 d_hat, is moderate); 1e-6 relative leaves that headroom and
// catches any misplaced term, which is O(1) relative.

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/contact/contact_closest_points.hpp"
#include "kresling/core/check.hpp"
#include "kresling/model/self_contact_family.hpp"
#include "kresling/solvers/tangent_solver.hpp"
#include "two_triangles_model.hpp"

using namespace kresling;

namespace {

using contact_test::lowered;
using contact_test::two_triangles;
constexpr double kDHat = contact_test::kTwoTrianglesDHat;

double energy(const model::Model& m, const VectorX& u) {
  VectorX force;
  assembly::Workspace w(m, assembly::all_dofs(m.num_dofs()));
  return assembly::assemble(m, w, u, force, false).total();
}

// The force the energy's central differences imply at u (h = 1e-6 of the 5 mm geometry).
VectorX energy_gradient(const model::Model& m, const VectorX& u) {
  const double h = 1e-6 * 5.0;
  VectorX fd(u.size());
  for (Index i = 0; i < u.size(); ++i) {
    VectorX up = u, down = u;
    up[i] += h;
    down[i] -= h;
    fd[i] = (energy(m, up) - energy(m, down)) / (2 * h);
  }
  return fd;
}

}  // namespace

TEST(SelfContact, PatternIsRebuiltOnlyWhenNewPairsEnter) {
  const model::Model m = two_triangles();
  assembly::Workspace w(m, assembly::all_dofs(18));
  const auto rest_id = w.pattern_id();
  const Index rest_nonzeros = w.matrix().nonZeros();
  EXPECT_EQ(rest_nonzeros, 18);  // no pair within d_hat at rest: the diagonal alone
  VectorX force;
  assembly::assemble(m, w, lowered(1.0), force, true);  // still 1 mm apart: no pair
  EXPECT_EQ(w.pattern_id(), rest_id);
  assembly::assemble(m, w, lowered(1.8), force, true);  // ~0.2 mm: pairs act
  const auto near_id = w.pattern_id();
  EXPECT_NE(near_id, rest_id);
  EXPECT_GT(w.matrix().nonZeros(), rest_nonzeros);
  assembly::assemble(m, w, lowered(1.8), force, true);  // same pairs: same pattern
  EXPECT_EQ(w.pattern_id(), near_id);
  // The tangent equals that of a workspace built afresh for the same state.
  assembly::Workspace fresh(m, assembly::all_dofs(18));
  VectorX fresh_force;
  assembly::assemble(m, fresh, lowered(1.8), fresh_force, true);
  EXPECT_EQ(Eigen::MatrixXd(w.matrix()), Eigen::MatrixXd(fresh.matrix()));
  EXPECT_EQ(force, fresh_force);
  // Apart again: the pattern keeps the pairs (few), which add only zeros.
  assembly::assemble(m, w, lowered(0.5), force, true);
  EXPECT_EQ(w.pattern_id(), near_id);
  assembly::Workspace apart(m, assembly::all_dofs(18));
  assembly::assemble(m, apart, lowered(0.5), fresh_force, true);
  EXPECT_EQ(apart.matrix().nonZeros(), rest_nonzeros);
  EXPECT_EQ(Eigen::MatrixXd(w.matrix()), Eigen::MatrixXd(apart.matrix()));
  EXPECT_EQ(force, fresh_force);
}

TEST(SelfContact, ForceIsTheEnergysGradientAndTheProjectedTangentIsPositiveSemiDefinite) {
  const model::Model m = two_triangles(model::SelfContactFamily::TangentForm::Projected);
  for (double drop : {1.7, 1.8, 1.9}) {
    const VectorX u = lowered(drop, static_cast<unsigned>(10 * drop));
    assembly::Workspace w(m, assembly::all_dofs(18));
    VectorX force, force_only;
    const double e = assembly::assemble(m, w, u, force, true).total();
    ASSERT_GT(e, 0.0) << "drop " << drop;
    assembly::assemble(m, w, u, force_only, false);
    EXPECT_EQ(force, force_only);  // the family finds the same pairs itself
    EXPECT_LT((energy_gradient(m, u) - force).norm(), 1e-6 * force.norm()) << "drop " << drop;
    const Eigen::MatrixXd K = Eigen::MatrixXd(w.matrix());
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    EXPECT_GT(eigenvalues.minCoeff(), -1e-9 * eigenvalues.cwiseAbs().maxCoeff());
  }
}

TEST(SelfContact, StepLimitStopsATriangleBeforeItPassesThrough) {
  const model::Model m = two_triangles();
  const auto& family = *m.find<model::SelfContactFamily>();
  const VectorX u = lowered(1.0);
  const VectorX through = lowered(4.0) - u;  // would end 2 mm below the lower triangle
  const double t = family.step_limit(m.nodes(), u, through);
  ASSERT_GT(t, 0.0);
  ASSERT_LT(t, 1.0);
  const VectorX after = u + t * through;
  EXPECT_GT(family.min_gap(m.deformed(after)), 0.0);
  // A step that stays clear is taken whole.
  EXPECT_EQ(family.step_limit(m.nodes(), VectorX::Zero(18), lowered(0.5)), 1.0);
}

TEST(SelfContact, RestStateWithinDHatIsRefused) {
  NodeMatrix X(6, 3);
  X << 0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0.3, 5, 1.5, 0.3, 0.5, 5, 0.3;
  auto family = std::make_shared<model::SelfContactFamily>(
      std::vector<Index>{0, 1, 2, 3, 4, 5}, kDHat, 10.0);
  EXPECT_THROW(model::Model(X, std::vector<std::uint8_t>(18, 0), {family}),
               std::invalid_argument);
}

TEST(SelfContact, MinGapIsTheNearestPairWhateverItsDistance) {
  const model::Model m = two_triangles();
  const auto& family = *m.find<model::SelfContactFamily>();
  // The planes are 2 mm apart and the upper triangle's nodes 1, 1 and 0.5 from the lower's
  // edges in plan: its nearest pair is point (1, 1, 2) over the lower face: 2 mm.
  EXPECT_NEAR(family.min_gap(m.nodes()), 2.0, 1e-12);
}

TEST(SelfContact, SolverAnalysesANewPattern) {
  const model::Model m = two_triangles();
  assembly::Workspace w(m, assembly::all_dofs(18), 1.0);  // shift 1: positive definite
  solvers::TangentSolver solver;
  VectorX force;
  for (double drop : {0.5, 1.85, 0.5}) {
    assembly::assemble(m, w, lowered(drop), force, true);
    solver.set_pattern(w.pattern_id());
    ASSERT_TRUE(solver.factorize(w.matrix()).ok);
    const VectorX b = VectorX::LinSpaced(18, 1.0, 2.0);
    const VectorX x = solver.solve(b);
    const Eigen::MatrixXd K = Eigen::MatrixXd(w.matrix());
    EXPECT_LT((K * x - b).norm(), 1e-10 * b.norm()) << "drop " << drop;
  }
}

TEST(SelfContact, ClosestPointsAreAtTheKernelsDistance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> c(-1.0, 1.0);
  auto point = [&] { return Vector3(c(rng), c(rng), c(rng)); };
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3 p = point(), a = point(), b = point(), d = point();
    const Vector3 q = contact::closest_point_on_triangle(p, a, b, d);
    EXPECT_NEAR((p - q).squaredNorm(), contact::point_triangle_distance(p, a, b, d, false).value,
                1e-12);
    const Vector3 e = point();
    const auto [x, y] = contact::closest_points_of_edges(p, a, b, e);
    EXPECT_NEAR((x - y).squaredNorm(), contact::edge_edge_distance(p, a, b, e, false).value,
                1e-12);
  }
}

// Panels of a thickness t: the barrier acts on the gap d - t between their faces.
constexpr double kThickness = 0.6;  // [mm]; the triangles start 2 mm apart

TEST(SelfContactThickness, ForceIsTheEnergysGradientWhereTheFacesAreWithinDHat) {
  // Lowered by 1.1 to 1.3 mm the triangles' mid-surfaces are ~0.7 to 0.9 mm apart: their
  // faces (0.1 to 0.3 mm apart) within d_hat, where without thickness no pair would act.
  const model::Model thick = two_triangles(model::SelfContactFamily::TangentForm::Exact,
                                           kThickness);
  const model::Model thin = two_triangles(model::SelfContactFamily::TangentForm::Exact);
  for (double drop : {1.1, 1.2, 1.3}) {
    const VectorX u = lowered(drop, static_cast<unsigned>(10 * drop));
    ASSERT_EQ(energy(thin, u), 0.0) << "drop " << drop;
    assembly::Workspace w(thick, assembly::all_dofs(18));
    VectorX force;
    ASSERT_GT(assembly::assemble(thick, w, u, force, true).total(), 0.0) << "drop " << drop;
    EXPECT_LT((energy_gradient(thick, u) - force).norm(), 1e-6 * force.norm())
        << "drop " << drop;
  }
}

TEST(SelfContactThickness, StepLimitKeepsTheMidSurfacesTheThicknessApart) {
  const model::Model m = two_triangles(model::SelfContactFamily::TangentForm::Adaptive,
                                       kThickness);
  const auto& family = *m.find<model::SelfContactFamily>();
  // The gap is the mid-surfaces' distance (2 mm at rest, the point (1, 1, 2) over the lower
  // face) less the thickness.
  EXPECT_NEAR(family.min_gap(m.nodes()), 2.0 - kThickness, 1e-12);
  const VectorX u = lowered(1.0);
  const VectorX through = lowered(4.0) - u;
  const double t = family.step_limit(m.nodes(), u, through);
  ASSERT_GT(t, 0.0);
  ASSERT_LT(t, 1.0);
  // Independent of the family: the upper triangle's lowest node over the lower face.
  const NodeMatrix x = m.deformed(u + t * through);
  EXPECT_GT(x.block(3, 2, 3, 1).minCoeff(), kThickness);
  EXPECT_GT(family.min_gap(x), 0.0);
  // Without thickness the same step goes further.
  const model::Model thin = two_triangles();
  EXPECT_GT(thin.find<model::SelfContactFamily>()->step_limit(thin.nodes(), u, through), t);
}

TEST(SelfContactThickness, RestStateCloserThanTheThicknessIsRefused) {
  // 2 mm apart at rest: a thickness of 2 mm or more would overlap, one of 1.6 mm leaves
  // the barrier (d_hat 0.5) acting at rest; both refused naming the thickness.
  for (double thickness : {2.5, 2.0, 1.6}) {
    try {
      two_triangles(model::SelfContactFamily::TangentForm::Adaptive, thickness);
      ADD_FAILURE() << "thickness " << thickness << " accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("thickness = " + format_number(thickness)),
                std::string::npos)
          << error.what();
    }
  }
  EXPECT_NO_THROW(two_triangles(model::SelfContactFamily::TangentForm::Adaptive, 1.4));
  EXPECT_THROW(two_triangles(model::SelfContactFamily::TangentForm::Adaptive, -0.1),
               std::invalid_argument);
  EXPECT_THROW(two_triangles(model::SelfContactFamily::TangentForm::Adaptive, std::nan("")),
               std::invalid_argument);
}
