// SPDX-License-Identifier: Apache-2.0
// Moment pyramids (texture/moment_pyramid_info.h) from arbitrary headers and
// MIP chains, opened as MomentTexture and looked up.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/texture/moment_texture.h"

#include <atomic>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    // A name of its own per input: TextureSystem caches by file name.
    static std::atomic<unsigned> serial{0};
    const std::string path =
        fuzz::write_scratch_file("moments-" + std::to_string(serial++ % 64) + ".cmfuzz", data, size);
    if (auto tex = MomentTexture::open(path)) {
        for (float lod : {0.0f, 0.5f, 3.0f}) {
            const MomentSample m = tex->lookup(0.3f, 0.7f, lod);
            fuzz::require(std::isfinite(m.mean) && std::isfinite(m.variance) && m.variance >= 0,
                          "a moment lookup gives a finite mean and a non-negative variance");
        }
        const MomentSample a = tex->lookup(0.5f, 0.5f, 0.01f, 0.0f, 0.0f, 0.002f);
        fuzz::require(std::isfinite(a.mean) && std::isfinite(a.variance), "an anisotropic lookup is finite");
    }
    (void)read_artefact_info(path);
    return 0;
}
