// arrays.cpp - checked NumPy inputs and outputs.
#include "arrays.hpp"

#include <cmath>

namespace py = pybind11;

namespace ggxpy {

namespace {

std::string shape_text(const py::array& a)
{
    std::string text = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k)
        text += (k ? ", " : "") + std::to_string(a.shape(k));
    return text + (a.ndim() == 1 ? ",)" : ")");
}

std::string wanted_shape(std::size_t rows, std::size_t columns)
{
    return columns == 0 ? "(" + std::to_string(rows) + ",)"
                        : "(" + std::to_string(rows) + ", " + std::to_string(columns) + ")";
}

} // namespace

bool is_array(const py::handle& value)
{
    if (py::isinstance<py::array>(value))
        return py::reinterpret_borrow<py::array>(value).ndim() > 0;
    return false;
}

std::vector<double> read_array(const py::handle& value, const char* name, std::size_t rows, std::size_t columns)
{
    if (!py::isinstance<py::array>(value))
        throw ggxcl::InvalidArgument(name, std::string(py::str(py::type::of(value).attr("__name__"))),
                                     "a NumPy array of shape " + wanted_shape(rows, columns));
    py::array a = py::reinterpret_borrow<py::array>(value);
    const bool f32 = a.dtype().is(py::dtype::of<float>());
    const bool f64 = a.dtype().is(py::dtype::of<double>());
    if (!f32 && !f64)
        throw ggxcl::InvalidArgument(name, "dtype " + std::string(py::str(a.dtype())), "float32 or float64");
    if (!(a.flags() & py::array::c_style))
        throw ggxcl::InvalidArgument(name, "a non-contiguous array",
                                     "a C-contiguous array (numpy.ascontiguousarray makes one)");
    const bool shape_ok = columns == 0 ? a.ndim() == 1 && std::size_t(a.shape(0)) == rows
                                       : a.ndim() == 2 && std::size_t(a.shape(0)) == rows &&
                                             std::size_t(a.shape(1)) == columns;
    if (!shape_ok)
        throw ggxcl::InvalidArgument(name, "shape " + shape_text(a), "shape " + wanted_shape(rows, columns));
    std::vector<double> values(a.size());
    if (f32)
        std::copy_n(static_cast<const float*>(a.data()), values.size(), values.begin());
    else
        std::copy_n(static_cast<const double*>(a.data()), values.size(), values.begin());
    return values;
}

std::vector<ggxcl::Vec3> read_vectors(const py::handle& value, const char* name, std::size_t rows)
{
    std::vector<double> v = read_array(value, name, rows, 3);
    std::vector<ggxcl::Vec3> out(rows);
    for (std::size_t j = 0; j < rows; ++j)
        out[j] = {float(v[3 * j]), float(v[3 * j + 1]), float(v[3 * j + 2])};
    return out;
}

std::vector<std::array<float, 2>> read_pairs(const py::handle& value, const char* name, std::size_t rows)
{
    std::vector<double> v = read_array(value, name, rows, 2);
    std::vector<std::array<float, 2>> out(rows);
    for (std::size_t j = 0; j < rows; ++j)
        out[j] = {float(v[2 * j]), float(v[2 * j + 1])};
    return out;
}

py::array_t<float> output_array(const py::object& out, ggxcl::Field field, std::size_t n, bool dielectric)
{
    const std::size_t columns = std::size_t(ggxcl::field_columns(field, dielectric));
    const std::string name(ggxcl::field_name(field));
    if (out.is_none() || !out.contains(py::str(name)))
        return columns == 1 ? py::array_t<float>({py::ssize_t(n)}) : py::array_t<float>({py::ssize_t(n), py::ssize_t(columns)});
    py::object given = out[py::str(name)];
    if (!py::isinstance<py::array>(given))
        throw ggxcl::InvalidArgument("out[" + name + "]", "not an array", "a float32 NumPy array");
    py::array a = py::reinterpret_borrow<py::array>(given);
    const bool shape_ok = columns == 1 ? a.ndim() == 1 && std::size_t(a.shape(0)) == n
                                       : a.ndim() == 2 && std::size_t(a.shape(0)) == n &&
                                             std::size_t(a.shape(1)) == columns;
    if (!a.dtype().is(py::dtype::of<float>()) || !(a.flags() & py::array::c_style) || !a.writeable() || !shape_ok)
        throw ggxcl::InvalidArgument("out[" + name + "]", "dtype " + std::string(py::str(a.dtype())) + ", shape " +
                                                            shape_text(a),
                                     "a writeable C-contiguous float32 array of shape " +
                                         wanted_shape(n, columns == 1 ? 0 : columns));
    return py::reinterpret_borrow<py::array_t<float>>(a);
}

} // namespace ggxpy
