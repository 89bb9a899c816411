// SPDX-License-Identifier: Apache-2.0
// Percent progress on stderr for long commands.
#include "command.h"

#include <iostream>

namespace cmfilter::cli {

std::function<void(double)> terminal_progress(const std::string& command)
{
    return [command, last = -1](double f) mutable {
        const int percent = static_cast<int>(f * 100);
        if (percent == last) return;
        last = percent;
        std::cerr << "\r" << command << ": " << percent << "%" << (percent == 100 ? "\n" : "") << std::flush;
    };
}

}  // namespace cmfilter::cli
