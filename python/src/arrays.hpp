// arrays.hpp - NumPy arrays in and out of the module: float32 or float64
// C-contiguous inputs of an exact shape checked with errors naming the
// argument (ggxcl::InvalidArgument, a ValueError in Python), and float32
// outputs, allocated or the caller's (`out=`).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <ggxcl/ggxcl.hpp>

namespace ggxpy {

// Whether `value` is a NumPy array (or anything array-like with more than
// one element, which is converted), as opposed to a number or short tuple.
bool is_array(const pybind11::handle& value);

// `value` as doubles of shape (rows, columns) (columns 0: shape (rows,)):
// float32 or float64, C-contiguous, finite checks left to the library.
std::vector<double> read_array(const pybind11::handle& value, const char* name, std::size_t rows,
                               std::size_t columns);

std::vector<ggxcl::Vec3> read_vectors(const pybind11::handle& value, const char* name, std::size_t rows);
std::vector<std::array<float, 2>> read_pairs(const pybind11::handle& value, const char* name, std::size_t rows);

// The output array of `field` for n samples: the caller's out[field]
// (float32, C-contiguous, writeable, shape (n, columns) or (n,)) or a new one.
pybind11::array_t<float> output_array(const pybind11::object& out, ggxcl::Field field, std::size_t n,
                                       bool dielectric = false);

} // namespace ggxpy
