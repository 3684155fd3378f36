#include "kresling/model/octave_arithmetic.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

extern "C" {
// LAPACK: minimum-norm least squares by a divide-and-conquer SVD.
void dgelsd_(const int* m, const int* n, const int* nrhs, double* a, const int* lda, double* b,
             const int* ldb, double* s, const double* rcond, int* rank, double* work,
             const int* lwork, int* iwork, int* info);
}

namespace kresling::model {

double octave_norm(const Vector3& v) {
  double scale = 0.0, sum = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double t = std::abs(v[k]);
    if (scale == t) {
      sum += 1.0;
    } else if (scale < t) {
      const double r = scale / t;
      sum *= r * r;
      sum += 1.0;
      scale = t;
    } else if (t != 0.0) {
      const double r = t / scale;
      sum += r * r;
    }
  }
  return scale * std::sqrt(sum);
}

bool octave_least_squares(const Eigen::Matrix<double, 3, 2>& A, const Vector3& b,
                          Eigen::Vector2d& x) {
  const int m = 3, n = 2, nrhs = 1, lda = 3, ldb = 3;
  double a[6], rhs[3], s[2];
  int rank = 0, info = 0;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) a[i + 3 * j] = A(i, j);  // column-major
  }
  for (int i = 0; i < 3; ++i) rhs[i] = b[i];
  const double rcond = -1.0;  // machine precision, Octave's choice
  // Workspace query first: LAPACK sizes its work arrays itself.
  double query = 0.0;
  int iquery = 0, lwork = -1;
  dgelsd_(&m, &n, &nrhs, a, &lda, rhs, &ldb, s, &rcond, &rank, &query, &lwork, &iquery, &info);
  if (info != 0) return false;
  lwork = static_cast<int>(query) + 1;
  std::vector<double> work(static_cast<std::size_t>(lwork));
  std::vector<int> iwork(static_cast<std::size_t>(std::max(iquery, 1)) + 64);
  dgelsd_(&m, &n, &nrhs, a, &lda, rhs, &ldb, s, &rcond, &rank, work.data(), &lwork, iwork.data(),
          &info);
  if (info != 0) return false;
  x = {rhs[0], rhs[1]};
  return true;
}

}  // namespace kresling::model
