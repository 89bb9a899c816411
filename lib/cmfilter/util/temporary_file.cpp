// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/temporary_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace cmfilter {

Expected<TemporaryFile> TemporaryFile::create(const std::string& stem, const std::string& extension)
{
    std::error_code ec;
    const fs::path dir = fs::temp_directory_path(ec);
    if (ec) return io_error("cannot find the temporary folder: " + ec.message());
    std::random_device entropy;
    std::string last_error;
    for (int attempt = 0; attempt < 16; ++attempt) {
        std::ostringstream name;
        name << stem << "-" << std::hex << entropy() << entropy() << extension;
        const std::string path = (dir / name.str()).string();
        // "x": fails if the file exists (C11, glibc), so the name is ours alone.
        if (std::FILE* f = std::fopen(path.c_str(), "wbx")) {
            std::fclose(f);
            TemporaryFile out;
            out.path_ = path;
            return out;
        }
        last_error = std::strerror(errno);
        if (errno != EEXIST) break;
    }
    return io_error("cannot create a temporary file in '" + dir.string() + "': " + last_error);
}

TemporaryFile::TemporaryFile(TemporaryFile&& other) noexcept : path_(std::move(other.path_)) { other.path_.clear(); }

TemporaryFile& TemporaryFile::operator=(TemporaryFile&& other) noexcept
{
    if (this != &other) {
        remove();
        path_ = std::move(other.path_);
        other.path_.clear();
    }
    return *this;
}

TemporaryFile::~TemporaryFile() { remove(); }

void TemporaryFile::remove()
{
    if (path_.empty()) return;
    std::error_code ec;
    fs::remove(path_, ec);
    path_.clear();
}

}  // namespace cmfilter
