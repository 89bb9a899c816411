// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/stale_temporary_outputs.h"

#include "cmfilter/util/temporary_output_name.h"

#include <signal.h>
#include <sys/stat.h>

#include <cerrno>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace cmfilter {

bool process_is_alive(long pid)
{
    if (pid <= 0) return false;
    return kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

namespace {

// Whether a temporary of `writer` at `path` (as lstat sees it: a link is not
// followed) is stale; one that cannot be looked at is not.
bool is_stale(const fs::path& path, const TemporaryOutputWriter& writer, const std::string& host,
              std::chrono::hours max_age)
{
    if (writer.host == host) return !process_is_alive(writer.pid);
    struct stat st {};
    if (lstat(path.c_str(), &st) != 0) return false;
    const auto age = std::chrono::system_clock::now() - std::chrono::system_clock::from_time_t(st.st_mtime);
    return age > max_age;
}

}  // namespace

Expected<std::vector<std::string>> remove_stale_temporary_outputs(const StaleTemporaryOptions& options)
{
    const fs::path destination(options.destination);
    fs::path dir = destination.parent_path();
    if (dir.empty()) dir = ".";
    const std::string destination_name = destination.filename().string();
    const std::string host = local_host_name();
    std::vector<std::string> removed;
    // Listed first, removed after: the listing is not changed under it.
    std::vector<fs::path> stale;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::path& path = it->path();
        const auto writer = parse_temporary_output_name(path.filename().string(), destination_name);
        if (writer && is_stale(path, *writer, host, options.max_age)) stale.push_back(path);
    }
    if (ec) return io_error("cannot list '" + dir.string() + "': " + ec.message());
    for (const fs::path& path : stale) {
        std::error_code removing;
        if (fs::symlink_status(path, removing).type() == fs::file_type::directory) fs::remove_all(path, removing);
        else fs::remove(path, removing);
        if (!removing) removed.push_back(path.string());
    }
    return removed;
}

}  // namespace cmfilter
