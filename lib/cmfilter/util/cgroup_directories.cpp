// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/cgroup_directories.h"

#include <sstream>

namespace cmfilter {

std::vector<CgroupDirectory> cgroup_directories(const std::string& proc_cgroup, const std::string& cgroup_root,
                                                const std::string& v1_controller)
{
    std::vector<CgroupDirectory> out;
    std::istringstream lines(proc_cgroup);
    for (std::string line; std::getline(lines, line);) {
        const auto a = line.find(':'), b = line.find(':', a == std::string::npos ? a : a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        const std::string controllers = line.substr(a + 1, b - a - 1);
        const bool v2 = controllers.empty();
        bool named = false;
        std::istringstream names(controllers);
        for (std::string name; std::getline(names, name, ',');) named = named || name == v1_controller;
        if (!v2 && !named) continue;
        std::string path = line.substr(b + 1);
        const std::string base = v2 ? cgroup_root : cgroup_root + "/" + controllers;
        for (;;) {
            out.push_back({base + (path == "/" ? std::string() : path), v2});
            if (path.empty() || path == "/") break;
            path = path.substr(0, path.find_last_of('/'));
            if (path.empty()) path = "/";
        }
    }
    return out;
}

}  // namespace cmfilter
