# SPDX-License-Identifier: Apache-2.0
# %% [markdown]
# # The prefiltered colour table T(v, sigma)
#
# Bakes the Gaussian colour table of a colour map (eq. 10 of Heitz et al.
# 2013: the map convolved with a normal distribution of standard deviation
# sigma) and plots it: the table as an image, value across and sigma down,
# and a few of its rows as curves, against the exact convolution.
#
#     python3 examples/python/table_plot.py [COLORMAP.png [OUT_DIR]]
#
# Written as notebook cells (`# %%`): open it in Jupyter or VS Code, or run it
# as a script (MPLBACKEND=Agg to draw without a display).

# %%
import pathlib
import sys

import matplotlib.pyplot as plt
import numpy as np

import cmfilter

here = pathlib.Path(__file__).resolve().parent
colormap = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here.parents[1] / "luts" / "terrain.png"
out = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else pathlib.Path("table-plot")
out.mkdir(parents=True, exist_ok=True)

# %% [markdown]
# Load the map (sRGB PNG -> scene-linear with OpenColorIO) over the driver
# domain [0, 1], and bake a 256 x 64 table up to sigma = 0.25.

# %%
cmap = cmfilter.ColorMap.load(str(colormap), vmin=0, vmax=1)
table = cmfilter.ColorTable.bake(cmap, values=256, sigmas=64, sigma_max=0.25)
table.write(str(out / "table.exr"))
print(f"{colormap.name}: {len(cmap.texels)} texels; table {table.data.shape}, sigma_max {table.sigma_max}")

# %% [markdown]
# T(v, sigma) on a regular grid (the table's own rows are spaced in sqrt
# sigma), shown as display colours.

# %%
v = np.linspace(-0.1, 1.1, 480)
sigma = np.linspace(0, 0.25, 160)
T = table.lookup(v[None, :], sigma[:, None])  # (160, 480, 3), scene-linear
display = np.where(T <= 0.0031308, 12.92 * T, 1.055 * np.clip(T, 0.0031308, None) ** (1 / 2.4) - 0.055)

fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), height_ratios=[3, 2])
top.imshow(np.clip(display, 0, 1), extent=(v[0], v[-1], sigma[-1], sigma[0]), aspect="auto")
top.set_xlabel("mean driver value v")
top.set_ylabel("sigma")
top.set_title(f"T(v, sigma) of {colormap.name}")

# %% [markdown]
# Rows of the table (luminance) against the exact convolution.

# %%
luminance = np.array([0.2126, 0.7152, 0.0722])
for s, colour in zip([0.0, 0.02, 0.08, 0.2], ["k", "tab:blue", "tab:orange", "tab:red"]):
    bottom.plot(v, table.lookup(v, s) @ luminance, color=colour, label=f"table, sigma = {s}")
    bottom.plot(v[::24], cmap.convolve(v[::24], s) @ luminance, "o", color=colour, markersize=3)
bottom.set_xlabel("v")
bottom.set_ylabel("luminance (scene-linear)")
bottom.legend(fontsize="small", title="dots: exact convolution", title_fontsize="small")
fig.tight_layout()
fig.savefig(out / "table.png", dpi=100)
print(f"wrote {out / 'table.png'} and {out / 'table.exr'}")
