// SPDX-License-Identifier: Apache-2.0
// Shared by the noise benchmarks: the noise a spec's text form describes, or
// none with the reason on stderr.
#pragma once

#include "cmfilter/noise/noise_spec.h"

#include <iostream>
#include <optional>
#include <string>
#include <utility>

inline std::optional<cmfilter::FractalNoise> noise_from_spec(const std::string& text)
{
    auto spec = cmfilter::parse_noise_spec(text);
    if (!spec) {
        std::cerr << spec.error().message << "\n";
        return std::nullopt;
    }
    auto noise = cmfilter::make_noise(*spec);
    if (!noise) {
        std::cerr << noise.error().message << "\n";
        return std::nullopt;
    }
    return std::move(*noise);
}
