// request.cpp - keyword arguments into SampleParams and PerSampleInputs.
#include "request.hpp"

#include "bind_user_sampler.hpp"

#include <cmath>

#include <pybind11/numpy.h>

#include "arrays.hpp"

namespace py = pybind11;

namespace ggxpy {

namespace {

// A Python number or sequence of `n` numbers.
std::vector<float> numbers(const py::handle& value, const char* name, std::size_t low, std::size_t high)
{
    std::vector<float> out;
    try {
        if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
            for (const py::handle item : py::reinterpret_borrow<py::sequence>(value))
                out.push_back(item.cast<float>());
        } else {
            out.push_back(value.cast<float>());
        }
    } catch (const py::cast_error&) {
        throw ggxcl::InvalidArgument(name, std::string(py::repr(value)), "a number or a sequence of numbers");
    }
    if (out.size() < low || out.size() > high)
        throw ggxcl::InvalidArgument(name, std::string(py::repr(value)),
                                     low == high ? std::to_string(low) + " numbers" : "one or two numbers");
    return out;
}

void set_alpha(const RequestArgs& args, Request& r)
{
    if (is_array(args.alpha)) {  // (n,) isotropic or (n, 2)
        const py::array a = py::reinterpret_borrow<py::array>(args.alpha);
        if (a.ndim() == 1) {
            for (double x : read_array(args.alpha, "alpha", args.count, 0))
                r.per_sample.alphas.push_back({float(x), float(x)});
        } else {
            r.per_sample.alphas = read_pairs(args.alpha, "alpha", args.count);
        }
        return;
    }
    std::vector<float> a = numbers(args.alpha, "alpha", 1, 2);
    r.params.alpha_x = a[0];
    r.params.alpha_y = a.back();
}

// A uniform vector, or per-sample vectors into `rows`.
void set_vector(const py::object& value, const char* name, std::size_t count, ggxcl::Vec3& uniform,
                std::vector<ggxcl::Vec3>& rows)
{
    if (is_array(value) && py::reinterpret_borrow<py::array>(value).ndim() == 2) {
        rows = read_vectors(value, name, count);
        return;
    }
    std::vector<float> v = numbers(value, name, 3, 3);
    uniform = {v[0], v[1], v[2]};
}

// (n, 2) uniforms, or (n, 3) for a dielectric: u3 into lobe_uniforms.
void set_uniforms(const RequestArgs& args, Request& r)
{
    const std::size_t columns = r.params.eta != 0.0f ? 3 : 2;
    std::vector<double> u = read_array(args.uniforms, "uniforms", args.count, columns);
    r.per_sample.uniforms.resize(args.count);
    r.per_sample.lobe_uniforms.resize(columns == 3 ? args.count : 0);
    for (std::size_t j = 0; j < args.count; ++j) {
        const double* row = u.data() + columns * j;
        r.per_sample.uniforms[j] = {ggxcl::uniform_to_float(row[0]), ggxcl::uniform_to_float(row[1])};
        if (columns == 3)
            r.per_sample.lobe_uniforms[j] = ggxcl::uniform_to_float(row[2]);
    }
}

void set_dielectric(const RequestArgs& args, Request& r)
{
    if (!args.eta.is_none()) {
        try {
            r.params.eta = args.eta.cast<float>();
        } catch (const py::cast_error&) {
            throw ggxcl::InvalidArgument("eta", std::string(py::repr(args.eta)), "None or a number");
        }
    }
    r.params.transport = ggxcl::parse_transport(args.transport);
}

// A count of samples: a whole number, also as a float (1e6, as the CLI's -n takes it), not a bool.
std::size_t count_of(const py::object& n)
{
    const std::string allowed = "a whole number of samples: 1000000, 1e6 or 2**20";
    if (py::isinstance<py::bool_>(n))
        throw ggxcl::InvalidArgument("n", std::string(py::repr(n)), allowed);
    if (py::isinstance<py::float_>(n)) {
        const double value = n.cast<double>();
        if (!(value >= 0.0 && value < 18446744073709551616.0 && value == std::floor(value)))
            throw ggxcl::InvalidArgument("n", std::string(py::repr(n)), allowed);
        return std::size_t(value);
    }
    PyObject* whole = PyNumber_Index(n.ptr());  // int, NumPy integers: anything with __index__
    if (!whole) {
        PyErr_Clear();
        throw ggxcl::InvalidArgument("n", std::string(py::repr(n)), allowed);
    }
    const py::int_ index = py::reinterpret_steal<py::int_>(whole);
    try {
        return index.cast<std::size_t>();
    } catch (const py::cast_error&) {
        throw ggxcl::InvalidArgument("n", std::string(py::repr(n)), allowed + ", from 0 to 2**64 - 1");
    }
}

} // namespace

RequestArgs args_of(const py::object& method, const py::object& n, const py::object& alpha, double theta, double phi,
                    const py::object& view, const py::object& normal, const py::object& precision,
                    const std::string& sequence, const py::object& uniforms, bool world_space)
{
    RequestArgs a;
    a.method = method;
    a.count = count_of(n);
    a.alpha = alpha;
    a.theta = theta;
    a.phi = phi;
    a.view = view;
    a.normal = normal;
    a.precision = precision;
    a.sequence = sequence;
    a.uniforms = uniforms;
    a.world_space = world_space;
    return a;
}

RequestArgs with_dielectric(RequestArgs args, const py::object& eta, const std::string& transport)
{
    args.eta = eta;
    args.transport = transport;
    return args;
}

Request make_request(const RequestArgs& args)
{
    Request r;
    set_dielectric(args, r);
    r.params.user_sampler = user_sampler_of(args.method);
    if (r.params.user_sampler)
        r.params.method = ggxcl::Method::user;
    else if (py::isinstance<py::str>(args.method))
        r.params.method = ggxcl::parse_method(args.method.cast<std::string>());
    else
        throw ggxcl::InvalidArgument("method", std::string(py::repr(args.method)),
                                     "one of " + ggxcl::method_list() + ", or a ggxcl.UserSampler");
    r.params.world_space = args.world_space;
    set_alpha(args, r);
    if (args.view.is_none()) {
        r.params.view = ggxcl::view_from_angles(args.theta, args.phi);
    } else {
        set_vector(args.view, "view", args.count, r.params.view, r.per_sample.views);
    }
    if (!args.normal.is_none())
        set_vector(args.normal, "normal", args.count, r.params.normal, r.per_sample.normals);
    if (!args.precision.is_none())
        r.params.precision = ggxcl::parse_precision(args.precision.cast<std::string>());
    r.params.sequence = ggxcl::parse_sequence(args.sequence);
    if (!args.uniforms.is_none())
        set_uniforms(args, r);
    ggxcl::validate(r.params);
    return r;
}

} // namespace ggxpy
