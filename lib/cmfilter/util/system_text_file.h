// SPDX-License-Identifier: Apache-2.0
// The whole text of a small file the system keeps (/proc/self/status,
// /proc/meminfo, a cgroup's cpu.max or memory.max): empty when it cannot be
// read, for readers that treat a missing file as "no limit".
#pragma once

#include <string>

namespace cmfilter {

std::string read_system_text_file(const std::string& path);

}  // namespace cmfilter
