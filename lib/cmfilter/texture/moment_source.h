// SPDX-License-Identifier: Apache-2.0
// The driver a moment pyramid was baked from, read back by what needs its
// level-0 texels beside the moments (apply's reference method, the
// renderer's supersampled methods): the file at driver_path (the pyramid's
// cmfilter:source, or a stand-in the user names) read as the bake read it
// (the same channel; non-finite texels replaced by 0 when the bake replaced
// them), refused unless it has the pyramid's size, and hashed, for the caller
// to compare with cmfilter:source_sha256 and say what a different file means.
#pragma once

#include "cmfilter/io/driver_image.h"
#include "cmfilter/util/error.h"
#include "cmfilter/texture/moment_pyramid_info.h"

#include <string>

namespace cmfilter {

// BadInput naming both files when the sizes differ; read_driver's errors
// otherwise.
Expected<HashedDriver> read_moment_source(const std::string& driver_path, const std::string& moments_path,
                                          const MomentPyramidInfo& info, int threads);

// Whether `driver` is the file the pyramid was baked from (its SHA-256 is
// cmfilter:source_sha256), and what to say when it is not: "driver 'P'
// (sha256 ...) is not the file 'M' was baked from (sha256 ...)", for the
// caller to complete with what to do.
bool is_moment_source(const HashedDriver& driver, const MomentPyramidInfo& info);
std::string moment_source_changed(const std::string& driver_path, const HashedDriver& driver,
                                  const std::string& moments_path, const MomentPyramidInfo& info);

}  // namespace cmfilter
