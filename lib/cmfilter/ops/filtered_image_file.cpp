// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/filtered_image_file.h"

#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/io/recorded_path.h"
#include "cmfilter/util/version.h"

namespace cmfilter {

Status check_filtered_image_output(const std::string& path) { return check_rgb_image_output(path); }

Status write_filtered_image(const std::string& path, const FilteredImage& image, const ColorConfig& config)
{
    // Inputs recorded relative to the output (io/recorded_path.h).
    const auto rel = [&](const std::string& input) { return path_for_record(input, path); };
    ImageAttributes a;
    a.text = {{"cmfilter:kind", kFilteredImageKind},        {"cmfilter:version", version()},
              {"cmfilter:method", to_string(image.method)}, {"cmfilter:moments", rel(image.moments_path)},
              {"cmfilter:table", rel(image.table_path)},    {"cmfilter:driver_source", rel(image.moments.source)}};
    if (!image.map_path.empty()) a.text.emplace_back("cmfilter:map", rel(image.map_path));
    if (!image.driver_path.empty()) a.text.emplace_back("cmfilter:driver", rel(image.driver_path));
    if (!image.histograms_path.empty()) a.text.emplace_back("cmfilter:histograms", rel(image.histograms_path));
    a.numbers = {{"cmfilter:lod", image.lod}, {"cmfilter:lod_requested", image.lod_requested}};
    if (const auto& c = image.method_choice) {  // io/method_tolerance_record.h
        a.numbers.emplace_back("cmfilter:method_tolerance", c->tolerance);
        a.numbers.emplace_back("cmfilter:method_error", c->error);
        a.text.emplace_back("cmfilter:method_lods", c->lods);
        a.text.emplace_back("cmfilter:method_table", rel(c->table));
    }
    return write_rgb_image(path, image.width, image.height, 3, image.rgb, image.linear_space, a, config);
}

}  // namespace cmfilter
