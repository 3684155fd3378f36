#pragma once
/// \file octave_arithmetic.hpp
/// Two computations done the way GNU Octave does them, to the last bit, so that a model
/// built here matches one MERLIN2 v1.1 built under Octave exactly (docs/model.md,
/// 'Material calibration', compatibility mode). Where MERLIN2's numbers hinge on rounding
/// (an arccosine a few ulps from -1, a centre node one ulp away) nothing else reproduces
/// them.

#include "kresling/core/types.hpp"

namespace kresling::model {

/// Octave's 2-norm of a vector: a running scale and a sum of squared ratios,
/// |v| = scale sqrt(sum), safe from overflow.
double octave_norm(const Vector3& v);

/// Octave's `A \ b` for a 3 x 2 matrix: the minimum-norm least-squares solution from
/// LAPACK's dgelsd (singular-value decomposition), as Octave solves non-square systems.
/// Returns false (and leaves x unset) if LAPACK reports a failure.
bool octave_least_squares(const Eigen::Matrix<double, 3, 2>& A, const Vector3& b,
                          Eigen::Vector2d& x);

}  // namespace kresling::model
