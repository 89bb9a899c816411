// SPDX-License-Identifier: Apache-2.0
// Representative images of a sample (sec. 4.1: "select a few hundred
// representative images"; Tong et al. 2002 cluster whole images): a
// farthest-point selection over whole images, each taken as one vector of
// its values. The first is the image of the largest variance; each next one
// the image whose smallest squared distance to those chosen is the largest
// (ties: the lower index).
#pragma once

#include <cstddef>
#include <vector>

namespace cmfilter {

// `images`: each image's values (all of one length). Returns min(count,
// images.size()) indices, ascending. count <= 0 keeps every image.
std::vector<int> select_representative_images(const std::vector<std::vector<float>>& images, int count,
                                              int threads = 0);

}  // namespace cmfilter
