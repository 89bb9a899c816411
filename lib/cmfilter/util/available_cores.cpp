// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/available_cores.h"

#include <sched.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <thread>

namespace cmfilter {

namespace {

std::string read_text(const std::string& path)
{
    std::ifstream in(path);
    if (!in) return {};
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

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
    std::istringstream lines(proc_cgroup);
    std::string line;
    while (std::getline(lines, line)) {
        const auto a = line.find(':'), b = line.find(':', a == std::string::npos ? a : a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        const std::string controllers = line.substr(a + 1, b - a - 1);
        std::string path = line.substr(b + 1);
        bool v1_cpu = false;
        std::istringstream names(controllers);
        for (std::string name; std::getline(names, name, ',');) v1_cpu = v1_cpu || name == "cpu";
        const bool v2 = controllers.empty();
        if (!v2 && !v1_cpu) continue;
        const std::string base = v2 ? cgroup_root : cgroup_root + "/" + controllers;
        for (;;) {
            const std::string dir = base + (path == "/" ? std::string() : path);
            if (v2) keep(quota_cores_from_cpu_max(read_text(dir + "/cpu.max")));
            else
                keep(quota_cores_from_cfs(read_text(dir + "/cpu.cfs_quota_us"), read_text(dir + "/cpu.cfs_period_us")));
            if (path.empty() || path == "/") break;
            path = path.substr(0, path.find_last_of('/'));
            if (path.empty()) path = "/";
        }
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
    if (auto quota = cgroup_quota_cores(read_text("/proc/self/cgroup"), "/sys/fs/cgroup"))
        cores = std::min(cores, *quota);
    return std::max(1, cores);
}

}  // namespace cmfilter
