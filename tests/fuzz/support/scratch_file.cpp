// SPDX-License-Identifier: Apache-2.0
#include "scratch_file.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace cmfilter::fuzz {

namespace {

std::string& created_folder()
{
    static std::string folder;
    return folder;
}

void remove_created_folder()
{
    std::error_code ec;
    if (!created_folder().empty()) fs::remove_all(created_folder(), ec);
}

}  // namespace

std::string scratch_folder()
{
    const fs::path folder = fs::temp_directory_path() / ("cmfilter-fuzz-" + std::to_string(getpid()));
    if (created_folder() == folder.string()) return created_folder();
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) {
        std::fprintf(stderr, "cannot create the scratch folder %s: %s\n", folder.c_str(), ec.message().c_str());
        std::abort();
    }
    if (created_folder().empty()) std::atexit(remove_created_folder);
    created_folder() = folder.string();
    return created_folder();
}

std::string write_scratch_file(const std::string& name, const std::uint8_t* data, std::size_t size)
{
    const std::string path = scratch_folder() + "/" + name;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f || (size > 0 && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
        std::fprintf(stderr, "cannot write the scratch file %s\n", path.c_str());
        std::abort();
    }
    return path;
}

}  // namespace cmfilter::fuzz
