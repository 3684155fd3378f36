// A fold that snaps (FoldOptions::snap, FollowOptions::snap): one hinge whose wing is pulled
// round by a zero-length spring, so that driving the hinge's rest angle past a limit point
// ends its equilibrium path, and the wing must snap over the spring's hill to the far branch.
//
// The closed form. The wing node turns about the hinge's axis at radius 1 (two stiff bars),
// by phi = theta - pi from flat. The hinge (linear law, k per length, length 1) rests at
// theta0 = pi + phi0; the spring (stiffness ks, anchor at distance d from the axis, in the
// direction phi_a) adds -ks d cos(phi - phi_a), so
//
//     E(phi) = k (phi - phi0)^2 / 2 - K cos(phi - phi_a),        K = ks d,  beta = K / k,
//     equilibrium    phi0 = phi + beta sin(phi - phi_a),
//     stability      1 + beta cos(phi - phi_a) > 0.
//
// With beta = 1.5 and phi_a = 2.0 rad the flat state (phi = 0) is a stable equilibrium for
// phi0 = beta sin(-phi_a) = -1.364, where the fold starts; driving phi0 down to -1.45, the
// branch ends where cos(phi - phi_a) = -1 / beta, at phi* = phi_a - acos(-1/beta) = -0.300
// and phi0* = -1.418 (63 % of the way), and the far branch's equilibrium lies near -2.9.
//
// Tolerances: each step is checked by its equilibrium, |phi0(phi) - phi0| (the branch's
// phi itself is ill-conditioned near the limit point). The bars (EA = 1e6 N) stretch under
// the spring's pull by ~1e-6 mm, which changes K by ~1e-6 relative; Newton's and the
// descent's 1e-8 mm add less. 1e-5 leaves room for both and catches any wrong state.

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "kresling/elements/dihedral.hpp"
#include "kresling/model/bar_family.hpp"
#include "wing_test_helpers.hpp"
#include "kresling/model/hinge_family.hpp"
#include "kresling/model/model.hpp"
#include "kresling/model/spring_family.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/energy_minimum.hpp"
#include "kresling/solvers/fold.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/stable_relaxation.hpp"

using namespace kresling;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBeta = 1.5, kPhiA = 2.0, kEnd = -1.45;
// Increments small enough that Newton, started from the last equilibrium near the limit
// point, finds nothing (with 10 to 100 it happens to converge on the far branch after 36 to
// 41 iterations, a jump this test does not rely on).
constexpr int kSteps = 400;

// phi0 of the equilibrium at phi.
double rest_offset(double phi) { return phi + kBeta * std::sin(phi - kPhiA); }

// The fold's start (the flat state's phi0) and its phi0 at fold fraction t.
const double kStart = rest_offset(0.0);
double rest_at(double t) { return kStart + t * (kEnd - kStart); }
// The fold fraction of the limit point.
double limit_fraction() {
  return (rest_offset(kPhiA - std::acos(-1.0 / kBeta)) - kStart) / (kEnd - kStart);
}

// The equilibrium phi at phi0 on the branch through [lo, hi] (bisection on the monotone
// rest_offset there).
double branch(double phi0, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rest_offset(mid) > phi0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Wing {
  model::Model model;
  double sign;  // theta = pi + sign * psi, psi the wing's turn about +x from +y towards +z
};

// Axis 0 -> 1 along x, held wing 2 at -y, turning wing 3 at +y; the spring's anchor at
// distance 1.5 in the direction phi_a.
Wing make_wing() {
  const NodeMatrix X = test::wing_nodes();
  const double turned = elements::dihedral_angle(X.row(0), X.row(1), X.row(2),
                                                 Vector3(0.5, std::cos(0.1), std::sin(0.1)));
  const double sign = turned > kPi ? 1.0 : -1.0;
  const std::vector<model::Bar> bars = test::wing_bars(X);
  model::Hinge h;
  h.nodes = {0, 1, 2, 3};
  h.stiffness = 1.0;
  h.rest_angle = kPi + kStart;
  h.length = 1.0;
  h.law.kind = elements::SpringLawKind::Linear;
  const double d = kBeta, psi_a = sign * kPhiA;  // K = ks d with ks = 1
  model::AnchorSpring spring{3, Vector3::Ones(), Vector3(0.5, d * std::cos(psi_a), d * std::sin(psi_a))};
  std::vector<std::uint8_t> fixed(12, 1);
  fixed[9] = fixed[10] = fixed[11] = 0;
  model::Model m(X, fixed,
                 {std::make_shared<model::BarFamily>(bars),
                  std::make_shared<model::HingeFamily>(std::vector<model::Hinge>{h}),
                  std::make_shared<model::SpringFamily>(std::vector<model::AnchorSpring>{spring})});
  return {std::move(m), sign};
}

double phi_of(const Wing& w, const VectorX& u) {
  const Vector3 x(0.5 + u[9], 1.0 + u[10], u[11]);
  return w.sign * std::atan2(x[2], x[1]);
}

solvers::PathResult fold_to_end(const Wing& w, bool snap, int steps) {
  solvers::FoldOptions o;
  o.snap = snap;
  o.newton.tolerance = 1e-8;
  return solvers::solve_fold(w.model, {{{0}, (VectorX(1) << kPi + kEnd).finished()}}, steps,
                             VectorX::Zero(12), o);
}

// A step's phi, once checked to be a stable equilibrium of the closed form.
double checked_phi(const Wing& w, const solvers::PathStep& s) {
  EXPECT_EQ(s.negative_eigenvalues, 0) << s.load_factor;
  const double phi = phi_of(w, s.displacement);
  EXPECT_NEAR(rest_offset(phi), rest_at(s.load_factor), 1e-5) << s.load_factor;
  return phi;
}

}  // namespace

TEST(FoldSnap, WithoutSnapTheFoldEndsAtTheLimitPoint) {
  const Wing w = make_wing();
  const double limit = limit_fraction();
  const auto path = fold_to_end(w, false, kSteps);
  ASSERT_FALSE(path.completed);
  const double last = path.steps.back().load_factor;
  EXPECT_LE(last, limit);
  EXPECT_GT(last, limit - 0.01);  // bisected to within a fraction of an increment of it
  for (const auto& s : path.steps) EXPECT_FALSE(s.snapped);
}

TEST(FoldSnap, WithSnapItJumpsToTheFarBranchAndFoldsOn) {
  const Wing w = make_wing();
  const double phi_star = kPhiA - std::acos(-1.0 / kBeta);
  const double far_edge = kPhiA - 2 * kPi + std::acos(-1.0 / kBeta);
  const double limit = limit_fraction();
  const auto path = fold_to_end(w, true, kSteps);
  ASSERT_TRUE(path.completed) << path.message;
  int snaps = 0;
  for (const auto& s : path.steps) {
    const double phi = checked_phi(w, s);
    if (s.snapped) {
      ++snaps;
      // Where the branch ends: past the limit point by less than an increment (the bars'
      // compliance moves it by ~1e-6 of the fold).
      EXPECT_GT(s.load_factor, limit - 1e-4);
      EXPECT_LT(s.load_factor, limit + 1.0 / kSteps);
    }
    if (snaps == 0) {
      EXPECT_GE(phi, phi_star - 1e-4);  // on the branch that leaves the flat state
    } else {
      EXPECT_LT(phi, far_edge) << s.load_factor;  // on the far branch
    }
  }
  EXPECT_EQ(snaps, 1);
  // The far branch's equilibrium at the end, solved on its own.
  EXPECT_NEAR(phi_of(w, path.steps.back().displacement), branch(kEnd, -kPi, far_edge), 1e-4);
}

// The sparse descent (minimize_energy_sparse, the snap of models beyond kMaxSnapDofs) finds
// the state the dense one finds: at the end's rest angle, past the limit point, from the
// flat state, the far branch's stable equilibrium.
TEST(FoldSnap, TheSparseDescentEndsWhereTheDenseOneDoes) {
  const Wing w = make_wing();
  const model::Model end = solvers::folded_rest_model(
      w.model, {{{0}, (VectorX(1) << kPi + kEnd).finished()}});
  const double expected = branch(kEnd, -kPi, kPhiA - 2 * kPi + std::acos(-1.0 / kBeta));
  solvers::EnergyMinimumOptions o;
  o.tolerance = 1e-10;
  o.max_iterations = 2000;
  o.max_step = 0.01;
  VectorX dense = VectorX::Zero(12), sparse = VectorX::Zero(12);
  assembly::Assembler full(end, assembly::unmasked_dofs(end.fixed()), 0.0,
                           assembly::Storage::Full);
  const auto d = solvers::minimize_energy(full, dense, o);
  assembly::Assembler lower(end, assembly::unmasked_dofs(end.fixed()), 0.0,
                            assembly::Storage::Lower);
  solvers::TangentSolver solver;
  const auto s = solvers::minimize_energy_sparse(lower, solver, sparse, o);
  ASSERT_TRUE(d.converged) << d.failure;
  ASSERT_TRUE(s.converged) << s.failure;
  EXPECT_EQ(s.negative_eigenvalues, 0);
  EXPECT_NEAR(phi_of(w, dense), expected, 1e-4);
  EXPECT_NEAR(phi_of(w, sparse), expected, 1e-4);
  EXPECT_NEAR(s.energy, d.energy, 1e-9 * std::abs(d.energy) + 1e-12);
}

// A relaxed fold (FoldOptions::relax) passes the limit point without halving down to it:
// the first increment past it, whose Newton solve fails, is relaxed whole from the last
// equilibrium to the far branch's stable state, and the fold goes on. Every step is a
// stable equilibrium of the closed form (tolerance as above), the one relaxed step lies
// within an increment past the limit point, and the steps before it on the near branch.
TEST(FoldSnap, ARelaxedFoldPassesTheLimitPointInWholeIncrements) {
  const Wing w = make_wing();
  const double phi_star = kPhiA - std::acos(-1.0 / kBeta);
  const double far_edge = kPhiA - 2 * kPi + std::acos(-1.0 / kBeta);
  const double limit = limit_fraction();
  for (const int steps : {40, kSteps}) {
    solvers::FoldOptions o;
    o.relax = true;
    // The bars (1e6 times the hinge) hold each of the relaxation's straight steps to a few
    // thousandths of the wing's turn: the far branch is some 1,000 of them away.
    o.relax_iterations = 3000;
    o.newton.tolerance = 1e-8;
    const auto path = solvers::solve_fold(w.model, {{{0}, (VectorX(1) << kPi + kEnd).finished()}},
                                          steps, VectorX::Zero(12), o);
    ASSERT_TRUE(path.completed) << path.message;
    EXPECT_EQ(static_cast<int>(path.steps.size()), steps);  // no increment halved
    int relaxed = 0;
    for (const auto& s : path.steps) {
      const double phi = checked_phi(w, s);
      if (s.snapped) {
        ++relaxed;
        EXPECT_GT(s.load_factor, limit);
        EXPECT_LT(s.load_factor, limit + 1.0 / steps + 1e-12);
      }
      if (relaxed == 0) {
        EXPECT_GE(phi, phi_star - 1e-4);
      } else {
        EXPECT_LT(phi, far_edge) << s.load_factor;
      }
    }
    EXPECT_EQ(relaxed, 1) << steps;
  }
}

// The relaxation leaves an exact saddle: started at the unstable equilibrium between the
// two branches (where the bistable wing's rest angle is the fold's start, found by Newton
// from the closed form's phi), it ends at one of the two stable equilibria of the closed
// form, with less energy. Its gradient there is zero to Newton's 1e-12 mm, so no step but
// the escape along the negative curvature leaves it.
TEST(FoldSnap, TheRelaxationLeavesASaddleForAStableState) {
  const Wing w = make_wing();
  const double phi_star = kPhiA - std::acos(-1.0 / kBeta);
  const double far_edge = kPhiA - 2 * kPi + std::acos(-1.0 / kBeta);
  // rest_offset rises as phi falls on the unstable branch: bisect in the reversed order.
  double lo = far_edge, hi = phi_star;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rest_offset(mid) > kStart ? lo : hi) = mid;
  }
  const double phi_u = 0.5 * (lo + hi);
  ASSERT_LT(1.0 + kBeta * std::cos(phi_u - kPhiA), 0.0);  // unstable
  VectorX u = VectorX::Zero(12);
  u[10] = std::cos(w.sign * phi_u) - 1.0;
  u[11] = std::sin(w.sign * phi_u);
  assembly::Assembler assembler(w.model, assembly::unmasked_dofs(w.model.fixed()), 0.0,
                                assembly::Storage::Lower);
  solvers::TangentSolver solver;
  solvers::NewtonOptions newton;
  newton.tolerance = 1e-12;
  const auto at_saddle =
      solvers::newton_equilibrium(assembler, solver, u, VectorX::Zero(12), newton);
  ASSERT_TRUE(at_saddle.converged) << at_saddle.failure;
  ASSERT_GT(at_saddle.negative_eigenvalues, 0);
  VectorX force;
  const double start_energy = assembler.assemble(u, force, false).total();
  solvers::RelaxationOptions o;
  o.tolerance = 1e-10;
  o.max_step = 0.05;
  o.escape_step = 0.01;
  // The bars (1e6 times the hinge) hold each straight step to a few thousandths of the
  // wing's turn (a longer one stretches them more than the turn gains): the far basin is
  // some 1,000 steps away.
  o.max_iterations = 3000;
  const auto rest = solvers::relax_to_stable(assembler, solver, u, o);
  ASSERT_TRUE(rest.converged) << rest.failure;
  EXPECT_LT(rest.energy, start_energy);
  const double phi = phi_of(w, u);
  EXPECT_GT(1.0 + kBeta * std::cos(phi - kPhiA), 0.0);  // stable by the closed form
  EXPECT_NEAR(rest_offset(phi), kStart, 1e-5);
  EXPECT_TRUE(std::abs(phi) < 1e-3 || phi < far_edge) << phi;
}
