# SPDX-License-Identifier: Apache-2.0
# Texture synthesis against NumPy and the cmfilter command: a synthesised
# map's coordinates lie in the sample (NumPy bounds), rendering through it
# is NumPy indexing of the sample, a fixed seed repeats, and the analysis
# file and the map equal the command's (synth-analyse, synth) for the same
# input and options, their EXRs read by oiiotool and tifffile.
import shutil

import numpy as np
import pytest
import tifffile

import cmfilter
from conftest import run, srgb_to_linear, write_png8

# Small enough for a few seconds under AddressSanitizer.
ANALYSIS = dict(levels=2, textons=16, candidates=4, neighbourhood=1)
FLAGS = ["--levels", "2", "--textons", "16", "--candidates", "4", "--neighbourhood", "1"]


@pytest.fixture(scope="module")
def sample(tmp_path_factory):
    """A 32 x 32 sRGB PNG of noisy stripes, and its scene-linear texels decoded by NumPy."""
    rng = np.random.default_rng(4)
    y, x = np.mgrid[0:32, 0:32]
    stripes = 0.5 + 0.4 * np.sin((x + 0.5 * y) * 0.8)
    values = np.stack([stripes, stripes[::-1], 1 - stripes], axis=-1) + rng.uniform(-0.1, 0.1, (32, 32, 3))
    path = tmp_path_factory.mktemp("sample") / "sample.png"
    codes = write_png8(path, np.clip(values, 0, 1))
    return path, srgb_to_linear(codes).astype(np.float32)


@pytest.fixture(scope="module")
def analysis(sample):
    return cmfilter.SampleAnalysis.analyse(str(sample[0]), seed=5, **ANALYSIS)


def exr_subimages(exr, tmp_path):
    """Every subimage of an EXR as a float array: converted by oiiotool to a multi-page TIFF
    (one page a subimage, its data window) and read by tifffile."""
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        pytest.skip("oiiotool is not installed")
    tif = tmp_path / (exr.stem + ".tif")
    run(oiiotool, "-a", exr, "-d", "float", "--compression", "none", "-o", tif)
    with tifffile.TiffFile(tif) as pages:
        return [page.asarray() for page in pages.pages]


def exr_attributes(exr):
    """An EXR's cmfilter: attributes, every subimage's, as oiiotool prints them, but the time taken."""
    info = run(shutil.which("oiiotool"), "--info", "-v", "-a", exr).stdout
    return [line.strip() for line in info.splitlines() if "cmfilter:" in line and "seconds" not in line]


def map_coords(uv, width, height):
    """Sample texels (x, y) of a coordinate map's (u, v): floor(u * width), floor(v * height)."""
    uv = uv.astype(np.float64)
    return np.stack([np.floor(uv[..., 0] * width), np.floor(uv[..., 1] * height)], axis=-1).astype(np.int32)


@pytest.mark.parametrize("levels,toroidal", [(1, False), (2, False), (2, True)])
def test_coordinates_lie_in_the_sample_at_every_level(analysis, levels, toroidal):
    cmap = cmfilter.synthesise(analysis, (64, 48), levels=levels, toroidal=toroidal, seed=5)
    assert (cmap.width, cmap.height, cmap.level_count) == (64, 48, levels)
    for level in range(levels):
        coords = cmap.coords(level)
        sw, sh = 32 >> level, 32 >> level
        assert cmap.sample_size(level) == (sw, sh)
        assert coords.shape == (48 >> level, 64 >> level, 2)
        assert coords[..., 0].min() >= 0 and coords[..., 0].max() < sw
        assert coords[..., 1].min() >= 0 and coords[..., 1].max() < sh
    # A synthesis copies patches of the sample, not one texel everywhere.
    assert len(np.unique(cmap.coords()[..., 1] * 32 + cmap.coords()[..., 0])) > 64


def test_full_size_render_is_the_sample_indexed(analysis, sample):
    cmap = cmfilter.synthesise(analysis, (64, 64), seed=5)
    linear = sample[1]
    coords = cmap.coords()
    np.testing.assert_array_equal(cmap.render(linear, lod=0, method="reference"), linear[coords[..., 1], coords[..., 0]])


def test_a_seed_repeats_and_another_differs(analysis):
    a = cmfilter.synthesise(analysis, (64, 64), seed=7, threads=1)
    b = cmfilter.synthesise(analysis, (64, 64), seed=7, threads=2)
    c = cmfilter.synthesise(analysis, (64, 64), seed=8)
    np.testing.assert_array_equal(a.coords(), b.coords())
    np.testing.assert_array_equal(a.coords(1), b.coords(1))
    assert np.any(a.coords() != c.coords())


def test_analysis_file_equals_the_command(cli, sample, analysis, tmp_path):
    ours, theirs = tmp_path / "python.exr", tmp_path / "command.exr"
    analysis.write(str(ours))
    run(cli, "synth-analyse", sample[0], "-o", theirs, "--seed", "5", *FLAGS, "--quiet")
    # Two levels: each a texels subimage (c0 .. c3, texton) and a dot subimage (M).
    a, b = exr_subimages(ours, tmp_path), exr_subimages(theirs, tmp_path)
    assert [p.shape for p in b] == [(32, 32, 5), (16, 16), (16, 16, 5), (16, 16)]
    for ours_pixels, theirs_pixels in zip(a, b):
        np.testing.assert_array_equal(ours_pixels, theirs_pixels)
    assert exr_attributes(ours) == exr_attributes(theirs) and len(exr_attributes(ours)) > 10
    # The arrays the object shows are the file's, as oiiotool reads it (OpenEXR sorts the
    # channels by name: c0 .. c3, texton).
    np.testing.assert_array_equal(analysis.textons(0), a[0][..., 4])
    np.testing.assert_array_equal(analysis.similar(1), b[2][..., :4])
    np.testing.assert_array_equal(analysis.dot(1), b[3])
    back = cmfilter.SampleAnalysis.read(str(theirs))
    assert back.sample_hash == analysis.sample_hash and back.level_count == 2


def test_an_array_is_analysed_as_its_file(sample, tmp_path):
    """A float TIFF is read as it is, so the array's analysis is the file's."""
    linear = sample[1]
    tif = tmp_path / "linear.tif"
    tifffile.imwrite(tif, linear, photometric="rgb")
    from_file = cmfilter.SampleAnalysis.analyse(str(tif), seed=3, **ANALYSIS)
    from_array = cmfilter.SampleAnalysis.analyse(linear, seed=3, **ANALYSIS)
    assert (from_array.width, from_array.height, from_array.channels) == (32, 32, 3)
    for level in range(2):
        np.testing.assert_array_equal(from_array.textons(level), from_file.textons(level))
        np.testing.assert_array_equal(from_array.similar(level), from_file.similar(level))
        np.testing.assert_array_equal(from_array.dot(level), from_file.dot(level))


def test_synthesis_equals_the_command(cli, sample, tmp_path):
    exr = tmp_path / "command-map.exr"
    run(cli, "synth", sample[0], "-o", exr, "--size", "64x48", "-k", "2", "--seed", "9", "--toroidal", *FLAGS,
        "--quiet")
    levels = exr_subimages(exr, tmp_path)
    assert [p.shape for p in levels] == [(48, 64, 2), (24, 32, 2)]
    analysis = cmfilter.SampleAnalysis.analyse(sample[0], seed=9, **ANALYSIS)
    cmap = cmfilter.synthesise(analysis, (64, 48), k=2, seed=9, toroidal=True)
    np.testing.assert_array_equal(cmap.coords(0), map_coords(levels[0], 32, 32))
    np.testing.assert_array_equal(cmap.coords(1), map_coords(levels[1], 16, 16))


def test_synthesis_errors(analysis, tmp_path):
    with pytest.raises(cmfilter.Error, match="missing.png") as e:
        cmfilter.SampleAnalysis.analyse(str(tmp_path / "missing.png"))
    assert e.value.kind == "io"
    with pytest.raises(cmfilter.Error, match="SynthesisOptions::k") as e:
        cmfilter.synthesise(analysis, (64, 64), k=0)
    assert e.value.kind == "bad_input"
    with pytest.raises(cmfilter.Error, match="AnalysisOptions::candidates"):
        cmfilter.SampleAnalysis.analyse(np.zeros((8, 8, 3)), candidates=0)
    with pytest.raises(cmfilter.Error, match="SynthesisOptions::levels"):
        cmfilter.synthesise(analysis, (64, 64), levels=3)
    with pytest.raises(cmfilter.Error, match="shape"):
        cmfilter.SampleAnalysis.analyse(np.zeros(8))
    with pytest.raises(cmfilter.Error, match="missing.exr"):
        cmfilter.SampleAnalysis.read(str(tmp_path / "missing.exr"))
