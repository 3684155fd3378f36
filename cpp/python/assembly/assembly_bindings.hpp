#pragma once
/// \file assembly_bindings.hpp
/// What the binding files of kresling._core.assembly share (cpp/python/assembly/bind_<header>.cpp
/// binds what cpp/kresling/assembly/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/parameter_jacobian.hpp"
#include "kresling/assembly/shape_jacobian.hpp"
#include "kresling/assembly/workspace.hpp"

namespace py = pybind11;
using kresling::model::Model;
