#include "cmfilter/box_pyramid_file.h"

#include "cmfilter/box_pyramid.h"

#include <algorithm>

namespace cmfilter {

Status write_box_pyramid_file(const BoxPyramidFileOptions& options, const BoxPyramidRowFill& fill)
{
    const int W = options.width, H = options.height;
    const int C = static_cast<int>(options.channel_names.size());
    const auto progress = [&](double f) {
        if (options.progress) options.progress(f);
    };
    OIIO::ImageSpec spec(W, H, C, OIIO::TypeDesc::FLOAT);
    spec.channelnames = options.channel_names;
    spec.tile_width = spec.tile_height = options.tile_size;
    spec.tile_depth = 1;
    spec.attribute("compression", options.compression);
    spec.attribute("textureformat", "Plain Texture");
    spec.attribute("openexr:levelmode", 1);     // MIPMAP_LEVELS
    spec.attribute("openexr:roundingmode", 0);  // ROUND_DOWN: level k is max(1, W >> k)
    if (options.set_metadata) options.set_metadata(spec);
    auto writer = OIIO::ImageOutput::create(options.path);
    if (!writer) return runtime_error("OpenImageIO cannot write EXR: " + OIIO::geterror());
    if (!writer->supports("mipmap") || !writer->supports("tiles"))
        return runtime_error("OpenImageIO's EXR writer cannot write tiled MIP-maps");
    const auto write_failed = [&]() -> Status {
        return io_error("cannot write '" + options.name + "': " + writer->geterror());
    };
    if (!writer->open(options.path, spec)) return write_failed();

    BoxPyramidAccumulator upper(W, H, C, options.threads);
    const int tile = options.tile_size;
    std::vector<float> tile_row(static_cast<std::size_t>(W) * tile * C);
    for (int y0 = 0; y0 < H; y0 += tile) {
        const int y1 = std::min(H, y0 + tile);
        upper.add_rows(y0, y1, [&](int y, int thread, double* planes) {
            fill(y, thread, planes);
            float* dst = tile_row.data() + static_cast<std::size_t>(y - y0) * W * C;
            for (int c = 0; c < C; ++c)
                for (int x = 0; x < W; ++x)
                    dst[static_cast<std::size_t>(x) * C + c] = static_cast<float>(planes[static_cast<std::size_t>(c) * W + x]);
        });
        if (!writer->write_tiles(0, W, y0, y1, 0, 1, OIIO::TypeDesc::FLOAT, tile_row.data()))
            return write_failed();
        progress(0.9 * y1 / H);
    }
    for (int k = 1; k < upper.levels(); ++k) {
        OIIO::ImageSpec level = spec;
        level.width = level.full_width = upper.level_width(k);
        level.height = level.full_height = upper.level_height(k);
        const std::vector<float> texels = upper.take_level(k);
        if (!writer->open(options.path, level, OIIO::ImageOutput::AppendMIPLevel) ||
            !writer->write_image(OIIO::TypeDesc::FLOAT, texels.data()))
            return write_failed();
        progress(0.9 + 0.1 * k / (upper.levels() - 1));
    }
    if (!writer->close()) return write_failed();
    progress(1.0);
    return ok();
}

}  // namespace cmfilter
