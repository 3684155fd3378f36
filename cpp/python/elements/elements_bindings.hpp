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
#include "kresling/elements/corner_angle.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/elements/spring_laws.hpp"
#include "kresling/model/model.hpp"

namespace py = pybind11;
using namespace kresling::elements;
