// SPDX-License-Identifier: Apache-2.0
// Hand-made .ptm and .rti files for the interchange tests, written byte by
// byte from their documented layouts (the PTM 1.2 format document; HSH
// .rti as RTIViewer reads it) without the library's writers, and a
// test-side parser of the header and coefficient bytes the writers produce.
#pragma once

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace cmfilter_test {

inline void write_bytes(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    REQUIRE(out);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    REQUIRE(out);
}

inline std::string read_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// ------------------------------------------------------------------ .ptm

// A PTM 1.2 header as text: the version and format lines, width and height
// (separated by `size_separator`: "\n" as the viewers write, " " as the
// format document allows), the scales line and the biases line, each line
// ended by `newline`.
inline std::string ptm_header_text(const std::string& format, int width, int height, const std::string& scales,
                                   const std::string& biases, const std::string& size_separator = "\n",
                                   const std::string& newline = "\n")
{
    return "PTM_1.2" + newline + format + newline + std::to_string(width) + size_separator + std::to_string(height) +
           newline + scales + newline + biases + newline;
}

// The coefficient bytes of a PTM_FORMAT_RGB file: three planes (R, G, B),
// each every pixel's six bytes a0..a5, rows bottom to top. `byte(c, x, y,
// k)` gives the byte of channel c, term k at image column x, row y (row 0
// the top).
inline std::string ptm_rgb_bytes(int width, int height, const std::function<int(int, int, int, int)>& byte)
{
    std::string data;
    for (int c = 0; c < 3; ++c)
        for (int y = height - 1; y >= 0; --y)
            for (int x = 0; x < width; ++x)
                for (int k = 0; k < 6; ++k) data.push_back(static_cast<char>(byte(c, x, y, k)));
    return data;
}

// The bytes of a PTM_FORMAT_LRGB file: every pixel's six luminance bytes
// (`lum(x, y, k)`), rows bottom to top, then every pixel's R G B
// (`rgb(x, y, c)`), rows bottom to top.
inline std::string ptm_lrgb_bytes(int width, int height, const std::function<int(int, int, int)>& lum,
                                  const std::function<int(int, int, int)>& rgb)
{
    std::string data;
    for (int y = height - 1; y >= 0; --y)
        for (int x = 0; x < width; ++x)
            for (int k = 0; k < 6; ++k) data.push_back(static_cast<char>(lum(x, y, k)));
    for (int y = height - 1; y >= 0; --y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) data.push_back(static_cast<char>(rgb(x, y, c)));
    return data;
}

// A .ptm's header and bytes as the format document defines them, parsed
// independently of the library's reader (for checking its writer).
struct ParsedPtm {
    std::string version, format;
    int width = 0, height = 0;
    double scales[6] = {};
    double biases[6] = {};  // as written; integers
    bool biases_integral = true;
    std::string data;  // the bytes after the header
};

inline ParsedPtm parse_ptm_by_hand(const std::string& bytes)
{
    ParsedPtm p;
    std::istringstream in(bytes);
    std::getline(in, p.version);
    std::getline(in, p.format);
    std::string line;
    std::getline(in, line);
    p.width = std::stoi(line);
    std::getline(in, line);
    p.height = std::stoi(line);
    std::getline(in, line);
    {
        std::istringstream s(line);
        for (double& v : p.scales) REQUIRE(static_cast<bool>(s >> v));
        std::string extra;
        const bool more = static_cast<bool>(s >> extra);
        CHECK_FALSE(more);
    }
    std::getline(in, line);
    {
        std::istringstream s(line);
        for (double& v : p.biases) {
            std::string token;
            REQUIRE(static_cast<bool>(s >> token));
            p.biases_integral = p.biases_integral && token.find_first_not_of("-0123456789") == std::string::npos;
            v = std::stod(token);
        }
        std::string extra;
        const bool more = static_cast<bool>(s >> extra);
        CHECK_FALSE(more);
    }
    p.data = bytes.substr(static_cast<std::size_t>(in.tellg()));
    return p;
}

// ------------------------------------------------------------------ .rti

inline void append_float_le(std::string& out, float v)
{
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    out.push_back(static_cast<char>(u & 0xff));
    out.push_back(static_cast<char>((u >> 8) & 0xff));
    out.push_back(static_cast<char>((u >> 16) & 0xff));
    out.push_back(static_cast<char>((u >> 24) & 0xff));
}

inline float float_le_at(const std::string& bytes, std::size_t pos)
{
    const std::uint32_t u = std::uint32_t(static_cast<unsigned char>(bytes[pos])) |
                            std::uint32_t(static_cast<unsigned char>(bytes[pos + 1])) << 8 |
                            std::uint32_t(static_cast<unsigned char>(bytes[pos + 2])) << 16 |
                            std::uint32_t(static_cast<unsigned char>(bytes[pos + 3])) << 24;
    float v;
    std::memcpy(&v, &u, 4);
    return v;
}

// An HSH .rti: "#HSH1.2", `comments` (each a line beginning '#'), the RTI
// type 3, "width height 3", "terms 2 1", the float32 scales and biases
// (little-endian), then `byte(x, y, c, k)` for rows top to bottom, pixels
// left to right, bands R G B, terms 0 .. terms-1.
inline std::string hsh_rti_bytes(int width, int height, int terms, const std::vector<float>& scales,
                                 const std::vector<float>& biases, const std::function<int(int, int, int, int)>& byte,
                                 const std::vector<std::string>& comments = {}, const std::string& newline = "\n")
{
    std::string out = "#HSH1.2" + newline;
    for (const std::string& c : comments) out += c + newline;
    out += "3" + newline + std::to_string(width) + " " + std::to_string(height) + " 3" + newline +
           std::to_string(terms) + " 2 1" + newline;
    for (float s : scales) append_float_le(out, s);
    for (float b : biases) append_float_le(out, b);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < terms; ++k) out.push_back(static_cast<char>(byte(x, y, c, k)));
    return out;
}

}  // namespace cmfilter_test
