#pragma once
/// \file model_bindings.hpp
/// What the binding files of kresling._core.model share (cpp/python/model/bind_<header>.cpp
/// binds what cpp/kresling/model/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/model/arm.hpp"
#include "kresling/model/calibration.hpp"
#include "kresling/model/family_registry.hpp"
#include "kresling/model/kresling_design_derivative.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/model/merlin2_rest_angle.hpp"
#include "kresling/model/model.hpp"
#include "kresling/model/panel_centre.hpp"
#include "kresling/model/panel_elements.hpp"
#include "kresling/model/topology.hpp"

namespace py = pybind11;

namespace kresling::python {

namespace {

// Rows of fixed-size index arrays as an (n, width) int64 array.
template <std::size_t Width>
py::array_t<Index> index_rows(const std::vector<std::array<Index, Width>>& v) {
  py::array_t<Index> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(Width)});
  auto w = a.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t k = 0; k < Width; ++k) w(i, k) = v[i][k];
  }
  return a;
}

template <typename T>
py::array_t<T> vector_array(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

std::vector<int> families(const std::vector<model::EdgeFamily>& f) {
  std::vector<int> out(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) out[i] = static_cast<int>(f[i]);
  return out;
}

}  // namespace

}  // namespace kresling::python
