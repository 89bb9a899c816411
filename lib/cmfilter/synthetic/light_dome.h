// SPDX-License-Identifier: Apache-2.0
// The lights of a synthetic image stack (make_stack.h): unit directions
// towards the light in the stack's frame (light_file.h: x right, y up,
// towards the image's top row, z towards the camera), on a hemisphere above
// a minimum elevation. The kinds, written `kind:N` on the command line
// (parse_dome):
//   regular:N    rings of equal elevation step from the minimum elevation
//                up to a single light at the zenith, each ring's azimuths
//                evenly spaced with a count proportional to the cosine of
//                its elevation, so that neighbours are about as far apart
//                along a ring as across rings. The step is chosen among
//                (90 - min) / R degrees, R = 1, 2, ..., as the one whose
//                azimuth spacing (2 pi / M for the scale M that gives N
//                lights) is closest to it; the ring counts max(1, M cos e)
//                are rounded by largest remainder so that they sum to N
//                exactly. Odd rings start half a step round.
//   fibonacci:N  the golden-angle spiral: light k at height z_k = z0 + (1 -
//                z0) (k + 1/2) / N, z0 = sin(min elevation), azimuth k times
//                the golden angle pi (3 - sqrt 5): uniform in solid angle
//                above the minimum elevation (the area of a spherical zone
//                is proportional to its height), mean z = (1 + z0) / 2.
//   stage:N      the uneven spread of a real light stage: floor(N / 2)
//                lights packed on two low rings (at the minimum elevation
//                and one sixth of the way up to the zenith) over the
//                azimuths -75 .. 75 degrees (the +x side, where a stage's
//                arms are mounted densely), alternately on the two rings;
//                the other ceil(N / 2) lights a Fibonacci spiral over the
//                whole hemisphere above the minimum elevation. The +x low
//                arc is then many times denser than the rest: the uneven
//                sampling that made the per-texel Lafortune fits of
//                Bosserhoff & Nicoll (sec. 4) go wrong between clusters.
//   file:PATH    the directions of a `.lp` light file (read_light_file),
//                in its order; the minimum elevation does not apply.
// Deterministic: the same options give the same directions.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

enum class DomeKind { Regular, Fibonacci, Stage, File };
const char* to_string(DomeKind kind);

// The most lights a made dome may have.
inline constexpr int kMaxDomeLights = 100000;

struct DomeOptions {
    DomeKind kind = DomeKind::Fibonacci;
    int count = 64;                     // regular, fibonacci, stage: 1 .. kMaxDomeLights
    double min_elevation_degrees = 10;  // regular, fibonacci, stage: 0 <= e < 90 (regular, stage: <= 80)
    std::string path;                   // file: the .lp
};

// "fibonacci:64", "regular:64", "stage:64" or "file:PATH.lp" (the minimum
// elevation stays the default). BadInput naming the text and what was
// expected (field DomeOptions::kind).
Expected<DomeOptions> parse_dome(const std::string& text);

// The text parse_dome reads back ("file:" and the path for a file dome).
std::string dome_text(const DomeOptions& options);

// The directions. BadInput naming the field (DomeOptions::count,
// DomeOptions::min_elevation_degrees) for a count or elevation out of range;
// a file dome: read_light_file's errors.
Expected<std::vector<Vec3>> make_dome(const DomeOptions& options);

}  // namespace cmfilter
