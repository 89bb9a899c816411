// SPDX-License-Identifier: Apache-2.0
// All-or-nothing file output: writers write to a temporary file beside the
// destination (same directory, same extension so OpenImageIO picks the same
// format) and commit() renames it into place. A writer that fails, or an
// AtomicOutput destroyed without commit(), leaves no file behind.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

class AtomicOutput {
public:
    // Fails (Io) when the destination's directory does not exist or the
    // destination is a directory.
    static Expected<AtomicOutput> begin(const std::string& destination);

    AtomicOutput(AtomicOutput&& other) noexcept;
    AtomicOutput& operator=(AtomicOutput&& other) noexcept;
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    const std::string& temp_path() const { return temp_; }
    const std::string& destination() const { return destination_; }
    Status commit();

private:
    AtomicOutput() = default;
    void discard();
    std::string destination_;
    std::string temp_;
    bool committed_ = false;
};

// Checks, before any work is done, that `path` could be written: its
// directory exists, it is not a directory, and (when extension is non-empty)
// it ends in that extension, compared case-insensitively.
Status check_output_path(const std::string& path, const std::string& extension);

// The extension of `path` with its dot, in lower case (".exr"); empty if none.
std::string lowercase_extension(const std::string& path);

}  // namespace cmfilter
