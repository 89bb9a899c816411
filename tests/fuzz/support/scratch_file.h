// SPDX-License-Identifier: Apache-2.0
// The harnesses' one file on disk: readers that take a path get the fuzz
// input written to <temp folder>/cmfilter-fuzz-<pid>/<name>, rewritten for
// every input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace cmfilter::fuzz {

// Writes data to the scratch file called `name` and returns its path.
std::string write_scratch_file(const std::string& name, const std::uint8_t* data, std::size_t size);

// The scratch folder (created on first use).
std::string scratch_folder();

}  // namespace cmfilter::fuzz
