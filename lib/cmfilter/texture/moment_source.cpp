// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/moment_source.h"

namespace cmfilter {

Expected<HashedDriver> read_moment_source(const std::string& driver_path, const std::string& moments_path,
                                          const MomentPyramidInfo& info, int threads)
{
    DriverReadOptions read;
    read.path = driver_path;
    read.channel = std::to_string(info.channel_index);
    read.nonfinite = info.nonfinite_replaced > 0 ? NonFinitePolicy::Zero : NonFinitePolicy::Error;
    read.threads = threads;
    auto driver = read_driver_and_hash(read);
    if (!driver) return driver.error();
    if (driver->image.width != info.width || driver->image.height != info.height)
        return bad_input("driver '" + driver_path + "' is " + std::to_string(driver->image.width) + " x " +
                         std::to_string(driver->image.height) + " but '" + moments_path + "' was baked from " +
                         std::to_string(info.width) + " x " + std::to_string(info.height) +
                         " (expected the same size)");
    return driver;
}

bool is_moment_source(const HashedDriver& driver, const MomentPyramidInfo& info)
{
    return driver.sha256 == info.source_sha256;
}

std::string moment_source_changed(const std::string& driver_path, const HashedDriver& driver,
                                  const std::string& moments_path, const MomentPyramidInfo& info)
{
    return "driver '" + driver_path + "' (sha256 " + driver.sha256 + ") is not the file '" + moments_path +
           "' was baked from (sha256 " + info.source_sha256 + ")";
}

}  // namespace cmfilter
