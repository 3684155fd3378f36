// Every family's parameter derivatives (ElementFamily::parameter_derivative) against central
// differences of the family's own force and energy, with the family rebuilt from its table
// with one entry moved; and the sensitivity of an equilibrium (solvers/sensitivity.hpp)
// against equilibria solved again with a parameter moved.
//
// Tolerances: the force and energy are smooth in each parameter where the elements are
// evaluated (bars stretched and compressed, hinges inside and beyond the enhanced-linear
// law's limits, a taut cable), so a central difference with a relative step of 1e-6 has
// truncation ~1e-12 and rounding ~1e-10 relative to the largest entry; 1e-7 catches any
// wrong term (those are O(1) relative). Parameters that enter linearly (areas, moduli,
// stiffnesses) have no truncation at all.

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "kresling/assembly/parameter_jacobian.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/shape_jacobian.hpp"
#include "kresling/elements/corner_angle.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/model/element_family.hpp"
#include "kresling/model/family_registry.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/displacement_control.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/sensitivity.hpp"

using namespace kresling;

namespace {

constexpr double kRelStep = 1e-6;
constexpr double kRelTol = 1e-7;

// Seven nodes: a bent quadrilateral strip (two hinges on a shared axis), a triangle off it.
NodeMatrix nodes() {
  NodeMatrix X(7, 3);
  X << 0, 0, 0,  //
      10, 0, 0,  //
      5, 8, 1,   //
      5, -7, 2,  //
      15, 6, -1, //
      2, 3, 9,   //
      12, -4, 6;
  return X;
}

model::Table table_of(const std::string& family) {
  using model::index_column;
  using model::real_column;
  const NodeMatrix X = nodes();
  auto length = [&](Index a, Index b) { return (X.row(b) - X.row(a)).norm(); };
  if (family == "bars") {
    // Ogden and linear laws, rest lengths off the reference so that the bars carry force.
    return {{"nodes", index_column({0, 1, 1, 2, 0, 3, 4, 5, 2, 6}, 2)},
            {"area", real_column({0.7, 1.1, 0.9, 1.3, 0.5})},
            {"rest_length", real_column({0.95 * length(0, 1), 1.04 * length(1, 2), length(0, 3),
                                         0.9 * length(4, 5), 1.1 * length(2, 6)})},
            {"law", index_column({1, 0, 1, 0, 1})},
            {"modulus", real_column({200.0, 150.0, 90.0, 300.0, 120.0})}};
  }
  if (family == "hinges") {
    // Linear, enhanced-linear inside and beyond its limits (theta1 close to the angle), and
    // the super-linear bend law.
    return {{"nodes", index_column({0, 1, 2, 3, 1, 0, 3, 2, 0, 1, 2, 4, 2, 0, 5, 1}, 4)},
            {"stiffness", real_column({0.8, 1.3, 0.6, 2.0})},
            {"rest_angle", real_column({3.0, 3.4, 2.5, 3.3})},
            {"length", real_column({10.0, 9.5, 10.0, 8.0})},
            {"law", index_column({0, 1, 1, 2})},
            {"theta1", real_column({0.5, 3.5, 0.3, 0.5})},
            {"theta2", real_column({5.5, 5.9, 5.0, 5.5})}};
  }
  if (family == "cables") {
    return {{"nodes", index_column({3, 0, 5, 6, 2, 4})}, {"node_count", index_column({4, 2})},
            {"stiffness", real_column({50.0, 80.0})},
            {"rest_length", real_column({0.9 * (length(3, 0) + length(0, 5) + length(5, 6)),
                                         0.97 * length(2, 4)})}};
  }
  if (family == "springs") {
    return {{"nodes", index_column({5, 6})},
            {"stiffness", real_column({1.0, 2.0, 0.5, 0.0, 3.0, 1.5}, 3)},
            {"anchor", real_column({1.0, 2.0, 8.0, 13.0, -3.0, 7.0}, 3)}};
  }
  // face_angles
  return {{"nodes", index_column({0, 1, 2, 1, 4, 2}, 3)},
          {"rest_angle", real_column({0.9, 1.0, 1.1, 0.7, 1.2, 1.2}, 3)},
          {"stiffness", real_column({2.0, 0.7})}};
}

VectorX displacement() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-0.6, 0.6);
  VectorX u(21);
  for (Index i = 0; i < u.size(); ++i) u[i] = d(rng);
  return u;
}

double evaluate(const model::Table& table, const std::string& family, const VectorX& u,
                VectorX& force) {
  const model::FamilyPtr f = model::family_kind(family).from_table(table);
  force = VectorX::Zero(u.size());
  model::AssemblyTarget target{force};
  return f->assemble(nodes(), u, target);
}

// Every pair of the seven nodes joined: a rigid truss, stiff enough (modulus 500) that the
// prestress of the hinges, cables and corner springs (rest states off the reference) moves
// it by a fraction of a millimetre, soft enough that their parameters move it visibly.
model::Table truss() {
  const NodeMatrix X = nodes();
  std::vector<Index> pairs;
  std::vector<double> rest;
  for (Index a = 0; a < 7; ++a) {
    for (Index b = a + 1; b < 7; ++b) {
      pairs.insert(pairs.end(), {a, b});
      rest.push_back((X.row(b) - X.row(a)).norm());
    }
  }
  const auto n = rest.size();
  return {{"nodes", model::index_column(pairs, 2)},
          {"area", model::real_column(std::vector<double>(n, 1.0))},
          {"rest_length", model::real_column(rest)},
          {"law", model::index_column(std::vector<Index>(n, 1))},
          {"modulus", model::real_column(std::vector<double>(n, 500.0))}};
}

const std::vector<std::string> kFamilies = {"bars", "hinges", "cables", "springs", "face_angles"};

}  // namespace

TEST(ParameterDerivatives, EveryFamilyMatchesCentralDifferences) {
  const VectorX u = displacement();
  for (const std::string& family : kFamilies) {
    const model::Table table = table_of(family);
    const model::FamilyPtr f = model::family_kind(family).from_table(table);
    f->check(nodes(), 20.0);
    ASSERT_FALSE(f->parameters().empty()) << family;
    for (const std::string& name : f->parameters()) {
      model::ParameterDerivative d;
      f->parameter_derivative(nodes(), u, name, d);
      const Index entries = table.at(name).size();
      ASSERT_EQ(d.energy.size(), entries) << family << "." << name;
      Eigen::SparseMatrix<double> G(u.size(), entries);
      G.setFromTriplets(d.force.begin(), d.force.end());
      const Eigen::MatrixXd dense = G;
      for (Index j = 0; j < entries; ++j) {
        const double value = table.at(name).reals[j];
        const double h = kRelStep * std::max(std::abs(value), 1.0);
        model::Table plus = table, minus = table;
        plus[name].reals[j] += h;
        minus[name].reals[j] -= h;
        VectorX fp, fm;
        const double ep = evaluate(plus, family, u, fp), em = evaluate(minus, family, u, fm);
        const VectorX fd = (fp - fm) / (2.0 * h);
        const double scale = std::max(fd.cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LE((dense.col(j) - fd).cwiseAbs().maxCoeff(), kRelTol * scale)
            << family << "." << name << "[" << j << "]";
        const double efd = (ep - em) / (2.0 * h);
        EXPECT_NEAR(d.energy[j], efd, kRelTol * std::max(std::abs(efd), 1e-12))
            << family << "." << name << "[" << j << "] energy";
      }
    }
  }
}

TEST(ParameterDerivatives, InternalFamiliesExertNoNetForceOrMoment) {
  // A parameter of an element changes forces the element's nodes exert on each other: their
  // resultant and moment vanish (the derivative of a force system in equilibrium). Springs
  // to fixed anchors are external and excluded.
  const VectorX u = displacement();
  NodeMatrix x = nodes();
  for (Index n = 0; n < x.rows(); ++n) x.row(n) += u.segment<3>(3 * n).transpose();
  for (const std::string& family : {"bars", "hinges", "cables", "face_angles"}) {
    const model::FamilyPtr f = model::family_kind(family).from_table(table_of(family));
    for (const std::string& name : f->parameters()) {
      model::ParameterDerivative d;
      f->parameter_derivative(nodes(), u, name, d);
      Eigen::SparseMatrix<double> G(u.size(), d.energy.size());
      G.setFromTriplets(d.force.begin(), d.force.end());
      const Eigen::MatrixXd dense = G;
      for (Index j = 0; j < dense.cols(); ++j) {
        Vector3 resultant = Vector3::Zero(), moment = Vector3::Zero();
        for (Index n = 0; n < x.rows(); ++n) {
          const Vector3 fn = dense.col(j).segment<3>(3 * n);
          resultant += fn;
          moment += x.row(n).transpose().cross(fn);
        }
        const double scale = std::max(dense.col(j).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LE(resultant.norm(), 1e-12 * scale) << family << "." << name << "[" << j << "]";
        EXPECT_LE(moment.norm(), 1e-12 * scale * 20.0) << family << "." << name << "[" << j << "]";
      }
    }
  }
}

TEST(ParameterDerivatives, AnUnknownParameterIsRefusedNamingWhatThereIs) {
  const model::FamilyPtr bars = model::family_kind("bars").from_table(table_of("bars"));
  model::ParameterDerivative d;
  try {
    bars->parameter_derivative(nodes(), displacement(), "stiffness", d);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("must be one of area, rest_length, modulus"),
              std::string::npos)
        << e.what();
  }
  const model::Model m(nodes(), std::vector<std::uint8_t>(21, 0),
                       {model::family_kind("bars").from_table(table_of("bars"))});
  EXPECT_THROW(assembly::parameter_jacobian(m, displacement(), "springs", "stiffness"),
               std::invalid_argument);
}

TEST(EquilibriumSensitivity, MatchesEquilibriaSolvedAgain) {
  // The bars, hinges and cables on nodes 0, 1, 3 held; a load on the others; solved by force
  // control. du/dp from one factorisation against central differences of equilibria solved
  // again (Newton to 1e-11 mm), for one parameter of each family.
  std::vector<std::uint8_t> fixed(21, 0);
  for (Index n : {0, 1, 3}) {
    for (int k = 0; k < 3; ++k) fixed[3 * n + k] = 1;
  }
  auto build = [&](const std::string& family, const std::string& name, Index entry, double dv) {
    std::vector<model::FamilyPtr> families;
    for (const std::string& f : {"bars", "hinges", "cables", "face_angles"}) {
      model::Table t = f == "bars" ? truss() : table_of(f);
      if (f == family) t[name].reals[entry] += dv;
      families.push_back(model::family_kind(f).from_table(t));
    }
    return model::Model(nodes(), fixed, families);
  };
  VectorX load = VectorX::Zero(21);
  load[3 * 2 + 2] = 0.3;
  load[3 * 4 + 1] = -0.2;
  load[3 * 6 + 0] = 0.25;
  solvers::ForceControlOptions options;
  options.newton.tolerance = 1e-11;
  auto equilibrium = [&](const model::Model& m) {
    const solvers::PathResult path = solvers::solve_force_control(m, load, 4, options);
    EXPECT_TRUE(path.completed) << path.message;
    return path.steps.back().displacement;
  };
  const model::Model base = build("", "", 0, 0.0);
  const VectorX u = equilibrium(base);
  const solvers::EquilibriumSensitivity sensitivity(base, u, {});
  ASSERT_TRUE(sensitivity.ok());
  EXPECT_EQ(sensitivity.negative_eigenvalues(), 0);
  const std::vector<std::tuple<std::string, std::string, Index>> cases = {
      {"bars", "modulus", 1}, {"bars", "rest_length", 3}, {"hinges", "rest_angle", 0},
      {"hinges", "stiffness", 2}, {"cables", "rest_length", 0}, {"face_angles", "rest_angle", 4}};
  for (const auto& [family, name, entry] : cases) {
    const auto j = assembly::parameter_jacobian(base, u, family, name);
    const Eigen::MatrixXd dforce = Eigen::MatrixXd(j.force).col(entry);
    const Eigen::MatrixXd du = sensitivity.displacement(dforce);
    const double value = (family == "bars" ? truss() : table_of(family)).at(name).reals[entry];
    const double h = 1e-5 * std::abs(value);
    const VectorX fd = (equilibrium(build(family, name, entry, h)) -
                        equilibrium(build(family, name, entry, -h))) / (2.0 * h);
    // Truncation ~(1e-5)^2 relative, Newton's residue 1e-11 mm over 2 h: 1e-6 relative.
    EXPECT_LE((du.col(0) - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff())
        << family << "." << name << "[" << entry << "]";
    // The supports' reactions change by d f_int/dp along du (the load is fixed).
    const Eigen::MatrixXd reactions = sensitivity.held_force(dforce, du);
    ASSERT_EQ(reactions.rows(), 9);
    // Their sum balances the (fixed) load: its derivative is zero.
    Vector3 total = Vector3::Zero();
    for (Index k = 0; k < 9; ++k) total[k % 3] += reactions(k, 0);
    VectorX free_force = (dforce + Eigen::MatrixXd(sensitivity.tangent()) * du).col(0);
    for (Index k = 0; k < 21; ++k) {
      if (!fixed[k]) EXPECT_NEAR(free_force[k], 0.0, 1e-9 * dforce.cwiseAbs().maxCoeff());
    }
    EXPECT_LE(total.norm(), 1e-9 * dforce.cwiseAbs().maxCoeff());
  }
}

TEST(EquilibriumSensitivity, AdjointAgreesWithTheDirectDerivative) {
  std::vector<std::uint8_t> fixed(21, 0);
  for (Index n : {0, 1, 3}) {
    for (int k = 0; k < 3; ++k) fixed[3 * n + k] = 1;
  }
  std::vector<model::FamilyPtr> families;
  for (const std::string& f : {"bars", "hinges", "cables"}) {
    families.push_back(model::family_kind(f).from_table(table_of(f)));
  }
  const model::Model m(nodes(), fixed, families);
  const VectorX u = displacement();  // any state: the identity is linear algebra
  const solvers::EquilibriumSensitivity s(m, u, {13});
  ASSERT_TRUE(s.ok());
  const auto j = assembly::parameter_jacobian(m, u, "hinges", "rest_angle");
  const Eigen::MatrixXd G = j.force;
  VectorX g = VectorX::LinSpaced(21, -1.0, 2.0);  // dJ/du of J = g . u
  const Eigen::MatrixXd du = s.displacement(G);
  const VectorX direct = du.transpose() * g;
  const VectorX lambda = s.adjoint(g);
  const VectorX adjoint = -(G.transpose() * lambda);
  // The held DOFs (supports and DOF 13) do not move; g there does not count.
  for (Index d : s.held_dofs()) EXPECT_EQ(du.row(d).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LE((direct - adjoint).cwiseAbs().maxCoeff(), 1e-10 * direct.cwiseAbs().maxCoeff());
}

namespace {

// A model built stress-free in X (every bar's rest length, the first two hinges' rest angles
// and lengths, the first face's corner angles taken from X), with a hinge and a face whose
// rest values are set (a fold target: they do not follow X) and springs to fixed anchors,
// which load it.
model::Model stress_free(const NodeMatrix& X) {
  using model::index_column;
  using model::real_column;
  auto length = [&](Index a, Index b) { return (X.row(b) - X.row(a)).norm(); };
  model::Table bars = truss();
  std::vector<double> rest;
  const auto& pairs = bars.at("nodes").indices;
  for (std::size_t i = 0; i < pairs.size(); i += 2) rest.push_back(length(pairs[i], pairs[i + 1]));
  bars["rest_length"] = real_column(rest);
  const std::vector<Index> hinge_nodes = {0, 1, 2, 3, 1, 2, 0, 4, 0, 1, 5, 3};
  std::vector<double> angles, lengths;
  for (int h = 0; h < 2; ++h) {
    const Index* n = &hinge_nodes[4 * h];
    angles.push_back(elements::dihedral_angle(X.row(n[0]), X.row(n[1]), X.row(n[2]), X.row(n[3])));
    lengths.push_back(length(n[0], n[1]));
  }
  angles.push_back(2.0);  // a target, not the geometry
  lengths.push_back(9.0);
  const model::Table hinges = {{"nodes", index_column(hinge_nodes, 4)},
                               {"stiffness", real_column({0.8, 1.3, 0.6})},
                               {"rest_angle", real_column(angles)},
                               {"length", real_column(lengths)},
                               {"law", index_column({0, 1, 0})},
                               {"theta1", real_column({0.5, 0.3, 0.5})},
                               {"theta2", real_column({5.5, 5.9, 5.5})}};
  const auto corners = elements::corner_angles(X.row(0), X.row(1), X.row(2));
  const model::Table faces = {
      {"nodes", index_column({0, 1, 2, 1, 4, 2}, 3)},
      {"rest_angle", real_column({corners[0], corners[1], corners[2], 0.7, 1.2, 1.2}, 3)},
      {"stiffness", real_column({2.0, 0.7})}};
  std::vector<model::FamilyPtr> families = {
      model::family_kind("bars").from_table(bars),
      model::family_kind("hinges").from_table(hinges),
      model::family_kind("springs").from_table(table_of("springs")),
      model::family_kind("face_angles").from_table(faces)};
  return model::Model(X, std::vector<std::uint8_t>(21, 0), families);
}

}  // namespace

TEST(ShapeJacobian, MatchesModelsRebuiltStressFreeInMovedPositions) {
  // d f_int / dX and dE/dX at fixed u against central differences of models built
  // stress-free in X +- h e_k (the set rest values kept): the derivative a shape
  // sensitivity needs. Smooth in X, step 1e-6 mm on lengths of ~10 mm: truncation ~1e-12
  // and rounding ~1e-9 relative to the column's largest entry; 1e-6 catches any missing
  // term (a bar's rest length left out moves a column by the bar's stiffness, O(1)).
  const VectorX u = displacement() * 0.5;
  const NodeMatrix X = nodes();
  const model::Model m = stress_free(X);
  const assembly::ShapeJacobian j = assembly::shape_jacobian(m, u);
  const Eigen::MatrixXd dense = j.force;
  const double h = 1e-6;
  double largest = 0.0;
  for (Index k = 0; k < 21; ++k) {
    NodeMatrix plus = X, minus = X;
    plus(k / 3, k % 3) += h;
    minus(k / 3, k % 3) -= h;
    VectorX fp, fm;
    const model::Model mp = stress_free(plus), mm = stress_free(minus);
    const double ep = assembly::Assembler(mp, assembly::all_dofs(21), 0.0).assemble(u, fp, false).total();
    const double em = assembly::Assembler(mm, assembly::all_dofs(21), 0.0).assemble(u, fm, false).total();
    const VectorX fd = (fp - fm) / (2.0 * h);
    largest = std::max(largest, fd.cwiseAbs().maxCoeff());
    EXPECT_LE((dense.col(k) - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff())
        << "X DOF " << k;
    EXPECT_NEAR(j.energy[k], (ep - em) / (2.0 * h), 1e-6 * std::max(1.0, std::abs(j.energy[k])))
        << "X DOF " << k << " energy";
  }
  EXPECT_GT(largest, 1.0);  // the differences are not all zero
  // The rest values that follow X matter: the tangent alone misses them by O(1) (a bar of
  // modulus 500 whose rest length follows its length has no force along that motion).
  assembly::Assembler tangent(m, assembly::all_dofs(21), 0.0);
  VectorX f;
  tangent.assemble(u, f, true);
  const Eigen::MatrixXd K = tangent.matrix();
  EXPECT_GT((dense - K).cwiseAbs().maxCoeff(), 1.0);
}

TEST(ShapeJacobian, ARigidMotionOfTheReferenceIsARigidMotionOfTheStructure) {
  // Moving X and u's reference together by a rigid translation changes nothing: the force
  // derivative along a translation of every node is zero (every family here is internal
  // but the springs, whose anchors stay: their part is -k per axis).
  const VectorX u = displacement() * 0.5;
  const model::Model m = stress_free(nodes());
  const Eigen::MatrixXd dense = assembly::shape_jacobian(m, u).force;
  for (int axis = 0; axis < 3; ++axis) {
    VectorX t = VectorX::Zero(21);
    for (Index n = 0; n < 7; ++n) t[3 * n + axis] = 1.0;
    VectorX expected = VectorX::Zero(21);
    const model::Table springs = table_of("springs");
    const auto& spring_nodes = springs.at("nodes").indices;
    for (std::size_t s = 0; s < spring_nodes.size(); ++s) {
      expected[3 * spring_nodes[s] + axis] = springs.at("stiffness").reals[3 * s + axis];
    }
    EXPECT_LE((dense * t - expected).cwiseAbs().maxCoeff(), 1e-9 * dense.cwiseAbs().maxCoeff())
        << "axis " << axis;
  }
}

TEST(PathSensitivity, AnAdaptivePathsSamplesFromItsKnotsAgreeWithEachSamplesOwn) {
  // The truss with its hinges, nodes 0, 1, 3 held, node 2 driven 1.5 mm along z in 60
  // samples by adaptive increments that keep their knots. The samples read off the knots'
  // Hermite curves are differentiated through the knots' derivatives and their rates
  // (interpolated_path_sensitivity); each sample differentiated on its own
  // (path_sensitivity) must agree to the interpolation error (~1e-9 of the force) and that
  // of the rates' central difference (~1e-7): asserted 1e-6 of the largest.
  std::vector<std::uint8_t> fixed(21, 0);
  for (Index n : {0, 1, 3}) {
    for (int k = 0; k < 3; ++k) fixed[3 * n + k] = 1;
  }
  const model::Model m(nodes(), fixed,
                       {model::family_kind("bars").from_table(truss()),
                        model::family_kind("hinges").from_table(table_of("hinges"))});
  VectorX prescribed = VectorX::Zero(21);
  prescribed[3 * 2 + 2] = 1.5;
  solvers::DisplacementControlOptions options;
  options.newton.tolerance = 1e-11;
  options.shift = 0.0;
  options.extrapolation = 2;
  options.adaptive = true;
  options.keep_knots = true;
  const solvers::PathResult path = solvers::solve_displacement_control(m, prescribed, 60, options);
  ASSERT_TRUE(path.completed) << path.message;
  ASSERT_GE(path.knots.size(), 2u);
  ASSERT_LT(path.knots.size(), 30u);  // most samples read off curves
  std::vector<VectorX> states;
  std::vector<double> fractions;
  for (const solvers::PathStep& s : path.steps) {
    states.push_back(s.displacement);
    fractions.push_back(s.load_factor);
  }
  solvers::PathKnots knots;
  for (const solvers::PathKnot& k : path.knots) {
    knots.t.push_back(k.t);
    knots.u.push_back(k.u);
    knots.velocity.push_back(k.velocity);
  }
  knots.step_knot = path.step_knot;
  // Two variables: every bar's modulus scaled, the hinges' rest angles moved together.
  std::vector<solvers::ColumnMotion> columns = {
      {"bars", "modulus", Eigen::MatrixXd::Zero(21, 2)},
      {"hinges", "rest_angle", Eigen::MatrixXd::Zero(4, 2)}};
  columns[0].weights.col(0).setConstant(500.0);
  columns[1].weights.col(1).setOnes();
  const Eigen::MatrixXd none(21, 0);
  const std::vector<Index> held = {3 * 2 + 2};
  const solvers::PathSensitivityResult exact =
      solvers::path_sensitivity(m, states, fractions, held, none, columns, Eigen::MatrixXd(21, 0));
  const solvers::PathSensitivityResult curves = solvers::interpolated_path_sensitivity(
      m, states, fractions, knots, held, none, columns, Eigen::MatrixXd(21, 0));
  ASSERT_EQ(curves.displacement.size(), states.size());
  for (Index p = 0; p < 2; ++p) {
    double du_scale = 0.0, du_error = 0.0, f_scale = 0.0, f_error = 0.0;
    for (std::size_t k = 0; k < states.size(); ++k) {
      du_scale = std::max(du_scale, exact.displacement[k].col(p).cwiseAbs().maxCoeff());
      du_error = std::max(du_error, (exact.displacement[k].col(p) - curves.displacement[k].col(p))
                                        .cwiseAbs().maxCoeff());
      f_scale = std::max(f_scale, exact.held_force[k].col(p).cwiseAbs().maxCoeff());
      f_error = std::max(f_error, (exact.held_force[k].col(p) - curves.held_force[k].col(p))
                                      .cwiseAbs().maxCoeff());
    }
    EXPECT_LE(du_error, 1e-6 * du_scale) << "variable " << p;
    EXPECT_LE(f_error, 1e-6 * f_scale) << "variable " << p;
    EXPECT_LE((exact.energy.col(p) - curves.energy.col(p)).cwiseAbs().maxCoeff(),
              1e-6 * exact.energy.col(p).cwiseAbs().maxCoeff());
  }
}
