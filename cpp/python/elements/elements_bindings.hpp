#pragma once
/// \file elements_bindings.hpp
/// What the binding files of kresling._core.elements share (cpp/python/elements/bind_<header>.cpp
/// binds what cpp/kresling/elements/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "kresling/core/check.hpp"
#include "kresling/elements/bar.hpp"
#include "kresling/elements/contact_barrier.hpp"
#include "kresling/elements/contact_barrier_stiffness.hpp"
#include "kresling/elements/contact_broad_phase.hpp"
#include "kresling/elements/contact_ccd.hpp"
#include "kresling/elements/contact_distance.hpp"
#include "kresling/elements/contact_mollifier.hpp"
#include "kresling/elements/corner_angle.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/elements/spring_laws.hpp"
#include "kresling/model/model.hpp"

namespace py = pybind11;
using namespace kresling::elements;

namespace kresling::python {

namespace {

// The contact kernels take positions as they are; from Python, check them first.
void require_finite_points(std::initializer_list<std::pair<const char*, const Vector3*>> points) {
  for (const auto& [name, p] : points) {
    if (!p->allFinite()) {
      throw std::invalid_argument(std::string(name) + ": every coordinate must be finite");
    }
  }
}

}  // namespace

}  // namespace kresling::python
