// bind_pyopencl.cpp - pyopencl handles in and out (see bind_pyopencl.hpp).
#include "python_docs.hpp"
#include "bind_pyopencl.hpp"

#include <pybind11/stl.h>

#include "request.hpp"

namespace py = pybind11;

namespace ggxpy {

namespace {

// The OpenCL handle of a pyopencl object (its int_ptr), with a reference of our own.
template <class Handle> Handle handle_of(const py::handle& object, const char* name, const char* kind)
{
    if (object.is_none() || !py::hasattr(object, "int_ptr"))
        throw ggxcl::InvalidArgument(name, std::string(py::repr(object)), std::string("a pyopencl.") + kind);
    using Raw = typename Handle::cl_type;
    return Handle(reinterpret_cast<Raw>(object.attr("int_ptr").cast<std::intptr_t>()), true);
}

// The buffers of a dict {name: pyopencl.Buffer} into `slot(name)`.
template <class Slot> void buffers_of(const py::object& dict, const char* what, Slot&& slot)
{
    if (dict.is_none())
        return;
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(dict)) {
        const std::string name = key.template cast<std::string>();
        slot(name) = handle_of<cl::Buffer>(value, (std::string(what) + "[" + name + "]").c_str(), "Buffer");
    }
}

cl::Buffer& input_slot(ggxcl::DeviceInputs& inputs, const std::string& name)
{
    if (name == "view") return inputs.view;
    if (name == "alpha") return inputs.alpha;
    if (name == "normal") return inputs.normal;
    if (name == "uniforms") return inputs.uniforms;
    throw ggxcl::InvalidArgument("inputs", name, "view, alpha, normal or uniforms");
}

py::object enqueue(ggxcl::Backend& backend, const py::object& queue, const RequestArgs& args, std::uint64_t seed,
                   std::uint64_t first, std::uint32_t stride, const py::object& outputs, const py::object& inputs,
                   bool views_above_horizon, bool isotropic, const py::object& wait_for)
{
    auto* sampler = dynamic_cast<ggxcl::Sampler*>(&backend);  // the caller's buffers are OpenCL's
    if (!sampler)
        throw ggxcl::InvalidArgument("api", ggxcl::api_name(backend.api()),
                                     "opencl for enqueue, which writes into pyopencl buffers (sample() works on "
                                     "every API)");
    ggxcl::Sampler& s = *sampler;
    cl::CommandQueue q = handle_of<cl::CommandQueue>(queue, "queue", "CommandQueue");
    const Request r = make_request(args);
    ggxcl::DeviceOutputs out;
    buffers_of(outputs, "outputs", [&](const std::string& name) -> cl::Buffer& { return out.of(ggxcl::parse_field(name)); });
    ggxcl::DeviceInputs in;
    buffers_of(inputs, "inputs", [&](const std::string& name) -> cl::Buffer& { return input_slot(in, name); });
    in.views_above_horizon = views_above_horizon;
    in.isotropic = isotropic;
    std::vector<cl::Event> wait;
    if (!wait_for.is_none())
        for (const py::handle e : py::reinterpret_borrow<py::iterable>(wait_for))
            wait.push_back(handle_of<cl::Event>(e, "wait_for", "Event"));
    cl::Event done = s.enqueue(q, r.params, {seed, first, args.count}, out, stride, in, wait.empty() ? nullptr : &wait);
    py::object event_class = py::module_::import("pyopencl").attr("Event");
    return event_class.attr("from_int_ptr")(reinterpret_cast<std::intptr_t>(done()), true);
}

} // namespace

std::unique_ptr<ggxcl::Sampler> sampler_on(const py::object& context, const py::object& device)
{
    return std::make_unique<ggxcl::Sampler>(handle_of<cl::Context>(context, "context", "Context"),
                                            handle_of<cl::Device>(device, "device", "Device"));
}

void add_enqueue(py::class_<ggxcl::Backend>& sampler)
{
    sampler.def(
        "enqueue",
        [](ggxcl::Backend& s, const py::object& queue, const py::object& method, const py::object& n,
           const py::object& outputs, std::uint64_t seed, std::uint64_t first, std::uint32_t stride,
           const py::object& alpha, double theta, double phi, const py::object& view, const py::object& normal,
           const py::object& precision, const std::string& sequence, const py::object& inputs,
           bool views_above_horizon, bool isotropic, const py::object& wait_for, const py::object& eta,
           const std::string& transport) {
            return enqueue(s, queue,
                           with_dielectric(args_of(method, n, alpha, theta, phi, view, normal, precision, sequence,
                                                   py::none(), false),
                                           eta, transport),
                           seed, first, stride, outputs, inputs, views_above_horizon, isotropic, wait_for);
        },
        py::arg("queue"), py::arg("method"), py::arg("n"), py::kw_only(), py::arg("outputs"), py::arg("seed") = 0,
        py::arg("first") = 0, py::arg("stride") = 0, py::arg("alpha") = 0.3, py::arg("theta") = 60.0,
        py::arg("phi") = 0.0, py::arg("view") = py::none(), py::arg("normal") = py::none(),
        py::arg("precision") = py::none(), py::arg("sequence") = "philox", py::arg("inputs") = py::none(),
        py::arg("views_above_horizon") = false, py::arg("isotropic") = false, py::arg("wait_for") = py::none(),
        py::arg("eta") = py::none(), py::arg("transport") = "radiance", docs::Sampler_enqueue);
}

} // namespace ggxpy
