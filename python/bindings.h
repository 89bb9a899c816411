// SPDX-License-Identifier: Apache-2.0
// What every part of the cmfilter Python module shares: the library's errors
// raised as cmfilter.Error, NumPy arrays that own a library buffer or view
// an object's, arrays of any shape broadcast against each other, and the
// OpenColorIO config a call uses.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/microsurface/smith_lambda.h"
#include "cmfilter/texture/pyramid_bake_options.h"
#include "cmfilter/util/error.h"
#include "cmfilter/util/parallel_for.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace cmfilter::python {

namespace py = pybind11;

// An array of doubles as the module takes them: any shape, any numeric type,
// converted (copied) only when it is not already C-contiguous float64.
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// Thrown by the bindings; raised in Python as cmfilter.Error with the
// library's message, and its kind ("usage", "io", "bad_input", "runtime")
// and field (the option it is about, or "").
struct LibraryError {
    Error error;
};

[[noreturn]] inline void raise(Error error) { throw LibraryError{std::move(error)}; }

template <typename T>
T unwrap(Expected<T>&& value)
{
    if (!value) raise(value.error());
    return std::move(value).value();
}

inline void check(const Status& status)
{
    if (!status) raise(status.error());
}

// A BadInput error for a value the Python caller passed, naming it.
[[noreturn]] inline void bad_argument(const std::string& message) { raise(bad_input(message)); }

// Registers cmfilter.Error in `m` and the translation of LibraryError to it.
void register_errors(py::module_& m);

// An array that owns `values` (moved, never copied), of `shape`.
template <typename T>
py::array_t<T> owning_array(std::vector<T>&& values, std::vector<py::ssize_t> shape)
{
    auto* holder = new std::vector<T>(std::move(values));
    py::capsule owner(holder, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(std::move(shape), holder->data(), owner);
}

// A read-only array of `shape` over `data`, which `owner` (a Python object)
// keeps alive.
template <typename T>
py::array_t<T> view_array(const T* data, std::vector<py::ssize_t> shape, py::handle owner)
{
    py::array_t<T> a(std::move(shape), data, owner);
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

// The arrays broadcast to one shape (NumPy's rules) as C-contiguous float64.
struct Broadcast {
    std::vector<py::ssize_t> shape;
    std::size_t size = 0;
    std::vector<DoubleArray> arrays;
};
Broadcast broadcast(const std::vector<py::object>& values);

// Calls body(i) for every i in [0, count), in blocks over `threads` threads
// (0: every core), with the GIL released: body must not touch Python.
template <typename Body>
void for_each_element(std::size_t count, int threads, Body&& body)
{
    py::gil_scoped_release release;
    constexpr std::size_t block = 4096;
    const int blocks = static_cast<int>((count + block - 1) / block);
    parallel_for(blocks, threads, [&](int k) {
        const std::size_t end = std::min(count, (static_cast<std::size_t>(k) + 1) * block);
        for (std::size_t i = static_cast<std::size_t>(k) * block; i < end; ++i) body(i);
    });
}

// The shape followed by `extra` trailing extents.
std::vector<py::ssize_t> with_trailing(std::vector<py::ssize_t> shape, std::initializer_list<py::ssize_t> extra);

// Each of the library's warnings as a Python UserWarning.
void warn_all(const std::vector<std::string>& warnings);

// The config a call names: a path, else $OCIO, else the one built into the
// library (as the cmfilter command chooses).
ColorConfig load_config(const std::string& path);

// An (N, 3) view of directions: one (3,) vector or N of them, as float64.
struct Directions {
    DoubleArray array;
    bool single = false;
    std::size_t count() const { return static_cast<std::size_t>(array.size() / 3); }
    const double* at(std::size_t i) const { return array.data() + 3 * i; }
};
Directions directions(const py::object& value, const char* what);

// What every pyramid's bake takes (MomentPyramid.bake, HistogramPyramid.bake):
// the driver and how to read it, the output, the wrap.
void set_pyramid_bake_options(PyramidBakeOptions& options, const std::string& driver, const std::string& output,
                              const std::string& channel, const std::string& wrap, const std::string& nonfinite,
                              int threads);

// "uncorrelated" or "correlated" (by the directions' azimuths), the option
// `what` names: BadInput naming it otherwise.
MaskingShadowing parse_masking(const std::string& name, const char* what);

void bind_tables(py::module_& m);
void bind_moments(py::module_& m);
void bind_noise(py::module_& m);
void bind_fits(py::module_& m);
void bind_coordinate_maps(py::module_& m);
void bind_ops(py::module_& m);
void bind_render(py::module_& m);
void bind_synthesis(py::module_& m);
void bind_histograms(py::module_& m);
void bind_microsurface(py::module_& m);
void bind_synthetic(py::module_& m);

}  // namespace cmfilter::python
