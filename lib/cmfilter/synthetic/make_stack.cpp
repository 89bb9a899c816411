// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthetic/make_stack.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/synthetic/synthetic_stack.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/sha256.h"
#include "cmfilter/util/stale_temporary_outputs.h"
#include "cmfilter/util/stopwatch.h"
#include "cmfilter/util/temporary_output_name.h"
#include "cmfilter/util/version.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace cmfilter {

namespace {

namespace fs = std::filesystem;

std::string vector_text(const Vec3& v)
{
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

// "stack-007.exr": at least 3 digits, as many as the count needs.
std::string image_name(const std::string& stem, std::size_t k, std::size_t count, const std::string& extension)
{
    const std::size_t digits = std::max<std::size_t>(3, std::to_string(count - 1).size());
    std::string number = std::to_string(k);
    number.insert(0, digits - std::min(digits, number.size()), '0');
    return stem + "-" + number + extension;
}

// The record (stack_record.h), written atomically.
Status write_stack_record(const std::string& path, const nlohmann::json& record)
{
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    {
        std::ofstream f(out->temp_path());
        f << record.dump(2) << "\n";
        f.close();
        if (!f) return out->write_error("the stack record could not be written");
    }
    return out->commit();
}

// The direction as the light file writes it (9 significant digits).
Vec3 as_written(const Vec3& d)
{
    const auto round = [](double v) {
        char text[40];
        std::snprintf(text, sizeof text, "%.9g", v);
        return std::strtod(text, nullptr);
    };
    return {round(d.x), round(d.y), round(d.z)};
}

Status check_views(const std::vector<Vec3>& views)
{
    if (views.empty())
        return bad_input("MakeStackOptions::views is empty: expected one view or more", "MakeStackOptions::views");
    for (std::size_t k = 0; k < views.size(); ++k) {
        const Vec3& v = views[k];
        const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        const std::string which = views.size() > 1 ? " " + std::to_string(k) : "";
        if (!finite || !(length(v) > 0))
            return bad_input("MakeStackOptions::views" + which + " " + vector_text(v) +
                                 " is invalid: expected a finite, nonzero direction towards the camera",
                             "MakeStackOptions::views");
        if (!(v.z > 0))
            return bad_input("MakeStackOptions::views" + which + " " + vector_text(v) +
                                 " is not above the horizon: expected z > 0 (the camera sees the surface from above)",
                             "MakeStackOptions::views");
    }
    return ok();
}

// A folder beside the output that every file of a run is written into
// first, named as AtomicOutput names its temporary files but without the
// extension (".<stem>.tmp-<host>-<pid>-<hex>", temporary_output_name.h),
// removed with what it holds unless its files were moved into place. The
// folders of runs killed before they finished are removed by the next run
// (stale_temporary_outputs.h).
class StagingFolder {
public:
    static Expected<StagingFolder> create(const fs::path& output)
    {
        fs::path dir = output.parent_path();
        if (dir.empty()) dir = ".";
        StaleTemporaryOptions stale;
        stale.destination = (dir / output.stem()).string();
        (void)remove_stale_temporary_outputs(stale);
        StagingFolder staging;
        staging.path_ = dir / new_temporary_output_name(output.stem().string());
        std::error_code ec;
        if (!fs::create_directory(staging.path_, ec) || ec)
            return io_error("cannot write '" + output.string() + "': cannot make the folder '" +
                            staging.path_.string() + "' to write it in: " + ec.message());
        return staging;
    }
    StagingFolder(StagingFolder&& o) noexcept : path_(std::move(o.path_)) { o.path_.clear(); }
    StagingFolder(const StagingFolder&) = delete;
    StagingFolder& operator=(const StagingFolder&) = delete;
    ~StagingFolder()
    {
        std::error_code ec;
        if (!path_.empty()) fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

    // Moves every file into the same place under `destination`: first the
    // destination's old light files and manifest are removed (a stack is
    // complete only while its .lp exists), then the images, normals and
    // records go into place, then the .lp files, then the manifest.
    Status commit(const fs::path& destination, const std::vector<fs::path>& last)
    {
        std::error_code ec;
        std::vector<fs::path> files;
        for (const auto& entry : fs::recursive_directory_iterator(path_, ec))
            if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), path_, ec));
        if (ec) return io_error("cannot list '" + path_.string() + "': " + ec.message());
        std::sort(files.begin(), files.end());
        const auto is_last = [&](const fs::path& f) { return std::find(last.begin(), last.end(), f) != last.end(); };
        // Nothing is moved unless every file can take its place.
        for (const fs::path& f : files) {
            if (fs::is_directory(destination / f, ec))
                return io_error("cannot write '" + (destination / f).string() + "': it is a directory");
            const fs::path folder = (destination / f).parent_path();
            if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
                return io_error("cannot write '" + (destination / f).string() + "': '" + folder.string() +
                                "' is not a folder");
        }
        for (const fs::path& f : last) fs::remove(destination / f, ec);
        const auto move = [&](const fs::path& f) -> Status {
            fs::create_directories((destination / f).parent_path(), ec);
            fs::rename(path_ / f, destination / f, ec);
            if (ec)
                return io_error("cannot move '" + (path_ / f).string() + "' to '" + (destination / f).string() +
                                "': " + ec.message());
            return ok();
        };
        for (const fs::path& f : files)
            if (!is_last(f))
                if (auto st = move(f); !st) return st;
        for (const fs::path& f : last)  // in their order: the manifest after the light files
            if (auto st = move(f); !st) return st;
        fs::remove_all(path_, ec);
        path_.clear();
        return ok();
    }

private:
    StagingFolder() = default;
    fs::path path_;
};

struct Slot {
    fs::path light_file;   // the slot's .lp
    std::string relative;  // as the manifest names it
    Vec3 view;
    fs::path placed;  // light_file where it will lie once the staging folder is committed
};

// Writes one view slot's files, its .lp last.
Status write_slot(const Slot& slot, std::size_t index, std::size_t slots, const SyntheticStack& stack,
                  const std::vector<Vec3>& written, const MakeStackOptions& options, const std::string& scene_path,
                  const std::string& scene_digest, const SyntheticSurface& surface, const ColorConfig& config,
                  MadeStack& made)
{
    const fs::path folder = slot.light_file.parent_path();
    const std::string stem = slot.light_file.stem().string();
    const std::size_t count = stack.lights.size(), texels = stack.texels();
    const bool exr = options.image_extension == ".exr";
    std::vector<LightEntry> entries;
    std::vector<float> image(texels * 3);
    for (std::size_t k = 0; k < count; ++k) {
        const std::string name = image_name(stem, k, count, options.image_extension);
        const float* p = stack.image(k);
        image.assign(p, p + texels * 3);
        const Vec3& l = stack.lights[k];
        ImageAttributes a;
        a.text = {{"cmfilter:kind", "synthetic-stack-image"},
                  {"cmfilter:version", version()},
                  {"cmfilter:light", vector_text(l)},
                  {"cmfilter:view", vector_text(stack.view)}};
        if (auto st = write_rgb_image((folder / name).string(), stack.size, stack.size, 3, image,
                                      exr ? config.scene_linear_name() : "", a, config);
            !st)
            return st;
        ++made.files;
        entries.push_back({name, written[k], 0});
    }
    ImageAttributes na;
    na.text = {{"cmfilter:kind", "synthetic-normals"},
               {"cmfilter:version", version()},
               {"cmfilter:frame", "x right, y up (top row), z towards the camera"}};
    const std::string normals = stem + ".normals.exr";
    if (auto st =
            write_rgb_image((folder / normals).string(), stack.size, stack.size, 3, stack.normals, "", na, config);
        !st)
        return st;
    ++made.files;
    std::string albedo;
    if (options.albedo) {
        albedo = stem + ".albedo.exr";
        ImageAttributes aa;
        aa.text = {{"cmfilter:kind", "synthetic-albedo"}, {"cmfilter:version", version()}};
        if (auto st = write_rgb_image((folder / albedo).string(), stack.size, stack.size, 3, stack.albedo,
                                      config.scene_linear_name(), aa, config);
            !st)
            return st;
        ++made.files;
    }

    nlohmann::json r;
    r["format"] = "cmfilter-synthetic-stack";
    r["version"] = kStackRecordVersion;
    r["cmfilter_version"] = version();
    r["scene_sha256"] = scene_digest;
    r["surface"] = options.surface;
    r["surface_kind"] = to_string(surface.kind());
    r["tile"] = surface.tile();
    r["view"] = {stack.view.x, stack.view.y, stack.view.z};
    r["view_slot"] = index;
    r["view_slots"] = slots;
    r["size"] = stack.size;
    r["samples"] = options.samples;
    r["seed"] = options.seed;
    r["specular"] = specular_text(options.specular);
    r["dome"] = {{"spec", dome_text(options.dome)},
                 {"min_elevation_degrees", options.dome.min_elevation_degrees},
                 {"count", count}};
    r["lights"] = slot.light_file.filename().string();
    r["images"] = options.image_extension;
    r["image_encoding"] = exr ? "scene-linear float" : "8-bit sRGB, clipped to [0, 1]";
    r["normals"] = normals;
    r["albedo"] = options.albedo ? nlohmann::json(albedo) : nlohmann::json(nullptr);
    r["frame"] = "stack: x right, y up (towards the top row), z towards the camera; the heightfield's (u, v, h) "
                 "is (x, -y, z); pixel (i, j) covers u in [i, i+1] tile/size, v in [j, j+1] tile/size";
    r["shading"] = "V <m,l>+ (colour + pi f_spec(m, l, v)) per visible hit, averaged over the pixel's rays; a white "
                   "Lambertian facet facing the light gives 1";
    r["rays"] = stack.rays;
    r["hits"] = stack.hits;
    // No time: the same inputs give the same bytes (the --json summary has it).
    const std::string record = stack_record_path(slot.light_file.string());
    // Relative to where the record will lie, not to the staging folder.
    r["scene"] = path_for_record(scene_path, stack_record_path(slot.placed.string()));
    if (auto st = write_stack_record(record, r); !st) return st;
    ++made.files;
    if (auto st = write_light_file(slot.light_file.string(), entries); !st) return st;
    ++made.files;
    made.light_files.push_back(slot.light_file.string());
    made.records.push_back(record);
    return ok();
}

}  // namespace

std::string stack_record_path(const std::string& light_file)
{
    return fs::path(light_file).replace_extension(".json").string();
}

Expected<MadeStack> make_stack(const MakeStackOptions& options, const ColorConfig& config)
{
    const Stopwatch clock;
    if (auto st = check_views(options.views); !st) return st.error();
    const bool several = options.views.size() > 1;
    if (auto st = check_output_path(options.output, several ? ".json" : ".lp"); !st)
        return Error{st.error().kind,
                     st.error().message + (several ? " (several views: the BTF manifest, .json)"
                                                   : " (one view: the stack's light file, .lp)"),
                     "MakeStackOptions::output"};
    if (options.image_extension != ".exr" && options.image_extension != ".png")
        return bad_input("MakeStackOptions::image_extension '" + options.image_extension +
                             "' is invalid: expected .exr (scene-linear float) or .png (8-bit sRGB)",
                         "MakeStackOptions::image_extension");
    SyntheticStackOptions so;
    so.size = options.size;
    so.samples = options.samples;
    so.specular = options.specular;
    so.seed = options.seed;
    so.threads = options.threads;
    so.albedo = options.albedo;
    // The options' own checks before any loading (render_synthetic_stack repeats them).
    if (auto st = check_synthetic_size(options.size, options.samples, "MakeStackOptions"); !st) return st.error();
    if (auto st = check_specular_lobe(options.specular); !st) return st.error();
    auto lights = make_dome(options.dome);
    if (!lights) return lights.error();
    if (static_cast<int>(lights->size()) < kMinStackLights)
        return bad_input("MakeStackOptions::dome '" + dome_text(options.dome) + "' has " +
                             std::to_string(lights->size()) + " light(s): a stack needs at least " +
                             std::to_string(kMinStackLights) + " (a PTM has 6 coefficients per channel)",
                         "MakeStackOptions::dome");

    std::error_code ec;
    const std::string scene_path = fs::absolute(options.scene, ec).lexically_normal().string();
    SyntheticSurfaceOptions surface_options;
    surface_options.scene = options.scene;
    surface_options.surface = options.surface;
    surface_options.threads = options.threads;
    auto surface = SyntheticSurface::load(surface_options, config);
    if (!surface) return surface.error();
    auto digest = sha256_file_hex(options.scene);
    if (!digest) return digest.error();

    // Every file is written into a staging folder beside the output and
    // moved into place only when all of them are written.
    const fs::path output(options.output);
    fs::path destination = output.parent_path();
    if (destination.empty()) destination = ".";
    auto staging = StagingFolder::create(output);
    if (!staging) return staging.error();
    std::vector<Slot> slots;
    std::vector<fs::path> last;  // moved into place last, in this order
    if (!several) {
        slots.push_back({staging->path() / output.filename(), output.filename().string(), normalize(options.views[0]),
                         destination / output.filename()});
        last.push_back(output.filename());
    } else {
        for (std::size_t k = 0; k < options.views.size(); ++k) {
            char name[32];
            std::snprintf(name, sizeof name, "view-%02zu", k);
            slots.push_back({staging->path() / name / "stack.lp", std::string(name) + "/stack.lp",
                             normalize(options.views[k]), destination / name / "stack.lp"});
            last.push_back(fs::path(name) / "stack.lp");
        }
        last.push_back(output.filename());
    }

    MadeStack made;
    made.kind = surface->kind();
    made.tile = surface->tile();
    made.lights = static_cast<int>(lights->size());
    made.size = options.size;
    made.samples = options.samples;
    // Rendered under the lights as the .lp holds them, so that a reader's
    // directions are those of the images.
    std::vector<Vec3> written;
    for (Vec3& l : *lights) {
        written.push_back(as_written(l));
        l = normalize(written.back());
    }
    std::vector<BtfView> btf;
    for (std::size_t k = 0; k < slots.size(); ++k) {
        so.view = slots[k].view;
        if (options.progress)
            so.progress = [&, k](double f) { options.progress((k + f) / static_cast<double>(slots.size())); };
        auto stack = render_synthetic_stack(*surface, *lights, so);
        if (!stack) return stack.error();
        made.rays += stack->rays;
        made.render_seconds += stack->seconds;
        if (several) {
            const fs::path folder = slots[k].light_file.parent_path();
            fs::create_directories(folder, ec);
            if (ec) return io_error(folder.string() + ": cannot make the view slot's folder: " + ec.message());
        }
        if (auto st = write_slot(slots[k], k, slots.size(), *stack, written, options, scene_path, *digest, *surface,
                                 config, made);
            !st)
            return st.error();
        btf.push_back({slots[k].relative, slots[k].view});
    }
    if (several) {
        if (auto st = write_btf_manifest((staging->path() / output.filename()).string(), btf); !st) return st.error();
        ++made.files;
        made.manifest = options.output;
    }
    // What was made, named where it will lie.
    for (auto* names : {&made.light_files, &made.records})
        for (std::string& name : *names)
            name = (destination / fs::path(name).lexically_relative(staging->path())).string();
    if (auto st = staging->commit(destination, last); !st) return st.error();
    made.seconds = clock.elapsed_ms() / 1000;
    return made;
}

}  // namespace cmfilter
