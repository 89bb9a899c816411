// SPDX-License-Identifier: Apache-2.0
// The cores this process may use, as a farm slot restricts them: the CPUs of
// its affinity mask (sched_getaffinity, as `taskset` and Slurm's cpusets set
// it), capped by its cgroup's CPU quota (cgroup v2 cpu.max "QUOTA PERIOD",
// v1 cpu.cfs_quota_us / cpu.cfs_period_us), rounded up; at least 1. What
// `--threads 0` means (parallel_for.h).
#pragma once

#include <optional>
#include <string>

namespace cmfilter {

int available_cores();

// The parts, for tests and for a caller that knows better where to look.
int affinity_cores();  // CPUs in the affinity mask; hardware_concurrency when it cannot be read
// The CPU quota in cores (rounded up) that the cgroup files under
// `cgroup_root` set for the process whose /proc/<pid>/cgroup text is
// `proc_cgroup`; none when unlimited or unreadable.
std::optional<int> cgroup_quota_cores(const std::string& proc_cgroup, const std::string& cgroup_root);
// From the text of cpu.max ("max 100000" or "200000 100000"), or of v1's
// quota and period files; none when unlimited or malformed.
std::optional<int> quota_cores_from_cpu_max(const std::string& cpu_max);
std::optional<int> quota_cores_from_cfs(const std::string& quota_us, const std::string& period_us);

}  // namespace cmfilter
