// SPDX-License-Identifier: Apache-2.0
// All-or-nothing file output: writers write to a temporary file beside the
// destination (same directory, same extension so OpenImageIO picks the same
// format) and commit() renames it into place. A writer that fails, or an
// AtomicOutput destroyed without commit(), leaves no file behind; a writer
// killed before commit() leaves the destination as it was (no file, or the
// previous complete one) and its temporary beside it.
//
// The temporary is named (temporary_output_name.h)
//
//     .<stem>.tmp-<host>-<pid>-<hex><ext>
//
// ".render.tmp-farm07-41234-3f9c0a17d2e4b586.exr" for "render.exr" written
// by process 41234 on host farm07. begin() removes the destination's stale
// temporaries (stale_temporary_outputs.h): those of this host whose process
// is gone, and those of other hosts last modified over 24 hours ago; never
// one of a live writer on this host.
//
// commit() fsync()s the temporary's data, renames it over the destination
// and fsync()s the directory, so that after a crash the destination names
// either the old file or the whole new one.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

class AtomicOutput {
public:
    // Fails (Io) when the destination's directory does not exist, is a file
    // or is not writable, or the destination is a directory. Removes the
    // destination's stale temporaries; creates no file (the writer creates
    // temp_path()).
    static Expected<AtomicOutput> begin(const std::string& destination);

    AtomicOutput(AtomicOutput&& other) noexcept;
    AtomicOutput& operator=(AtomicOutput&& other) noexcept;
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    const std::string& temp_path() const { return temp_; }
    const std::string& destination() const { return destination_; }
    // Syncs temp_path() to disk, renames it to destination() and syncs the
    // directory. Fails (Io, naming the destination and what failed) when the
    // temporary cannot be opened, synced or renamed, the temporary then
    // removed; or when the directory cannot be synced, the new file then in
    // place. A file system that does not support fsync (EINVAL) counts as
    // synced, and a directory that cannot be opened is not synced.
    Status commit();

    // The error for a writer that failed to write temp_path() and said
    // `detail`: Io, "cannot write '<destination>': " and the reason, its cause
    // (a full disk, the file size limit; write_failure.h) first when known.
    Error write_error(const std::string& detail) const;

private:
    AtomicOutput() = default;
    void discard();
    std::string destination_;
    std::string temp_;
    bool committed_ = false;
};

// Checks, before any work is done, that `path` could be written: its
// directory exists, it is not a directory, and (when extension is non-empty)
// it ends in that extension, compared case-insensitively.
Status check_output_path(const std::string& path, const std::string& extension);

// The extension of `path` with its dot, in lower case (".exr"); empty if none.
std::string lowercase_extension(const std::string& path);

}  // namespace cmfilter
