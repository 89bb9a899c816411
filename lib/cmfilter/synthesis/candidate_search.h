// SPDX-License-Identifier: Apache-2.0
// The k-coherence candidate sets (Tong et al. 2002; Bosserhoff & Nicoll
// sec. 4.2, "for each pixel in the sample, a number of (for example 10)
// pixels with the most similar neighborhoods", found "by simple brute force
// search in the sample"): per texel p the m texels q != p of the smallest
// sum over the (2n + 1)^2 offsets o of dist(texton(p + o), texton(q + o)),
// nearest first, ties by the lower texel index. Reads outside the sample
// wrap when it is periodic and clamp to its edge otherwise.
#pragma once

#include <cstdint>
#include <vector>

namespace cmfilter {

struct CandidateSearch {
    int width = 0, height = 0;
    const std::int32_t* texton = nullptr;  // width * height
    int textons = 0;
    const float* distance = nullptr;  // textons * textons squared distances, each >= 0
    int neighbourhood = 1;            // n
    int candidates = 1;               // m, < width * height
    bool periodic = false;
    int threads = 0;
};

// width * height * m texel indices (y * width + x).
std::vector<std::int32_t> find_candidate_sets(const CandidateSearch& search);

}  // namespace cmfilter
