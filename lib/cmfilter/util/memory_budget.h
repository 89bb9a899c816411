// SPDX-License-Identifier: Apache-2.0
// The memory this process may still allocate, as a farm slot or a shell
// limits it, so that an input declaring a huge size (an image header
// claiming 10^5 x 10^5 pixels, a scene asking for the largest resolution) is
// refused before the allocation, with the limit named, instead of taking
// the machine down or dying half-way. The budget is the smallest of:
//   - CMFILTER_MEMORY_LIMIT, when set (bytes, or with a K, M, G or T suffix:
//     "512M", "8G"), the cap a pipeline gives cmfilter itself;
//   - the address-space limit (`ulimit -v`, RLIMIT_AS) less what is mapped;
//   - the data limit (`ulimit -d`, RLIMIT_DATA) less the data in use;
//   - the cgroup's memory.max (v2) or memory.limit_in_bytes (v1) less its
//     usage, as a container or a Slurm job sets it;
//   - the machine's available memory and free swap (/proc/meminfo).
#pragma once

#include "cmfilter/util/error.h"

#include <cstdint>
#include <optional>
#include <string>

namespace cmfilter {

struct MemoryBudget {
    std::uint64_t bytes = 0;  // what may still be allocated
    std::string limit;        // what sets it, for messages ("the address-space limit (ulimit -v) of 2.0 GB")
    std::string error;        // CMFILTER_MEMORY_LIMIT set but not a size (then it is not applied)
};

MemoryBudget memory_budget();

// BadInput unless `bytes` fit in the memory budget (or when
// CMFILTER_MEMORY_LIMIT is not a size): "<what> needs <size>,
// more than the <budget> this process may allocate (<limit>)". `what`
// names the file or the option and the sizes it declares.
Status check_allocation(double bytes, const std::string& what);

// "512 B", "1.5 KB", "2.0 GB": decimal units, two or three significant digits.
std::string byte_size_text(double bytes);

// "4096", "512K", "512M", "2G", "1T" (binary multiples, case-insensitive, an
// optional trailing B); none when malformed or zero.
std::optional<std::uint64_t> parse_byte_size(const std::string& text);

}  // namespace cmfilter
