// SPDX-License-Identifier: Apache-2.0
// The memory budget (memory_budget.h): sizes parsed and written as worked
// out by hand, the budget against /proc/meminfo and the process's own
// rlimits read independently here, and CMFILTER_MEMORY_LIMIT applied and
// named in the refusal.
#include "cmfilter/util/memory_budget.h"

#include "scoped_env.h"

#include <doctest/doctest.h>

#include <sys/resource.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

using namespace cmfilter;
using cmfilter_test::ScopedEnv;

namespace {

std::uint64_t meminfo_bytes(const std::string& key)
{
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key, 0) == 0) {
            std::istringstream fields(line.substr(key.size()));
            unsigned long long kb = 0;
            fields >> kb;
            return kb * 1024ull;
        }
    return 0;
}

}  // namespace

TEST_CASE("memory budget: sizes are parsed with binary multiples and refused when malformed")
{
    CHECK(parse_byte_size("4096") == std::optional<std::uint64_t>(4096));
    CHECK(parse_byte_size("512K") == std::optional<std::uint64_t>(512ull * 1024));
    CHECK(parse_byte_size("512m") == std::optional<std::uint64_t>(512ull * 1024 * 1024));
    CHECK(parse_byte_size("2G") == std::optional<std::uint64_t>(2ull << 30));
    CHECK(parse_byte_size("2GB") == std::optional<std::uint64_t>(2ull << 30));
    CHECK(parse_byte_size("1T") == std::optional<std::uint64_t>(1ull << 40));
    for (const char* bad : {"", "0", "G", "-1", "1.5G", "2X", "12 G", "99999999999999999999"})
        CHECK_MESSAGE(!parse_byte_size(bad), bad);
}

TEST_CASE("memory budget: sizes are written in decimal units")
{
    CHECK(byte_size_text(512) == "512 B");
    CHECK(byte_size_text(1500) == "1.5 KB");
    CHECK(byte_size_text(2.0e9) == "2.0 GB");
    CHECK(byte_size_text(120.0e9) == "120 GB");
}

TEST_CASE("memory budget: never more than the machine's available memory and swap, nor the rlimits")
{
    const MemoryBudget budget = memory_budget();
    // MemAvailable moves while the test runs: allow 1 GB of slack.
    const double machine = double(meminfo_bytes("MemAvailable:") + meminfo_bytes("SwapFree:"));
    CHECK(double(budget.bytes) <= machine + 1e9);
    rlimit r{};
    if (getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY) CHECK(budget.bytes <= r.rlim_cur);
    CHECK(!budget.limit.empty());
}

TEST_CASE("memory budget: CMFILTER_MEMORY_LIMIT caps it and is named when an allocation is refused")
{
    ScopedEnv env("CMFILTER_MEMORY_LIMIT", "1M");
    const MemoryBudget budget = memory_budget();
    CHECK(budget.bytes == 1024u * 1024u);
    CHECK(budget.limit == "CMFILTER_MEMORY_LIMIT=1M");
    CHECK(check_allocation(1024.0 * 1024.0, "a buffer"));
    const auto refused = check_allocation(1e10, "'huge.exr' (100000 x 100000 pixels)");
    REQUIRE(!refused);
    CHECK(refused.error().kind == ErrorKind::BadInput);
    CHECK(refused.error().message ==
          "'huge.exr' (100000 x 100000 pixels) needs 10 GB, more than the 1.0 MB this process may allocate "
          "(CMFILTER_MEMORY_LIMIT=1M)");
    CHECK(!check_allocation(-1, "a negative size"));
}

TEST_CASE("memory budget: a CMFILTER_MEMORY_LIMIT that is not a size is an error, not ignored")
{
    ScopedEnv env("CMFILTER_MEMORY_LIMIT", "lots");
    const auto refused = check_allocation(10, "a buffer");
    REQUIRE(!refused);
    CHECK(refused.error().message.find("CMFILTER_MEMORY_LIMIT 'lots' is not a size") != std::string::npos);
}
