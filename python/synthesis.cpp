// SPDX-License-Identifier: Apache-2.0
// Texture synthesis (Bosserhoff & Nicoll sec. 4, Tong et al. 2002): a
// sample's analysis (textons, their dot products, candidate sets per
// pyramid level) from an image file or an array, read and written as the
// analysis file synth-analyse writes, and k-coherence synthesis from it to
// a coordinate map, one level or hierarchically.
#include "bindings.h"

#include "cmfilter/synthesis/analysis_file.h"
#include "cmfilter/synthesis/kcoherence_synthesis.h"
#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/synthesis/synthesis_sample.h"

#include <pybind11/stl.h>

#include <optional>

namespace cmfilter::python {

namespace {

// A path (str or os.PathLike) as text, or nothing for anything else.
std::optional<std::string> as_path(const py::object& value)
{
    if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
        return py::module_::import("os").attr("fspath")(value).cast<std::string>();
    return std::nullopt;
}

// The sample an image file or an (H, W[, C]) array of features holds.
SynthesisSample load_sample(const py::object& sample, int levels, int select, bool periodic,
                            const std::string& colorspace, const std::string& ocio_config, int threads)
{
    if (auto path = as_path(sample)) {
        SampleOptions options;
        options.path = *path;
        options.colorspace = colorspace;
        options.select_images = select;
        options.levels = levels;
        options.periodic = periodic;
        options.threads = threads;
        const ColorConfig config = load_config(ocio_config);
        py::gil_scoped_release release;
        return unwrap(load_synthesis_sample(options, config));
    }
    const auto features = py::cast<FloatArray>(sample);
    if (features.ndim() != 2 && features.ndim() != 3)
        bad_argument("sample must be a path or an array of shape (H, W) or (H, W, C) (its features per texel)");
    const int height = static_cast<int>(features.shape(0));
    const int width = static_cast<int>(features.shape(1));
    const int dims = features.ndim() == 3 ? static_cast<int>(features.shape(2)) : 1;
    std::vector<float> values(features.data(), features.data() + features.size());
    py::gil_scoped_release release;
    return unwrap(sample_from_features(width, height, dims, std::move(values), levels, periodic));
}

SampleAnalysis analyse(const py::object& sample, int levels, int textons, int candidates, int neighbourhood, int select,
                       bool periodic, std::uint64_t seed, const std::string& colorspace, const std::string& ocio_config,
                       int threads)
{
    const SynthesisSample loaded = load_sample(sample, levels, select, periodic, colorspace, ocio_config, threads);
    AnalysisOptions options;
    options.textons = textons;
    options.candidates = candidates;
    options.neighbourhood = neighbourhood;
    options.seed = seed;
    options.threads = threads;
    py::gil_scoped_release release;
    return unwrap(analyse_sample(loaded, options));
}

const LevelAnalysis& analysis_level(const SampleAnalysis& analysis, int level)
{
    if (level < 0 || level >= static_cast<int>(analysis.levels.size()))
        bad_argument("level " + std::to_string(level) + " is invalid (expected 0 .. " +
                     std::to_string(analysis.levels.size() - 1) + ")");
    return analysis.levels[static_cast<std::size_t>(level)];
}

CoordinateMap synthesise_map(const SampleAnalysis& analysis, std::pair<int, int> size, int k, int neighbourhood,
                             int levels, bool toroidal, std::uint64_t seed, int threads)
{
    SynthesisOptions options;
    options.width = size.first;
    options.height = size.second;
    options.k = k;
    options.neighbourhood = neighbourhood > 0 ? neighbourhood : analysis.neighbourhood;
    options.levels = levels > 0 ? levels : static_cast<int>(analysis.levels.size());
    options.toroidal = toroidal;
    options.seed = seed;
    options.threads = threads;
    py::gil_scoped_release release;
    return unwrap(synthesise(analysis, options));
}

}  // namespace

void bind_synthesis(py::module_& m)
{
    py::class_<SampleAnalysis>(m, "SampleAnalysis",
                               "A synthesis sample's analysis: per pyramid level its texels' textons, the textons' "
                               "dot products and each texel's most similar texels (cmfilter synth-analyse).")
        .def_static("analyse", &analyse, py::arg("sample"), py::kw_only(), py::arg("levels") = 1,
                    py::arg("textons") = 0, py::arg("candidates") = 10, py::arg("neighbourhood") = 2,
                    py::arg("select") = 0, py::arg("periodic") = false, py::arg("seed") = 1, py::arg("colorspace") = "",
                    py::arg("ocio_config") = "", py::arg("threads") = 0,
                    "Analyses a sample: an image, a stack (.lp) or a BTF manifest by path, or an (H, W[, C]) array "
                    "of features, over `levels` pyramid levels, with `textons` k-means textons per level (0: "
                    "min(2000, texels / 4)), `candidates` (m) similar texels per texel compared over "
                    "(2 neighbourhood + 1)^2 windows, `select` representative images (0: all).")
        .def_static(
            "read",
            [](const std::string& path) {
        py::gil_scoped_release release;
        return unwrap(read_analysis_exr(path));
            },
            py::arg("path"), "Reads an analysis EXR (cmfilter synth-analyse).")
        .def(
            "write",
            [](const SampleAnalysis& analysis, const std::string& path) {
        py::gil_scoped_release release;
        check(write_analysis_exr(path, analysis));
            },
            py::arg("path"), "Writes the analysis as cmfilter synth-analyse does, for synth --analysis.")
        .def(
            "textons",
            [](py::object self, int level) {
        const LevelAnalysis& l = analysis_level(self.cast<const SampleAnalysis&>(), level);
        return view_array(l.texton.data(), {l.height, l.width}, self);
            },
            py::arg("level") = 0, "(H, W) int32 texton of each texel of a level (a read-only view)")
        .def(
            "dot",
            [](py::object self, int level) {
        const LevelAnalysis& l = analysis_level(self.cast<const SampleAnalysis&>(), level);
        return view_array(l.dot.data(), {l.textons, l.textons}, self);
            },
            py::arg("level") = 0, "(T, T) float32 dot products of a level's textons, M (a read-only view)")
        .def(
            "similar",
            [](py::object self, int level) {
        const LevelAnalysis& l = analysis_level(self.cast<const SampleAnalysis&>(), level);
        return view_array(l.similar.data(), {l.height, l.width, l.candidates}, self);
            },
            py::arg("level") = 0,
            "(H, W, m) int32 most similar texels (y * width + x) of each texel of a level, nearest first (a "
            "read-only view)")
        .def(
            "inertia", [](const SampleAnalysis& a, int level) { return analysis_level(a, level).inertia; },
            py::arg("level") = 0, "The k-means inertia of a level")
        .def_property_readonly("width", &SampleAnalysis::width)
        .def_property_readonly("height", &SampleAnalysis::height)
        .def_property_readonly("level_count", [](const SampleAnalysis& a) { return a.levels.size(); })
        .def_property_readonly("neighbourhood", [](const SampleAnalysis& a) { return a.neighbourhood; })
        .def_property_readonly("channels", [](const SampleAnalysis& a) { return a.channels; })
        .def_property_readonly("periodic", [](const SampleAnalysis& a) { return a.periodic; })
        .def_property_readonly("sample_path", [](const SampleAnalysis& a) { return a.sample_path; })
        .def_property_readonly("sample_hash", [](const SampleAnalysis& a) { return a.sample_hash; })
        .def_property_readonly("sample_kind", [](const SampleAnalysis& a) { return to_string(a.sample_kind); })
        .def_property_readonly("seconds", [](const SampleAnalysis& a) { return a.seconds; });

    m.def("synthesise", &synthesise_map, py::arg("analysis"), py::arg("size"), py::kw_only(), py::arg("k") = 3,
          py::arg("neighbourhood") = 0, py::arg("levels") = 0, py::arg("toroidal") = false, py::arg("seed") = 1,
          py::arg("threads") = 0,
          "k-coherence synthesis of a surface of size (width, height) from an analysis, as a CoordinateMap: k "
          "candidates per neighbour (1 .. m + 1), (2 neighbourhood + 1)^2 windows (0: the analysis's), the finest "
          "`levels` of the analysis hierarchically (0: all of them; 1: one level), toroidal to tile seamlessly. "
          "The same map for any thread count (cmfilter synth).");
}

}  // namespace cmfilter::python
