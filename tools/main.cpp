// SPDX-License-Identifier: Apache-2.0
// cmfilter: the command-line front end of libcmfilter. Parses, dispatches to
// one subcommand, prints its error once and exits with the error's code.
#include "command.h"

#include "cmfilter/util/available_cores.h"
#include "cmfilter/util/version.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <iostream>
#include <new>
#include <vector>

int main(int argc, char** argv)
{
    using namespace cmfilter;
    // OpenImageIO's and OpenEXR's own pools get the cores this process may
    // use (its affinity and cgroup quota), not every core of the machine.
    const int cores = available_cores();
    OIIO::attribute("threads", cores);
    OIIO::attribute("exr_threads", cores);
    // OpenImageIO built without NDEBUG (as Debian's is) prints debug lines on
    // stdout, where they would break --json; on only when asked for by
    // OPENIMAGEIO_DEBUG, as OpenImageIO's own variable.
    if (std::getenv("OPENIMAGEIO_DEBUG") == nullptr) OIIO::attribute("debug", 0);
    CLI::App app{"cmfilter: filters colour-mapped textures and surfaces correctly at every scale\n"
                 "(Heitz et al. 2013, \"Filtering Color Mapped Textures and Surfaces\").",
                 "cmfilter"};
    app.set_version_flag("--version", std::string("cmfilter ") + version());
    app.require_subcommand(1);
    app.footer("Exit codes: 0 ok, 1 usage, 2 I/O, 3 bad input, 4 runtime error;\n"
               "compare's gates: 5 over --warn, 6 over --fail.\n"
               "Run 'cmfilter <command> --help' for a command's options.");

    std::vector<cli::Command> commands = {
        cli::setup_bake_colormap(app), cli::setup_bake_moments(app),  cli::setup_apply(app),
        cli::setup_compare(app),       cli::setup_info(app),          cli::setup_noise_image(app),
        cli::setup_bake_noise(app),    cli::setup_render(app),        cli::setup_bench(app),
        cli::setup_make_stack(app),    cli::setup_fit(app),           cli::setup_relight(app),
        cli::setup_normals(app),       cli::setup_synth_analyse(app), cli::setup_synth(app),
        cli::setup_synth_apply(app)};

    auto prefix = [&]() {
        std::string p = "cmfilter";
        for (const auto* sub : app.get_subcommands()) p += " " + sub->get_name();
        return p;
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << prefix() << ": error: " << e.what() << "\n"
                  << "Run '" << prefix() << " --help' for usage.\n";
        return static_cast<int>(ErrorKind::Usage);
    }

    for (const auto& command : commands) {
        if (!command.app->parsed()) continue;
        // The library refuses what it can see will not fit before it
        // allocates (util/memory_budget.h); an allocation that fails anyway
        // ends the command here, its outputs' temporaries removed on the way.
        Status status = runtime_error("");
        try {
            status = command.run();
        } catch (const std::bad_alloc&) {
            std::cerr << prefix() << ": error: out of memory: an allocation failed (the inputs need more memory "
                      << "than this process may use)\n";
            return static_cast<int>(ErrorKind::Runtime);
        }
        if (!status) {
            std::cerr << prefix() << ": error: " << cli::name_flags(status.error().message, command.flags) << "\n";
            return static_cast<int>(status.error().kind);
        }
        return command.success_code ? command.success_code() : 0;
    }
    return 0;
}
