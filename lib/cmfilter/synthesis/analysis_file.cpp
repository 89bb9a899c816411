// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/analysis_file.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/artefact_file.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <map>

namespace cmfilter {

namespace {

// An integral value as text, however large: casting one past long long's
// range to print it is undefined.
std::string integral_text(double v)
{
    char text[64];
    std::snprintf(text, sizeof text, "%.0f", v);
    return text;
}

constexpr int kFormatVersion = 1;
// Indices are stored as floats: exact up to 2^24.
constexpr double kLargestIndex = 16777216.0;

std::string texels_name(std::size_t level) { return "level-" + std::to_string(level) + "-texels"; }
std::string dot_name(std::size_t level) { return "level-" + std::to_string(level) + "-dot"; }

bool parse_sample_kind(const std::string& name, SampleKind* kind)
{
    for (SampleKind k : {SampleKind::Image, SampleKind::Stack, SampleKind::Btf})
        if (name == to_string(k)) {
            *kind = k;
            return true;
        }
    return false;
}

bool is_hex_digest(const std::string& s)
{
    if (s.size() != 64) return false;
    for (char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

Status check_level(const std::string& path, std::size_t l, const LevelAnalysis& level)
{
    const std::size_t texels = level.texels();
    if (level.width <= 0 || level.height <= 0 || level.textons < 1 || level.candidates < 1 ||
        level.texton.size() != texels || level.similar.size() != texels * level.candidates ||
        level.dot.size() != static_cast<std::size_t>(level.textons) * level.textons ||
        static_cast<double>(texels) > kLargestIndex || static_cast<std::size_t>(level.textons) > texels ||
        static_cast<std::size_t>(level.candidates) >= texels)
        return bad_input("the analysis for '" + path + "' is inconsistent at level " + std::to_string(l) + ": " +
                         std::to_string(level.width) + " x " + std::to_string(level.height) + " texels, " +
                         std::to_string(level.textons) + " textons, " + std::to_string(level.candidates) +
                         " candidates");
    for (std::int32_t t : level.texton)
        if (t < 0 || t >= level.textons)
            return bad_input("the analysis for '" + path + "' has texton " + std::to_string(t) + " at level " +
                             std::to_string(l) + "; expected [0, " + std::to_string(level.textons) + ")");
    for (std::int32_t q : level.similar)
        if (q < 0 || static_cast<std::size_t>(q) >= texels)
            return bad_input("the analysis for '" + path + "' has candidate texel " + std::to_string(q) + " at level " +
                             std::to_string(l) + "; expected [0, " + std::to_string(texels) + ")");
    for (float v : level.dot)
        if (!std::isfinite(v))
            return bad_input("the analysis for '" + path + "' has non-finite dot products at level " +
                             std::to_string(l));
    return ok();
}

}  // namespace

Status write_analysis_exr(const std::string& path, const SampleAnalysis& analysis)
{
    if (analysis.levels.empty()) return bad_input("the analysis for '" + path + "' has no levels");
    for (std::size_t l = 0; l < analysis.levels.size(); ++l)
        if (auto st = check_level(path, l, analysis.levels[l]); !st) return st;
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();

    std::vector<OIIO::ImageSpec> specs;
    std::vector<std::vector<float>> pixels;
    for (std::size_t l = 0; l < analysis.levels.size(); ++l) {
        const LevelAnalysis& level = analysis.levels[l];
        const int m = level.candidates;
        OIIO::ImageSpec texels(level.width, level.height, 1 + m, OIIO::TypeDesc::FLOAT);
        texels.channelnames.clear();
        texels.channelnames.push_back("texton");
        for (int c = 0; c < m; ++c) texels.channelnames.push_back("c" + std::to_string(c));
        texels.attribute("oiio:subimagename", texels_name(l));
        texels.attribute("compression", "zip");
        texels.attribute("cmfilter:level", static_cast<int>(l));
        texels.attribute("cmfilter:textons", level.textons);
        texels.attribute("cmfilter:candidates", m);
        set_double_attribute(texels, "cmfilter:inertia", level.inertia);
        if (l == 0) {
            texels.attribute("cmfilter:kind", kSynthesisAnalysisKind);
            texels.attribute("cmfilter:format_version", kFormatVersion);
            texels.attribute("cmfilter:version", version());
            texels.attribute("cmfilter:levels", static_cast<int>(analysis.levels.size()));
            texels.attribute("cmfilter:sample", path_for_record(analysis.sample_path, path));
            texels.attribute("cmfilter:sample_kind", to_string(analysis.sample_kind));
            texels.attribute("cmfilter:sample_hash", analysis.sample_hash);
            texels.attribute("cmfilter:sample_images", analysis.sample_images);
            texels.attribute("cmfilter:images_used", analysis.images_used);
            texels.attribute("cmfilter:channels", analysis.channels);
            texels.attribute("cmfilter:periodic", analysis.periodic ? 1 : 0);
            texels.attribute("cmfilter:neighbourhood", analysis.neighbourhood);
        }
        std::vector<float> tp(level.texels() * static_cast<std::size_t>(1 + m));
        for (std::size_t t = 0; t < level.texels(); ++t) {
            tp[t * (1 + m)] = static_cast<float>(level.texton[t]);
            for (int c = 0; c < m; ++c) tp[t * (1 + m) + 1 + c] = static_cast<float>(level.similar[t * m + c]);
        }
        specs.push_back(texels);
        pixels.push_back(std::move(tp));

        OIIO::ImageSpec dot(level.textons, level.textons, 1, OIIO::TypeDesc::FLOAT);
        dot.channelnames = {"M"};
        dot.attribute("oiio:subimagename", dot_name(l));
        dot.attribute("compression", "zip");
        dot.attribute("cmfilter:level", static_cast<int>(l));
        specs.push_back(dot);
        pixels.push_back(level.dot);
    }

    return write_float_artefact_parts(*out, std::move(specs), pixels);
}

Expected<SampleAnalysis> read_analysis_exr(const std::string& path)
{
    auto opened = open_image_input(path);
    if (!opened) return opened.error();
    std::unique_ptr<OIIO::ImageInput> in = std::move(*opened);
    const OIIO::ImageSpec spec0 = in->spec();
    if (auto st = check_artefact_kind(spec0, path, kSynthesisAnalysisKind, "synthesis analysis", kFormatVersion); !st)
        return st.error();
    auto bad = [&](const std::string& what) { return bad_input("'" + path + "' " + what); };

    SampleAnalysis analysis;
    analysis.sample_path = path_from_record(spec0.get_string_attribute("cmfilter:sample"), path);
    analysis.sample_hash = spec0.get_string_attribute("cmfilter:sample_hash");
    if (!is_hex_digest(analysis.sample_hash))
        return bad("has cmfilter:sample_hash '" + analysis.sample_hash + "'; expected 64 lowercase hex digits");
    const std::string kind = spec0.get_string_attribute("cmfilter:sample_kind");
    if (!parse_sample_kind(kind, &analysis.sample_kind))
        return bad("has an unknown cmfilter:sample_kind '" + kind + "' (expected image, stack or btf)");
    analysis.sample_images = spec0.get_int_attribute("cmfilter:sample_images", 0);
    analysis.images_used = spec0.get_int_attribute("cmfilter:images_used", 0);
    analysis.channels = spec0.get_int_attribute("cmfilter:channels", 0);
    if (analysis.sample_images < 1 || analysis.images_used < 1 || analysis.images_used > analysis.sample_images ||
        analysis.channels < 1)
        return bad("has cmfilter:sample_images " + std::to_string(analysis.sample_images) + ", cmfilter:images_used " +
                   std::to_string(analysis.images_used) + " and cmfilter:channels " +
                   std::to_string(analysis.channels) +
                   "; expected 1 <= images_used <= sample_images and channels >= 1");
    const int periodic = spec0.get_int_attribute("cmfilter:periodic", -1);
    if (periodic != 0 && periodic != 1)
        return bad("has cmfilter:periodic " + std::to_string(periodic) + "; expected 0 or 1");
    analysis.periodic = periodic == 1;
    analysis.neighbourhood = spec0.get_int_attribute("cmfilter:neighbourhood", 0);
    // No time is written (outputs are the same bytes for the same inputs);
    // files that record one must record a valid one.
    if (spec0.find_attribute("cmfilter:seconds")) {
        analysis.seconds = double_attribute(spec0, "cmfilter:seconds");
        if (!std::isfinite(analysis.seconds) || analysis.seconds < 0)
            return bad("has no valid cmfilter:seconds; expected a time >= 0");
    }
    const int levels = spec0.get_int_attribute("cmfilter:levels", 0);
    if (levels < 1) return bad("has cmfilter:levels " + std::to_string(levels) + "; expected >= 1");

    for (int l = 0; l < levels; ++l) {
        const std::size_t level_index = static_cast<std::size_t>(l);
        LevelAnalysis level;
        // The texels subimage: texton and candidate indices by channel name
        // (OpenEXR stores channels sorted by name).
        if (!in->seek_subimage(2 * l, 0)) return bad("has no subimage " + texels_name(level_index));
        const OIIO::ImageSpec ts = in->spec();
        const std::string tname = ts.get_string_attribute("oiio:subimagename");
        if (tname != texels_name(level_index))
            return bad("has subimage " + std::to_string(2 * l) + " named '" + tname + "'; expected '" +
                       texels_name(level_index) + "'");
        level.width = ts.width;
        level.height = ts.height;
        level.textons = ts.get_int_attribute("cmfilter:textons", 0);
        level.candidates = ts.nchannels - 1;
        level.inertia = double_attribute(ts, "cmfilter:inertia");
        if (!std::isfinite(level.inertia) || level.inertia < 0)
            return bad("has no valid cmfilter:inertia on " + tname + "; expected a value >= 0");
        if (ts.get_int_attribute("cmfilter:candidates", -1) != level.candidates || level.candidates < 1)
            return bad("has " + std::to_string(ts.nchannels) + " channels in " + tname + " and cmfilter:candidates " +
                       std::to_string(ts.get_int_attribute("cmfilter:candidates", -1)) +
                       "; expected texton and c0 .. c{m-1}, m >= 1");
        if (level.width < 1 || level.height < 1 || level.textons < 1 ||
            static_cast<double>(level.texels()) > kLargestIndex)
            return bad("has " + tname + " of " + std::to_string(level.width) + " x " + std::to_string(level.height) +
                       " texels and " + std::to_string(level.textons) + " textons; inconsistent sizes");
        if (l > 0) {
            const LevelAnalysis& finer = analysis.levels.back();
            if (level.width != (finer.width + 1) / 2 || level.height != (finer.height + 1) / 2)
                return bad("has " + tname + " of " + std::to_string(level.width) + " x " +
                           std::to_string(level.height) + " under a level of " + std::to_string(finer.width) + " x " +
                           std::to_string(finer.height) + "; inconsistent sizes (each level halves the one before)");
        }
        std::map<std::string, int> column;
        for (int c = 0; c < ts.nchannels; ++c) column[ts.channelnames[static_cast<std::size_t>(c)]] = c;
        std::vector<int> source(static_cast<std::size_t>(1 + level.candidates));
        for (int c = 0; c <= level.candidates; ++c) {
            const std::string name = c == 0 ? std::string("texton") : "c" + std::to_string(c - 1);
            const auto it = column.find(name);
            if (it == column.end()) return bad("has no channel " + name + " in " + tname);
            source[static_cast<std::size_t>(c)] = it->second;
        }
        if (auto fits = check_image_allocation(ts, path, ts.nchannels, 2); !fits) return fits.error();
        std::vector<float> tp(level.texels() * static_cast<std::size_t>(ts.nchannels));
        if (!read_float_pixels(*in, 2 * l, 0, 0, ts.nchannels, tp.data()))
            return io_error("cannot read '" + path + "': " + in->geterror());
        const std::size_t texels = level.texels();
        level.texton.resize(texels);
        level.similar.resize(texels * static_cast<std::size_t>(level.candidates));
        for (std::size_t t = 0; t < texels; ++t)
            for (int c = 0; c <= level.candidates; ++c) {
                const float v = tp[t * ts.nchannels + static_cast<std::size_t>(source[static_cast<std::size_t>(c)])];
                const double limit = c == 0 ? level.textons : static_cast<double>(texels);
                const std::string what = c == 0 ? "texton" : "candidate texel";
                if (!std::isfinite(v) || v != std::floor(v))
                    return bad("has a non-integral " + what + " index " + std::to_string(v) + " in " + tname +
                               " at texel (" + std::to_string(t % level.width) + ", " +
                               std::to_string(t / level.width) + ")");
                if (v < 0 || v >= limit || (c > 0 && static_cast<std::size_t>(v) == t))
                    return bad("has " + what + " index " + integral_text(v) + " in " + tname + " at texel (" +
                               std::to_string(t % level.width) + ", " + std::to_string(t / level.width) +
                               "); expected [0, " + integral_text(limit) + ")" +
                               (c > 0 ? " and not the texel itself" : ""));
                if (c == 0) level.texton[t] = static_cast<std::int32_t>(v);
                else
                    level.similar[t * level.candidates + static_cast<std::size_t>(c - 1)] =
                        static_cast<std::int32_t>(v);
            }

        // The dot subimage: M, textons x textons, finite and symmetric.
        if (!in->seek_subimage(2 * l + 1, 0)) return bad("has no subimage " + dot_name(level_index));
        const OIIO::ImageSpec ds = in->spec();
        const std::string dname = ds.get_string_attribute("oiio:subimagename");
        if (dname != dot_name(level_index))
            return bad("has subimage " + std::to_string(2 * l + 1) + " named '" + dname + "'; expected '" +
                       dot_name(level_index) + "'");
        if (ds.width != level.textons || ds.height != level.textons || ds.nchannels != 1 || ds.channelnames[0] != "M")
            return bad("has " + dname + " of " + std::to_string(ds.width) + " x " + std::to_string(ds.height) + " x " +
                       std::to_string(ds.nchannels) + "; expected " + std::to_string(level.textons) + " x " +
                       std::to_string(level.textons) + " of channel M (the level's textons)");
        if (auto fits = check_image_allocation(ds, path, 1); !fits) return fits.error();
        level.dot.resize(static_cast<std::size_t>(level.textons) * level.textons);
        if (!read_float_pixels(*in, 2 * l + 1, 0, 0, 1, level.dot.data()))
            return io_error("cannot read '" + path + "': " + in->geterror());
        const int k = level.textons;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j <= i; ++j) {
                const float a = level.dot[static_cast<std::size_t>(i) * k + j];
                const float b = level.dot[static_cast<std::size_t>(j) * k + i];
                if (!std::isfinite(a) || !std::isfinite(b))
                    return bad("has a non-finite dot product in " + dname + " at (" + std::to_string(i) + ", " +
                               std::to_string(j) + ")");
                if (a != b)
                    return bad("has a non-symmetric dot-product matrix in " + dname + ": M(" + std::to_string(i) +
                               ", " + std::to_string(j) + ") != M(" + std::to_string(j) + ", " + std::to_string(i) +
                               ")");
            }
        analysis.levels.push_back(std::move(level));
    }
    if (in->seek_subimage(2 * levels, 0))
        return bad("has more subimages than its cmfilter:levels " + std::to_string(levels) + " describe");
    const LevelAnalysis& coarsest = analysis.levels.back();
    if (analysis.neighbourhood < 1 || 2 * analysis.neighbourhood + 1 > std::min(coarsest.width, coarsest.height))
        return bad("has cmfilter:neighbourhood " + std::to_string(analysis.neighbourhood) +
                   "; expected >= 1 with a (2n + 1)^2 window within the coarsest level (" +
                   std::to_string(coarsest.width) + " x " + std::to_string(coarsest.height) + ")");
    return analysis;
}

Status check_analysis_matches(const SampleAnalysis& analysis, const std::string& analysis_path,
                              const SynthesisSample& sample)
{
    const std::string sample_name = sample.path.empty() ? std::string("the sample in memory") : "'" + sample.path + "'";
    if (analysis.sample_hash != sample.hash)
        return bad_input("analysis '" + analysis_path + "' was made from sample '" + analysis.sample_path + "' (hash " +
                         analysis.sample_hash + "), not from " + sample_name + " (hash " + sample.hash + ")");
    if (analysis.width() != sample.width() || analysis.height() != sample.height() ||
        analysis.images_used != static_cast<int>(sample.used.size()) || analysis.channels != sample.channels)
        return bad_input("analysis '" + analysis_path + "' describes " + std::to_string(analysis.width()) + " x " +
                         std::to_string(analysis.height()) + " texels of " + std::to_string(analysis.images_used) +
                         " images of " + std::to_string(analysis.channels) + " channels, but sample " + sample_name +
                         " holds " + std::to_string(sample.width()) + " x " + std::to_string(sample.height()) +
                         " texels of " + std::to_string(sample.used.size()) + " images of " +
                         std::to_string(sample.channels) + " channels");
    return ok();
}

}  // namespace cmfilter
