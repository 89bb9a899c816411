// SPDX-License-Identifier: Apache-2.0
// gnuplot started without a shell: posix_spawnp finds it on the PATH, the
// program goes to its standard input through a pipe, and what it prints on
// standard output and standard error comes back through another.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter::bench {

// Runs `gnuplot` on `program` and returns what it printed. Io when it
// cannot be started (not installed: the message says why), or when it exits
// with a status other than 0 or dies of a signal (the message holds what it
// printed).
Expected<std::string> run_gnuplot(const std::string& program);

}  // namespace cmfilter::bench
