// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_spec.h"

#include "cmfilter/noise/gabor_box_correlation.h"
#include "cmfilter/noise/gradient_noise.h"
#include "cmfilter/noise/lattice_box_correlation.h"
#include "cmfilter/noise/value_noise.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

namespace cmfilter {

namespace {

// Shortest decimal text that parses back to the same double.
std::string number_text(double v)
{
    char buffer[32];
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
        if (std::strtod(buffer, nullptr) == v) break;
    }
    return buffer;
}

Expected<double> parse_number(const std::string& key, const std::string& text)
{
    char* end = nullptr;
    errno = 0;
    const double v = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || errno == ERANGE)
        return bad_input("noise parameter " + key + ": '" + text + "' is not a finite number");
    return v;
}

Expected<std::uint64_t> parse_seed(const std::string& text)
{
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = text.empty() ? 0 : std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || text[0] == '+' || end != text.c_str() + text.size() || errno == ERANGE)
        return bad_input("noise parameter seed: '" + text + "' is not an unsigned 64-bit integer");
    return static_cast<std::uint64_t>(v);
}

// Kinds and bases case-insensitively ("fBm", RenderMan's spelling).
std::string lower_case(std::string text)
{
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

Expected<NoiseBasis> parse_basis(const std::string& given)
{
    const std::string text = lower_case(given);
    // "perlin" and "snoise": OSL's noise("perlin") and noise("snoise") are
    // signed gradient noise, and most tools call gradient noise Perlin
    // noise (docs/noise.md, names other tools use).
    if (text == "gradient" || text == "perlin" || text == "snoise") return NoiseBasis::Gradient;
    if (text == "value") return NoiseBasis::Value;
    if (text == "gabor") return NoiseBasis::Gabor;
    return bad_input("noise basis '" + given + "' is unknown (expected gradient (or perlin, snoise), value or gabor)");
}

// Kind, then each key=value pair in order.
struct SpecText {
    std::string kind;
    std::vector<std::pair<std::string, std::string>> pairs;
};

Expected<SpecText> split_spec(const std::string& text)
{
    SpecText out;
    const auto colon = text.find(':');
    out.kind = text.substr(0, colon);
    if (colon == std::string::npos) return out;
    const std::string rest = text.substr(colon + 1);
    std::set<std::string> seen;
    std::size_t start = 0;
    while (start <= rest.size()) {
        const auto comma = rest.find(',', start);
        const std::string item = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0) return bad_input("noise parameter '" + item + "' is not key=value");
        const std::string key = item.substr(0, eq);
        if (!seen.insert(key).second) return bad_input("noise parameter " + key + " is given twice");
        out.pairs.emplace_back(key, item.substr(eq + 1));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

}  // namespace

const char* to_string(NoiseBasis basis)
{
    switch (basis) {
    case NoiseBasis::Gradient: return "gradient";
    case NoiseBasis::Value: return "value";
    default: return "gabor";
    }
}

bool operator==(const NoiseSpec& a, const NoiseSpec& b)
{
    const FractalOptions &fa = a.fractal_options, &fb = b.fractal_options;
    const GaborNoiseOptions &ga = a.gabor, &gb = b.gabor;
    return a.basis == b.basis && a.fractal == b.fractal && a.seed == b.seed && fa.octaves == fb.octaves &&
           fa.lacunarity == fb.lacunarity && fa.gain == fb.gain && fa.sum == fb.sum && ga.amplitude == gb.amplitude &&
           ga.bandwidth == gb.bandwidth && ga.frequency == gb.frequency && ga.orientation == gb.orientation &&
           ga.impulse_density == gb.impulse_density;
}

Expected<NoiseSpec> parse_noise_spec(const std::string& text)
{
    auto split = split_spec(text);
    if (!split) return split.error();
    NoiseSpec spec;
    const std::string kind = lower_case(split->kind);
    if (kind == "fbm" || kind == "turbulence") {
        spec.fractal = kind == "fbm" ? FractalSum::Fbm : FractalSum::Turbulence;
        spec.fractal_options.sum = *spec.fractal;
        for (const auto& [key, value] : split->pairs)
            if (key == "base") {
                auto basis = parse_basis(value);
                if (!basis) return basis.error();
                spec.basis = *basis;
            }
    } else {
        auto basis = parse_basis(split->kind);
        if (!basis)
            return bad_input("noise kind '" + split->kind +
                             "' is unknown (expected gradient (or perlin, snoise), value, gabor, fbm or turbulence)");
        spec.basis = *basis;
    }
    for (const auto& [key, value] : split->pairs) {
        if (key == "base" && spec.fractal) continue;
        if (key == "seed") {
            auto seed = parse_seed(value);
            if (!seed) return seed.error();
            spec.seed = *seed;
            continue;
        }
        const bool fractal_key = key == "octaves" || key == "lacunarity" || key == "gain";
        const bool gabor_key = key == "amplitude" || key == "bandwidth" || key == "frequency" || key == "orientation" ||
                               key == "density";
        if ((fractal_key && !spec.fractal) || (gabor_key && spec.basis != NoiseBasis::Gabor) ||
            (!fractal_key && !gabor_key))
            return bad_input("noise parameter " + key + " does not apply to '" + split->kind +
                             (spec.fractal ? std::string(" with base ") + to_string(spec.basis) : std::string()) + "'");
        auto number = parse_number(key, value);
        if (!number) return number.error();
        const double v = *number;
        if (key == "octaves") {
            if (v != std::floor(v) || std::fabs(v) > 1e6)
                return bad_input("noise parameter octaves: '" + value + "' is not an integer");
            spec.fractal_options.octaves = static_cast<int>(v);
        } else if (key == "lacunarity") spec.fractal_options.lacunarity = v;
        else if (key == "gain") spec.fractal_options.gain = v;
        else if (key == "amplitude") spec.gabor.amplitude = v;
        else if (key == "bandwidth") spec.gabor.bandwidth = v;
        else if (key == "frequency") spec.gabor.frequency = v;
        else if (key == "orientation") spec.gabor.orientation = v;
        else spec.gabor.impulse_density = v;
    }
    return spec;
}

std::string to_string(const NoiseSpec& spec)
{
    std::string out;
    if (spec.fractal) {
        const FractalOptions& f = spec.fractal_options;
        out = std::string(to_string(*spec.fractal)) + ":base=" + to_string(spec.basis) +
              ",octaves=" + std::to_string(f.octaves) + ",lacunarity=" + number_text(f.lacunarity) +
              ",gain=" + number_text(f.gain) + ",";
    } else {
        out = std::string(to_string(spec.basis)) + ":";
    }
    if (spec.basis == NoiseBasis::Gabor) {
        const GaborNoiseOptions& g = spec.gabor;
        out += "amplitude=" + number_text(g.amplitude) + ",bandwidth=" + number_text(g.bandwidth) +
               ",frequency=" + number_text(g.frequency) + ",density=" + number_text(g.impulse_density) + ",";
        if (g.orientation) out += "orientation=" + number_text(*g.orientation) + ",";
    }
    return out + "seed=" + std::to_string(spec.seed);
}

Expected<FractalNoise> make_noise(const NoiseSpec& spec)
{
    BaseNoise base;
    switch (spec.basis) {
    case NoiseBasis::Gradient: {
        const GradientNoise g(spec.seed);
        base.evaluate = [g](double x, double y) { return g(x, y); };
        base.correlation = gradient_noise_box_correlation();
        break;
    }
    case NoiseBasis::Value: {
        const ValueNoise v(spec.seed);
        base.evaluate = [v](double x, double y) { return v(x, y); };
        base.correlation = value_noise_box_correlation();
        break;
    }
    case NoiseBasis::Gabor: {
        auto g = GaborNoise::create(spec.gabor, spec.seed);
        if (!g) return g.error();
        base.period = g->period();
        base.evaluate = [g = *g](double x, double y) { return g(x, y); };
        base.correlation = gabor_noise_box_correlation(spec.gabor);
        break;
    }
    }
    FractalOptions options = spec.fractal_options;
    if (!spec.fractal) options = FractalOptions{1, 2.0, 1.0, FractalSum::Fbm};
    else options.sum = *spec.fractal;
    if (options.sum == FractalSum::Turbulence) base.mean_abs = measure_mean_abs(base.evaluate, base.period);
    // The octave shifts draw from a stream apart from the basis' own.
    return FractalNoise::create(std::move(base), options, spec.seed ^ 0x632BE59BD9B4E019ull);
}

}  // namespace cmfilter
