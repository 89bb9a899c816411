// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/light_file.h"

#include "cmfilter/util/atomic_output.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace cmfilter {

namespace {

std::vector<std::string> split_fields(const std::string& line)
{
    std::vector<std::string> fields;
    std::string field;
    for (char ch : line) {
        if (ch == ' ' || ch == '\t' || ch == '\r') {
            if (!field.empty()) fields.push_back(field);
            field.clear();
        } else {
            field += ch;
        }
    }
    if (!field.empty()) fields.push_back(field);
    return fields;
}

// A whole field as a number; false when it is not one.
bool parse_number(const std::string& text, double& value)
{
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && errno != ERANGE;
}

bool looks_like_decimal_comma(const std::string& text)
{
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos || text.find('.') != std::string::npos) return false;
    std::string dotted = text;
    dotted[comma] = '.';
    double v = 0;
    return parse_number(dotted, v);
}

std::string folder_of(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

}  // namespace

std::string LightFile::image_path(std::size_t k) const
{
    const std::string& name = lights.at(k).image;
    const std::string folder = folder_of(path);
    const std::string direct = !name.empty() && name[0] == '/' ? name : folder + name;
    std::error_code ec;
    if (std::filesystem::exists(direct, ec)) return direct;
    // Written on another machine: Windows separators, or that machine's
    // absolute paths. The same relative path with '/', then the file of the
    // same name beside the .lp.
    std::string slashed = name;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    const bool windows_absolute = slashed.size() > 2 && slashed[1] == ':' && slashed[2] == '/';
    if (slashed != name && !windows_absolute && slashed[0] != '/' && std::filesystem::exists(folder + slashed, ec))
        return folder + slashed;
    // Only for names that are another machine's (absolute, or with '\\'):
    // a missing relative name is reported as it is, not replaced by another
    // file that happens to share its name.
    const bool foreign = windows_absolute || slashed != name || name[0] == '/';
    const std::size_t cut = slashed.find_last_of('/');
    if (foreign && cut != std::string::npos && cut + 1 < slashed.size()) {
        const std::string beside = folder + slashed.substr(cut + 1);
        if (std::filesystem::exists(beside, ec)) return beside;
    }
    return direct;
}

Expected<LightFile> read_light_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return io_error("cannot read light file '" + path + "': no such file or not readable");
    LightFile file;
    file.path = path;
    auto at = [&](int line, const std::string& what) {
        return bad_input("light file '" + path + "' line " + std::to_string(line) + ": " + what);
    };

    std::string line;
    int number = 0;
    long long count = -1;
    int count_line = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::vector<std::string> fields = split_fields(line);
        if (fields.empty()) continue;
        if (count < 0) {
            double n = 0;
            if (fields.size() != 1 || !parse_number(fields[0], n) || n != std::floor(n) || n < 1 || n > 1e7)
                return at(number, "expected the number of lights (a whole number >= 1) alone on the first line, got '" +
                                      line + "'");
            count = static_cast<long long>(n);
            count_line = number;
            continue;
        }
        // A name may hold spaces: the last three fields are the direction
        // and the rest of the line before them the name, unless the field
        // after the first is a number too (a line with a number too many).
        double probe = 0;
        if (fields.size() < 4 || (fields.size() > 4 && parse_number(fields[1], probe)))
            return at(number, "expected 'image x y z' (a file name and three numbers), got " +
                                  std::to_string(fields.size()) + " field" + (fields.size() == 1 ? "" : "s") + ": '" +
                                  line + "'");
        const std::size_t first_number = fields.size() - 3;
        double v[3];
        for (int i = 0; i < 3; ++i) {
            const std::string& f = fields[first_number + i];
            if (parse_number(f, v[i])) continue;
            if (looks_like_decimal_comma(f))
                return at(number, "'" + f + "' has a decimal comma; expected a decimal point ('.')");
            return at(number, "'" + f + "' is not a number; expected 'image x y z'");
        }
        std::string name = fields[0];
        if (fields.size() > 4) {
            // From the first field's start to the end of the last name field,
            // the fields found in order along the line.
            std::size_t cursor = 0, start = 0, end = 0;
            for (std::size_t i = 0; i < first_number; ++i) {
                const std::size_t at_field = line.find(fields[i], cursor);
                if (i == 0) start = at_field;
                cursor = end = at_field + fields[i].size();
            }
            name = line.substr(start, end - start);
        }
        const Vec3 d{v[0], v[1], v[2]};
        if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z))
            return at(number, "the light direction of '" + name + "' is not finite");
        const double len = length(d);
        if (!(len > 0) || !std::isfinite(len))
            return at(number, "the light direction of '" + name + "' is zero; expected a direction");
        const Vec3 unit = d / len;
        if (unit.z < 0) {
            std::ostringstream msg;
            msg << "the light direction of '" << name << "' (" << d.x << ", " << d.y << ", " << d.z
                << ") is below the horizon (z < 0); expected z >= 0, towards the camera";
            return at(number, msg.str());
        }
        file.lights.push_back({name, unit, number});
    }
    if (count < 0)
        return bad_input("light file '" + path + "' is empty; expected the number of lights, then one line per image");
    if (static_cast<long long>(file.lights.size()) != count)
        return bad_input("light file '" + path + "': line " + std::to_string(count_line) + " says " +
                         std::to_string(count) + " light" + (count == 1 ? "" : "s") + " but " +
                         std::to_string(file.lights.size()) + " follow" + (file.lights.size() == 1 ? "s" : ""));
    return file;
}

std::string format_light_file(const std::vector<LightEntry>& lights)
{
    std::ostringstream out;
    out << lights.size() << "\n";
    char buffer[128];
    for (const LightEntry& l : lights) {
        std::snprintf(buffer, sizeof buffer, " %.9g %.9g %.9g\n", l.direction.x, l.direction.y, l.direction.z);
        out << l.image << buffer;
    }
    return out.str();
}

Status write_light_file(const std::string& path, const std::vector<LightEntry>& lights)
{
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    {
        std::ofstream f(out->temp_path(), std::ios::binary);
        f << format_light_file(lights);
        f.close();
        if (!f) return out->write_error("the light file could not be written");
    }
    return out->commit();
}

}  // namespace cmfilter
