// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/output_date.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace cmfilter {

Expected<std::string> source_date_text()
{
    const char* value = std::getenv("SOURCE_DATE_EPOCH");
    if (value == nullptr || *value == '\0') return std::string();
    // Digits only, at most year 9999 (so the text keeps four digits of year).
    const bool digits = std::strspn(value, "0123456789") == std::strlen(value);
    errno = 0;
    const long long seconds = digits ? std::strtoll(value, nullptr, 10) : -1;
    if (!digits || errno == ERANGE || seconds < 0 || seconds > 253402300799LL)
        return bad_input(std::string("SOURCE_DATE_EPOCH '") + value +
                         "' is not a time (expected whole seconds since 1970-01-01 00:00:00 UTC, up to year 9999)");
    const std::time_t t = static_cast<std::time_t>(seconds);
    std::tm utc{};
    gmtime_r(&t, &utc);
    char text[64];
    std::snprintf(text, sizeof text, "%04d:%02d:%02d %02d:%02d:%02d", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                  utc.tm_hour, utc.tm_min, utc.tm_sec);
    return std::string(text);
}

Status set_output_date(OIIO::ImageSpec& spec, const OIIO::ImageOutput& writer)
{
    auto date = source_date_text();
    if (!date) return date.error();
    spec.erase_attribute("DateTime");
    if (!date->empty()) spec.attribute("DateTime", *date);
    else if (std::strcmp(writer.format_name(), "openexr") == 0) spec.attribute("DateTime", 0);
    return ok();
}

}  // namespace cmfilter
