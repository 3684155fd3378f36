// The Kresling specimen builder (counts, supports, rest state) and one run of the bending
// test against MERLIN2's reference numbers.
//
// Element counts, from the builder's panels: every level is a fan of n triangles around its
// centre and every cell a band of 2n triangles. Spokes, valleys and mountains lie in two
// triangles each; a polygon edge in two at the end levels and three at intermediate ones.
// MERLIN2's duplicated topology puts a bar and a hinge on each pair of triangles of an edge:
//     n (cells + 1) + 2n + 3n (cells - 1) + 2n cells = 6 n cells   of each;
// the de-duplicated one a bar per edge, 2n (cells + 1) + 2n cells = 4 n cells + 2n, and a
// hinge per neighbouring pair, 6 n cells - n (cells - 1) = 5 n cells + n.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "kresling/analyses/bending_test.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/solvers/linear_stiffness.hpp"
#include "kresling/solvers/rigid_body.hpp"

using namespace kresling;
using geometry::Design;
using model::EdgeFamily;

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

std::vector<int> alternating(int cells) {
  std::vector<int> c(cells);
  for (int i = 0; i < cells; ++i) c[i] = i % 2 ? -1 : 1;
  return c;
}

template <typename T>
long count(const std::vector<T>& v, T value) {
  return std::count(v.begin(), v.end(), value);
}

// The bending test's supports: vertices 0 and n/2 and the centre of both end polygons.
std::vector<std::uint8_t> bending_supports(int n, int cells) {
  std::vector<std::uint8_t> fixed(3 * (cells + 1) * (n + 1), 0);
  for (int level : {0, cells}) {
    for (int j : {0, n / 2, n}) {
      for (int k = 0; k < 3; ++k) fixed[3 * (level * (n + 1) + j) + k] = 1;
    }
  }
  return fixed;
}

// Rigid-body check outcome: empty if constrained, else the message.
std::string rigid_body_failure(const model::Model& m, const std::vector<std::uint8_t>& held) {
  try {
    solvers::require_rigid_body_constrained(m, held);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Specimen, CountsFollowNAndCells) {
  for (int n : {3, 4, 6, 8}) {
    for (int cells : {1, 2, 3, 4}) {
      const Design d(n, 30.0, 0.8, 20.0);
      const std::vector<int> states(cells, 1);
      for (bool duplicate : {true, false}) {
        model::SpecimenParameters p;
        p.duplicate_shared_edges = duplicate;
        const auto s = model::build_kresling_specimen(d, states, alternating(cells), p);
        SCOPED_TRACE("n = " + std::to_string(n) + ", cells = " + std::to_string(cells) +
                     (duplicate ? ", duplicated" : ", de-duplicated"));
        EXPECT_EQ(s.model.num_nodes(), (cells + 1) * (n + 1));
        EXPECT_EQ(s.bar_family.size(), s.model.bars().size());
        EXPECT_EQ(s.hinge_family.size(), s.model.hinges().size());
        EXPECT_EQ(count(s.bar_family, EdgeFamily::Mountain), n * cells);
        EXPECT_EQ(count(s.hinge_family, EdgeFamily::Valley), n * cells);
        EXPECT_EQ(count(s.hinge_family, EdgeFamily::Mountain), n * cells);
        EXPECT_EQ(count(s.hinge_family, EdgeFamily::PolygonSpoke), n * (cells + 1));
        if (duplicate) {
          EXPECT_EQ(s.model.bars().size(), 6u * n * cells);
          EXPECT_EQ(s.model.hinges().size(), 6u * n * cells);
          EXPECT_EQ(count(s.hinge_family, EdgeFamily::PolygonEdge), 2 * n + 3 * n * (cells - 1));
        } else {
          EXPECT_EQ(s.model.bars().size(), 4u * n * cells + 2u * n);
          EXPECT_EQ(s.model.hinges().size(), 5u * n * cells + n);
          EXPECT_EQ(count(s.hinge_family, EdgeFamily::PolygonEdge), 2 * n + 2 * n * (cells - 1));
        }
        ASSERT_EQ(s.level_height.size(), static_cast<std::size_t>(cells + 1));
        EXPECT_NEAR(s.level_height.back(), cells * d.height(geometry::State::Extended), 1e-12);
      }
    }
  }
}

TEST(Specimen, FamiliesSetTheStiffness) {
  const model::SpecimenParameters p;  // the thesis's: hinges kf, spokes 10 kf, mountains 0
  const auto s = model::build_kresling_specimen(Design(6, 30.0, 0.8, 20.0), {1, 0}, {1, -1}, p);
  const auto& hinges = s.model.hinges();
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    const double factor = s.hinge_family[i] == EdgeFamily::Mountain       ? 0.0
                          : s.hinge_family[i] == EdgeFamily::PolygonSpoke ? 10.0
                                                                          : 1.0;
    EXPECT_EQ(hinges[i].stiffness, factor * p.kf) << "hinge " << i;
  }
  const auto& bars = s.model.bars();
  for (std::size_t i = 0; i < bars.size(); ++i) {
    EXPECT_EQ(bars[i].area, s.bar_family[i] == EdgeFamily::Mountain ? 0.01 : 1.0) << "bar " << i;
    EXPECT_EQ(bars[i].law.modulus, 1e5 * p.kf);
  }
}

TEST(Specimen, BendingSupportsLeaveNoRigidBodyMotion) {
  const int n = 6, cells = 4;
  const auto s = model::build_kresling_specimen(Design(n, 30.0, 0.8, 20.0),
                                                std::vector<int>(cells, 1), alternating(cells), {},
                                                bending_supports(n, cells));
  EXPECT_EQ(rigid_body_failure(s.model, s.model.fixed()), "");
  // The check can fail: with no supports all six motions are free; with only the base
  // pinned along its line (through vertices 0 and n/2 on the x axis), the turn about it is.
  const std::vector<std::uint8_t> none(s.model.num_dofs(), 0);
  EXPECT_NE(rigid_body_failure(s.model, none).find("6 rigid-body motions are left free"),
            std::string::npos)
      << rigid_body_failure(s.model, none);
  std::vector<std::uint8_t> base = bending_supports(n, cells);
  for (int j : {0, n / 2, n}) {
    for (int k = 0; k < 3; ++k) base[3 * s.node(cells, j) + k] = 0;
  }
  const std::string turn = "1 rigid-body motion is left free (rotation about x)";
  EXPECT_NE(rigid_body_failure(s.model, base).find(turn), std::string::npos)
      << rigid_body_failure(s.model, base);
  // And the tangent agrees: held rows removed, the unshifted tangent at rest is positive
  // definite; unsupported it has exactly six zero eigenvalues. Rounding puts those at
  // ~eps |K| ~ 1e-16 |K|; the softest real mode (hinges: kf L / arm^2 against bars' C0 / L)
  // is ~1e-5 |K| here. 1e-10 |K| separates the two.
  const Eigen::MatrixXd K(solvers::tangent_matrix(s.model, VectorX::Zero(s.model.num_dofs())));
  const VectorX all = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  const double largest = all.cwiseAbs().maxCoeff();
  std::vector<Index> free_rows;
  for (Index i = 0; i < s.model.num_dofs(); ++i) {
    if (!s.model.fixed()[i]) free_rows.push_back(i);
  }
  Eigen::MatrixXd K_free(free_rows.size(), free_rows.size());
  for (std::size_t a = 0; a < free_rows.size(); ++a) {
    for (std::size_t b = 0; b < free_rows.size(); ++b) K_free(a, b) = K(free_rows[a], free_rows[b]);
  }
  const VectorX held = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K_free).eigenvalues();
  EXPECT_EQ((all.array().abs() <= 1e-10 * largest).count(), 6);
  EXPECT_GT(held.minCoeff(), 1e-10 * largest);
}

TEST(Specimen, RestStateIsStressFreeWithAnglesInsideTheTurn) {
  // Rest lengths and angles are measured on the very nodes of the model, so at u = 0 the
  // strains are rounding (~eps) and the moments zero: forces of ~C0 A eps ~ 1e-12 N. A rest
  // length off by 1e-9 of itself would already give C0 A 1e-9 ~ 5e-6 N.
  for (int n : {4, 7}) {
    for (const auto& states : {std::vector<int>{1, 1, 1}, std::vector<int>{0, 1, 0}}) {
      const auto s =
          model::build_kresling_specimen(Design(n, 30.0, 0.75, 25.0), states, {1, -1, -1});
      for (const auto& h : s.model.hinges()) {
        EXPECT_GT(h.rest_angle, 0.0);
        EXPECT_LT(h.rest_angle, kTwoPi);
      }
      assembly::Assembler a(s.model, assembly::all_dofs(s.model.num_dofs()));
      VectorX f;
      const auto e = a.assemble(VectorX::Zero(s.model.num_dofs()), f, false);
      const double modulus = s.model.bars()[0].law.modulus;
      EXPECT_LE(f.cwiseAbs().maxCoeff(), 1e-13 * modulus) << "n = " << n;
      EXPECT_LE(e.total(), 1e-20 * modulus);
    }
  }
}

TEST(BendingTest, ReproducesMerlin2OnTheN4Design) {
  // MERLIN2's reference run (kresling/data/merlin2: n = 4, Lc = 30, lambda = 0.7, extended,
  // 5 mm in 350 steps): K_B = 3.604556 N m / rad, printed to six decimals, so agreement is
  // checked to half a unit of the last digit; its force history is checked to 1e-6
  // relative at the first and last steps, and the Newton path (3 iterations per increment).
  const Design d(4, 30.0, 0.7, 30.0);
  const analyses::BendingResult r = analyses::bending_test(d, 1);
  ASSERT_TRUE(r.completed) << r.message;
  ASSERT_EQ(r.force.size(), 350u);
  EXPECT_NEAR(r.stiffness, 3.604556, 0.5e-6);
  EXPECT_NEAR(r.module_length, 2 * 41.06858707, 1e-7);  // the table's Le, to its 8 decimals
  EXPECT_NEAR(r.force.front() / 0.00753285046225, 1.0, 1e-6);
  EXPECT_NEAR(r.force.back() / 2.69129438987, 1.0, 1e-6);
  EXPECT_NEAR(r.angle.back(), 0.0607987518404, 1e-12);
  EXPECT_EQ(std::accumulate(r.iterations.begin(), r.iterations.end(), 0), 1050);
  EXPECT_EQ(r.num_dofs, 75);
  EXPECT_EQ(std::count(r.negative_eigenvalues.begin(), r.negative_eigenvalues.end(), 0), 350);
}
