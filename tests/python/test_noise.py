# SPDX-License-Identifier: Apache-2.0
# Noise and its sigma tables against NumPy: the within-footprint standard
# deviation measured here from dense grids of point values, the table's
# linear interpolation by numpy.interp.
import numpy as np
import pytest

import cmfilter

SPEC = "gradient:seed=3"


def empirical_box_sigma(noise, width, footprints=300, grid=24, seed=5):
    """sqrt of the mean over random square footprints of the variance of f
    over a dense grid of cell centres inside each."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(0, 256 * noise.base_period, (footprints, 2))
    offsets = (np.arange(grid) + 0.5) / grid - 0.5
    ox, oy = np.meshgrid(offsets * width, offsets * width)
    x = centres[:, 0, None, None] + ox
    y = centres[:, 1, None, None] + oy
    values = noise(x, y).reshape(footprints, -1)
    return np.sqrt(values.var(axis=1).mean())


def test_box_sigma_matches_empirical_std():
    noise = cmfilter.Noise(SPEC)
    bake = cmfilter.bake_noise_sigma(SPEC, lod_step=1, lod_last=1, initial_footprints=512, max_footprints=2048,
                                     relative_half_width=0.02, global_samples=4096, threads=2)
    lods = bake["lods"]
    np.testing.assert_allclose(np.diff(lods), 1)
    for lod, sigma in zip(lods, bake["box_sigma"]):
        if lod < -3:
            continue  # a footprint far below a period: sigma near 0, relative error meaningless
        measured = empirical_box_sigma(noise, noise.base_period * 2.0**lod)
        assert sigma == pytest.approx(measured, rel=0.06), f"LOD {lod}"
    # The Gaussian footprint of the same width (2 standard deviations) sees
    # more of the noise than the box: its sigma is larger.
    assert np.all(bake["gaussian_sigma"][lods >= -3] > bake["box_sigma"][lods >= -3])


def test_written_table_reads_back_and_interpolates(tmp_path):
    path = tmp_path / "sigma.exr"
    bake = cmfilter.bake_noise_sigma(SPEC, output=str(path), lod_step=0.5, lod_last=0, initial_footprints=256,
                                     max_footprints=256, global_samples=1024, threads=2)
    table = cmfilter.NoiseSigmaTable.read(str(path), "box")
    np.testing.assert_allclose(table.lods, bake["lods"])
    np.testing.assert_allclose(table.sigmas, bake["box_sigma"], rtol=1e-6)
    lod = np.linspace(table.lods[0] - 1, table.lods[-1] + 1, 41)
    np.testing.assert_allclose(table.sigma_at(lod), np.interp(lod, table.lods, table.sigmas), rtol=1e-12)
    assert table.noise_spec == cmfilter.Noise(SPEC).spec


def test_noise_image_samples_pixel_centres():
    noise = cmfilter.Noise("fbm:octaves=3,seed=2")
    image = cmfilter.noise_image("fbm:octaves=3,seed=2", width=12, height=7, scale=0.3)
    j, i = np.mgrid[0:7, 0:12]
    np.testing.assert_allclose(image, noise(0.3 * (i + 0.5), 0.3 * (j + 0.5)), rtol=1e-6, atol=1e-7)


def test_bad_spec_names_the_key():
    with pytest.raises(cmfilter.Error, match="octaves") as e:
        cmfilter.Noise("fbm:octaves=0")
    assert e.value.kind == "bad_input"
    with pytest.raises(cmfilter.Error, match="not-a-table.exr") as e:
        cmfilter.NoiseSigmaTable.read("not-a-table.exr")
