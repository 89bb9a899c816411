// SPDX-License-Identifier: Apache-2.0
// The light file of an image stack, in the common RTI `.lp` format that
// light-stage software and RTI viewers read and write:
//     N
//     image_0.png  x y z
//     ...
//     image_N-1.png  x y z
// The first line holds the count N; then one line per image: its file name
// (relative to the `.lp` file's folder, or absolute) and the light
// direction towards the light, in the image's frame: x right, y up (towards
// the image's top row), z towards the camera. Fields are separated by
// spaces or tabs; blank lines and trailing whitespace are ignored. A name
// may hold spaces: the last three fields are the direction, the rest of the
// line before them the name (unless its second field is a number: a line
// with one number too many is malformed).
// Directions are normalised on read.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

struct LightEntry {
    std::string image;  // as written in the file
    Vec3 direction;     // unit, z >= 0
    int line = 0;       // 1-based line of the file it came from (0: made in memory)
};

struct LightFile {
    std::string path;  // the .lp file read
    std::vector<LightEntry> lights;
    // image k's path: its name resolved against the .lp file's folder
    // (absolute names kept). A light file written on another machine (RTI
    // capture software records that machine's paths, often Windows ones:
    // "C:\\capture\\jpeg\\img_01.jpg") still opens when its images lie
    // beside it: a name that does not exist is tried with '\\' read as '/',
    // then, if it is absolute or has a '\\', as the file of the same name in
    // the .lp's folder (a missing relative name is reported as written).
    std::string image_path(std::size_t k) const;
};

// BadInput naming the file and the 1-based line: a first line that is not a
// positive count, a count that does not match the lines that follow, a line
// that is not "name x y z" (malformed), a number written with a decimal
// comma, a zero or non-finite direction, a direction below the horizon
// (z < 0). Io when the file cannot be read.
Expected<LightFile> read_light_file(const std::string& path);

// The text of a light file for `lights` (directions written with 9
// significant digits, as given: not normalised again).
std::string format_light_file(const std::vector<LightEntry>& lights);

// Writes format_light_file atomically (atomic_output.h).
Status write_light_file(const std::string& path, const std::vector<LightEntry>& lights);

}  // namespace cmfilter
