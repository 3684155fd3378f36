#pragma once
/// \file contact_bindings.hpp
/// What the binding files of kresling._core.contact share (cpp/python/contact/bind_<header>.cpp
/// binds what cpp/kresling/contact/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "kresling/core/check.hpp"
#include "kresling/contact/contact_barrier.hpp"
#include "kresling/contact/contact_barrier_stiffness.hpp"
#include "kresling/contact/contact_broad_phase.hpp"
#include "kresling/contact/contact_ccd.hpp"
#include "kresling/contact/contact_distance.hpp"
#include "kresling/contact/contact_mollifier.hpp"

namespace py = pybind11;
using namespace kresling::contact;

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
