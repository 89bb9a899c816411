// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/artefact_file.h"

#include "cmfilter/io/output_date.h"

namespace cmfilter {

Status check_artefact_kind(const OIIO::ImageSpec& spec, const std::string& path, const std::string& kind,
                           const std::string& what, int version)
{
    const std::string found = spec.get_string_attribute("cmfilter:kind");
    if (found != kind)
        return bad_input("'" + path + "' is not a cmfilter " + what + " (cmfilter:kind is '" + found + "', expected '" +
                         kind + "')");
    const int found_version = spec.get_int_attribute("cmfilter:format_version", 0);
    if (found_version != version)
        return bad_input("'" + path + "' has " + what + " format version " + std::to_string(found_version) +
                         ", this cmfilter reads version " + std::to_string(version));
    return ok();
}

Expected<ArtefactImage> read_artefact_image(const std::string& path, const std::string& kind, const std::string& what,
                                            int version,
                                            const std::function<Status(const OIIO::ImageSpec&)>& check_header)
{
    ArtefactImage out;
    {
        auto in = open_image_input(path);
        if (!in) return in.error();
        out.spec = (*in)->spec();
    }
    if (auto st = check_artefact_kind(out.spec, path, kind, what, version); !st) return st.error();
    if (check_header)
        if (auto st = check_header(out.spec); !st) return st.error();
    auto image = read_image(path);
    if (!image) return image.error();
    out.image = std::move(*image);
    return out;
}

Status write_float_artefact(AtomicOutput& out, OIIO::ImageSpec spec, const float* pixels,
                            const ExrOutputOptions& storage)
{
    if (auto st = check_exr_output_options(storage, "ExrOutputOptions"); !st) return st;
    if (auto st = check_half_range(pixels, spec.image_pixels() * static_cast<std::size_t>(spec.nchannels), storage,
                                   out.destination());
        !st)
        return st;
    apply_exr_output_options(spec, storage);
    auto writer = OIIO::ImageOutput::create(out.temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write EXR: " + OIIO::geterror());
    if (auto st = set_output_date(spec, *writer); !st) return st;
    if (!writer->open(out.temp_path(), spec) || !writer->write_image(OIIO::TypeDesc::FLOAT, pixels) || !writer->close())
        return out.write_error(writer->geterror());
    return out.commit();
}

Status write_float_artefact_parts(AtomicOutput& out, std::vector<OIIO::ImageSpec> specs,
                                  const std::vector<std::vector<float>>& pixels)
{
    const std::string& path = out.destination();
    for (OIIO::ImageSpec& spec : specs) {
        spec.full_x = spec.full_y = 0;
        spec.full_width = specs[0].width;
        spec.full_height = specs[0].height;
    }
    auto writer = OIIO::ImageOutput::create(out.temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write EXR: " + OIIO::geterror());
    if (specs.size() > 1 && !writer->supports("multiimage"))
        return runtime_error("OpenImageIO's writer for '" + path + "' cannot write several subimages");
    for (OIIO::ImageSpec& spec : specs)
        if (auto st = set_output_date(spec, *writer); !st) return st;
    if (!writer->open(out.temp_path(), static_cast<int>(specs.size()), specs.data()))
        return out.write_error(writer->geterror());
    for (std::size_t s = 0; s < specs.size(); ++s) {
        if (s > 0 && !writer->open(out.temp_path(), specs[s], OIIO::ImageOutput::AppendSubimage))
            return out.write_error(writer->geterror());
        if (!writer->write_image(OIIO::TypeDesc::FLOAT, pixels[s].data())) return out.write_error(writer->geterror());
    }
    if (!writer->close()) return out.write_error(writer->geterror());
    return out.commit();
}

}  // namespace cmfilter
