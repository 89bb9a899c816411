# SPDX-License-Identifier: Apache-2.0
# The installed module, imported from the prefix alone: it lies under
# PREFIX/SITE_DIR, loads the prefix's libcmfilter (a shared build) or holds it
# (a static one), and bakes and looks up a table from the prefix's colour map.
#   check_installed_module.py PREFIX SITE_DIR
import os
import pathlib
import sys

prefix = pathlib.Path(sys.argv[1]).resolve()
site = pathlib.Path(sys.argv[2])
site = site if site.is_absolute() else prefix / site
sys.path.insert(0, str(site))
import cmfilter  # noqa: E402

module = pathlib.Path(cmfilter.__file__).resolve()
assert module.parent == site.resolve(), f"cmfilter imported from {module}, not from {site}"
maps = pathlib.Path("/proc/self/maps").read_text().splitlines()
libraries = {line.split()[-1] for line in maps if "libcmfilter.so" in line}
assert all(pathlib.Path(p).resolve().is_relative_to(prefix) for p in libraries), \
    f"libcmfilter loaded from outside {prefix}: {libraries}"
table = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(prefix / "share/cmfilter/luts/stripes.png")),
                                 values=64, sigmas=8)
rgb = table.lookup(0.5, 0.0)
assert rgb.shape == (3,) and all(0 < c < 1 for c in rgb), rgb
print(f"imported {module} (libcmfilter: {', '.join(sorted(libraries)) or 'static'}); T(0.5, 0) = {rgb}")
