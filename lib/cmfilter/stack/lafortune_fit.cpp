// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/lafortune_fit.h"

#include "cmfilter/stack/lafortune_scalar_fit.h"
#include "cmfilter/stack/light_density.h"
#include "cmfilter/stack/linear_model.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

std::string number(double v)
{
    std::ostringstream s;
    s << v;
    return s.str();
}

// One scalar's fit as the model's floats (rho_d, then ax, ay, az, n per
// slot; unused slots (0, 0, 0, 1)); the lobes used.
int store_scalar(const ScalarLobeFit& fit, int slots, double max_exponent, float* out)
{
    out[0] = static_cast<float>(fit.rho);
    int used = 0;
    for (int i = 0; i < slots; ++i) {
        float* lobe = out + 1 + kLafortuneLobeFloats * i;
        lobe[0] = lobe[1] = lobe[2] = 0;
        lobe[3] = 1;
        if (i >= static_cast<int>(fit.shapes.size()) || !(fit.scales[i] > 0)) continue;
        const double n = lobe_shape_exponent(fit.shapes[i], max_exponent);
        const Vec3 a = std::pow(fit.scales[i], 1 / n) * lobe_shape_axis(fit.shapes[i]);
        lobe[0] = static_cast<float>(a.x);
        lobe[1] = static_cast<float>(a.y);
        lobe[2] = static_cast<float>(a.z);
        lobe[3] = static_cast<float>(n);
        ++used;
    }
    return used;
}

// The lights' weights for one scalar: the density weights times
// 1 / (value + epsilon)^2 (relative_epsilon > 0), scaled to mean 1.
void relative_weights(const std::vector<double>& density, const double* values, double epsilon,
                      std::vector<double>* out)
{
    const std::size_t K = density.size();
    out->resize(K);
    double sum = 0;
    for (std::size_t k = 0; k < K; ++k) {
        const double d = std::max(0.0, values[k]) + epsilon;
        (*out)[k] = density[k] / (d * d);
        sum += (*out)[k];
    }
    for (double& w : *out) w *= K / sum;
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

double lafortune_max_exponent(const std::vector<Vec3>& lights, const LafortuneFitOptions& options)
{
    if (!(options.spacing_cap > 0)) return kLafortuneMaxExponent;
    const double n = exponent_for_lobe_width(options.spacing_cap * mean_light_spacing(lights));
    return std::clamp(n, 2.0, kLafortuneMaxExponent);
}

std::vector<double> lafortune_light_weights(const std::vector<Vec3>& lights, const LafortuneFitOptions& options)
{
    return light_density_weights(lights, options.density_radius * kPi / 180);
}

Expected<LafortuneFit> fit_lafortune(const ImageStack& stack, const LafortuneFitOptions& options)
{
    const int most = max_lafortune_lobes(options.variant);
    if (options.lobes < 1 || options.lobes > most)
        return bad_input("LafortuneFitOptions::lobes " + std::to_string(options.lobes) + " is invalid: a " +
                             to_string(options.variant) + " fit takes 1 to " + std::to_string(most) + " lobes",
                         "LafortuneFitOptions::lobes");
    if (options.auto_lobes && !(std::isfinite(options.tolerance) && options.tolerance > 0))
        return bad_input("LafortuneFitOptions::tolerance " + number(options.tolerance) +
                             " is invalid: the auto lobe count needs an RMS tolerance above 0",
                         "LafortuneFitOptions::tolerance");
    if (!(options.min_gain >= 0 && options.min_gain < 1))
        return bad_input("LafortuneFitOptions::min_gain " + number(options.min_gain) +
                             " is invalid: expected a fraction in [0, 1)",
                         "LafortuneFitOptions::min_gain");
    const Vec3& v = options.view;
    const double view_length = length(v);
    if (!(std::isfinite(view_length) && view_length > 0) || !(v.z / view_length > 1e-9))
        return bad_input("LafortuneFitOptions::view (" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) +
                             ") is invalid: expected a direction above the horizon (z > 0)",
                         "LafortuneFitOptions::view");
    if (options.max_iterations < 1)
        return bad_input("LafortuneFitOptions::max_iterations " + std::to_string(options.max_iterations) +
                             " is invalid: expected at least 1",
                         "LafortuneFitOptions::max_iterations");
    if (!(options.function_tolerance > 0 && options.function_tolerance < 1))
        return bad_input("LafortuneFitOptions::function_tolerance " + number(options.function_tolerance) +
                             " is invalid: expected a fraction in (0, 1)",
                         "LafortuneFitOptions::function_tolerance");
    if (!(options.density_radius >= 0 && options.density_radius <= 90))
        return bad_input("LafortuneFitOptions::density_radius " + number(options.density_radius) +
                             " is invalid: expected an angle in degrees in [0, 90] (0: no density weights)",
                         "LafortuneFitOptions::density_radius");
    if (!(std::isfinite(options.spacing_cap) && options.spacing_cap >= 0))
        return bad_input("LafortuneFitOptions::spacing_cap " + number(options.spacing_cap) +
                             " is invalid: expected a multiple of the light spacing >= 0 (0: no cap)",
                         "LafortuneFitOptions::spacing_cap");
    if (!(std::isfinite(options.exponent_penalty) && options.exponent_penalty >= 0))
        return bad_input("LafortuneFitOptions::exponent_penalty " + number(options.exponent_penalty) +
                             " is invalid: expected a fraction >= 0 (0: no penalty)",
                         "LafortuneFitOptions::exponent_penalty");
    if (!(std::isfinite(options.relative_epsilon) && options.relative_epsilon >= 0))
        return bad_input("LafortuneFitOptions::relative_epsilon " + number(options.relative_epsilon) +
                             " is invalid: expected a value >= 0 (0: no relative weighting)",
                         "LafortuneFitOptions::relative_epsilon");
    const int needed = lafortune_scalar_parameters(options.lobes);
    if (stack.count() < needed)
        return bad_input("LafortuneFitOptions::lobes " + std::to_string(options.lobes) + " needs at least " +
                             std::to_string(needed) + " lights (rho_d and 4 parameters per lobe), but the stack '" +
                             stack.light_file + "' has " + std::to_string(stack.count()),
                         "LafortuneFitOptions::lobes");
    if (options.variant == LafortuneVariant::Rgb && stack.channels != 3)
        return bad_input("LafortuneFitOptions::variant rgb needs a 3-channel stack, but '" + stack.light_file +
                             "' has " + std::to_string(stack.channels) +
                             " channels (one channel: the luminance variant; a fourth is not a reflectance)",
                         "LafortuneFitOptions::variant");
    if (options.variant == LafortuneVariant::Luminance && stack.channels != 1 && stack.channels != 3)
        return bad_input("LafortuneFitOptions::variant luminance needs a 1- or 3-channel stack, but '" +
                             stack.light_file + "' has " + std::to_string(stack.channels) + " channels",
                         "LafortuneFitOptions::variant");
    if (stack.width <= 0 || stack.height <= 0 ||
        stack.pixels.size() != stack.texels() * stack.channels * static_cast<std::size_t>(stack.count()))
        return bad_input("the stack '" + stack.light_file +
                         "' is inconsistent: " + std::to_string(stack.pixels.size()) + " values for " +
                         std::to_string(stack.width) + " x " + std::to_string(stack.height) + " texels, " +
                         std::to_string(stack.channels) + " channels and " + std::to_string(stack.count()) + " lights");

    LafortuneFit fit;
    fit.variant = options.variant;
    fit.width = stack.width;
    fit.height = stack.height;
    fit.channels = stack.channels;
    fit.lobes = options.lobes;
    fit.auto_lobes = options.auto_lobes;
    fit.view = v / view_length;
    fit.encoding = stack.encoding;
    fit.colorspace = stack.colorspace;
    const std::size_t texels = stack.texels();
    const int ch = stack.channels;
    const int K = stack.count();
    const bool luminance = options.variant == LafortuneVariant::Luminance;
    const int scalars = luminance ? 1 : ch;
    fit.parameters.assign(texels * fit.stride(), 0.0f);
    fit.lobe_counts.assign(texels * scalars, 0);

    const std::vector<double> density = lafortune_light_weights(stack.lights, options);
    const LobeLights lights(stack.lights, density);
    const bool relative = options.relative_epsilon > 0;
    const double max_exponent = lafortune_max_exponent(stack.lights, options);
    ScalarLobeSettings settings;
    settings.max_exponent = max_exponent;
    settings.exponent_penalty = options.exponent_penalty;
    settings.lobes = options.lobes;
    settings.auto_lobes = options.auto_lobes;
    settings.tolerance = options.tolerance;
    settings.min_gain = options.min_gain;
    settings.max_iterations = options.max_iterations;
    settings.function_tolerance = options.function_tolerance;
    std::vector<long long> row_fallbacks(stack.height, 0);
    parallel_for(stack.height, options.threads, [&](int row) {
        std::vector<double> values(K), colour(static_cast<std::size_t>(K) * ch), weights;
        // The lights with this scalar's relative weights (when asked for).
        auto fit_values = [&]() {
            if (!relative) return fit_scalar_lobes(lights, values.data(), settings);
            relative_weights(density, values.data(), options.relative_epsilon, &weights);
            return fit_scalar_lobes(LobeLights(stack.lights, weights), values.data(), settings);
        };
        for (int x = 0; x < stack.width; ++x) {
            const std::size_t t = static_cast<std::size_t>(row) * stack.width + x;
            for (int k = 0; k < K; ++k)
                for (int c = 0; c < ch; ++c) colour[k * ch + c] = stack.pixels[(k * texels + t) * ch + c];
            float* out = fit.parameters.data() + t * fit.stride();
            if (!luminance) {
                for (int c = 0; c < ch; ++c) {
                    for (int k = 0; k < K; ++k) values[k] = colour[k * ch + c];
                    const ScalarLobeFit s = fit_values();
                    row_fallbacks[row] += s.fallbacks;
                    fit.lobe_counts[t * ch + c] = static_cast<unsigned char>(
                        store_scalar(s, fit.lobes, max_exponent, out + c * fit.scalar_stride()));
                }
                continue;
            }
            for (int k = 0; k < K; ++k) {
                const double* I = &colour[k * ch];
                values[k] = ch == 1
                                ? I[0]
                                : kRec709Luminance[0] * I[0] + kRec709Luminance[1] * I[1] + kRec709Luminance[2] * I[2];
            }
            const ScalarLobeFit s = fit_values();
            row_fallbacks[row] += s.fallbacks;
            fit.lobe_counts[t] = static_cast<unsigned char>(store_scalar(s, fit.lobes, max_exponent, out));
            // The base colour (lafortune_model.h): least squares for the
            // fitted luminance, as PTM-LRGB's.
            double fitted2 = 0, measured2 = 0, mean_y = 0;
            std::vector<double> cross(ch, 0.0), mean_c(ch, 0.0);
            for (int k = 0; k < K; ++k) {
                const Vec3 u = stack.lights[k];
                const double yf = std::max(0.0, u.z) * lafortune_reflectance(out, fit.lobes, u, fit.view, fit.view);
                fitted2 += yf * yf;
                measured2 += values[k] * values[k];
                mean_y += values[k];
                for (int c = 0; c < ch; ++c) {
                    cross[c] += colour[k * ch + c] * yf;
                    mean_c[c] += colour[k * ch + c];
                }
            }
            float* base = out + fit.scalar_stride();
            const bool negligible = !(fitted2 > std::max(1e-12 * measured2, 1e-30));
            for (int c = 0; c < ch; ++c) {
                double b = 0;
                if (!negligible) b = cross[c] / fitted2;
                else if (std::abs(mean_y) > 1e-30) b = mean_c[c] / mean_y;
                base[c] = static_cast<float>(std::isfinite(b) ? b : 0.0);
            }
        }
    });
    for (long long f : row_fallbacks) fit.fallbacks += f;
    return fit;
}

std::vector<float> relight_lafortune(const LafortuneFit& fit, const Vec3& light, const Vec3& view, int threads)
{
    std::vector<float> out(fit.texels() * fit.channels);
    parallel_for(fit.height, threads, [&](int row) {
        for (int x = 0; x < fit.width; ++x) {
            const std::size_t t = static_cast<std::size_t>(row) * fit.width + x;
            lafortune_texel_value(fit, t, light, view, out.data() + t * fit.channels);
        }
    });
    return out;
}

std::vector<float> relight_lafortune(const LafortuneFit& fit, const Vec3& light, int threads)
{
    return relight_lafortune(fit, light, fit.view, threads);
}

}  // namespace cmfilter
