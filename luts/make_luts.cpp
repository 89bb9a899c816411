// SPDX-License-Identifier: Apache-2.0
// cmfilter-make-luts: writes the example colour maps that ship in luts/.
// Each map is an RGB 8-bit PNG whose texels are sRGB-encoded values (256 x 1
// gradients, and one 64 x 64 slope-vector map);
// every map is defined by a closed-form formula, stated in the comment above
// the function that computes it, evaluated in double precision and rounded
// to the nearest 8-bit code. Texel i covers the map domain [i/256, (i+1)/256)
// and its centre is u_i = (i + 0.5) / 256. The committed PNGs are the output
// of this program; the ctest test luts.regenerate checks that they still are.
// Usage: cmfilter-make-luts OUTPUT_DIRECTORY. Each file is written to a
// temporary name in the output directory and renamed into place, so a failed
// run never leaves a truncated map behind.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace {

constexpr int kTexelCount = 256;

// An sRGB-encoded colour, each channel in [0, 255] but not yet rounded.
struct EncodedColor {
    double r, g, b;
};

EncodedColor mix(const EncodedColor& a, const EncodedColor& b, double s)
{
    return {a.r + (b.r - a.r) * s, a.g + (b.g - a.g) * s, a.b + (b.b - a.b) * s};
}

double smoothstep(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

// ---------------------------------------------------------------------------
// terrain.png: a smooth terrain-like gradient. Key colours (sRGB-encoded) at
// positions t along the domain:
//   t = 0.00 deep water    ( 10,  30,  90)
//   t = 0.30 shallow water ( 40, 120, 190)
//   t = 0.40 sand          (225, 205, 145)
//   t = 0.55 grass         ( 70, 150,  60)
//   t = 0.80 rock          (125, 110,  95)
//   t = 1.00 snow          (250, 250, 250)
// Texel i uses t = i / 255 (so the end texels are exactly the end keys). For
// t between keys k and k+1: c(t) = c_k + (c_{k+1} - c_k) * S((t - t_k) /
// (t_{k+1} - t_k)), with S(x) = 3x^2 - 2x^3, blended in encoded space.
// ---------------------------------------------------------------------------
struct Key {
    double position;
    EncodedColor color;
};

// Keys blended with smoothstep between neighbours, texel i at t = i / 255.
template <std::size_t N>
EncodedColor keyed(const std::array<Key, N>& keys, int i)
{
    const double t = static_cast<double>(i) / (kTexelCount - 1);
    for (std::size_t k = 0; k + 1 < keys.size(); ++k) {
        const Key& lo = keys[k];
        const Key& hi = keys[k + 1];
        if (t <= hi.position) {
            return mix(lo.color, hi.color, smoothstep((t - lo.position) / (hi.position - lo.position)));
        }
    }
    return keys.back().color;
}

EncodedColor terrain(int i)
{
    static const std::array<Key, 6> keys = {{
        {0.00, {10, 30, 90}},     // deep water
        {0.30, {40, 120, 190}},   // shallow water
        {0.40, {225, 205, 145}},  // sand
        {0.55, {70, 150, 60}},    // grass
        {0.80, {125, 110, 95}},   // rock
        {1.00, {250, 250, 250}},  // snow
    }};
    return keyed(keys, i);
}

// ---------------------------------------------------------------------------
// sand-snow.png: a colour map over microsurface heights (laid over
// [-3 sigma_h, 3 sigma_h] in the bundled scenes): damp soil in the hollows,
// sand, rock, and snow on the crests above a sharp snow line. Key colours
// (sRGB-encoded) at positions t, blended as terrain.png's:
//   t = 0.00 damp soil ( 60,  45,  35)
//   t = 0.35 sand      (205, 175, 115)
//   t = 0.55 rock      (115, 105,  95)
//   t = 0.62 rock      (115, 105,  95)
//   t = 0.68 snow      (245, 248, 255)
//   t = 1.00 snow      (250, 250, 255)
// ---------------------------------------------------------------------------
EncodedColor sand_snow(int i)
{
    static const std::array<Key, 6> keys = {{
        {0.00, {60, 45, 35}},     // damp soil
        {0.35, {205, 175, 115}},  // sand
        {0.55, {115, 105, 95}},   // rock
        {0.62, {115, 105, 95}},   // rock
        {0.68, {245, 248, 255}},  // snow line
        {1.00, {250, 250, 255}},  // snow
    }};
    return keyed(keys, i);
}

// ---------------------------------------------------------------------------
// stripes.png: 8 equal hard stripes of 32 texels each. Stripe s = floor(i / 32);
// even stripes are dark red (120, 10, 20), odd stripes pale cyan
// (170, 235, 240). No transition texels.
// ---------------------------------------------------------------------------
EncodedColor stripes(int i)
{
    const EncodedColor dark_red{120, 10, 20};
    const EncodedColor pale_cyan{170, 235, 240};
    const int stripe = i / (kTexelCount / 8);
    return stripe % 2 == 0 ? dark_red : pale_cyan;
}

// ---------------------------------------------------------------------------
// step.png: one sharp step at the middle of the domain. Texels 0..127 are dark
// navy (15, 25, 80), texels 128..255 bright orange (255, 150, 20).
// ---------------------------------------------------------------------------
EncodedColor step(int i)
{
    const EncodedColor dark_navy{15, 25, 80};
    const EncodedColor bright_orange{255, 150, 20};
    return i < kTexelCount / 2 ? dark_navy : bright_orange;
}

// ---------------------------------------------------------------------------
// narrow-band.png: a dark grey background (40, 40, 40) with one bright yellow
// band (255, 230, 40) 4 texels wide centred at u = 0.7. Texel i belongs to the
// band when its centre lies within 2 texels of 0.7, i.e.
// |(i + 0.5) - 0.7 * 256| <= 2, which selects texels 177..180.
// ---------------------------------------------------------------------------
EncodedColor narrow_band(int i)
{
    const EncodedColor dark_grey{40, 40, 40};
    const EncodedColor bright_yellow{255, 230, 40};
    const double band_centre = 0.7 * kTexelCount;  // in texels
    const double band_half_width = 2.0;            // in texels
    return std::fabs((i + 0.5) - band_centre) <= band_half_width ? bright_yellow : dark_grey;
}

// ---------------------------------------------------------------------------
// snake-green.png: a snake's base skin over a noise: dark olive (40, 60, 20)
// at t = 0, green (90, 140, 40) at 0.5, yellow-green (170, 190, 70) at 1,
// blended as terrain.png's (texel i at t = i / 255).
// ---------------------------------------------------------------------------
EncodedColor snake_green(int i)
{
    static const std::array<Key, 3> keys = {{
        {0.0, {40, 60, 20}},
        {0.5, {90, 140, 40}},
        {1.0, {170, 190, 70}},
    }};
    return keyed(keys, i);
}

// ---------------------------------------------------------------------------
// snake-rims.png: a steepness map for scales, laid over [0, 90] degrees
// (texel i at angle 90 i / 255): cream scale tops, red flanks, black rims.
//   0 and 15 degrees  cream (235, 220, 170)
//   30 and 40 degrees red   (190, 40, 25)
//   55 and 90 degrees black (20, 10, 10)
// ---------------------------------------------------------------------------
EncodedColor snake_rims(int i)
{
    static const std::array<Key, 6> keys = {{
        {0.0 / 90, {235, 220, 170}},
        {15.0 / 90, {235, 220, 170}},
        {30.0 / 90, {190, 40, 25}},
        {40.0 / 90, {190, 40, 25}},
        {55.0 / 90, {20, 10, 10}},
        {90.0 / 90, {20, 10, 10}},
    }};
    return keyed(keys, i);
}

// A hue h in [0, 1) at saturation s and value 1, by the HSV formula of
// hue-ramp.png: each channel 255 (1 - s (1 - unit channel)).
EncodedColor hue_at(double h, double saturation)
{
    const double sector = 6.0 * (h - std::floor(h));
    const double x = 1.0 - std::fabs(std::fmod(sector, 2.0) - 1.0);
    EncodedColor unit{0, 0, 0};
    switch (std::min(5, static_cast<int>(sector))) {
    case 0: unit = {1, x, 0}; break;
    case 1: unit = {x, 1, 0}; break;
    case 2: unit = {0, 1, x}; break;
    case 3: unit = {0, x, 1}; break;
    case 4: unit = {x, 0, 1}; break;
    default: unit = {1, 0, x}; break;
    }
    const auto channel = [&](double c) { return 255.0 * (1.0 - saturation * (1.0 - c)); };
    return {channel(unit.r), channel(unit.g), channel(unit.b)};
}

// ---------------------------------------------------------------------------
// hue-ramp.png: a full hue circle at full saturation and value, computed in
// encoded space with the standard HSV -> RGB formula. Texel i has hue
// h = 360 * i / 256 degrees (so the ramp is periodic: texel 255 leads back
// into texel 0). With H = h / 60, X = 1 - |H mod 2 - 1|, (r, g, b) is
// (1,X,0), (X,1,0), (0,1,X), (0,X,1), (X,0,1), (1,0,X) for floor(H) = 0..5,
// each scaled by 255.
// ---------------------------------------------------------------------------
EncodedColor hue_ramp(int i) { return hue_at(static_cast<double>(i) / kTexelCount, 1.0); }

// ---------------------------------------------------------------------------
// grass-rock.png: a steepness map, laid over slope angles [0, 90] degrees
// (texel i at angle 90 i / 255): grass on the flat, rock on the slopes, a dark
// cliff face on the steepest. Keys (sRGB-encoded) blended as terrain.png's:
//   0 and 25 degrees  grass (92, 148, 51)
//   35 and 60 degrees rock  (140, 128, 115)
//   70 and 90 degrees cliff (64, 56, 51)
// ---------------------------------------------------------------------------
EncodedColor grass_rock(int i)
{
    static const std::array<Key, 6> keys = {{
        {0.0 / 90, {92, 148, 51}},     // grass
        {25.0 / 90, {92, 148, 51}},    // grass
        {35.0 / 90, {140, 128, 115}},  // rock
        {60.0 / 90, {140, 128, 115}},  // rock
        {70.0 / 90, {64, 56, 51}},     // cliff
        {90.0 / 90, {64, 56, 51}},     // cliff
    }};
    return keyed(keys, i);
}

// ---------------------------------------------------------------------------
// slope-wheel.png: a 64 x 64 slope-vector map, laid over the slope plane
// [-s_max, s_max]^2 (row 0 at s_y = +s_max, column 0 at s_x = -s_max). Texel
// (i, j) has the normalised slope a = -1 + (2 i + 1) / 64, b = 1 - (2 j + 1) /
// 64; its hue is the slope's direction, atan2(b, a) / (2 pi), and its
// saturation min(1, 2 sqrt(a^2 + b^2)): white on the flat, full colour from
// half of s_max on.
// ---------------------------------------------------------------------------
constexpr int kWheelSide = 64;

EncodedColor slope_wheel(int i, int j)
{
    const double a = -1.0 + (2.0 * i + 1.0) / kWheelSide, b = 1.0 - (2.0 * j + 1.0) / kWheelSide;
    const double pi = 3.14159265358979323846;
    return hue_at(std::atan2(b, a) / (2 * pi), std::min(1.0, 2 * std::hypot(a, b)));
}

struct ColorMapDefinition {
    const char* file_name;
    std::function<EncodedColor(int, int)> texel;  // (column, row)
    int width = kTexelCount, height = 1;
};

// A 256 x 1 gradient's definition.
ColorMapDefinition gradient(const char* file_name, EncodedColor (*texel)(int))
{
    return {file_name, [texel](int i, int) { return texel(i); }};
}

std::uint8_t to_code(double encoded) { return static_cast<std::uint8_t>(std::lround(std::clamp(encoded, 0.0, 255.0))); }

std::vector<std::uint8_t> evaluate(const ColorMapDefinition& map)
{
    std::vector<std::uint8_t> pixels;
    pixels.reserve(static_cast<std::size_t>(3 * map.width * map.height));
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            const EncodedColor c = map.texel(i, j);
            pixels.push_back(to_code(c.r));
            pixels.push_back(to_code(c.g));
            pixels.push_back(to_code(c.b));
        }
    return pixels;
}

// Writes `pixels` as a width x height RGB 8-bit sRGB PNG at `destination`, via a
// temporary file in the same directory (same extension, so OpenImageIO picks
// the PNG writer) that is renamed into place only once fully written.
// Returns an empty string on success, otherwise a message naming the path.
std::string write_png_atomically(const std::filesystem::path& destination, int width, int height,
                                 const std::vector<std::uint8_t>& pixels)
{
    const std::filesystem::path temp =
        destination.parent_path() /
        ("." + destination.stem().string() + ".tmp" + std::to_string(::getpid()) + destination.extension().string());

    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");

    auto output = OIIO::ImageOutput::create(temp.string());
    if (!output) return "cannot create a PNG writer for '" + temp.string() + "': " + OIIO::geterror();
    const bool written = output->open(temp.string(), spec) &&
                         output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && output->close();
    if (!written) {
        const std::string reason = output->geterror();
        output.reset();
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        return "cannot write '" + temp.string() + "': " + reason;
    }
    output.reset();

    std::error_code renamed;
    std::filesystem::rename(temp, destination, renamed);
    if (renamed) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        return "cannot rename '" + temp.string() + "' to '" + destination.string() + "': " + renamed.message();
    }
    return {};
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: cmfilter-make-luts OUTPUT_DIRECTORY\n"
                     "Writes the example colour maps (RGB 8-bit sRGB PNGs) into\n"
                     "OUTPUT_DIRECTORY, replacing any files of the same names.\n";
        return 1;
    }
    const std::filesystem::path output_directory = argv[1];
    std::error_code status;
    if (!std::filesystem::is_directory(output_directory, status)) {
        std::cerr << "cmfilter-make-luts: output directory '" << output_directory.string()
                  << "' does not exist or is not a directory\n";
        return 2;
    }

    const std::vector<ColorMapDefinition> maps = {
        gradient("terrain.png", terrain),
        gradient("stripes.png", stripes),
        gradient("step.png", step),
        gradient("narrow-band.png", narrow_band),
        gradient("hue-ramp.png", hue_ramp),
        gradient("sand-snow.png", sand_snow),
        gradient("grass-rock.png", grass_rock),
        {"slope-wheel.png", slope_wheel, kWheelSide, kWheelSide},
        gradient("snake-green.png", snake_green),
        gradient("snake-rims.png", snake_rims),
    };
    for (const ColorMapDefinition& map : maps) {
        const std::string error =
            write_png_atomically(output_directory / map.file_name, map.width, map.height, evaluate(map));
        if (!error.empty()) {
            std::cerr << "cmfilter-make-luts: " << error << "\n";
            return 2;
        }
    }
    return 0;
}
