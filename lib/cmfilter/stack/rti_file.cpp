// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/rti_file.h"

#include "cmfilter/stack/quantised_fit_file.h"
#include "cmfilter/stack/relit_difference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace cmfilter {

namespace {

constexpr int kRtiMaxSide = 65536;

constexpr QuantisedFitFormat kRtiFormat = {
    ".rti", "an HSH .rti", "an .rti", {LinearModel::Hsh2, LinearModel::Hsh3}, kRtiMaxSide};

// ---------------------------------------------------------------- bytes

void put_float_le(std::string& out, float v)
{
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((u >> (8 * i)) & 0xffu));
}

float get_float_le(const unsigned char* p)
{
    std::uint32_t u = 0;
    for (int i = 0; i < 4; ++i) u |= std::uint32_t(p[i]) << (8 * i);
    float v;
    std::memcpy(&v, &u, sizeof v);
    return v;
}

// ---------------------------------------------------------------- reading

// The line's whitespace-separated integers; false unless there are exactly `count`.
bool line_integers(const std::string& line, int count, std::vector<long long>& values)
{
    std::istringstream in(line);
    std::string token;
    values.clear();
    while (in >> token) {
        long long v;
        if (!parse_integer_token(token, v)) return false;
        values.push_back(v);
    }
    return static_cast<int>(values.size()) == count;
}

}  // namespace

Expected<LinearFit> decode_rti(const std::string& bytes, const std::string& name)
{
    const std::string where = "'" + name + "' ";
    ByteCursor in{bytes};
    std::string line;
    in.line(line);
    if (line.rfind("#HSH1.2", 0) != 0)
        return bad_input(where + "is not an HSH .rti file: its first line is " + quoted_header(line) +
                         ", expected #HSH1.2");
    do {
        if (!in.line(line)) return bad_input(where + "ends before its RTI type line");
    } while (!line.empty() && line[0] == '#');

    std::vector<long long> v;
    if (!line_integers(line, 1, v))
        return bad_input(where + "has RTI type line " + quoted_header(line) + ", expected 3 (HSH)");
    if (v[0] != 3) {
        const char* names[] = {"reserved", "PTM", "SH", "HSH", "adaptive basis"};
        const std::string kind = v[0] >= 0 && v[0] <= 4 ? std::string(" (") + names[v[0]] + ")" : std::string();
        return bad_input(where + "is of RTI type " + std::to_string(v[0]) + kind +
                         ", which cmfilter does not support; it reads HSH (3)");
    }
    if (!in.line(line)) return bad_input(where + "ends before its size line (width height bands)");
    if (!line_integers(line, 3, v))
        return bad_input(where + "has size line " + quoted_header(line) +
                         ", expected three integers: width height bands");
    for (int i = 0; i < 2; ++i)
        if (v[i] < 1 || v[i] > kRtiMaxSide)
            return bad_input(where + "has " + (i == 0 ? "width " : "height ") + std::to_string(v[i]) +
                             ", expected an integer in 1 .. " + std::to_string(kRtiMaxSide));
    if (v[2] != 3) return bad_input(where + "has " + std::to_string(v[2]) + " bands; cmfilter reads 3 (RGB)");
    LinearFit fit;
    fit.width = static_cast<int>(v[0]);
    fit.height = static_cast<int>(v[1]);
    fit.channels = 3;
    fit.encoding = StackEncoding::DisplayEncoded;
    fit.colorspace = "sRGB";

    if (!in.line(line)) return bad_input(where + "ends before its basis line (terms basis-type element-size)");
    if (!line_integers(line, 3, v))
        return bad_input(where + "has basis line " + quoted_header(line) +
                         ", expected three integers: terms basis-type element-size");
    if (v[0] == 4) {
        fit.model = LinearModel::Hsh2;
    } else if (v[0] == 9) {
        fit.model = LinearModel::Hsh3;
    } else {
        return bad_input(where + "has " + std::to_string(v[0]) +
                         " terms; cmfilter reads HSH of order 2 (4 terms) and 3 (9 terms)");
    }
    if (v[2] != 1)
        return bad_input(where + "has element size " + std::to_string(v[2]) + "; cmfilter reads 1-byte coefficients");

    const int terms = fit.terms();
    const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data());
    std::size_t pos = in.pos;
    const std::size_t available = pos < bytes.size() ? bytes.size() - pos : 0;
    const std::size_t header_floats = 2 * static_cast<std::size_t>(terms) * 4;
    if (available < header_floats)
        return bad_input(where + "is truncated: expected " + std::to_string(header_floats) +
                         " bytes of scales and biases, found " + std::to_string(available));
    float scale[kMaxLinearTerms], bias[kMaxLinearTerms];
    for (int k = 0; k < terms; ++k) scale[k] = get_float_le(data + pos + 4 * k);
    for (int k = 0; k < terms; ++k) bias[k] = get_float_le(data + pos + 4 * (terms + k));
    for (int k = 0; k < terms; ++k) {
        if (!std::isfinite(scale[k])) return bad_input(where + "has a non-finite scale for term " + std::to_string(k));
        if (!std::isfinite(bias[k])) return bad_input(where + "has a non-finite bias for term " + std::to_string(k));
        // A coefficient is byte / 255 * scale + bias: it must stay a finite float.
        if (!(std::fabs(double(scale[k])) + std::fabs(double(bias[k])) <= std::numeric_limits<float>::max()))
            return bad_input(where + "has a scale and bias for term " + std::to_string(k) +
                             " whose coefficients overflow a 32-bit float");
    }
    pos += header_floats;

    const std::size_t texels = fit.texels();
    const std::size_t needed = texels * 3 * terms;
    const std::size_t found = bytes.size() - pos;
    if (found < needed)
        return bad_input(where + "is truncated: expected " + std::to_string(needed) + " bytes of coefficients (" +
                         std::to_string(fit.width) + " x " + std::to_string(fit.height) + " x 3 bands x " +
                         std::to_string(terms) + " terms), found " + std::to_string(found));

    // Rows top to bottom; per pixel the bands, per band the terms: the
    // LinearFit's own order ([c * terms + k]).
    fit.coefficients.resize(needed);
    const unsigned char* b = data + pos;
    for (std::size_t i = 0; i < needed; ++i) {
        const int k = static_cast<int>(i % terms);
        fit.coefficients[i] = static_cast<float>(b[i] / 255.0 * scale[k] + bias[k]);
    }
    return fit;
}

Expected<LinearFit> read_rti(const std::string& path)
{
    auto bytes = read_file_bytes(path);
    if (!bytes) return bytes.error();
    return decode_rti(*bytes, path);
}

Status write_rti(const std::string& path, const LinearFit& fit, RtiQuantisation* quantisation)
{
    if (auto checked = check_writable_fit(path, fit, kRtiFormat); !checked) return checked.error();
    const int terms = fit.terms();
    float scale[kMaxLinearTerms], bias[kMaxLinearTerms];
    for (int k = 0; k < terms; ++k) {
        double lo = fit.coefficients[k], hi = lo;
        for (std::size_t i = k; i < fit.coefficients.size(); i += terms) {
            lo = std::min(lo, double(fit.coefficients[i]));
            hi = std::max(hi, double(fit.coefficients[i]));
        }
        bias[k] = static_cast<float>(lo);
        scale[k] = hi > lo ? static_cast<float>(hi - lo) : 1.0f;
    }

    std::ostringstream header;
    header << "#HSH1.2\n3\n" << fit.width << " " << fit.height << " 3\n" << terms << " 2 1\n";
    std::string bytes = header.str();
    for (int k = 0; k < terms; ++k) put_float_le(bytes, scale[k]);
    for (int k = 0; k < terms; ++k) put_float_le(bytes, bias[k]);
    bytes.reserve(bytes.size() + fit.coefficients.size());
    for (std::size_t i = 0; i < fit.coefficients.size(); ++i) {
        const int k = static_cast<int>(i % terms);
        const double q = (double(fit.coefficients[i]) - bias[k]) / scale[k] * 255.0;
        bytes.push_back(static_cast<char>(std::lround(std::clamp(q, 0.0, 255.0))));
    }

    if (quantisation) {
        auto decoded = decode_rti(bytes, path);
        if (!decoded)
            return runtime_error("the .rti written for '" + path + "' does not decode: " + decoded.error().message);
        RtiQuantisation q;
        q.terms = terms;
        for (int k = 0; k < terms; ++k) {
            q.scales[k] = scale[k];
            q.biases[k] = bias[k];
        }
        for (std::size_t i = 0; i < fit.coefficients.size(); ++i) {
            const int k = static_cast<int>(i % terms);
            q.max_coefficient_error[k] =
                std::max(q.max_coefficient_error[k], std::abs(double(decoded->coefficients[i]) - fit.coefficients[i]));
        }
        q.max_value_error = max_relit_difference(fit, *decoded, hemisphere_directions());
        *quantisation = q;
    }

    return write_file_bytes(path, bytes);
}

}  // namespace cmfilter
