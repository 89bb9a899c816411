// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/artefact_file.h"

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

Status write_float_artefact(AtomicOutput& out, const OIIO::ImageSpec& spec, const float* pixels)
{
    auto writer = OIIO::ImageOutput::create(out.temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write EXR: " + OIIO::geterror());
    if (!writer->open(out.temp_path(), spec) || !writer->write_image(OIIO::TypeDesc::FLOAT, pixels) ||
        !writer->close()) {
        std::string why = writer->geterror();
        return io_error("cannot write '" + out.destination() + "': " + why);
    }
    return out.commit();
}

}  // namespace cmfilter
