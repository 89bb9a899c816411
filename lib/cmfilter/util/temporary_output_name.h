// SPDX-License-Identifier: Apache-2.0
// The name of the temporary file an output is written to before it is moved
// into place (AtomicOutput), beside the destination:
//
//     .<stem>.tmp-<host>-<pid>-<hex><ext>
//
// <stem> and <ext> are the destination's (".render.tmp-...-....exr" for
// "render.exr"; the extension last, so OpenImageIO picks the destination's
// format), <host> the writer's host name (characters other than letters,
// digits, '.', '-' and '_' written as '_'), <pid> its process id in decimal
// and <hex> 16 random lower-case hex digits. Host and process id say whose
// a leftover temporary is, so a later run can tell a dead writer's file
// from a live one's (stale_temporary_outputs.h).
#pragma once

#include <optional>
#include <string>

namespace cmfilter {

// Who wrote a temporary output: a host name (as temporary_output_name writes
// it) and a process id on that host.
struct TemporaryOutputWriter {
    std::string host;
    long pid = 0;
};

// This host's name as temporary output names hold it.
std::string local_host_name();

// The writer this process is: local_host_name() and getpid().
TemporaryOutputWriter this_writer();

// The file name (no folder) of a temporary for the destination file name
// `destination_name` ("render.exr"), written by `writer`, with `random` as
// its 16 hex digits.
std::string temporary_output_name(const std::string& destination_name, const TemporaryOutputWriter& writer,
                                  unsigned long long random);

// A fresh name for this process: this_writer(), 16 hex digits from
// std::random_device.
std::string new_temporary_output_name(const std::string& destination_name);

// The writer named by `name` if it is a temporary output name for
// `destination_name` (the pattern above, with a process id > 0); nothing if
// it is not.
std::optional<TemporaryOutputWriter> parse_temporary_output_name(const std::string& name,
                                                                 const std::string& destination_name);

}  // namespace cmfilter
