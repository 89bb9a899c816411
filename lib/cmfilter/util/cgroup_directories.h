// SPDX-License-Identifier: Apache-2.0
// The cgroup folders whose limits bind a process, from its /proc/<pid>/cgroup
// text: for each line ("ID:CONTROLLERS:PATH"; v2 is "0::PATH", v1 names its
// controllers), when it is v2 or names `v1_controller`, its folder under
// `cgroup_root` and every folder above it up to the root, innermost first.
// Shared by available_cores.h (cpu) and memory_budget.h (memory).
#pragma once

#include <string>
#include <vector>

namespace cmfilter {

struct CgroupDirectory {
    std::string path;
    bool v2 = false;  // v2's files (cpu.max, memory.max) rather than v1's
};

std::vector<CgroupDirectory> cgroup_directories(const std::string& proc_cgroup, const std::string& cgroup_root,
                                                const std::string& v1_controller);

}  // namespace cmfilter
