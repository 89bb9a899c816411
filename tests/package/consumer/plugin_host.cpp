// SPDX-License-Identifier: Apache-2.0
// Loads a plugin with dlopen() and calls its cmfilter_plugin_lookup.
//   plugin_host PLUGIN.so TABLE.exr MEAN SIGMA
#include <dlfcn.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 5) {
        std::cerr << "usage: plugin_host PLUGIN.so TABLE.exr MEAN SIGMA\n";
        return 1;
    }
    void* plugin = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!plugin) {
        std::cerr << "plugin_host: " << dlerror() << "\n";
        return 1;
    }
    using Lookup = int (*)(const char*, double, double, float*);
    auto lookup = reinterpret_cast<Lookup>(dlsym(plugin, "cmfilter_plugin_lookup"));
    if (!lookup) {
        std::cerr << "plugin_host: " << dlerror() << "\n";
        return 1;
    }
    float rgb[3];
    if (lookup(argv[2], std::atof(argv[3]), std::atof(argv[4]), rgb) != 0) {
        std::cerr << "plugin_host: the plugin could not read " << argv[2] << "\n";
        return 1;
    }
    std::cout << rgb[0] << " " << rgb[1] << " " << rgb[2] << "\n";
    dlclose(plugin);
    return 0;
}
