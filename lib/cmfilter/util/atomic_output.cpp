// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/atomic_output.h"

#include <cctype>
#include <filesystem>
#include <random>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace cmfilter {

Expected<AtomicOutput> AtomicOutput::begin(const std::string& destination)
{
    if (destination.empty()) return bad_input("the output path is empty");
    const fs::path dest(destination);
    fs::path dir = dest.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        return io_error("cannot write '" + destination + "': directory '" + dir.string() + "' does not exist");
    if (fs::is_directory(dest, ec)) return io_error("cannot write '" + destination + "': it is a directory");

    std::random_device entropy;
    std::ostringstream name;
    name << "." << dest.stem().string() << ".tmp-" << std::hex << entropy() << entropy() << dest.extension().string();
    AtomicOutput out;
    out.destination_ = destination;
    out.temp_ = (dir / name.str()).string();
    return out;
}

std::string lowercase_extension(const std::string& path)
{
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

Status check_output_path(const std::string& path, const std::string& extension)
{
    if (!extension.empty()) {
        if (lowercase_extension(path) != extension)
            return bad_input("output '" + path + "' has the wrong extension (expected a " + extension + " file)");
    }
    auto probe = AtomicOutput::begin(path);
    if (!probe) return probe.error();
    return ok();
}

AtomicOutput::AtomicOutput(AtomicOutput&& other) noexcept
    : destination_(std::move(other.destination_)), temp_(std::move(other.temp_)), committed_(other.committed_)
{
    other.temp_.clear();
}

AtomicOutput& AtomicOutput::operator=(AtomicOutput&& other) noexcept
{
    if (this != &other) {
        discard();
        destination_ = std::move(other.destination_);
        temp_ = std::move(other.temp_);
        committed_ = other.committed_;
        other.temp_.clear();
    }
    return *this;
}

AtomicOutput::~AtomicOutput() { discard(); }

void AtomicOutput::discard()
{
    if (!committed_ && !temp_.empty()) {
        std::error_code ec;
        fs::remove(temp_, ec);
    }
}

Status AtomicOutput::commit()
{
    std::error_code ec;
    fs::rename(temp_, destination_, ec);
    if (ec) return io_error("cannot write '" + destination_ + "': " + ec.message());
    committed_ = true;
    return ok();
}

}  // namespace cmfilter
