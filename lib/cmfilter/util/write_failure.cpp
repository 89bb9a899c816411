// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/write_failure.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace cmfilter {

std::string write_failure_cause(const std::string& path)
{
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    struct statvfs disk {};
    if (statvfs(dir.c_str(), &disk) == 0) {
        // root may use the blocks reserved for it; others may not.
        const unsigned long long blocks = geteuid() == 0 ? disk.f_bfree : disk.f_bavail;
        const unsigned long long free_bytes = blocks * disk.f_frsize;
        if (free_bytes < (1ull << 20))
            return "the disk holding '" + dir.string() + "' is full (" + std::to_string(free_bytes) + " bytes free)";
    }
    struct rlimit limit {};
    struct stat file {};
    if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && stat(path.c_str(), &file) == 0 &&
        static_cast<unsigned long long>(file.st_size) >= static_cast<unsigned long long>(limit.rlim_cur))
        return "the file reached this process's file size limit of " + std::to_string(limit.rlim_cur) +
               " bytes (ulimit -f)";
    return {};
}

std::string write_failure_reason(const std::string& path, const std::string& detail)
{
    const std::string cause = write_failure_cause(path);
    if (cause.empty()) return detail.empty() ? "the write failed" : detail;
    return detail.empty() ? cause : cause + " (" + detail + ")";
}

}  // namespace cmfilter
