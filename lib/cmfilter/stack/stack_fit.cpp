// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/stack_fit.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/fit_loading.h"
#include "cmfilter/stack/lafortune_error.h"
#include "cmfilter/stack/lafortune_file.h"
#include "cmfilter/stack/lafortune_fit.h"

#include <cmath>
#include <cstdio>

namespace cmfilter {

namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

std::string number(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// A linear fit holds the one view it was fitted at, taken as the zenith.
Status check_linear_view(const Vec3& view)
{
    if (std::abs(view.x) <= 1e-9 && std::abs(view.y) <= 1e-9 && std::abs(view.z - 1) <= 1e-9) return ok();
    return bad_input("the view (" + number(view.x) + ", " + number(view.y) + ", " + number(view.z) +
                     ") cannot be rendered: a PTM/HSH holds one view, the one it was fitted at (expected no view, or "
                     "0,0,1; a Lafortune fit renders other views)");
}

}  // namespace

Expected<StackFit> load_stack_fit(const std::string& path)
{
    if (fit_file_format(path) != FitFileFormat::Exr) {
        auto fit = load_fit(path);
        if (!fit) return fit.error();
        return StackFit{std::move(*fit)};
    }
    auto in = open_image_input(path);
    if (!in) return in.error();
    const std::string kind = (*in)->spec().get_string_attribute("cmfilter:kind");
    (*in)->close();
    if (kind == kLafortuneFitKind) {
        auto fit = read_lafortune_exr(path);
        if (!fit) return fit.error();
        return StackFit{std::move(*fit)};
    }
    if (kind == kLinearFitKind) {
        auto fit = read_fit_exr(path);
        if (!fit) return fit.error();
        return StackFit{std::move(*fit)};
    }
    return bad_input("'" + path + "' is not a fit of an image stack (cmfilter:kind is '" + kind + "', expected '" +
                     kLinearFitKind + "' or '" + kLafortuneFitKind + "', or a .ptm or .rti file)");
}

int stack_fit_width(const StackFit& fit)
{
    return std::visit([](const auto& f) { return f.width; }, fit);
}

int stack_fit_height(const StackFit& fit)
{
    return std::visit([](const auto& f) { return f.height; }, fit);
}

int stack_fit_channels(const StackFit& fit)
{
    return std::visit([](const auto& f) { return f.channels; }, fit);
}

std::size_t stack_fit_texels(const StackFit& fit)
{
    return std::visit([](const auto& f) { return f.texels(); }, fit);
}

StackEncoding stack_fit_encoding(const StackFit& fit)
{
    return std::visit([](const auto& f) { return f.encoding; }, fit);
}

std::string stack_fit_model_name(const StackFit& fit)
{
    return std::visit(Overloaded{[](const LinearFit& f) { return std::string(to_string(f.model)); },
                                 [](const LafortuneFit& f) {
        return std::string(f.variant == LafortuneVariant::Rgb ? "lafortune-rgb" : "lafortune");
                                 }},
                      fit);
}

Vec3 stack_fit_view(const StackFit& fit)
{
    if (const auto* f = std::get_if<LafortuneFit>(&fit)) return f->view;
    return {0, 0, 1};
}

Expected<std::vector<float>> relight_stack_fit(const StackFit& fit, const Vec3& light, const std::optional<Vec3>& view,
                                               int threads)
{
    if (const auto* f = std::get_if<LafortuneFit>(&fit))
        return relight_lafortune(*f, light, view.value_or(f->view), threads);
    if (view)
        if (auto st = check_linear_view(*view); !st) return st.error();
    return relight(std::get<LinearFit>(fit), light, threads);
}

Expected<RelightError> stack_fit_error(const StackFit& fit, const StackLoadOptions& reference,
                                       const ColorConfig& config, int threads, const std::optional<Vec3>& view)
{
    if (const auto* f = std::get_if<LafortuneFit>(&fit))
        return relit_model_error_from_files(lafortune_relit_model(*f, view.value_or(f->view)), reference, config,
                                            threads);
    if (view)
        if (auto st = check_linear_view(*view); !st) return st.error();
    return relight_error_from_files(std::get<LinearFit>(fit), reference, config, threads);
}

}  // namespace cmfilter
