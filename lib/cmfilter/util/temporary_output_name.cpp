// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/util/temporary_output_name.h"

#include <unistd.h>

#include <cctype>
#include <climits>
#include <cstdio>
#include <filesystem>
#include <random>

namespace fs = std::filesystem;

namespace cmfilter {

namespace {

constexpr std::size_t kRandomDigits = 16;

bool all_of(const std::string& s, int (*is)(int))
{
    if (s.empty()) return false;
    for (char c : s)
        if (!is(static_cast<unsigned char>(c))) return false;
    return true;
}

int is_lower_hex(int c) { return std::isdigit(c) || (c >= 'a' && c <= 'f'); }

int is_host_char(int c) { return std::isalnum(c) || c == '.' || c == '-' || c == '_'; }

std::string prefix_of(const fs::path& destination) { return "." + destination.stem().string() + ".tmp-"; }

}  // namespace

std::string local_host_name()
{
    char buffer[256] = {};
    if (gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0') return "unknown";
    std::string host(buffer);
    for (char& c : host)
        if (!is_host_char(static_cast<unsigned char>(c))) c = '_';
    return host;
}

TemporaryOutputWriter this_writer() { return {local_host_name(), static_cast<long>(getpid())}; }

std::string temporary_output_name(const std::string& destination_name, const TemporaryOutputWriter& writer,
                                  unsigned long long random)
{
    const fs::path destination(destination_name);
    char hex[kRandomDigits + 1];
    std::snprintf(hex, sizeof hex, "%016llx", random);
    return prefix_of(destination) + writer.host + "-" + std::to_string(writer.pid) + "-" + hex +
           destination.extension().string();
}

std::string new_temporary_output_name(const std::string& destination_name)
{
    std::random_device entropy;
    const unsigned long long random = (static_cast<unsigned long long>(entropy()) << 32) ^ entropy();
    return temporary_output_name(destination_name, this_writer(), random);
}

std::optional<TemporaryOutputWriter> parse_temporary_output_name(const std::string& name,
                                                                 const std::string& destination_name)
{
    const fs::path destination(destination_name);
    const std::string prefix = prefix_of(destination);
    const std::string extension = destination.extension().string();
    if (name.size() <= prefix.size() + extension.size()) return std::nullopt;
    if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    if (name.compare(name.size() - extension.size(), extension.size(), extension) != 0) return std::nullopt;
    // <host>-<pid>-<hex>: the host may hold '-', so split from the right.
    const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    const std::size_t last = middle.rfind('-');
    if (last == std::string::npos || last == 0) return std::nullopt;
    const std::size_t before = middle.rfind('-', last - 1);
    if (before == std::string::npos || before == 0) return std::nullopt;
    const std::string host = middle.substr(0, before);
    const std::string pid = middle.substr(before + 1, last - before - 1);
    const std::string random = middle.substr(last + 1);
    if (random.size() != kRandomDigits || !all_of(random, is_lower_hex)) return std::nullopt;
    if (pid.size() > 10 || !all_of(pid, [](int c) { return std::isdigit(c); })) return std::nullopt;
    if (!all_of(host, is_host_char)) return std::nullopt;
    const long long value = std::stoll(pid);
    if (value <= 0 || value > INT_MAX) return std::nullopt;
    return TemporaryOutputWriter{host, static_cast<long>(value)};
}

}  // namespace cmfilter
