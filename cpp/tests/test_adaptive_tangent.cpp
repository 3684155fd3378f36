// The adaptive contact tangent (SelfContactFamily::TangentForm::Adaptive, with
// solvers::factorize_tangent): the family gives its exact pair Hessians unless the assembly
// asks for a definite tangent, and then exactly the projected ones; the solvers factorise the
// exact tangent where it is positive definite and fall back to the projected one where it is
// not.
//
// References: the tangents of the same pairs built with the Projected and Exact forms (equal
// bit for bit: the same kernels, called the same way), and central differences of the
// force for the exact form (h = 1e-6 of the geometry's size: truncation and rounding errors
// ~1e-9 of the tangent's scale at the gaps used, so 1e-6 relative catches any misplaced
// term).

#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/self_contact_family.hpp"
#include "kresling/solvers/newton.hpp"
#include "two_triangles_model.hpp"

using namespace kresling;
using Form = model::SelfContactFamily::TangentForm;

namespace {

using contact_test::lowered;
using contact_test::two_triangles;
constexpr double kDHat = contact_test::kTwoTrianglesDHat;

Eigen::MatrixXd tangent(const model::Model& m, const VectorX& u, bool definite = false) {
  assembly::Workspace w(m, assembly::all_dofs(18), 0.0);
  VectorX force;
  assembly::assemble(m, w, u, force, true, definite);
  return Eigen::MatrixXd(w.matrix());
}

double smallest_eigenvalue(const Eigen::MatrixXd& K) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues().minCoeff();
}

// A state whose exact contact tangent has a negative eigenvalue (pairs act, so the barrier's
// negative curvature terms show); ASSERTs that one is found.
VectorX indefinite_state(const model::Model& exact) {
  for (unsigned seed = 1; seed < 50; ++seed) {
    for (double drop : {1.6, 1.7, 1.8, 1.9}) {
      const VectorX u = lowered(drop, seed);
      const Eigen::MatrixXd K = tangent(exact, u);
      if (smallest_eigenvalue(K) < -1e-6 * K.cwiseAbs().maxCoeff()) return u;
    }
  }
  ADD_FAILURE() << "no state with an indefinite exact tangent";
  return VectorX::Zero(18);
}

}  // namespace

TEST(AdaptiveTangent, ExactUnlessDefiniteIsAskedThenProjected) {
  const model::Model adaptive = two_triangles(Form::Adaptive);
  const model::Model exact = two_triangles(Form::Exact);
  const model::Model projected = two_triangles(Form::Projected);
  for (double drop : {1.7, 1.8, 1.9}) {
    const VectorX u = lowered(drop, static_cast<unsigned>(10 * drop));
    const Eigen::MatrixXd K = tangent(adaptive, u);
    ASSERT_GT(K.cwiseAbs().maxCoeff(), 0.0) << "drop " << drop;  // pairs act
    EXPECT_EQ(K, tangent(exact, u)) << "drop " << drop;
    EXPECT_EQ(tangent(adaptive, u, /*definite=*/true), tangent(projected, u)) << "drop " << drop;
    // Families that do not adapt ignore the request.
    EXPECT_EQ(tangent(exact, u, /*definite=*/true), K) << "drop " << drop;
    // The exact form is the force's Jacobian.
    const double h = 1e-6 * 5.0;
    Eigen::MatrixXd fd(18, 18);
    for (int i = 0; i < 18; ++i) {
      VectorX up = u, down = u, f_up, f_down;
      up[i] += h;
      down[i] -= h;
      assembly::Workspace w(adaptive, assembly::all_dofs(18));
      assembly::assemble(adaptive, w, up, f_up, false);
      assembly::assemble(adaptive, w, down, f_down, false);
      fd.col(i) = (f_up - f_down) / (2 * h);
    }
    EXPECT_LT((fd - K).norm(), 1e-6 * K.norm()) << "drop " << drop;
  }
}

TEST(AdaptiveTangent, SolversFactoriseTheExactTangentWhereItIsPositiveDefinite) {
  const model::Model adaptive = two_triangles(Form::Adaptive);
  const model::Model exact = two_triangles(Form::Exact);
  const VectorX u = indefinite_state(exact);
  // A diagonal shift larger than the most negative eigenvalue makes the exact tangent
  // positive definite: it is the one factorised.
  const double shift = 2.0 * std::abs(smallest_eigenvalue(tangent(exact, u))) + 1.0;
  assembly::Assembler assembler(adaptive, assembly::all_dofs(18), shift);
  solvers::TangentSolver solver;
  VectorX force;
  assembler.assemble(u, force, true);
  const solvers::FactorizeInfo info = solvers::factorize_tangent(assembler, solver, u, force);
  ASSERT_TRUE(info.ok);
  EXPECT_EQ(info.negative_eigenvalues, 0);
  const Eigen::MatrixXd K = tangent(exact, u) + shift * Eigen::MatrixXd::Identity(18, 18);
  const VectorX b = VectorX::LinSpaced(18, 1.0, 2.0);
  EXPECT_LT((K * solver.solve(b) - b).norm(), 1e-10 * b.norm());
}

TEST(AdaptiveTangent, SolversFallBackToTheProjectedTangentWhereTheExactOneIsIndefinite) {
  const model::Model adaptive = two_triangles(Form::Adaptive);
  const model::Model exact = two_triangles(Form::Exact);
  const model::Model projected = two_triangles(Form::Projected);
  const VectorX u = indefinite_state(exact);
  const double shift = 1.0;  // below the exact tangent's most negative eigenvalue's size
  ASSERT_LT(smallest_eigenvalue(tangent(exact, u)) + shift, 0.0);
  assembly::Assembler assembler(adaptive, assembly::all_dofs(18), shift);
  solvers::TangentSolver solver;
  VectorX force, own_force;
  assembler.assemble(u, force, true);
  const solvers::FactorizeInfo info = solvers::factorize_tangent(assembler, solver, u, force);
  ASSERT_TRUE(info.ok);
  EXPECT_EQ(info.negative_eigenvalues, 0);  // the projection is positive semi-definite
  const Eigen::MatrixXd K = tangent(projected, u) + shift * Eigen::MatrixXd::Identity(18, 18);
  EXPECT_EQ(Eigen::MatrixXd(assembler.matrix()), K);
  const VectorX b = VectorX::LinSpaced(18, 1.0, 2.0);
  EXPECT_LT((K * solver.solve(b) - b).norm(), 1e-10 * b.norm());
  // The force assembled again with it is the same.
  assembly::Workspace w(adaptive, assembly::all_dofs(18));
  assembly::assemble(adaptive, w, u, own_force, false);
  EXPECT_EQ(force, own_force);
}

TEST(AdaptiveTangent, TableRoundTripsTheForm) {
  for (Form form : {Form::Projected, Form::Exact, Form::Adaptive}) {
    const model::SelfContactFamily family({0, 1, 2}, kDHat, 10.0, form);
    const model::Table table = family.table();
    // The default form is written as no column.
    EXPECT_EQ(table.count("tangent") == 0, form == Form::Adaptive);
    if (table.count("tangent")) {
      EXPECT_EQ(table.at("tangent").reals, std::vector<double>{static_cast<double>(form)});
    }
    const auto again = model::SelfContactFamily::from_table(table);
    EXPECT_EQ(again->adapts_tangent(), form == Form::Adaptive);
    EXPECT_EQ(again->table().count("tangent"), table.count("tangent"));
  }
  model::Table bad = model::SelfContactFamily({0, 1, 2}, kDHat, 10.0).table();
  bad["tangent"] = model::real_column({3.0});
  EXPECT_THROW(model::SelfContactFamily::from_table(bad), std::invalid_argument);
}
