#include "kresling/solvers/rigid_body.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace kresling::solvers {

namespace {

void require_every_node_on_a_bar(const model::Model& model,
                                 const std::vector<std::uint8_t>& held) {
  const NodeMatrix& X = model.nodes();
  std::vector<char> has_bar(static_cast<std::size_t>(X.rows()), 0);
  for (const auto& bar : model.bars()) has_bar[bar.nodes[0]] = has_bar[bar.nodes[1]] = 1;
  for (Index i = 0; i < X.rows(); ++i) {
    if (!has_bar[i] && !(held[3 * i] && held[3 * i + 1] && held[3 * i + 2])) {
      throw std::invalid_argument("node " + std::to_string(i) +
                                  " is attached to no bar: its free DOFs have no stiffness; "
                                  "connect it or support it");
    }
  }
}

// Rows: held DOFs; columns: the six rigid motions (rotations about `centre` scaled by the
// model's size `scale` so that all columns are commensurate).
Eigen::MatrixXd rigid_motions_of_held_dofs(const NodeMatrix& X,
                                           const std::vector<std::uint8_t>& held,
                                           const Vector3& centre, double scale) {
  std::vector<Eigen::Matrix<double, 1, 6>> rows;
  for (Index i = 0; i < X.rows(); ++i) {
    const Vector3 r = (X.row(i).transpose() - centre) / scale;
    for (int k = 0; k < 3; ++k) {
      if (!held[3 * i + k]) continue;
      Eigen::Matrix<double, 1, 6> row = Eigen::Matrix<double, 1, 6>::Zero();
      row[k] = 1.0;
      for (int a = 0; a < 3; ++a) {  // component k of (e_a x r)
        row[3 + a] = Vector3::Unit(a).cross(r)[k];
      }
      rows.push_back(row);
    }
  }
  Eigen::MatrixXd R(static_cast<Index>(rows.size()), 6);
  for (std::size_t i = 0; i < rows.size(); ++i) R.row(static_cast<Index>(i)) = rows[i];
  return R;
}

}  // namespace

void require_rigid_body_constrained(const model::Model& model,
                                    const std::vector<std::uint8_t>& supported) {
  // DOFs a family ties to the ground (anchor springs) block rigid motions as supports do.
  std::vector<std::uint8_t> held = supported;
  for (const auto& family : model.families()) family->mark_grounded_dofs(held);
  require_every_node_on_a_bar(model, held);
  const NodeMatrix& X = model.nodes();
  const Vector3 centre = X.colwise().mean().transpose();
  const double scale = std::max((X.rowwise() - centre.transpose()).rowwise().norm().maxCoeff(), 1e-300);
  const Eigen::MatrixXd R = rigid_motions_of_held_dofs(X, held, centre, scale);
  // Free motions: the (numerical) null space of R.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(R.rows() ? R : Eigen::MatrixXd::Zero(1, 6),
                                        Eigen::ComputeFullV);
  const auto& sigma = svd.singularValues();
  std::string free;
  int count = 0;
  static const char* names[6] = {"translation along x", "translation along y",
                                 "translation along z", "rotation about x",
                                 "rotation about y",    "rotation about z"};
  for (int j = 0; j < 6; ++j) {
    const double s = j < sigma.size() ? sigma[j] : 0.0;
    if (s > 1e-9) continue;
    const Eigen::Matrix<double, 6, 1> v = svd.matrixV().col(j);
    // A rotation about an axis through every node (a single node, or nodes on one line)
    // moves nothing: it is no motion of the model.
    double moved = 0.0;
    for (Index i = 0; i < X.rows(); ++i) {
      const Vector3 r = (X.row(i).transpose() - centre) / scale;
      moved = std::max(moved, (v.head<3>() + v.tail<3>().cross(r)).norm());
    }
    if (moved <= 1e-9) continue;
    int dominant = 0;
    v.cwiseAbs().maxCoeff(&dominant);
    free += (count++ ? ", " : "") + std::string(names[dominant]);
  }
  if (count) {
    throw std::invalid_argument(
        "supports: " + std::to_string(count) + " rigid-body motion" + (count > 1 ? "s are" : " is") +
        " left free (" + free + "); support or impose more DOFs");
  }
}

}  // namespace kresling::solvers
