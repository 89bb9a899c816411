# SPDX-License-Identifier: Apache-2.0
# apply and compare against NumPy and scikit-image: the naive method as C0 of
# NumPy's box mean of the driver, the gaussian one as the quadrature of
# eq. 10 at NumPy's box mean and sigma, RMSE by NumPy, CIEDE2000 by
# scikit-image.
import numpy as np
import pytest
import skimage.color
import tifffile

import cmfilter
from conftest import c0, linear_colormap, read_png, write_png8
from test_tables import quadrature_T


@pytest.fixture
def baked(tmp_path, luts):
    y, x = np.mgrid[0:16, 0:16]
    f = write_png8(tmp_path / "driver.png", 0.5 + 0.35 * np.sin(x * 1.3) * np.cos(y * 0.9))
    cmfilter.MomentPyramid.bake(str(tmp_path / "driver.png"), str(tmp_path / "moments.exr"))
    table = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "terrain.png")), values=256, sigmas=64)
    table.write(str(tmp_path / "table.exr"))
    return f, str(tmp_path / "moments.exr"), str(tmp_path / "table.exr")


def test_apply_naive_and_gaussian_at_lod_2(baked, luts):
    f, moments, table = baked
    texels = linear_colormap(luts / "terrain.png")
    blocks = lambda x: x.reshape(4, 4, 4, 4).mean(axis=(1, 3))
    mean = blocks(f)
    sigma = np.sqrt(np.maximum(blocks(f * f) - mean * mean, 0))
    naive = cmfilter.apply(moments, table, lod=2, method="naive")
    assert naive.shape == (4, 4, 3) and naive.dtype == np.float32
    np.testing.assert_allclose(naive, c0(texels, 0, 1, mean), atol=5e-4)
    gaussian = cmfilter.apply(moments, table, lod=2, method="gaussian")
    expected = np.array([quadrature_T(texels, 0, 1, m, s) for m, s in zip(mean.ravel(), sigma.ravel())])
    np.testing.assert_allclose(gaussian.reshape(-1, 3), expected, atol=4e-3)
    # The reference: the box mean of C0(f) over the same 4 x 4 texels.
    reference = cmfilter.apply(moments, table, lod=2, method="reference")
    np.testing.assert_allclose(reference, c0(texels, 0, 1, f).reshape(4, 4, 4, 4, 3).mean(axis=(1, 3)), atol=5e-4)


def test_apply_mixture_of_a_two_valued_driver_is_its_box_mean(tmp_path, luts):
    # Two values per 4 x 4 block in varying shares: the mixture of four
    # moments is the two values themselves (width 0), so the colour is NumPy's
    # box mean of C0(f) up to the table's interpolation; the Gaussian of two
    # moments blurs the step between them.
    rng = np.random.default_rng(3)
    f = write_png8(tmp_path / "two.png", np.where(rng.random((16, 16)) < 0.35, 0.3, 0.7))
    cmfilter.MomentPyramid.bake(str(tmp_path / "two.png"), str(tmp_path / "m4.exr"), order=4)
    table = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "step.png")), values=1024, sigmas=64)
    table.write(str(tmp_path / "step.exr"))
    texels = linear_colormap(luts / "step.png")
    box = c0(texels, 0, 1, f).reshape(4, 4, 4, 4, 3).mean(axis=(1, 3))
    mixture = cmfilter.apply(str(tmp_path / "m4.exr"), str(tmp_path / "step.exr"), lod=2, method="mixture")
    gaussian = cmfilter.apply(str(tmp_path / "m4.exr"), str(tmp_path / "step.exr"), lod=2, method="gaussian")
    assert np.abs(mixture - box).max() < 5e-3
    assert np.abs(gaussian - box).max() > 0.02  # 0.035 measured: the test tells the two apart
    cmfilter.MomentPyramid.bake(str(tmp_path / "two.png"), str(tmp_path / "m2.exr"))
    with pytest.raises(cmfilter.Error, match="holds 2 moments"):
        cmfilter.apply(str(tmp_path / "m2.exr"), str(tmp_path / "step.exr"), lod=2, method="mixture")


def test_color_pyramid_is_numpys_box_mean_of_c0_and_refuses_another_map(baked, luts, tmp_path):
    f, moments, table = baked
    texels = linear_colormap(luts / "terrain.png")
    pyramid = str(tmp_path / "colors.exr")
    baked_info = cmfilter.bake_color_pyramid(str(tmp_path / "driver.png"), pyramid, table=table)
    assert baked_info["levels"] == 5 and baked_info["bytes_per_texel"] == 12
    for lod, n in ((0, 16), (1, 8), (2, 4)):
        got = cmfilter.apply(pyramid, table, lod=lod, method="color-pyramid")
        b = 16 // n
        want = c0(texels, 0, 1, f).reshape(n, b, n, b, 3).mean(axis=(1, 3))
        np.testing.assert_allclose(got, want, atol=5e-4)
    # Another map's table: refused, naming the pyramid.
    other = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "stripes.png")), values=64, sigmas=16)
    other.write(str(tmp_path / "other.exr"))
    with pytest.raises(cmfilter.Error, match="was baked through another colour map"):
        cmfilter.apply(pyramid, str(tmp_path / "other.exr"), lod=1, method="color-pyramid")
    # The choice measures it: exact, so it meets a tolerance gaussian does not.
    choice = cmfilter.choose_method(moments, table, tolerance=1e-3, lods=[1, 2], color_pyramid=pyramid)
    assert choice["method"] == "color-pyramid"
    assert [t["method"] for t in choice["trials"]][:3] == ["naive", "gaussian", "color-pyramid"]


def test_segment_pyramid_recoloured_is_numpys_box_mean_of_the_new_map(baked, luts, tmp_path):
    # The step map's breakpoints, baked once; applied with the step's texels
    # permuted B, R, G (other colours, the same breakpoints): NumPy's box
    # mean of that map's C0(f). Stripes break elsewhere: refused.
    f, moments, _ = baked
    step = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "step.png")), values=256, sigmas=64)
    step.write(str(tmp_path / "step.exr"))
    pyramid = str(tmp_path / "segments.exr")
    info = cmfilter.bake_segment_pyramid(str(tmp_path / "driver.png"), pyramid, tables=[str(tmp_path / "step.exr")])
    assert info["channels"] == len(info["breakpoints"]) - 1 and info["fit_de"] < 1e-9
    codes = read_png(luts / "step.png")[:, :, [2, 0, 1]]
    write_png8(tmp_path / "recoloured.png", codes)
    recoloured = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(tmp_path / "recoloured.png")), values=256,
                                          sigmas=64)
    recoloured.write(str(tmp_path / "recoloured.exr"))
    texels = linear_colormap(tmp_path / "recoloured.png")
    for lod, n in ((0, 16), (1, 8), (2, 4)):
        got = cmfilter.apply(pyramid, str(tmp_path / "recoloured.exr"), lod=lod, method="segments")
        b = 16 // n
        want = c0(texels, 0, 1, f).reshape(n, b, n, b, 3).mean(axis=(1, 3))
        np.testing.assert_allclose(got, want, atol=1e-5)
    other = cmfilter.ColorTable.bake(cmfilter.ColorMap.load(str(luts / "stripes.png")), values=64, sigmas=16)
    other.write(str(tmp_path / "stripes.exr"))
    with pytest.raises(cmfilter.Error, match="does not fit them"):
        cmfilter.apply(pyramid, str(tmp_path / "stripes.exr"), lod=1, method="segments")
    choice = cmfilter.choose_method(moments, str(tmp_path / "step.exr"), tolerance=1e-3, lods=[1, 2],
                                    segment_pyramid=pyramid)
    assert choice["method"] == "segments"


def test_segment_colors_of_a_tolerance_bake_are_numpys_weighted_least_squares(baked, luts, tmp_path):
    # A tolerance bake of the smooth terrain map: the colours at its
    # breakpoints are NumPy's least squares of C0 over the driver's values
    # (hat functions of the breakpoints, each value weighted by its share),
    # and apply(method="segments") is the box mean of the curve through them.
    f, _, table = baked
    pyramid = str(tmp_path / "fitted.exr")
    info = cmfilter.bake_segment_pyramid(str(tmp_path / "driver.png"), pyramid, tables=[table], tolerance=1.0)
    got = cmfilter.segment_colors(pyramid, table)
    t = np.array(got["breakpoints"])
    assert info["breakpoints"] == got["breakpoints"] and got["colors"].shape == (len(t), 3)
    values, counts = np.unique(f.astype(np.float32), return_counts=True)
    hats = np.stack([np.interp(values, t, np.eye(len(t))[k]) for k in range(len(t))], axis=1)
    texels = linear_colormap(luts / "terrain.png")
    w = np.sqrt(counts / counts.sum())[:, None]
    want, *_ = np.linalg.lstsq(w * hats, w * c0(texels, 0, 1, values), rcond=None)
    np.testing.assert_allclose(got["colors"], want, atol=1e-5)
    curve = np.stack([np.interp(f, t, got["colors"][:, ch]) for ch in range(3)], axis=-1)
    for lod, n in ((0, 16), (2, 4)):
        b = 16 // n
        np.testing.assert_allclose(cmfilter.apply(pyramid, table, lod=lod, method="segments"),
                                   curve.reshape(n, b, n, b, 3).mean(axis=(1, 3)), atol=1e-5)


def test_apply_clamped_lod_warns(baked):
    _, moments, table = baked
    with pytest.warns(UserWarning, match="lod"):
        cmfilter.apply(moments, table, lod=40, method="naive")


def srgb_encode(linear):
    linear = np.clip(linear, 0, 1)
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * linear ** (1 / 2.4) - 0.055)


def test_compare_arrays_against_numpy_and_skimage():
    rng = np.random.default_rng(9)
    a = rng.uniform(0, 1, (6, 7, 3)).astype(np.float32)
    b = np.clip(a + rng.normal(0, 0.05, a.shape), 0, 1.2).astype(np.float32)
    result = cmfilter.compare(a, b)
    d = a.astype(np.float64) - b
    assert result["rmse"] == pytest.approx(np.sqrt(np.mean(d * d)), rel=1e-9)
    np.testing.assert_allclose(result["rmse_rgb"], np.sqrt(np.mean(d * d, axis=(0, 1))), rtol=1e-9)
    # scikit-image decodes sRGB itself; its D65 white differs from RGB (1, 1, 1)'s XYZ in the 4th digit.
    de = skimage.color.deltaE_ciede2000(skimage.color.rgb2lab(srgb_encode(a)), skimage.color.rgb2lab(srgb_encode(b)))
    np.testing.assert_allclose(result["de2000_pixels"], de, rtol=0.01, atol=0.01)
    assert result["de2000"]["mean"] == pytest.approx(de.mean(), rel=0.01)
    assert result["de2000"]["max"] == pytest.approx(de.max(), rel=0.01)


def test_compare_files_matches_arrays(tmp_path):
    rng = np.random.default_rng(10)
    a = rng.uniform(0, 1, (5, 8, 3)).astype(np.float32)
    b = rng.uniform(0, 1, (5, 8, 3)).astype(np.float32)
    tifffile.imwrite(tmp_path / "a.tif", a, photometric="rgb")
    tifffile.imwrite(tmp_path / "b.tif", b, photometric="rgb")
    result = cmfilter.compare(str(tmp_path / "a.tif"), tmp_path / "b.tif")
    d = a.astype(np.float64) - b
    assert result["rmse"] == pytest.approx(np.sqrt(np.mean(d * d)), rel=1e-9)
    assert (result["width"], result["height"]) == (8, 5)


def test_compare_errors(tmp_path):
    with pytest.raises(cmfilter.Error, match="same size"):
        cmfilter.compare(np.zeros((2, 3, 3)), np.zeros((3, 2, 3)))
    with pytest.raises(cmfilter.Error, match="absent.exr") as e:
        cmfilter.compare(str(tmp_path / "absent.exr"), str(tmp_path / "absent.exr"))
    assert e.value.kind == "io"
    with pytest.raises(cmfilter.Error, match="non-finite"):
        cmfilter.compare(np.full((1, 1, 3), np.nan), np.zeros((1, 1, 3)))


def test_choose_method_measures_naive_as_numpy_and_skimage_do(baked, luts):
    # naive's error at LOD k: the mean over the 2^k blocks of CIEDE2000
    # (scikit-image) between C0 of the block mean of f and the block mean of
    # C0(f), both in NumPy; a tolerance everything meets takes naive, the
    # cheapest, and one nothing meets leaves the method None.
    f, moments, table = baked
    texels = linear_colormap(luts / "terrain.png")
    choice = cmfilter.choose_method(moments, table, tolerance=100, lods=[1, 2])
    assert choice["method"] == "naive" and choice["lods"] == [1, 2]
    assert [t["method"] for t in choice["trials"]] == ["naive", "gaussian"]
    assert any("mixture" in s for s in choice["skipped"])
    naive = choice["trials"][0]
    for i, k in enumerate([1, 2]):
        n = 16 >> k
        blocks = lambda x: x.reshape(n, 16 // n, n, 16 // n, *x.shape[2:]).mean(axis=(1, 3))
        got = np.clip(c0(texels, 0, 1, blocks(f)), 0, 1)
        want = np.clip(blocks(c0(texels, 0, 1, f)), 0, 1)
        de = skimage.color.deltaE_ciede2000(skimage.color.rgb2lab(srgb_encode(got)), skimage.color.rgb2lab(srgb_encode(want)))
        assert de.mean() > 0.05  # the test means something
        assert naive["errors"][i] == pytest.approx(de.mean(), rel=0.02, abs=0.01)
    none = cmfilter.choose_method(moments, table, tolerance=1e-9, lods=[1])
    assert none["method"] is None and none["error"] is None
    with pytest.raises(cmfilter.Error, match="tolerance 0 is invalid"):
        cmfilter.choose_method(moments, table, tolerance=0)
