// TEMPORARY: stands in for histogram_pyramid.cpp until it lands, so that the
// exact method links. Drop this file when the implementation is merged.
#include <OpenImageIO/texture.h>  // histogram_pyramid.h names OIIO_NAMESPACE before defining it

#include "cmfilter/histogram_pyramid.h"

namespace cmfilter {

Expected<HistogramPyramidInfo> bake_histogram_pyramid(const HistogramBakeOptions&)
{
    return runtime_error("histogram pyramids are not implemented yet");
}

Expected<HistogramTexture> HistogramTexture::open(const std::string&)
{
    return runtime_error("histogram pyramids are not implemented yet");
}

bool HistogramTexture::lookup(float, float, float, float*) const { return false; }

}  // namespace cmfilter
