#pragma once
/// \file geometry_bindings.hpp
/// What the binding files of kresling._core.geometry share (cpp/python/geometry/bind_<header>.cpp
/// binds what cpp/kresling/geometry/<header>.hpp declares).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/geometry/design_derivative.hpp"
#include "kresling/geometry/design_table.hpp"

namespace py = pybind11;
using kresling::geometry::Design;
using kresling::geometry::State;
