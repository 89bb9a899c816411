// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/available_cores.h"

#include "cmfilter/util/cgroup_directories.h"
#include "cmfilter/util/system_text_file.h"

#include <sched.h>

#include <algorithm>
#include <sstream>
#include <thread>

namespace cmfilter {

namespace {

std::optional<long long> parse_integer(const std::string& text)
{
    std::istringstream in(text);
    long long value = 0;
    if (!(in >> value)) return std::nullopt;
    return value;
}

std::optional<int> cores_from(long long quota, long long period)
{
    if (quota <= 0 || period <= 0) return std::nullopt;
    return static_cast<int>(std::max<long long>(1, (quota + period - 1) / period));
}

}  // namespace

std::optional<int> quota_cores_from_cpu_max(const std::string& cpu_max)
{
    std::istringstream in(cpu_max);
    std::string quota;
    long long period = 0;
    if (!(in >> quota >> period) || quota == "max") return std::nullopt;
    auto q = parse_integer(quota);
    if (!q) return std::nullopt;
    return cores_from(*q, period);
}

std::optional<int> quota_cores_from_cfs(const std::string& quota_us, const std::string& period_us)
{
    auto q = parse_integer(quota_us), p = parse_integer(period_us);
    if (!q || !p) return std::nullopt;
    return cores_from(*q, *p);  // a quota of -1 is unlimited
}

std::optional<int> cgroup_quota_cores(const std::string& proc_cgroup, const std::string& cgroup_root)
{
    // Lines "ID:CONTROLLERS:PATH": v2 is "0::PATH"; v1 names "cpu" among
    // its controllers. The tightest quota on the way up the hierarchy wins.
    std::optional<int> tightest;
    auto keep = [&](std::optional<int> cores) {
        if (cores && (!tightest || *cores < *tightest)) tightest = cores;
    };
    for (const CgroupDirectory& dir : cgroup_directories(proc_cgroup, cgroup_root, "cpu")) {
        if (dir.v2) keep(quota_cores_from_cpu_max(read_system_text_file(dir.path + "/cpu.max")));
        else
            keep(quota_cores_from_cfs(read_system_text_file(dir.path + "/cpu.cfs_quota_us"),
                                      read_system_text_file(dir.path + "/cpu.cfs_period_us")));
    }
    return tightest;
}

int affinity_cores()
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        const int count = CPU_COUNT(&set);
        if (count > 0) return count;
    }
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

int available_cores()
{
    int cores = affinity_cores();
    if (auto quota = cgroup_quota_cores(read_system_text_file("/proc/self/cgroup"), "/sys/fs/cgroup"))
        cores = std::min(cores, *quota);
    return std::max(1, cores);
}

}  // namespace cmfilter
