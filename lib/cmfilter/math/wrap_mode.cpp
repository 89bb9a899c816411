// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/wrap_mode.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

const char* to_string(WrapMode mode)
{
    switch (mode) {
    case WrapMode::Clamp: return "clamp";
    case WrapMode::Repeat: return "repeat";
    case WrapMode::Mirror: return "mirror";
    }
    return "clamp";
}

Expected<WrapMode> parse_wrap_mode(const std::string& name)
{
    if (name == "clamp") return WrapMode::Clamp;
    if (name == "repeat") return WrapMode::Repeat;
    if (name == "mirror") return WrapMode::Mirror;
    return bad_input("unknown wrap mode '" + name + "' (expected clamp, repeat or mirror)");
}

long wrap_texel_index(long k, long n, WrapMode mode)
{
    switch (mode) {
    case WrapMode::Clamp: return std::clamp(k, 0L, n - 1);
    case WrapMode::Repeat: {
        long m = k % n;
        return m < 0 ? m + n : m;
    }
    case WrapMode::Mirror: {
        long m = k % (2 * n);
        if (m < 0) m += 2 * n;
        return m < n ? m : 2 * n - 1 - m;
    }
    }
    return 0;
}

double wrap_coordinate(double x, double period, WrapMode mode)
{
    switch (mode) {
    case WrapMode::Clamp: return x;
    case WrapMode::Repeat: {
        double m = std::fmod(x, period);
        if (m < 0) m += period;
        return m >= period ? 0.0 : m;
    }
    case WrapMode::Mirror: {
        double m = std::fmod(x, 2 * period);
        if (m < 0) m += 2 * period;
        return m <= period ? m : 2 * period - m;
    }
    }
    return x;
}

}  // namespace cmfilter
