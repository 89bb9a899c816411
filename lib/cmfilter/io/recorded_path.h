// SPDX-License-Identifier: Apache-2.0
// The paths an artefact records to the files it was made from
// (cmfilter:source, cmfilter:sample, cmfilter:scene, ...). They are written
// relative to the artefact's own folder, so that the same inputs give the
// same bytes wherever a bake runs (another checkout, another farm node's
// scratch folder) and a folder of assets can move as a whole; the SHA-256
// recorded beside a source is what identifies it. Read back, a recorded
// path is resolved against the artefact's folder again; an absolute path
// (as older files record) is kept as it is.
#pragma once

#include <string>

namespace cmfilter {

// `input` as `artefact` records it: relative to the artefact's folder
// ("../maps/terrain.png"), with forward slashes; absolute when the two have
// no common root; empty for an empty input. Lexical: symbolic links are
// not followed.
std::string path_for_record(const std::string& input, const std::string& artefact);

// A path recorded in `artefact` as a path to open: a relative one joined to
// the artefact's folder and normalised ("maps/../x.png" -> "x.png"); an
// absolute or empty one unchanged.
std::string path_from_record(const std::string& recorded, const std::string& artefact);

}  // namespace cmfilter
