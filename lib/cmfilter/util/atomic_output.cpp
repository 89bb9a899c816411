// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/atomic_output.h"

#include "cmfilter/util/stale_temporary_outputs.h"
#include "cmfilter/util/temporary_output_name.h"
#include "cmfilter/util/write_failure.h"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace cmfilter {

Expected<AtomicOutput> AtomicOutput::begin(const std::string& destination)
{
    if (destination.empty()) return bad_input("the output path is empty");
    const fs::path dest(destination);
    fs::path dir = dest.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        return io_error("cannot write '" + destination + "': '" + dir.string() + "' is not a directory");
    if (!fs::is_directory(dir, ec))
        return io_error("cannot write '" + destination + "': directory '" + dir.string() + "' does not exist");
    if (fs::is_directory(dest, ec)) return io_error("cannot write '" + destination + "': it is a directory");
    // Found before any work is done rather than when the writer opens its
    // temporary (root passes: permissions do not stop it).
    if (access(dir.c_str(), W_OK | X_OK) != 0)
        return io_error("cannot write '" + destination + "': directory '" + dir.string() +
                        "' is not writable: " + std::strerror(errno));

    // Leftovers of writers that were killed: best effort, a directory that
    // cannot be listed is no reason not to write.
    StaleTemporaryOptions stale;
    stale.destination = destination;
    (void)remove_stale_temporary_outputs(stale);

    AtomicOutput out;
    out.destination_ = destination;
    out.temp_ = (dir / new_temporary_output_name(dest.filename().string())).string();
    return out;
}

namespace {

// The outcome of fsync()ing a path: whether it could be opened, and the
// reason it could not be opened or synced (empty when it was synced).
struct SyncResult {
    bool opened = false;
    std::string failure;
};

// fsync()s what `path` names, opened read-only with `flags` added. A file
// system that cannot sync (EINVAL) counts as synced.
SyncResult sync_to_disk(const std::string& path, int flags)
{
    int fd;
    do fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
    while (fd < 0 && errno == EINTR);
    if (fd < 0) return {false, std::string("cannot open it: ") + std::strerror(errno)};
    const int synced = fsync(fd);
    const int fsync_errno = errno;
    close(fd);
    if (synced != 0 && fsync_errno != EINVAL) return {true, std::strerror(fsync_errno)};
    return {true, {}};
}

}  // namespace

std::string lowercase_extension(const std::string& path)
{
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

Status check_output_path(const std::string& path, const std::string& extension)
{
    if (!extension.empty()) {
        if (lowercase_extension(path) != extension)
            return bad_input("output '" + path + "' has the wrong extension (expected a " + extension + " file)");
    }
    auto probe = AtomicOutput::begin(path);
    if (!probe) return probe.error();
    return ok();
}

AtomicOutput::AtomicOutput(AtomicOutput&& other) noexcept
    : destination_(std::move(other.destination_)), temp_(std::move(other.temp_)), committed_(other.committed_)
{
    other.temp_.clear();
}

AtomicOutput& AtomicOutput::operator=(AtomicOutput&& other) noexcept
{
    if (this != &other) {
        discard();
        destination_ = std::move(other.destination_);
        temp_ = std::move(other.temp_);
        committed_ = other.committed_;
        other.temp_.clear();
    }
    return *this;
}

AtomicOutput::~AtomicOutput() { discard(); }

void AtomicOutput::discard()
{
    if (!committed_ && !temp_.empty()) {
        std::error_code ec;
        fs::remove(temp_, ec);
        temp_.clear();
    }
}

Error AtomicOutput::write_error(const std::string& detail) const
{
    return io_error("cannot write '" + destination_ + "': " + write_failure_reason(temp_, detail));
}

Status AtomicOutput::commit()
{
    // The data reaches the disk before the name does: a crash after the
    // rename cannot leave the destination naming a file with holes.
    if (const SyncResult file = sync_to_disk(temp_, 0); !file.failure.empty()) {
        const std::string temp = temp_;
        discard();
        return io_error("cannot write '" + destination_ + "': cannot sync its temporary file '" + temp +
                        "' to disk: " + file.failure);
    }
    std::error_code ec;
    fs::rename(temp_, destination_, ec);
    if (ec) {
        discard();
        return io_error("cannot write '" + destination_ + "': " + ec.message());
    }
    committed_ = true;
    // The rename itself reaches the disk. A directory that cannot be opened
    // (read permission withheld) is left to the file system's own flush.
    fs::path dir = fs::path(destination_).parent_path();
    if (dir.empty()) dir = ".";
    if (const SyncResult folder = sync_to_disk(dir.string(), O_DIRECTORY); folder.opened && !folder.failure.empty())
        return io_error("cannot write '" + destination_ + "': cannot sync its directory '" + dir.string() +
                        "' to disk: " + folder.failure);
    return ok();
}

}  // namespace cmfilter
