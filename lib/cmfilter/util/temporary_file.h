// SPDX-License-Identifier: Apache-2.0
// A file of the caller's own in the system's temporary folder, removed when
// its TemporaryFile is destroyed: for data a library bakes for itself but
// must hand to OpenImageIO by path (a moment pyramid that TextureSystem
// reads). The name is reserved by creating the file empty, exclusively, so
// no other process can have it; the owner then overwrites it.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

class TemporaryFile {
public:
    // <temp folder>/<stem>-<random hex><extension>, created empty. Io when
    // the temporary folder cannot be written.
    static Expected<TemporaryFile> create(const std::string& stem, const std::string& extension);

    TemporaryFile(TemporaryFile&& other) noexcept;
    TemporaryFile& operator=(TemporaryFile&& other) noexcept;
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile();

    const std::string& path() const { return path_; }

private:
    TemporaryFile() = default;
    void remove();
    std::string path_;
};

}  // namespace cmfilter
