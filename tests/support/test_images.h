// SPDX-License-Identifier: Apache-2.0
// Helpers for unit tests that read image files: a scratch directory per test
// file, and writing pixels (optionally tagged with a colour space) with
// OpenImageIO.
#pragma once

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

namespace cmfilter_test {

// A directory under the system temporary directory, created if needed.
inline std::string temp_dir(const std::string& name)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::create_directories(dir);
    return dir.string();
}

// Whether two paths name the same file, lexically (as cmfilter records the
// paths of its inputs relative to its outputs and resolves them back).
inline bool same_file_path(const std::string& a, const std::string& b)
{
    return std::filesystem::absolute(a).lexically_normal() == std::filesystem::absolute(b).lexically_normal();
}

inline void write_image(const std::string& path, int w, int h, int ch, OIIO::TypeDesc type, const void* data,
                        const char* colorspace = nullptr)
{
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    OIIO::ImageSpec spec(w, h, ch, type);
    if (colorspace) spec.attribute("colorInteropID", colorspace);
    REQUIRE(out->open(path, spec));
    REQUIRE(out->write_image(type, data));
    REQUIRE(out->close());
}

}  // namespace cmfilter_test
