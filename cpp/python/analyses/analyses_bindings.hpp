#pragma once
/// \file analyses_bindings.hpp
/// What the binding files of kresling._core.analyses share (cpp/python/analyses/bind_<header>.cpp
/// binds what cpp/kresling/analyses/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <type_traits>
#include <vector>

#include "bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/arm_crease_switching.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/linear_bending.hpp"
#include "kresling/analyses/snap_through.hpp"
#include "kresling/analyses/switching.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace py = pybind11;
using kresling::geometry::Design;
using kresling::model::SpecimenParameters;
using kresling::model::Arm;
using namespace kresling::analyses;

namespace kresling::python {

namespace {

// A copy of `v` as a numpy array (the Python side owns its arrays).
template <typename T>
py::array_t<T> array(const std::vector<T>& v) {
  return py::array_t<T>(v.size(), v.data());
}

// A field of a result struct as a read-only property: vectors as numpy arrays (copies: the
// Python side owns its arrays), the rest as they are. The docstring is the C++ comment's.
template <typename Class, typename T, typename Result>
void field(py::class_<Result>& c, const char* name, T Class::*member, const char* doc) {
  c.def_property_readonly(
      name,
      [member](const Result& r) {
        if constexpr (std::is_same_v<T, std::vector<double>> || std::is_same_v<T, std::vector<int>>) {
          return array((r.*member));
        } else if constexpr (std::is_same_v<T, VectorX>) {
          return py::array_t<double>((r.*member).size(), (r.*member).data());
        } else {
          return r.*member;
        }
      },
      doc);
}

// Every path-following call runs without the GIL (the interrupt check takes it back).
template <typename F>
auto unlocked(F&& f) {
  py::gil_scoped_release release;
  return f();
}

}  // namespace

}  // namespace kresling::python
