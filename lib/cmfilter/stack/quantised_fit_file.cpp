// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/quantised_fit_file.h"

#include "cmfilter/util/atomic_output.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace cmfilter {

Status check_writable_fit(const std::string& path, const LinearFit& fit, const QuantisedFitFormat& format)
{
    const std::string where = "cannot write '" + path + "' as " + format.name + ": ";
    const std::string holder = format.holder, encoded_holder = format.encoded_holder;
    if (fit.model != format.models[0] && fit.model != format.models[1])
        return bad_input(where + "the fit's model is " + to_string(fit.model) + "; " + holder + " holds " +
                         to_string(format.models[0]) + " or " + to_string(format.models[1]));
    if (fit.channels != 3)
        return bad_input(where + "the fit has " + std::to_string(fit.channels) + " channel(s); " + holder +
                         " holds 3 (RGB)");
    if (fit.encoding != StackEncoding::DisplayEncoded)
        return bad_input(where + "the fit is of scene-linear values; " + encoded_holder +
                         " holds display-encoded ones (fit the stack with its values display-encoded)");
    if (fit.width <= 0 || fit.height <= 0 || fit.width > format.max_side || fit.height > format.max_side)
        return bad_input(where + "its size " + std::to_string(fit.width) + " x " + std::to_string(fit.height) +
                         " is not within 1 .. " + std::to_string(format.max_side));
    if (fit.coefficients.size() != fit.texels() * fit.stride())
        return bad_input(where + "it holds " + std::to_string(fit.coefficients.size()) + " coefficients, not " +
                         std::to_string(fit.texels() * fit.stride()));
    for (std::size_t i = 0; i < fit.coefficients.size(); ++i)
        if (!std::isfinite(fit.coefficients[i])) {
            const std::size_t t = i / fit.stride();
            return bad_input(where + "texel (" + std::to_string(t % fit.width) + ", " + std::to_string(t / fit.width) +
                             ") has a non-finite coefficient");
        }
    return ok();
}

bool ByteCursor::line(std::string& out)
{
    if (at_end()) return false;
    const std::size_t end = bytes.find('\n', pos);
    out = bytes.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    pos = end == std::string::npos ? bytes.size() : end + 1;
    while (!out.empty() && (out.back() == '\r' || out.back() == ' ' || out.back() == '\t')) out.pop_back();
    return true;
}

bool ByteCursor::token(std::string& out)
{
    while (!at_end() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    if (at_end()) return false;
    const std::size_t start = pos;
    while (!at_end() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    out = bytes.substr(start, pos - start);
    return true;
}

bool ByteCursor::end_of_line()
{
    while (!at_end() && (bytes[pos] == ' ' || bytes[pos] == '\t' || bytes[pos] == '\r')) ++pos;
    if (at_end() || bytes[pos] != '\n') return false;
    ++pos;
    return true;
}

std::string quoted_header(const std::string& text)
{
    std::string q;
    for (char c : text.substr(0, 40)) q += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if (text.size() > 40) q += "...";
    return "'" + q + "'";
}

bool parse_integer_token(const std::string& token, long long& value)
{
    if (token.empty()) return false;
    errno = 0;
    char* end = nullptr;
    value = std::strtoll(token.c_str(), &end, 10);
    return errno == 0 && end == token.c_str() + token.size();
}

Expected<std::string> read_file_bytes(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) return io_error("cannot open '" + path + "' for reading");
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (file.bad()) return io_error("cannot read '" + path + "'");
    return bytes;
}

Status write_file_bytes(const std::string& path, const std::string& bytes)
{
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    {
        std::ofstream file(out->temp_path(), std::ios::binary);
        if (!file) return out->write_error("cannot open its temporary file '" + out->temp_path() + "'");
        file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        file.close();
        if (!file) return out->write_error("");
    }
    return out->commit();
}

}  // namespace cmfilter
