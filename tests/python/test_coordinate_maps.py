# SPDX-License-Identifier: Apache-2.0
# Coordinate maps against NumPy: rendering through a map is fancy indexing
# of the sample, its reference at LOD L a box mean over 2^L x 2^L texels.
import numpy as np
import pytest

import cmfilter


@pytest.fixture
def patchwork():
    """A 16 x 12 map of 4 x 4 patches copied from random places of a 10 x 9 sample."""
    rng = np.random.default_rng(2)
    sample = rng.uniform(0, 1, (9, 10, 3)).astype(np.float32)
    coords = np.zeros((12, 16, 2), np.int32)
    for py in range(0, 12, 4):
        for px in range(0, 16, 4):
            sx, sy = rng.integers(0, 7), rng.integers(0, 6)
            y, x = np.mgrid[0:4, 0:4]
            coords[py:py + 4, px:px + 4, 0] = sx + x
            coords[py:py + 4, px:px + 4, 1] = sy + y
    return cmfilter.CoordinateMap(coords, (10, 9)), coords, sample


def test_full_size_is_the_sample_indexed(patchwork):
    cmap, coords, sample = patchwork
    out = cmap.render(sample, lod=0, method="reference")
    np.testing.assert_array_equal(out, sample[coords[..., 1], coords[..., 0]])
    np.testing.assert_array_equal(cmap.coords(), coords)


@pytest.mark.parametrize("method", ["reference", "patches"])
def test_lod_is_the_box_mean_of_the_full_size_surface(patchwork, method):
    cmap, coords, sample = patchwork
    full = sample[coords[..., 1], coords[..., 0]].astype(np.float64)
    box = full.reshape(6, 2, 8, 2, 3).mean(axis=(1, 3))
    # Footprints of 2 x 2 lie inside a 4 x 4 patch: the patches method is exact there too.
    np.testing.assert_allclose(cmap.render(sample, lod=1, method=method), box, atol=1e-6)


def test_file_round_trip_and_uv(patchwork, tmp_path):
    cmap, coords, _ = patchwork
    cmap.write(str(tmp_path / "map.exr"))
    back = cmfilter.CoordinateMap.read(str(tmp_path / "map.exr"))
    np.testing.assert_array_equal(back.coords(), coords)
    assert back.sample_size() == (10, 9)
    np.testing.assert_allclose(back.uv()[..., 0], (coords[..., 0] + 0.5) / 10, rtol=1e-6)
    np.testing.assert_allclose(back.uv()[..., 1], (coords[..., 1] + 0.5) / 9, rtol=1e-6)


def test_map_errors(patchwork):
    cmap, coords, sample = patchwork
    with pytest.raises(cmfilter.Error, match="outside"):
        cmfilter.CoordinateMap(coords + 20, (10, 9))
    with pytest.raises(cmfilter.Error, match="LodOptions::lod"):
        cmap.render(sample, lod=-1)
