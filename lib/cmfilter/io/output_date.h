// SPDX-License-Identifier: Apache-2.0
// The date an output file records. None by default, so that identical
// inputs give byte-identical files; with SOURCE_DATE_EPOCH set (the
// reproducible-builds.org convention: seconds since 1970-01-01 UTC), that
// time, in UTC, as the image's DateTime ("YYYY:MM:DD HH:MM:SS", as
// OpenImageIO spells it; OpenEXR's capDate).
#pragma once

#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <string>

namespace cmfilter {

// Sets `spec`'s DateTime for a file written by `writer`: SOURCE_DATE_EPOCH's
// time when it is set, else none. OpenImageIO's OpenEXR writer stamps the
// current time on any spec without a DateTime and leaves out a DateTime that
// is not text, so an EXR without a date gets an integer DateTime (which
// OpenImageIO 2.4 reports as a debug line on stdout where its "debug"
// attribute is on, as it is by default in builds without NDEBUG: the
// cmfilter command turns it off). BadInput when SOURCE_DATE_EPOCH is set but
// not a non-negative integer.
Status set_output_date(OIIO::ImageSpec& spec, const OIIO::ImageOutput& writer);

// SOURCE_DATE_EPOCH's time as DateTime text; empty when it is unset; an
// error naming the variable and its value when malformed.
Expected<std::string> source_date_text();

}  // namespace cmfilter
