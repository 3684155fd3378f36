// The global assembler: internal force and tangent against finite differences, invariance
// under rigid motions, lower-triangle storage and reuse of one assembler.
//
// Tolerances: as in the element tests, central differences with a step h = 1e-6 times the
// model's size leave truncation (~h^2) and rounding (~eps / h) errors near 1e-10 of the
// derivative's scale; 1e-6 relative on the norm has that headroom and still catches any
// wrongly scattered entry, which is O(1) relative to its column.

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/model/topology.hpp"

using namespace kresling;
using assembly::Assembler;
using assembly::Storage;

namespace {

constexpr double kStep = 1e-6;    // finite-difference step per unit of the model's size
constexpr double kRelTol = 1e-6;  // see the file comment
// Rigid motions: positions of magnitude |X| + |t| ~ 3 L round to eps |x|, which moves bar
// strains by ~10 eps and hinge angles by ~eps |x| / arm, against strains and angle changes
// of ~1e-2: ~1e-13 relative. 1e-10 has that margin; a term left unrotated is O(1).
constexpr double kRigidTol = 1e-10;

// A few non-planar panels (two quads split on their shorter diagonal, two triangles), bars
// on every edge, hinges on every shared edge, laws mixed, node positions jittered.
model::Model small_model() {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  NodeMatrix X(7, 3);
  X << 0, 0, 0, 1, 0, 0.1, 1.2, 1, 0, 0, 0.9, 0.2, 2, 0.4, 0.3, 1.8, 1.6, -0.2, 0.5, 1.8, 0.5;
  for (Index i = 0; i < X.size(); ++i) X.data()[i] += jitter(rng);
  const auto topo = model::build_topology(X, {{0, 1, 2, 3}, {1, 4, 2}, {2, 4, 5}, {3, 2, 5, 6}},
                                          model::PanelSplit::N4B5);
  std::vector<model::Bar> bars;
  for (std::size_t e = 0; e < topo.bars.size(); ++e) {
    const auto& b = topo.bars[e];
    const auto kind = e % 2 ? elements::BarLawKind::Ogden : elements::BarLawKind::Linear;
    bars.push_back({b, 0.5 + 0.1 * e, (X.row(b[1]) - X.row(b[0])).norm(), {kind, 10.0}});
  }
  std::vector<model::Hinge> hinges;
  for (std::size_t e = 0; e < topo.hinges.size(); ++e) {
    const auto& h = topo.hinges[e];
    elements::SpringLaw law{elements::SpringLawKind::EnhancedLinear, 0.1, 6.1};
    if (topo.hinge_is_bend[e]) law.kind = elements::SpringLawKind::SuperLinearBend;
    else if (e % 2) law.kind = elements::SpringLawKind::Linear;
    hinges.push_back({h, 1.0 + 0.3 * e,
                      elements::dihedral_angle(X.row(h[0]), X.row(h[1]), X.row(h[2]), X.row(h[3])),
                      (X.row(h[1]) - X.row(h[0])).norm(), law});
  }
  return model::Model(X, bars, hinges, std::vector<std::uint8_t>(3 * X.rows(), 0));
}

// A three-cell Kresling stack, mixed states. Bars get modulus kf instead of the thesis's
// 1e5 kf: there the hinges' share of the force is ~1e-6 of the bars', below what a 1e-6
// relative check resolves; with C0 = kf both families weigh alike.
model::KreslingSpecimen specimen(double lam = 0.7) {
  model::SpecimenParameters p;
  p.modulus_factor = 1.0;
  return model::build_kresling_specimen(geometry::Design(4, 30.0, lam, 30.0), {1, 0, 1},
                                        {1, -1, 1}, p);
}

double size_of(const model::Model& m) {
  const NodeMatrix& X = m.nodes();
  return (X.colwise().maxCoeff() - X.colwise().minCoeff()).norm();
}

VectorX random_displacement(const model::Model& m, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  VectorX d(m.num_dofs());
  for (Index i = 0; i < d.size(); ++i) d[i] = u(rng);
  return d;
}

Eigen::MatrixXd dense(const assembly::SparseMatrix& K) { return Eigen::MatrixXd(K); }

void expect_derivatives_match(const model::Model& m, const VectorX& u) {
  Assembler a(m, assembly::all_dofs(m.num_dofs()), /*shift=*/0.0, Storage::Full);
  VectorX f, fp, fm;
  a.assemble(u, f, true);
  const Eigen::MatrixXd K = dense(a.matrix());
  const double h = kStep * size_of(m);
  VectorX f_fd(m.num_dofs());
  Eigen::MatrixXd K_fd(m.num_dofs(), m.num_dofs());
  for (Index k = 0; k < m.num_dofs(); ++k) {
    VectorX up = u, um = u;
    up[k] += h;
    um[k] -= h;
    const double ep = a.assemble(up, fp, false).total(), em = a.assemble(um, fm, false).total();
    f_fd[k] = (ep - em) / (2 * h);
    K_fd.col(k) = (fp - fm) / (2 * h);
  }
  EXPECT_GT(f.norm(), 0.0);  // u is a strained state: the check is not 0 against 0
  EXPECT_LE((f - f_fd).norm(), kRelTol * f.norm());
  EXPECT_LE((K - K_fd).norm(), kRelTol * K.norm());
}

// u' with X + u' = Q (X + u) + t, node by node.
VectorX moved_rigidly(const model::Model& m, const VectorX& u, const Matrix3& Q, const Vector3& t) {
  VectorX v(u.size());
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const Vector3 x = m.nodes().row(i).transpose() + u.segment<3>(3 * i);
    v.segment<3>(3 * i) = Q * x + t - m.nodes().row(i).transpose();
  }
  return v;
}

}  // namespace

TEST(Assembly, SmallModelForceAndTangentMatchFiniteDifferences) {
  const model::Model m = small_model();
  ASSERT_GE(m.hinges().size(), 4u);
  expect_derivatives_match(m, random_displacement(m, 0.05, 1));
}

TEST(Assembly, KreslingSpecimenForceAndTangentMatchFiniteDifferences) {
  const auto s = specimen();
  expect_derivatives_match(s.model, random_displacement(s.model, 0.3, 2));
}

TEST(Assembly, RigidMotionKeepsEnergyAndRotatesForceAndTangent) {
  for (const model::Model& m : {small_model(), specimen().model}) {
    const VectorX u = random_displacement(m, 0.01 * size_of(m), 3);
    const Matrix3 Q = Eigen::AngleAxisd(2.1, Vector3(1, -2, 0.5).normalized()).toRotationMatrix();
    const Vector3 t = Vector3(0.3, -0.2, 0.4) * size_of(m);
    Assembler a(m, assembly::all_dofs(m.num_dofs()), 0.0);
    VectorX f, g;
    const double e = a.assemble(u, f, true).total();
    const Eigen::MatrixXd K = dense(a.matrix());
    const double e_moved = a.assemble(moved_rigidly(m, u, Q, t), g, true).total();
    const Eigen::MatrixXd K_moved = dense(a.matrix());
    EXPECT_GT(e, 0.0);
    EXPECT_NEAR(e_moved, e, kRigidTol * e);
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m.num_dofs(), m.num_dofs());
    for (Index i = 0; i < m.num_nodes(); ++i) R.block<3, 3>(3 * i, 3 * i) = Q;
    EXPECT_LE((g - R * f).norm(), kRigidTol * f.norm());
    EXPECT_LE((K_moved - R * K * R.transpose()).norm(), kRigidTol * K.norm());
  }
}

TEST(Assembly, LowerStorageIsTheLowerTriangleOfTheSymmetricTangent) {
  const auto s = specimen();
  const model::Model& m = s.model;
  const VectorX u = random_displacement(m, 0.3, 4);
  // Some DOFs left out, as supports leave them: the reduced rows must be the submatrix.
  std::vector<std::uint8_t> held(m.num_dofs(), 0);
  for (Index i : {0, 1, 2, 4, 13, 14, 40}) held[i] = 1;
  const auto rows = assembly::unmasked_dofs(held);
  VectorX f;
  Assembler all(m, assembly::all_dofs(m.num_dofs()), 1e-8, Storage::Full);
  Assembler full(m, rows, 1e-8, Storage::Full);
  Assembler lower(m, rows, 1e-8, Storage::Lower);
  all.assemble(u, f, true);
  full.assemble(u, f, true);
  lower.assemble(u, f, true);
  const Eigen::MatrixXd K_all = dense(all.matrix()), K = dense(full.matrix());
  ASSERT_EQ(lower.size(), m.num_dofs() - 7);
  // Every stored entry of the lower matrix is on or below the diagonal.
  const auto& L = lower.matrix();
  for (int c = 0; c < L.outerSize(); ++c) {
    for (assembly::SparseMatrix::InnerIterator it(L, c); it; ++it) EXPECT_GE(it.row(), it.col());
  }
  // Element matrices are symmetrised on the way in, 0.5 (K_ab + K_ba): the same
  // floating-point sum for both entries, so the whole matrix is exactly symmetric.
  EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0);
  // Both storages add the same element values into each entry; only the order of the sums
  // could differ, which is rounding, ~eps relative: 1e-14 of the largest entry.
  const double scale = K.cwiseAbs().maxCoeff();
  const Eigen::MatrixXd K_lower = dense(L);
  EXPECT_LE((K_lower - Eigen::MatrixXd(K.triangularView<Eigen::Lower>())).cwiseAbs().maxCoeff(),
            1e-14 * scale);
  for (Index i = 0; i < m.num_dofs(); ++i) {
    for (Index j = 0; j < m.num_dofs(); ++j) {
      if (rows[i] >= 0 && rows[j] >= 0) {
        ASSERT_NEAR(K(rows[i], rows[j]), K_all(i, j), 1e-14 * scale) << i << ", " << j;
      }
    }
  }
}

TEST(Assembly, RefillAndRebindMatchAFreshAssembler) {
  // The same arithmetic in the same order: results are expected bitwise equal.
  const auto s1 = specimen(0.7), s2 = specimen(0.8);
  const model::Model &m1 = s1.model, &m2 = s2.model;
  const VectorX u1 = random_displacement(m1, 0.3, 5), u2 = random_displacement(m1, 0.3, 6);
  const auto rows = assembly::all_dofs(m1.num_dofs());
  Assembler reused(m1, rows, 1e-8, Storage::Lower);
  VectorX f, f_first, f_fresh;
  const double e_first = reused.assemble(u1, f_first, true).total();
  const Eigen::MatrixXd K_first = dense(reused.matrix());
  EXPECT_EQ(reused.assemble(u1, f, true).total(), e_first);  // refilled, not accumulated
  EXPECT_EQ((dense(reused.matrix()) - K_first).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((f - f_first).cwiseAbs().maxCoeff(), 0.0);

  auto expect_as_fresh = [&](Assembler& a, const model::Model& m, const VectorX& u) {
    Assembler fresh(m, rows, 1e-8, Storage::Lower);
    const double e = a.assemble(u, f, true).total();
    EXPECT_EQ(e, fresh.assemble(u, f_fresh, true).total());
    EXPECT_EQ((f - f_fresh).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((dense(a.matrix()) - dense(fresh.matrix())).cwiseAbs().maxCoeff(), 0.0);
    // A force-only call leaves the force as the full one computed it.
    VectorX f_only;
    EXPECT_EQ(a.assemble(u, f_only, false).total(), e);
    EXPECT_EQ((f_only - f).cwiseAbs().maxCoeff(), 0.0);
  };
  expect_as_fresh(reused, m1, u2);  // after a change of u

  // Another design of the same n and cells: same elements, other geometry.
  ASSERT_TRUE(reused.same_connectivity(m2));
  reused.rebind(m2);
  expect_as_fresh(reused, m2, u2);
  VectorX f_m1;
  Assembler(m1, rows).assemble(u2, f_m1, false);
  EXPECT_GT((f - f_m1).norm(), 1e-3 * f.norm());  // the rebound model is really evaluated

  const model::Model other = small_model();
  EXPECT_FALSE(reused.same_connectivity(other));
  EXPECT_THROW(reused.rebind(other), std::invalid_argument);
}

// The model/workspace split: a Workspace keeps the pattern and slot map of one connectivity
// and no reference to a model; assemble(model, workspace, u) serves any model of that
// connectivity exactly as a workspace built for it would, and refuses any other.

namespace {

// Bitwise: the same arithmetic in the same order (the slots differ only in where they come
// from), so equality is exact, not to a tolerance.
void expect_same_as_fresh(const model::Model& m, assembly::Workspace& w, const VectorX& u) {
  assembly::Workspace fresh(m, w.rows(), w.shift(), w.storage());
  VectorX f, f_fresh;
  const assembly::Energies e = assembly::assemble(m, w, u, f, true);
  const assembly::Energies e_fresh = assembly::assemble(m, fresh, u, f_fresh, true);
  EXPECT_EQ(e[0], e_fresh[0]);  // bars
  EXPECT_EQ(e[1], e_fresh[1]);  // hinges
  EXPECT_EQ((f - f_fresh).cwiseAbs().maxCoeff(), 0.0);
  const auto& K = w.matrix();
  const auto& K_fresh = fresh.matrix();
  ASSERT_EQ(K.nonZeros(), K_fresh.nonZeros());
  ASSERT_EQ(K.rows(), K_fresh.rows());
  for (Index j = 0; j <= K.outerSize(); ++j) {
    ASSERT_EQ(K.outerIndexPtr()[j], K_fresh.outerIndexPtr()[j]);
  }
  for (Index k = 0; k < K.nonZeros(); ++k) {
    ASSERT_EQ(K.innerIndexPtr()[k], K_fresh.innerIndexPtr()[k]);
    ASSERT_EQ(K.valuePtr()[k], K_fresh.valuePtr()[k]) << "entry " << k;
  }
}

}  // namespace

TEST(Workspace, ServesEveryModelOfItsConnectivityAsAFreshOneBitwise) {
  const auto s1 = specimen(0.7), s2 = specimen(0.8), s3 = specimen(0.9);
  for (Storage storage : {Storage::Full, Storage::Lower}) {
    // Built from a model that is gone before the workspace is used: it keeps no reference
    // (under make sanitize, any read of the dead model would be reported).
    std::unique_ptr<assembly::Workspace> w;
    {
      const auto gone = specimen(0.75);
      std::vector<std::uint8_t> mask(gone.model.num_dofs(), 0);
      for (int k = 0; k < 9; ++k) mask[k] = 1;  // three nodes held: a reduced numbering
      w = std::make_unique<assembly::Workspace>(gone.model, assembly::unmasked_dofs(mask), 1e-8,
                                                storage);
    }
    for (const model::Model* m : {&s1.model, &s2.model, &s3.model, &s1.model}) {
      ASSERT_TRUE(w->fits(*m));
      expect_same_as_fresh(*m, *w, random_displacement(*m, 0.3, 11));
    }
    // The shift is a setting of the workspace, not of its pattern.
    w->set_shift(0.0);
    expect_same_as_fresh(s2.model, *w, random_displacement(s2.model, 0.3, 12));
  }
  // Each model through the shared workspace gives its own values (not the last model's).
  assembly::Workspace w(s1.model, assembly::all_dofs(s1.model.num_dofs()));
  const VectorX u = random_displacement(s1.model, 0.3, 13);
  VectorX f1, f2;
  assembly::assemble(s1.model, w, u, f1, false);
  assembly::assemble(s2.model, w, u, f2, false);
  EXPECT_GT((f1 - f2).norm(), 1e-3 * f1.norm());
}

TEST(Workspace, RefusesAModelOfAnotherConnectivityNamingIt) {
  const auto s = specimen(0.7);
  assembly::Workspace w(s.model, assembly::all_dofs(s.model.num_dofs()));
  VectorX f;
  auto expect_refused = [&](const model::Model& other) {
    EXPECT_FALSE(w.fits(other));
    try {
      assembly::assemble(other, w, VectorX::Zero(other.num_dofs()), f, true);
      ADD_FAILURE() << "a model of another connectivity was assembled";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("workspace: was built for a model of another "
                                           "connectivity"), std::string::npos) << e.what();
    }
    EXPECT_THROW(Assembler(other, w), std::invalid_argument);
  };
  expect_refused(small_model());  // other sizes
  // Same counts of nodes, bars and hinges, other elements: the middle cell's chirality
  // flipped moves its diagonal creases to the other vertices.
  model::SpecimenParameters p;
  p.modulus_factor = 1.0;
  const auto flipped = model::build_kresling_specimen(geometry::Design(4, 30.0, 0.7, 30.0),
                                                      {1, 0, 1}, {1, 1, 1}, p);
  ASSERT_EQ(flipped.model.num_nodes(), s.model.num_nodes());
  ASSERT_EQ(flipped.model.bars().size(), s.model.bars().size());
  ASSERT_EQ(flipped.model.hinges().size(), s.model.hinges().size());
  expect_refused(flipped.model);
  // One bar's two nodes swapped: the same elements in another order are another pattern
  // (the element matrices' rows would land in the wrong slots).
  std::vector<model::Bar> bars = s.model.bars();
  std::swap(bars[3].nodes[0], bars[3].nodes[1]);
  const model::Model swapped(s.model.nodes(), bars, s.model.hinges(), s.model.fixed());
  expect_refused(swapped);
}
