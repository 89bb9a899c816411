// SPDX-License-Identifier: Apache-2.0
// The cores a process may use (available_cores.h): quotas worked out by
// hand from the cgroup files' text, a cgroup tree written here, and the
// affinity mask against the kernel's own Cpus_allowed_list in
// /proc/self/status (also run under `taskset -c 0` by ctest).
#include "cmfilter/util/available_cores.h"

#include "test_images.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace cmfilter;

namespace {

void write_file(const std::filesystem::path& path, const std::string& text)
{
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

// CPUs in a list such as "0-3,8,10-11".
int count_cpu_list(const std::string& list)
{
    int count = 0;
    std::istringstream in(list);
    for (std::string range; std::getline(in, range, ',');) {
        const auto dash = range.find('-');
        if (dash == std::string::npos) ++count;
        else count += std::stoi(range.substr(dash + 1)) - std::stoi(range.substr(0, dash)) + 1;
    }
    return count;
}

}  // namespace

TEST_CASE("available cores: cpu.max and v1 quotas in cores, rounded up, unlimited as none")
{
    CHECK_FALSE(quota_cores_from_cpu_max("max 100000\n"));
    CHECK(quota_cores_from_cpu_max("200000 100000\n") == 2);
    CHECK(quota_cores_from_cpu_max("150000 100000") == 2);
    CHECK(quota_cores_from_cpu_max("50000 100000") == 1);
    CHECK_FALSE(quota_cores_from_cpu_max(""));
    CHECK_FALSE(quota_cores_from_cpu_max("lots"));
    CHECK_FALSE(quota_cores_from_cfs("-1\n", "100000\n"));
    CHECK(quota_cores_from_cfs("300000\n", "100000\n") == 3);
    CHECK(quota_cores_from_cfs("250000", "100000") == 3);
    CHECK_FALSE(quota_cores_from_cfs("", "100000"));
}

TEST_CASE("available cores: the tightest quota on the way up a cgroup tree, v2 and v1")
{
    const std::filesystem::path root = cmfilter_test::temp_dir("cmfilter-available-cores");
    std::filesystem::remove_all(root);
    write_file(root / "v2" / "cpu.max", "max 100000\n");
    write_file(root / "v2" / "farm" / "cpu.max", "400000 100000\n");
    write_file(root / "v2" / "farm" / "slot" / "cpu.max", "200000 100000\n");
    CHECK(cgroup_quota_cores("0::/farm/slot\n", (root / "v2").string()) == 2);
    write_file(root / "v2" / "farm" / "slot" / "cpu.max", "max 100000\n");
    CHECK(cgroup_quota_cores("0::/farm/slot\n", (root / "v2").string()) == 4);
    CHECK_FALSE(cgroup_quota_cores("0::/\n", (root / "v2").string()));

    write_file(root / "v1" / "cpu,cpuacct" / "job" / "cpu.cfs_quota_us", "150000\n");
    write_file(root / "v1" / "cpu,cpuacct" / "job" / "cpu.cfs_period_us", "100000\n");
    CHECK(cgroup_quota_cores("5:memory:/job\n4:cpu,cpuacct:/job\n0::/\n", (root / "v1").string()) == 2);
    // Controllers other than cpu are not a CPU quota.
    CHECK_FALSE(cgroup_quota_cores("5:memory:/job\n", (root / "v1").string()));
    std::filesystem::remove_all(root);
}

TEST_CASE("available cores: the affinity mask is the kernel's Cpus_allowed_list")
{
    std::ifstream status("/proc/self/status");
    REQUIRE(status);
    std::string line, list;
    while (std::getline(status, line))
        if (line.rfind("Cpus_allowed_list:", 0) == 0) list = line.substr(line.find(':') + 1);
    REQUIRE_FALSE(list.empty());
    list.erase(0, list.find_first_not_of(" \t"));
    CHECK(affinity_cores() == count_cpu_list(list));
    CHECK(available_cores() >= 1);
    CHECK(available_cores() <= affinity_cores());
}
