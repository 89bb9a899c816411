// SPDX-License-Identifier: Apache-2.0
// Why a file could not be written, as far as the file system tells: image
// and stream writers report a failed write without its cause (EFBIG,
// ENOSPC), so the cause is found from the state the failure left: the disk
// full, or the file at this process's file size limit.
#pragma once

#include <string>

namespace cmfilter {

// "the disk holding '<dir>' is full (<n> bytes free)" when the file system
// holding `path` has under 1 MiB free to this process; "the file reached
// this process's file size limit of <n> bytes (ulimit -f)" when `path` is
// that large (both said of the output the caller names); empty when neither
// holds.
std::string write_failure_cause(const std::string& path);

// What to say after "cannot write '<output>': " when writing `path` failed
// and the writer said `detail`: the cause first when there is one, then the
// detail; "the write failed" when both are empty.
std::string write_failure_reason(const std::string& path, const std::string& detail);

}  // namespace cmfilter
