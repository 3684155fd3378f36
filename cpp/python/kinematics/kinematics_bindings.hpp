#pragma once
/// \file kinematics_bindings.hpp
/// What the binding files of kresling._core.kinematics share (cpp/python/kinematics/bind_<header>.cpp
/// binds what cpp/kresling/kinematics/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/kinematics/chain.hpp"
#include "kresling/kinematics/constant_curvature.hpp"
#include "kresling/kinematics/inverse.hpp"
#include "kresling/kinematics/module_transform.hpp"

namespace py = pybind11;
namespace kk = kresling::kinematics;

namespace kresling::python {

namespace {

using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

Rows3 as_rows3(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
               const char* name) {
  if (!((a.ndim() == 2 && a.shape(1) == 3) || (a.ndim() == 1 && a.shape(0) == 3))) {
    throw std::invalid_argument(std::string(name) + " must have shape (3,) or (n, 3)");
  }
  const py::ssize_t rows = a.ndim() == 1 ? 1 : a.shape(0);
  return Eigen::Map<const Rows3>(a.data(), rows, 3);
}

}  // namespace

}  // namespace kresling::python
