// SPDX-License-Identifier: Apache-2.0
// Histogram pyramids (texture/histogram_pyramid.h) from arbitrary headers and
// MIP chains, opened as HistogramTexture and looked up.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/texture/histogram_pyramid.h"

#include <atomic>
#include <vector>

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static std::atomic<unsigned> serial{0};
    const std::string path =
        fuzz::write_scratch_file("histogram-" + std::to_string(serial++ % 64) + ".cmfuzz", data, size);
    if (auto tex = HistogramTexture::open(path)) {
        std::vector<float> weights(static_cast<std::size_t>(tex->bins()));
        if (tex->lookup(0.4f, 0.6f, 1.0f, weights.data()))
            fuzz::require_finite(weights, "histogram weights are finite");
    }
    (void)read_artefact_info(path);
    return 0;
}
