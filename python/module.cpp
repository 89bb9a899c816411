// SPDX-License-Identifier: Apache-2.0
// The cmfilter Python module (docs/python.md): libcmfilter's tables, moment
// and histogram pyramids, noise, fits, texture synthesis, coordinate maps,
// microsurface functions, synthetic stacks, apply, render and compare on
// NumPy arrays. Each concern is bound in a file of its own; this one holds
// what they share and the module itself.
#include "bindings.h"

#include "cmfilter/util/version.h"

#include <cstdlib>

namespace cmfilter::python {

namespace {

const char* kind_name(ErrorKind kind)
{
    switch (kind) {
    case ErrorKind::Usage: return "usage";
    case ErrorKind::Io: return "io";
    case ErrorKind::BadInput: return "bad_input";
    case ErrorKind::Runtime: return "runtime";
    }
    return "runtime";
}

}  // namespace

void register_errors(py::module_& m)
{
    py::handle type = PyErr_NewExceptionWithDoc(
        "cmfilter.Error",
        "An error from libcmfilter: str(e) is the library's message (naming the file, value and what was expected), "
        "e.kind is 'usage', 'io', 'bad_input' or 'runtime', e.field the option it is about (or '').",
        PyExc_RuntimeError, nullptr);
    m.add_object("Error", type);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const LibraryError& e) {
            py::object error_type = py::module_::import("cmfilter").attr("Error");
            py::object error = error_type(e.error.message);
            error.attr("kind") = kind_name(e.error.kind);
            error.attr("field") = e.error.field;
            PyErr_SetObject(error_type.ptr(), error.ptr());
        }
    });
}

Broadcast broadcast(const std::vector<py::object>& values)
{
    py::tuple args(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) args[i] = values[i];
    py::list arrays = py::module_::import("numpy").attr("broadcast_arrays")(*args);
    Broadcast out;
    for (py::handle a : arrays) out.arrays.push_back(py::cast<DoubleArray>(a));
    const DoubleArray& first = out.arrays.front();
    out.shape.assign(first.shape(), first.shape() + first.ndim());
    out.size = static_cast<std::size_t>(first.size());
    return out;
}

std::vector<py::ssize_t> with_trailing(std::vector<py::ssize_t> shape, std::initializer_list<py::ssize_t> extra)
{
    shape.insert(shape.end(), extra.begin(), extra.end());
    return shape;
}

void warn_all(const std::vector<std::string>& warnings)
{
    if (warnings.empty()) return;
    py::object warn = py::module_::import("warnings").attr("warn");
    for (const auto& w : warnings) warn(w);
}

ColorConfig load_config(const std::string& path)
{
    std::string chosen = path;
    if (chosen.empty())
        if (const char* env = std::getenv("OCIO"); env && *env) chosen = env;
    return unwrap(ColorConfig::load(chosen));
}

Directions directions(const py::object& value, const char* what)
{
    Directions d;
    d.array = py::cast<DoubleArray>(value);
    const auto n = d.array.ndim();
    if (n == 1 && d.array.shape(0) == 3) {
        d.single = true;
    } else if (!(n == 2 && d.array.shape(1) == 3)) {
        std::string shape;
        for (py::ssize_t i = 0; i < n; ++i) shape += (i ? ", " : "") + std::to_string(d.array.shape(i));
        bad_argument(std::string(what) + " has shape (" + shape + ") (expected (3,) or (N, 3) directions)");
    }
    return d;
}

}  // namespace cmfilter::python

PYBIND11_MODULE(cmfilter, m)
{
    using namespace cmfilter::python;
    m.doc() = "cmfilter: colour-map filtering (Heitz et al. 2013) and linear relighting fits on NumPy arrays. "
              "See docs/python.md.";
    m.attr("__version__") = cmfilter::version();
    register_errors(m);
    bind_tables(m);
    bind_moments(m);
    bind_noise(m);
    bind_fits(m);
    bind_coordinate_maps(m);
    bind_ops(m);
    bind_render(m);
    bind_synthesis(m);
    bind_histograms(m);
    bind_microsurface(m);
    bind_synthetic(m);
}
