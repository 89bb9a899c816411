# SPDX-License-Identifier: Apache-2.0
# What the Python module's tests share: the source tree, the cmfilter
# command, and the independent readers and colour conversions they check
# against (NumPy, matplotlib's PNG reader, tifffile), never the module itself.
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("CMFILTER_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def luts():
    return SOURCE_DIR / "luts"


@pytest.fixture
def cli():
    path = os.environ.get("CMFILTER_CLI")
    if not path:
        pytest.skip("CMFILTER_CLI is not set (ctest sets it)")
    return path


def run(*args):
    """Runs a command, failing the test with its output when it fails. The
    sanitizer runtime a checked build preloads into the interpreter is not
    passed on: a sanitized command holds its own."""
    env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, env=env)
    assert done.returncode == 0, f"{args} failed ({done.returncode}):\n{done.stdout}\n{done.stderr}"
    return done


def srgb_to_linear(code):
    """IEC 61966-2-1's sRGB decoding of values in [0, 1]."""
    code = np.asarray(code, dtype=np.float64)
    return np.where(code <= 0.04045, code / 12.92, ((code + 0.055) / 1.055) ** 2.4)


def read_png(path):
    """A PNG's pixels as floats in [0, 1] (matplotlib's own reader)."""
    import matplotlib.image

    return np.asarray(matplotlib.image.imread(str(path)), dtype=np.float64)


def write_png8(path, values):
    """Writes values in [0, 1] as an 8-bit grey or RGB PNG (scikit-image)."""
    import skimage.io

    codes = np.clip(np.rint(np.asarray(values) * 255), 0, 255).astype(np.uint8)
    skimage.io.imsave(str(path), codes, check_contrast=False)
    return codes.astype(np.float64) / 255


def linear_colormap(path):
    """The scene-linear texels of a one-row colour-map PNG, decoded here."""
    return srgb_to_linear(read_png(path)[0, :, :3])


def c0(texels, vmin, vmax, v):
    """The continuous colour map C0 of a clamp map (sec. 4): linear between
    texel centres, the end colours beyond."""
    n = len(texels)
    centres = vmin + (np.arange(n) + 0.5) * (vmax - vmin) / n
    v = np.asarray(v, dtype=np.float64)
    return np.stack([np.interp(v, centres, texels[:, c]) for c in range(3)], axis=-1)
