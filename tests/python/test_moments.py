# SPDX-License-Identifier: Apache-2.0
# Drivers and moment pyramids against NumPy: the driver's codes / 255 read
# here, each level's mean and sigma as box means of f and f^2 (sec. 4.2).
import numpy as np
import pytest

import cmfilter
from conftest import write_png8


def box_levels(f, level):
    """Box means of f and f^2 over 2^level x 2^level blocks (a power-of-two driver)."""
    b = 2**level
    h, w = f.shape
    blocks = lambda x: x.reshape(h // b, b, w // b, b).mean(axis=(1, 3))
    return blocks(f), blocks(f * f)


@pytest.fixture
def driver(tmp_path):
    rng = np.random.default_rng(11)
    y, x = np.mgrid[0:32, 0:32]
    values = 0.5 + 0.3 * np.sin(x / 3.0) * np.cos(y / 5.0) + 0.1 * rng.standard_normal((32, 32))
    path = tmp_path / "driver.png"
    return path, write_png8(path, np.clip(values, 0, 1))


def test_read_driver_is_codes_over_255(driver):
    path, f = driver
    read = cmfilter.read_driver(str(path))
    assert read.dtype == np.float32 and read.shape == (32, 32)
    np.testing.assert_allclose(read, f, atol=1e-7)


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_level_mean_and_sigma_are_box_moments(driver, tmp_path, level):
    path, f = driver
    pyramid = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"), threads=1)
    assert (pyramid.width, pyramid.height, pyramid.levels) == (32, 32, 6)
    m1, m2 = box_levels(f, level)
    mean, sigma = pyramid.level(level)
    np.testing.assert_allclose(mean, m1, atol=2e-6)
    np.testing.assert_allclose(sigma, np.sqrt(np.maximum(m2 - m1 * m1, 0)), atol=5e-4)


def test_lookup_at_texel_centres_and_between_levels(driver, tmp_path):
    path, f = driver
    pyramid = cmfilter.MomentPyramid.bake(str(path), str(tmp_path / "moments.exr"))
    m1, _ = box_levels(f, 2)
    y, x = np.mgrid[0:8, 0:8]
    mean, sigma = pyramid.lookup((x + 0.5) / 8, (y + 0.5) / 8, 2.0)
    np.testing.assert_allclose(mean, m1, atol=2e-6)
    # A fractional LOD blends levels 1 and 2 linearly; at level 1's texel
    # centres level 2 is read bilinearly (edge texels clamped).
    a, _ = box_levels(f, 1)
    b, _ = box_levels(f, 2)
    y, x = np.mgrid[0:16, 0:16]
    mean, _ = pyramid.lookup((x + 0.5) / 16, (y + 0.5) / 16, 1.25)
    np.testing.assert_allclose(mean, 0.75 * a + 0.25 * bilinear(b, x / 2 - 0.25, y / 2 - 0.25), atol=2e-6)


def bilinear(img, cx, cy):
    """img at continuous texel coordinates (centre of texel i at i), edges clamped."""
    x0, y0 = np.floor(cx).astype(int), np.floor(cy).astype(int)
    fx, fy = cx - x0, cy - y0
    h, w = img.shape
    at = lambda yy, xx: img[np.clip(yy, 0, h - 1), np.clip(xx, 0, w - 1)]
    top = (1 - fx) * at(y0, x0) + fx * at(y0, x0 + 1)
    bottom = (1 - fx) * at(y0 + 1, x0) + fx * at(y0 + 1, x0 + 1)
    return (1 - fy) * top + fy * bottom


def test_not_a_moment_pyramid(luts):
    with pytest.raises(cmfilter.Error, match="terrain.png") as e:
        cmfilter.MomentPyramid.open(str(luts / "terrain.png"))
    assert e.value.kind == "bad_input"
    with pytest.raises(cmfilter.Error, match="nothing-here.png") as e:
        cmfilter.read_driver("nothing-here.png")
    assert e.value.kind == "io"
