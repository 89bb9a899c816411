// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/memory_budget.h"

#include "cmfilter/util/cgroup_directories.h"
#include "cmfilter/util/system_text_file.h"

#include <sys/resource.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace cmfilter {

namespace {

// The value in kB of `key` ("VmSize:") in /proc's status-style text, in bytes.
std::optional<std::uint64_t> kb_field(const std::string& text, const std::string& key)
{
    const auto at = text.find(key);
    if (at == std::string::npos) return std::nullopt;
    std::istringstream in(text.substr(at + key.size()));
    unsigned long long kb = 0;
    if (!(in >> kb)) return std::nullopt;
    return static_cast<std::uint64_t>(kb) * 1024;
}

std::optional<std::uint64_t> integer_file(const std::string& path)
{
    std::istringstream in(read_system_text_file(path));
    unsigned long long v = 0;
    if (!(in >> v)) return std::nullopt;  // also "max"
    return static_cast<std::uint64_t>(v);
}

std::uint64_t less(std::uint64_t limit, std::optional<std::uint64_t> used)
{
    const std::uint64_t u = used.value_or(0);
    return limit > u ? limit - u : 0;
}

// memory.max / memory.limit_in_bytes less usage, up the cgroup hierarchy of
// /proc/self/cgroup; the tightest.
std::optional<std::uint64_t> cgroup_remaining()
{
    std::optional<std::uint64_t> tightest;
    for (const CgroupDirectory& dir :
         cgroup_directories(read_system_text_file("/proc/self/cgroup"), "/sys/fs/cgroup", "memory")) {
        const auto limit = integer_file(dir.path + (dir.v2 ? "/memory.max" : "/memory.limit_in_bytes"));
        // v1 writes "no limit" as a huge number (2^63 rounded to pages).
        if (limit && *limit < (std::uint64_t(1) << 60)) {
            const std::uint64_t left =
                less(*limit, integer_file(dir.path + (dir.v2 ? "/memory.current" : "/memory.usage_in_bytes")));
            if (!tightest || left < *tightest) tightest = left;
        }
    }
    return tightest;
}

}  // namespace

std::string byte_size_text(double bytes)
{
    const char* units[] = {"B", "KB", "MB", "GB", "TB", "PB", "EB"};
    int u = 0;
    while (bytes >= 1000 && u < 6) {
        bytes /= 1000;
        ++u;
    }
    char text[32];
    if (u == 0) std::snprintf(text, sizeof text, "%.0f B", bytes);
    else std::snprintf(text, sizeof text, bytes < 10 ? "%.1f %s" : "%.0f %s", bytes, units[u]);
    return text;
}

std::optional<std::uint64_t> parse_byte_size(const std::string& text)
{
    std::size_t digits = 0;
    while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
    if (digits == 0 || digits > 15) return std::nullopt;
    std::uint64_t value = std::stoull(text.substr(0, digits));
    std::string suffix = text.substr(digits);
    for (char& c : suffix) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (suffix.size() > 1 && suffix.back() == 'B') suffix.pop_back();
    int shift = 0;
    if (suffix == "K") shift = 10;
    else if (suffix == "M") shift = 20;
    else if (suffix == "G") shift = 30;
    else if (suffix == "T") shift = 40;
    else if (!suffix.empty() && suffix != "B") return std::nullopt;
    if (value == 0 || value > (std::numeric_limits<std::uint64_t>::max() >> shift)) return std::nullopt;
    return value << shift;
}

MemoryBudget memory_budget()
{
    MemoryBudget budget;
    budget.bytes = std::numeric_limits<std::uint64_t>::max();
    budget.limit = "no limit";
    const auto keep = [&](std::uint64_t bytes, const std::string& limit) {
        if (bytes < budget.bytes) {
            budget.bytes = bytes;
            budget.limit = limit;
        }
    };
    const std::string status = read_system_text_file("/proc/self/status");
    rlimit r{};
    if (getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
        keep(less(r.rlim_cur, kb_field(status, "VmSize:")),
             "the address-space limit (ulimit -v) of " + byte_size_text(double(r.rlim_cur)));
    if (getrlimit(RLIMIT_DATA, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
        keep(less(r.rlim_cur, kb_field(status, "VmData:")),
             "the data limit (ulimit -d) of " + byte_size_text(double(r.rlim_cur)));
    if (auto left = cgroup_remaining()) keep(*left, "the memory limit of this process's cgroup");
    const std::string meminfo = read_system_text_file("/proc/meminfo");
    if (auto available = kb_field(meminfo, "MemAvailable:"))
        keep(*available + kb_field(meminfo, "SwapFree:").value_or(0), "the memory this machine has available");
    if (const char* env = std::getenv("CMFILTER_MEMORY_LIMIT")) {
        if (auto cap = parse_byte_size(env)) keep(*cap, std::string("CMFILTER_MEMORY_LIMIT=") + env);
        else
            budget.error = std::string("CMFILTER_MEMORY_LIMIT '") + env +
                           "' is not a size (expected bytes, or a number with K, M, G or T: 512M, 8G)";
    }
    return budget;
}

Status check_allocation(double bytes, const std::string& what)
{
    const MemoryBudget budget = memory_budget();
    if (!budget.error.empty()) return bad_input(budget.error);
    if (!(bytes >= 0) || bytes > static_cast<double>(budget.bytes))
        return bad_input(what + " needs " + byte_size_text(bytes) + ", more than the " +
                         byte_size_text(static_cast<double>(budget.bytes)) + " this process may allocate (" +
                         budget.limit + ")");
    return ok();
}

}  // namespace cmfilter
