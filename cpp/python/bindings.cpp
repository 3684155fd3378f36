// What the binding files of several folders share (bindings.hpp).
#include "bindings.hpp"

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace kresling::python {

py::tuple csc(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& K) {
  // Copies: the Python side owns its arrays.
  py::array_t<int> indptr(K.outerSize() + 1, K.outerIndexPtr());
  py::array_t<int> indices(K.nonZeros(), K.innerIndexPtr());
  py::array_t<double> data(K.nonZeros(), K.valuePtr());
  return py::make_tuple(data, indices, indptr, py::make_tuple(K.rows(), K.cols()));
}

}  // namespace kresling::python
