// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/ptm_file.h"

#include "cmfilter/stack/quantised_fit_file.h"
#include "cmfilter/stack/relit_difference.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace cmfilter {

namespace {

constexpr int kPtmTerms = 6;
constexpr int kPtmMaxSide = 65536;

constexpr QuantisedFitFormat kPtmFormat = {
    ".ptm", "a .ptm", "a .ptm", {LinearModel::PtmRgb, LinearModel::PtmLrgb}, kPtmMaxSide};

// ---------------------------------------------------------------- writing

// The scale and bias of one term (ptm_file.h, "Writing").
struct TermCode {
    double scale = 1;  // as a reader parses the text
    int bias = 0;
    std::string scale_text = "1";
};

std::string decimal_text(double v)
{
    // Fixed notation (no exponent), nine significant digits.
    const int magnitude = v > 0 ? static_cast<int>(std::floor(std::log10(v))) : 0;
    const int decimals = std::clamp(8 - magnitude, 6, 40);
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

TermCode choose_term_code(double lo, double hi)
{
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
    TermCode code;
    if (!(hi - lo > 0)) return code;
    double best = std::numeric_limits<double>::infinity();
    for (int b = 0; b <= 255; ++b) {
        if (b == 0 && lo < 0) continue;
        if (b == 255 && hi > 0) continue;
        const double s = std::max(b > 0 ? -lo / b : 0.0, b < 255 ? hi / (255 - b) : 0.0);
        if (s < best) best = s, code.bias = b;
    }
    // A hair wider, so that the decimal text, read back as a float, still
    // covers the range.
    code.scale_text = decimal_text(best * (1 + 1e-6));
    code.scale = static_cast<float>(std::strtod(code.scale_text.c_str(), nullptr));
    return code;
}

unsigned char quantise(double v, const TermCode& code)
{
    const double q = std::clamp(v / code.scale + code.bias, 0.0, 255.0);
    return static_cast<unsigned char>(std::lround(q));
}

// The fit's per-texel terms in codes, as the file stores them: RGB 18 per
// texel ([c * 6 + k]); LRGB the 6 polynomial terms (after the base colour's
// factor moved into them) then the colour in [0, 1].
struct PtmTerms {
    std::vector<double> values;
    int stride = 0;
};

PtmTerms file_terms(const LinearFit& fit)
{
    PtmTerms terms;
    const std::size_t n = fit.texels();
    if (fit.model == LinearModel::PtmRgb) {
        terms.stride = 3 * kPtmTerms;
        terms.values.resize(n * terms.stride);
        for (std::size_t i = 0; i < terms.values.size(); ++i) terms.values[i] = 255.0 * fit.coefficients[i];
        return terms;
    }
    terms.stride = kPtmTerms + 3;
    terms.values.resize(n * terms.stride);
    for (std::size_t t = 0; t < n; ++t) {
        const float* in = fit.texel(t);
        double* out = terms.values.data() + t * terms.stride;
        const double m = std::max({0.0, double(in[6]), double(in[7]), double(in[8])});
        const double factor = m > 0 ? m : 1.0;
        for (int k = 0; k < kPtmTerms; ++k) out[k] = 255.0 * in[k] * factor;
        for (int c = 0; c < 3; ++c) out[kPtmTerms + c] = m > 0 ? std::clamp(in[kPtmTerms + c] / m, 0.0, 1.0) : 0.0;
    }
    return terms;
}

std::string ptm_header(const LinearFit& fit, const TermCode (&codes)[kPtmTerms])
{
    std::ostringstream header;
    header << "PTM_1.2\n" << (fit.model == LinearModel::PtmRgb ? "PTM_FORMAT_RGB" : "PTM_FORMAT_LRGB") << "\n";
    header << fit.width << "\n" << fit.height << "\n";
    for (int k = 0; k < kPtmTerms; ++k) header << codes[k].scale_text << (k + 1 < kPtmTerms ? " " : "\n");
    for (int k = 0; k < kPtmTerms; ++k) header << codes[k].bias << (k + 1 < kPtmTerms ? " " : "\n");
    return header.str();
}

// ---------------------------------------------------------------- reading

bool parse_double(const std::string& token, double& value)
{
    if (token.empty()) return false;
    errno = 0;
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return errno == 0 && end == token.c_str() + token.size() && std::isfinite(value);
}

}  // namespace

Expected<LinearFit> decode_ptm(const std::string& bytes, const std::string& name)
{
    const std::string where = "'" + name + "' ";
    ByteCursor in{bytes};
    std::string version, format;
    in.line(version);
    if (version != "PTM_1.2") {
        if (version.rfind("PTM_", 0) == 0)
            return bad_input(where + "is PTM version " + quoted_header(version) + "; cmfilter reads PTM_1.2");
        return bad_input(where + "is not a PTM 1.2 file: its first line is " + quoted_header(version) +
                         ", expected PTM_1.2");
    }
    if (!in.line(format)) return bad_input(where + "ends after its version line (expected a format line)");
    LinearModel model;
    if (format == "PTM_FORMAT_RGB") {
        model = LinearModel::PtmRgb;
    } else if (format == "PTM_FORMAT_LRGB") {
        model = LinearModel::PtmLrgb;
    } else if (format == "PTM_FORMAT_JPEG_RGB" || format == "PTM_FORMAT_JPEG_LRGB" ||
               format == "PTM_FORMAT_JPEGLS_RGB" || format == "PTM_FORMAT_JPEGLS_LRGB" || format == "PTM_FORMAT_LUM" ||
               format == "PTM_FORMAT_PTM_LUT" || format == "PTM_FORMAT_PTM_C_LUT") {
        return bad_input(where + "is in format " + format +
                         ", which cmfilter does not support; it reads PTM_FORMAT_RGB and PTM_FORMAT_LRGB");
    } else {
        return bad_input(where + "has an unknown format line " + quoted_header(format) +
                         " (expected PTM_FORMAT_RGB or PTM_FORMAT_LRGB)");
    }

    long long size[2] = {};
    const char* size_names[2] = {"width", "height"};
    for (int i = 0; i < 2; ++i) {
        std::string token;
        if (!in.token(token)) return bad_input(where + "ends before its " + size_names[i]);
        if (!parse_integer_token(token, size[i]) || size[i] < 1 || size[i] > kPtmMaxSide)
            return bad_input(where + "has " + size_names[i] + " " + quoted_header(token) +
                             ", expected an integer in 1 .. " + std::to_string(kPtmMaxSide));
    }
    double scale[kPtmTerms];
    long long bias[kPtmTerms];
    for (int k = 0; k < kPtmTerms; ++k) {
        std::string token;
        if (!in.token(token)) return bad_input(where + "ends before its scale " + std::to_string(k));
        if (!parse_double(token, scale[k]))
            return bad_input(where + "has scale " + std::to_string(k) + " " + quoted_header(token) +
                             ", expected a finite number");
        scale[k] = static_cast<float>(scale[k]);  // as the viewers hold it
        // A coefficient is (byte - bias) * scale / 255 with |bias| <= 2^24:
        // it must stay a finite float.
        if (!(std::fabs(scale[k]) * (255.0 + (1 << 24)) / 255.0 <= std::numeric_limits<float>::max()))
            return bad_input(where + "has scale " + std::to_string(k) + " " + quoted_header(token) +
                             ", expected one whose coefficients fit a 32-bit float");
    }
    for (int k = 0; k < kPtmTerms; ++k) {
        std::string token;
        if (!in.token(token)) return bad_input(where + "ends before its bias " + std::to_string(k));
        if (!parse_integer_token(token, bias[k]) || std::llabs(bias[k]) > (1 << 24))
            return bad_input(where + "has bias " + std::to_string(k) + " " + quoted_header(token) +
                             ", expected an integer");
    }
    if (!in.end_of_line() && !in.at_end())
        return bad_input(where + "has more than six biases, or no newline after them");

    LinearFit fit;
    fit.model = model;
    fit.width = static_cast<int>(size[0]);
    fit.height = static_cast<int>(size[1]);
    fit.channels = 3;
    fit.encoding = StackEncoding::DisplayEncoded;
    fit.colorspace = "sRGB";
    const std::size_t texels = fit.texels();
    const std::size_t needed = texels * (model == LinearModel::PtmRgb ? 18 : 9);
    const std::size_t found = in.at_end() ? 0 : bytes.size() - in.pos;
    if (found < needed)
        return bad_input(where + "is truncated: expected " + std::to_string(needed) + " bytes of coefficients (" +
                         std::to_string(fit.width) + " x " + std::to_string(fit.height) + " " + format + "), found " +
                         std::to_string(found));

    const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data()) + in.pos;
    fit.coefficients.assign(texels * fit.stride(), 0.0f);
    double code_scale[kPtmTerms];
    for (int k = 0; k < kPtmTerms; ++k) code_scale[k] = scale[k] / 255.0;
    const std::size_t w = static_cast<std::size_t>(fit.width), h = static_cast<std::size_t>(fit.height);
    // File row r is the image's row h - 1 - r (rows bottom to top).
    if (model == LinearModel::PtmRgb) {
        for (int c = 0; c < 3; ++c)
            for (std::size_t r = 0; r < h; ++r)
                for (std::size_t x = 0; x < w; ++x) {
                    const std::size_t t = (h - 1 - r) * w + x;
                    float* out = fit.coefficients.data() + t * fit.stride() + c * kPtmTerms;
                    for (int k = 0; k < kPtmTerms; ++k, ++data)
                        out[k] = static_cast<float>((double(*data) - double(bias[k])) * code_scale[k]);
                }
    } else {
        for (std::size_t r = 0; r < h; ++r)
            for (std::size_t x = 0; x < w; ++x) {
                float* out = fit.coefficients.data() + ((h - 1 - r) * w + x) * fit.stride();
                for (int k = 0; k < kPtmTerms; ++k, ++data)
                    out[k] = static_cast<float>((double(*data) - double(bias[k])) * code_scale[k]);
            }
        for (std::size_t r = 0; r < h; ++r)
            for (std::size_t x = 0; x < w; ++x) {
                float* out = fit.coefficients.data() + ((h - 1 - r) * w + x) * fit.stride() + kPtmTerms;
                for (int c = 0; c < 3; ++c, ++data) out[c] = static_cast<float>(*data / 255.0);
            }
    }
    return fit;
}

Expected<LinearFit> read_ptm(const std::string& path)
{
    auto bytes = read_file_bytes(path);
    if (!bytes) return bytes.error();
    return decode_ptm(*bytes, path);
}

Status write_ptm(const std::string& path, const LinearFit& fit, PtmQuantisation* quantisation)
{
    if (auto checked = check_writable_fit(path, fit, kPtmFormat); !checked) return checked.error();
    const PtmTerms terms = file_terms(fit);
    const std::size_t n = fit.texels();
    const int planes = fit.model == LinearModel::PtmRgb ? 3 : 1;

    // Per term, the range over texels (and channels).
    TermCode codes[kPtmTerms];
    for (int k = 0; k < kPtmTerms; ++k) {
        double lo = 0, hi = 0;
        for (std::size_t t = 0; t < n; ++t)
            for (int c = 0; c < planes; ++c) {
                const double v = terms.values[t * terms.stride + c * kPtmTerms + k];
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        codes[k] = choose_term_code(lo, hi);
    }

    std::string bytes = ptm_header(fit, codes);
    const std::size_t header_size = bytes.size();
    bytes.reserve(header_size + n * (fit.model == LinearModel::PtmRgb ? 18 : 9));
    const std::size_t w = static_cast<std::size_t>(fit.width), h = static_cast<std::size_t>(fit.height);
    for (int c = 0; c < planes; ++c)
        for (std::size_t r = 0; r < h; ++r)
            for (std::size_t x = 0; x < w; ++x) {
                const double* v = terms.values.data() + ((h - 1 - r) * w + x) * terms.stride + c * kPtmTerms;
                for (int k = 0; k < kPtmTerms; ++k) bytes.push_back(static_cast<char>(quantise(v[k], codes[k])));
            }
    if (fit.model == LinearModel::PtmLrgb)
        for (std::size_t r = 0; r < h; ++r)
            for (std::size_t x = 0; x < w; ++x) {
                const double* v = terms.values.data() + ((h - 1 - r) * w + x) * terms.stride + kPtmTerms;
                for (int c = 0; c < 3; ++c)
                    bytes.push_back(static_cast<char>(std::lround(std::clamp(v[c], 0.0, 1.0) * 255.0)));
            }

    if (quantisation) {
        auto decoded = decode_ptm(bytes, path);
        if (!decoded)
            return runtime_error("the .ptm written for '" + path + "' does not decode: " + decoded.error().message);
        PtmQuantisation q;
        for (int k = 0; k < kPtmTerms; ++k) {
            q.scales[k] = codes[k].scale;
            q.biases[k] = codes[k].bias;
        }
        for (std::size_t t = 0; t < n; ++t) {
            const float* d = decoded->texel(t);
            const double* v = terms.values.data() + t * terms.stride;
            for (int c = 0; c < planes; ++c)
                for (int k = 0; k < kPtmTerms; ++k)
                    q.max_coefficient_error[k] =
                        std::max(q.max_coefficient_error[k],
                                 std::abs(double(d[c * kPtmTerms + k]) - v[c * kPtmTerms + k] / 255.0));
            if (fit.model == LinearModel::PtmLrgb)
                for (int c = 0; c < 3; ++c)
                    q.max_color_error =
                        std::max(q.max_color_error, std::abs(double(d[kPtmTerms + c]) - v[kPtmTerms + c]));
        }
        q.max_value_error = max_relit_difference(fit, *decoded, hemisphere_directions());
        *quantisation = q;
    }

    return write_file_bytes(path, bytes);
}

}  // namespace cmfilter
