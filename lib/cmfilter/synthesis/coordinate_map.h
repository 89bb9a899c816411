// SPDX-License-Identifier: Apache-2.0
// A coordinate map (sec. 4.2, "Using large BTFs for rendering"): a large
// surface stored as, per output texel, the sample texel it copies, so that
// the surface costs the sample plus this map. Hierarchical synthesis also
// leaves one map per coarser level, into the sample's own pyramid level.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cmfilter {

struct CoordinateLevel {
    int width = 0, height = 0;                // this level of the output
    int sample_width = 0, sample_height = 0;  // the sample's pyramid level it points into
    std::vector<std::int32_t> coords;         // width * height * 2: sample texel x, y
    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
    std::int32_t x(std::size_t t) const { return coords[2 * t]; }
    std::int32_t y(std::size_t t) const { return coords[2 * t + 1]; }
};

// How a map was made, recorded in its file.
struct CoordinateMapInfo {
    std::string sample_path;
    std::string sample_hash;
    std::string sample_kind;  // "image", "stack", "btf"
    bool sample_periodic = false;
    int k = 0, neighbourhood = 0, levels = 0;
    bool toroidal = false;
    std::uint64_t seed = 0;
    double seconds = 0;  // synthesis time
};

struct CoordinateMap {
    CoordinateMapInfo info;
    // levels[0]: the output at full size, into the sample's level 0;
    // levels[l]: hierarchical synthesis's level l (about width / 2^l), into
    // the sample's level l. At least one.
    std::vector<CoordinateLevel> levels;
    const CoordinateLevel& full() const { return levels.front(); }
    int width() const { return levels.empty() ? 0 : levels[0].width; }
    int height() const { return levels.empty() ? 0 : levels[0].height; }
};

}  // namespace cmfilter
