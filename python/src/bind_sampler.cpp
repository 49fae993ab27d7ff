// bind_sampler.cpp - the Python Sampler: each call checks its arguments,
// releases the GIL while the device works, and between chunks takes it back
// to check for signals, so Ctrl-C stops a long call with KeyboardInterrupt.
#include "python_docs.hpp"
#include "bind_sampler.hpp"

#include <cstring>
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bind_pyopencl.hpp"
#include "ggx_stats.hpp"
#include "pdf_bins.hpp"
#include "reference_bridge.hpp"
#include "request.hpp"

namespace py = pybind11;

namespace ggxpy {

namespace {


// Raises KeyboardInterrupt (or what a signal handler raised) in the middle of a call.
void check_signals()
{
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0)
        throw py::error_already_set();
}

std::vector<ggxcl::Field> fields_of(const py::object& fields)
{
    std::vector<ggxcl::Field> list;
    for (const py::handle item : py::reinterpret_borrow<py::iterable>(fields)) {
        ggxcl::Field f = ggxcl::parse_field(item.cast<std::string>());
        for (ggxcl::Field seen : list)
            if (seen == f)
                throw ggxcl::InvalidArgument("fields", std::string(py::repr(fields)), "each field at most once");
        list.push_back(f);
    }
    if (list.empty())
        throw ggxcl::InvalidArgument("fields", "()", "at least one of " + ggxcl::field_list());
    return list;
}

// Copies a planar chunk of `field` into rows [offset, offset + count) of `out`.
void copy_rows(const ggxcl::SampleSet& chunk, ggxcl::Field field, bool dielectric, std::uint64_t offset, float* out)
{
    const std::vector<float>& planes = chunk.column_source(field);
    const int columns = ggxcl::field_columns(field, dielectric);
    for (std::uint64_t j = 0; j < chunk.count; ++j)
        for (int c = 0; c < columns; ++c)
            out[(offset + j) * columns + c] = planes[c * chunk.count + j];
}

py::dict sample(ggxcl::Backend& s, const RequestArgs& args, std::uint64_t seed, std::uint64_t first,
                const py::object& fields, const py::object& out)
{
    if (args.count == 0)
        throw ggxcl::InvalidArgument("n", "0", "at least 1 sample");
    const Request r = make_request(args);
    const std::vector<ggxcl::Field> list = fields_of(fields);
    const bool dielectric = r.params.eta != 0.0f;
    py::dict result;
    std::vector<std::pair<ggxcl::Field, float*>> targets;
    for (ggxcl::Field f : list) {
        py::array_t<float> a = output_array(out, f, args.count, dielectric);
        targets.push_back({f, a.mutable_data()});
        result[py::str(std::string(ggxcl::field_name(f)))] = a;
    }
    {
        py::gil_scoped_release released;
        s.generate_chunks(r.params, {seed, first, args.count}, ggxcl::FieldSet(list),
                          [&](const ggxcl::SampleSet& chunk, std::uint64_t offset) {
                              for (const auto& [field, data] : targets)
                                  copy_rows(chunk, field, dielectric, offset, data);
                              check_signals();
                          },
                          r.per_sample);
    }
    return result;
}

// The pdf (eval = false) or the BRDF value (eval = true) of each direction of an (n, 3) array.
py::array_t<float> of_directions(ggxcl::Backend& s, RequestArgs args, const py::object& directions, bool eval)
{
    if (!is_array(directions))
        throw ggxcl::InvalidArgument("directions", std::string(py::repr(directions)), "a NumPy array of shape (n, 3)");
    args.count = std::size_t(py::reinterpret_borrow<py::array>(directions).shape(0));
    const std::vector<ggxcl::Vec3> o = read_vectors(directions, "directions", args.count);
    const Request r = make_request(args);
    std::vector<float> values;
    {
        py::gil_scoped_release released;
        values = eval ? s.eval(r.params, o, r.per_sample) : s.pdf(r.params, o, r.per_sample);
    }
    return py::array_t<float>(values.size(), values.data());
}

py::dict furnace(ggxcl::Backend& s, const RequestArgs& args, std::uint64_t seed, std::uint64_t first)
{
    const Request r = make_request(args);
    ggxcl::FurnaceSums sums;
    {
        py::gil_scoped_release released;
        sums = s.furnace(r.params, {seed, first, args.count});
    }
    py::dict result;
    result["mean"] = sums.mean();
    result["variance"] = sums.variance();
    result["count"] = sums.count;
    if (r.params.eta != 0.0f) {
        result["reflectance"] = sums.reflectance();
        result["transmittance"] = sums.transmittance();
    }
    return result;
}

py::dict histogram(ggxcl::Backend& s, const RequestArgs& args, std::uint64_t seed, std::uint64_t first, int bins_z,
                   int bins_phi, const std::string& of, const py::object& against)
{
    const Request r = make_request(args);
    const ggxcl::Field direction = ggxcl::parse_field(of);
    if (direction != ggxcl::Field::o && direction != ggxcl::Field::m)
        throw ggxcl::InvalidArgument("of", of, "o or m");
    const bool user = r.params.method == ggxcl::Method::user;
    if (user && !against.is_none())
        throw ggxcl::InvalidArgument("against", std::string(py::str(against)),
                                     "None for a user sampler: its own pdf gives the expectation");
    if (user && bins_z % 2 != 0)
        throw ggxcl::InvalidArgument("bins_z", std::to_string(bins_z),
                                     "an even number for a user sampler, so that the horizon is a bin edge");
    const ggxcl::Method expected_of = against.is_none() ? r.params.method : ggxcl::parse_method(against.cast<std::string>());
    ggxcl::Histogram counts;
    std::vector<double> probabilities;
    ggxbridge::UserFits fits;
    {
        py::gil_scoped_release released;
        counts = s.histogram(r.params, {seed, first, args.count}, bins_z, bins_phi, direction);
        const ggxbridge::BinRequest request{bins_z, bins_phi, direction, args.count, &counts.counts};
        if (user)
            fits = ggxbridge::user_fits(
                ggxbridge::direction_pdf(s), r.params, counts, request,
                direction == ggxcl::Field::o ? ggxbridge::claimed_bin_probabilities(r.params, bins_z, bins_phi)
                                             : std::vector<double>{});
        else
            probabilities =
                ggxbridge::bin_probabilities(expected_of, ggxcl::normalized(r.params), bins_z, bins_phi, direction);
    }
    if (user)
        probabilities = fits.own.kept;
    const ggxref::ChiSquare fit =
        user ? fits.own_fit : ggxbridge::histogram_fit(counts, probabilities, r.params.eta != 0.0f);
    py::array_t<std::uint64_t> observed({bins_z, bins_phi});
    py::array_t<double> expected({bins_z, bins_phi});
    std::memcpy(observed.mutable_data(), counts.counts.data(), counts.counts.size() * sizeof(std::uint64_t));
    for (std::size_t b = 0; b < probabilities.size(); ++b)
        expected.mutable_data()[b] = probabilities[b] * double(args.count);
    py::dict result;
    result["counts"] = observed;
    result["expected"] = expected;
    result["chi_square"] = fit.statistic;
    result["dof"] = fit.dof;
    result["p_value"] = fit.p_value;
    result["non_finite"] = counts.non_finite;
    result["invalid"] = counts.invalid;
    if (user) {
        result["pdf_integral"] = fits.own.whole_total();
        result["pdf_integral_error"] = fits.own.error_total();
        result["quadrature_error"] = fits.own.error_total();
        result["pdf_above_horizon"] = fits.own.kept_total();
        result["discarded"] = counts.invalid;
    }
    if (fits.claims) {
        const ggxref::ChiSquare& theirs = fits.claimed_fit;
        py::dict against_claim;
        against_claim["distribution"] = std::string(ggxcl::distribution_name(r.params.user_sampler->distribution()));
        against_claim["chi_square"] = theirs.statistic;
        against_claim["dof"] = theirs.dof;
        against_claim["p_value"] = theirs.p_value;
        against_claim["below_horizon"] = fits.claimed.below;
        result["claimed"] = against_claim;
    }
    return result;
}

// The OpenCL devices and the Vulkan devices; a machine with the drivers of one API lists that one's,
// and one with neither raises OpenCL's DeviceError (what to install).
py::list devices()
{
    // What every entry holds, whatever its API.
    auto entry = [](const char* api, std::size_t index, const std::string& name, const std::string& label) {
        py::dict info;
        info["api"] = api;
        info["index"] = index;
        info["selector"] = std::to_string(index);
        info["name"] = name;
        info["label"] = label;
        return info;
    };
    py::list list;
    std::vector<ggxcl::DeviceInfo> opencl;
    std::optional<ggxcl::DeviceError> no_opencl;
    try {
        opencl = ggxcl::list_devices();
    } catch (const ggxcl::DeviceError& e) {
        no_opencl = e;
    }
    for (const ggxcl::DeviceInfo& d : opencl) {
        py::dict info = entry("opencl", d.index, d.name, d.label());
        info["platform"] = d.platform;
        info["type"] = d.type;
        info["compute_units"] = d.compute_units;
        info["opencl_version"] = d.opencl_version;
        list.append(info);
    }
    std::vector<ggxcl::VulkanDeviceInfo> vulkan;
    try {
        if (ggxcl::vulkan_built())
            vulkan = ggxcl::list_vulkan_devices();
    } catch (const ggxcl::DeviceError&) {  // no Vulkan driver: the OpenCL devices alone
    }
    if (no_opencl && vulkan.empty())
        throw *no_opencl;
    for (const ggxcl::VulkanDeviceInfo& d : vulkan)
        list.append(entry("vulkan", d.index, d.name, d.label()));
    return list;
}

// A back end on `api`'s device, or an OpenCL Sampler on pyopencl's context.
std::unique_ptr<ggxcl::Backend> open_sampler(const py::object& device, const py::object& context, const std::string& api,
                                             const py::object& shader_language)
{
    const ggxcl::Api chosen = ggxcl::parse_api(api);
    if (chosen != ggxcl::Api::vulkan && !shader_language.is_none())
        throw ggxcl::InvalidArgument("shader_language", std::string(py::str(shader_language)),
                                     "None with api='opencl' (its kernels are OpenCL C)");
    if (!context.is_none()) {  // pyopencl objects
        if (chosen != ggxcl::Api::opencl)
            throw ggxcl::InvalidArgument("context", std::string(py::repr(context)),
                                         "None with api='vulkan' (a pyopencl context is OpenCL's)");
        return sampler_on(context, device);
    }
    const std::string selector = device.is_none() ? "" : std::string(py::str(device));
    const ggxcl::ShaderLanguage language = shader_language.is_none()
                                               ? ggxcl::ShaderLanguage::glsl
                                               : ggxcl::parse_shader_language(shader_language.cast<std::string>());
    return ggxcl::open_backend(chosen, selector, language);
}

} // namespace

void register_sampler(py::module_& m)
{
    m.def("devices", &devices, docs::devices);
    py::class_<ggxcl::Backend> sampler(m, "Sampler", docs::Sampler);
    sampler
        .def(py::init(&open_sampler), py::arg("device") = py::none(), py::arg("context") = py::none(),
             py::kw_only(), py::arg("api") = "opencl", py::arg("shader_language") = py::none(), docs::Sampler_init)
        .def_property_readonly("device_name", &ggxcl::Backend::device_name)
        .def_property_readonly(
            "api", [](const ggxcl::Backend& s) { return std::string(ggxcl::api_name(s.api())); }, docs::Sampler_api)
        .def_property_readonly(
            "shader_language",
            [](const ggxcl::Backend& s) -> py::object {
                if (!s.shader_language())
                    return py::none();
                return py::str(ggxcl::shader_language_name(*s.shader_language()));
            },
            docs::Sampler_shader_language)
        .def_property("chunk_size", &ggxcl::Backend::chunk_size, &ggxcl::Backend::set_chunk_size)
        .def(
            "sample",
            [](ggxcl::Backend& s, const py::object& method, const py::object& n, const py::object& alpha, double theta,
               double phi, const py::object& view, const py::object& normal, std::uint64_t seed, std::uint64_t first,
               const py::object& fields, const py::object& precision, const std::string& sequence,
               const py::object& uniforms, bool world_space, const py::object& out, const py::object& eta,
               const std::string& transport) {
                return sample(s,
                              with_dielectric(args_of(method, n, alpha, theta, phi, view, normal, precision, sequence,
                                                      uniforms, world_space),
                                              eta, transport),
                              seed, first, fields, out);
            },
            py::arg("method"), py::arg("n"), py::kw_only(), py::arg("alpha") = 0.3, py::arg("theta") = 60.0,
            py::arg("phi") = 0.0, py::arg("view") = py::none(), py::arg("normal") = py::none(), py::arg("seed") = 0,
            py::arg("first") = 0, py::arg("fields") = py::make_tuple("m", "o", "pdf_m", "pdf_o", "weight"),
            py::arg("precision") = py::none(), py::arg("sequence") = "philox", py::arg("uniforms") = py::none(),
            py::arg("world_space") = false, py::arg("out") = py::none(), py::arg("eta") = py::none(),
            py::arg("transport") = "radiance", docs::Sampler_sample)
        .def(
            "pdf",
            [](ggxcl::Backend& s, const py::object& method, const py::object& directions, const py::object& alpha,
               double theta, double phi, const py::object& view, const py::object& normal, const py::object& precision,
               bool world_space, const py::object& eta) {
                return of_directions(s,
                                     with_dielectric(args_of(method, py::int_(0), alpha, theta, phi, view, normal, precision,
                                                             "philox", py::none(), world_space),
                                                     eta, "radiance"),
                                     directions, false);
            },
            py::arg("method"), py::arg("directions"), py::kw_only(), py::arg("alpha") = 0.3, py::arg("theta") = 60.0,
            py::arg("phi") = 0.0, py::arg("view") = py::none(), py::arg("normal") = py::none(),
            py::arg("precision") = py::none(), py::arg("world_space") = false, py::arg("eta") = py::none(),
            docs::Sampler_pdf)
        .def(
            "eval",
            [](ggxcl::Backend& s, const py::object& directions, const py::object& alpha, double theta, double phi,
               const py::object& view, const py::object& normal, const py::object& precision, bool world_space,
               const py::object& eta, const std::string& transport) {
                if (!normal.is_none() && !world_space)
                    throw ggxcl::InvalidArgument("normal", std::string(py::repr(normal)),
                                                 "None in tangent space (the normal is z), or world_space=True");
                // The value is the same for every method: caps's program computes it.
                return of_directions(s,
                                     with_dielectric(args_of(py::str("caps"), py::int_(0), alpha, theta, phi, view, normal, precision,
                                                             "philox", py::none(), world_space),
                                                     eta, transport),
                                     directions, true);
            },
            py::arg("directions"), py::kw_only(), py::arg("alpha") = 0.3, py::arg("theta") = 60.0,
            py::arg("phi") = 0.0, py::arg("view") = py::none(), py::arg("normal") = py::none(),
            py::arg("precision") = py::none(), py::arg("world_space") = false, py::arg("eta") = py::none(),
            py::arg("transport") = "radiance", docs::Sampler_eval)
        .def(
            "furnace",
            [](ggxcl::Backend& s, const py::object& method, const py::object& n, const py::object& alpha, double theta,
               double phi, const py::object& view, const py::object& normal, std::uint64_t seed, std::uint64_t first,
               const py::object& precision, const std::string& sequence, const py::object& eta,
               const std::string& transport) {
                return furnace(s,
                               with_dielectric(args_of(method, n, alpha, theta, phi, view, normal, precision, sequence,
                                                       py::none(), false),
                                               eta, transport),
                               seed, first);
            },
            py::arg("method"), py::arg("n"), py::kw_only(), py::arg("alpha") = 0.3, py::arg("theta") = 60.0,
            py::arg("phi") = 0.0, py::arg("view") = py::none(), py::arg("normal") = py::none(), py::arg("seed") = 0,
            py::arg("first") = 0, py::arg("precision") = py::none(), py::arg("sequence") = "philox",
            py::arg("eta") = py::none(), py::arg("transport") = "radiance", docs::Sampler_furnace)
        .def(
            "histogram",
            [](ggxcl::Backend& s, const py::object& method, const py::object& n, const py::object& alpha, double theta,
               double phi, const py::object& normal, std::uint64_t seed, std::uint64_t first, int bins_z, int bins_phi,
               const std::string& of, const py::object& against, const py::object& precision,
               const std::string& sequence, const py::object& eta) {
                return histogram(s,
                                 with_dielectric(args_of(method, n, alpha, theta, phi, py::none(), normal, precision,
                                                         sequence, py::none(), false),
                                                 eta, "radiance"),
                                 seed, first, bins_z, bins_phi, of, against);
            },
            py::arg("method"), py::arg("n"), py::kw_only(), py::arg("alpha") = 0.3, py::arg("theta") = 60.0,
            py::arg("phi") = 0.0, py::arg("normal") = py::none(), py::arg("seed") = 0, py::arg("first") = 0,
            py::arg("bins_z") = 32, py::arg("bins_phi") = 64, py::arg("of") = "o", py::arg("against") = py::none(),
            py::arg("precision") = py::none(), py::arg("sequence") = "philox", py::arg("eta") = py::none(),
            docs::Sampler_histogram);
    add_enqueue(sampler);
}

} // namespace ggxpy
