# SPDX-License-Identifier: Apache-2.0
# render to an array against the cmfilter command's own render of the same
# scene, its EXR read by OpenImageIO's oiiotool (converted to a float TIFF)
# and tifffile, never by the module.
import re
import shutil

import numpy as np
import pytest
import tifffile

import cmfilter
from conftest import run


@pytest.mark.parametrize("method", ["naive", "gaussian"])
def test_render_equals_the_command(cli, source_dir, tmp_path, method):
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        pytest.skip("oiiotool is not installed")
    scene = source_dir / "tests/cli/scenes/good.json"
    exr, tif = tmp_path / "render.exr", tmp_path / "render.tif"
    run(cli, "render", scene, "--method", method, "--size", "16x9", "-o", exr, "--quiet")
    run(oiiotool, exr, "-d", "float", "--compression", "none", "-o", tif)
    expected = tifffile.imread(tif)
    image = cmfilter.render(str(scene), method=method, size=(16, 9))
    assert image.shape == (9, 16, 3) and image.dtype == np.float32
    np.testing.assert_array_equal(image, expected[..., :3])


def test_render_segments_equals_the_command_and_the_colour_pyramid(cli, source_dir, tmp_path):
    # segments through the two-colour map: the command's image pixel for
    # pixel, and the colour pyramid's box means of C0(f), a second
    # computation, within float rounding.
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        pytest.skip("oiiotool is not installed")
    scene = source_dir / "tests/cli/scenes/texture-step.json"
    exr, tif = tmp_path / "render.exr", tmp_path / "render.tif"
    run(cli, "render", scene, "--method", "segments", "-o", exr, "--quiet")
    run(oiiotool, exr, "-d", "float", "--compression", "none", "-o", tif)
    image = cmfilter.render(str(scene), method="segments")
    np.testing.assert_array_equal(image, tifffile.imread(tif)[..., :3])
    colors = cmfilter.render(str(scene), method="color-pyramid")
    assert np.abs(image - colors).max() < 1e-4
    assert np.abs(image - cmfilter.render(str(scene), method="naive")).max() > 0.05


def test_render_aovs_and_region(source_dir):
    scene = str(source_dir / "tests/cli/scenes/good.json")
    whole = cmfilter.render(scene, method="naive", size=(16, 9), aovs=True)
    assert set(whole) >= {"rgb", "hit", "distance", "mean", "sigma", "lod", "surface"}
    assert whole["sigma"].shape == (9, 16)
    # One plane below the horizon: its index where a centre ray hits, -1 in the sky.
    assert whole["surface"].dtype == np.int32
    np.testing.assert_array_equal(whole["surface"], np.where(whole["hit"] == 1, 0, -1))
    assert 0 < whole["hit"].sum() < 16 * 9
    part = cmfilter.render(scene, method="naive", size=(16, 9), region=(4, 2, 12, 7))
    np.testing.assert_array_equal(part, whole["rgb"][2:7, 4:12])


def test_render_errors(source_dir, tmp_path):
    with pytest.raises(cmfilter.Error, match="missing.json"):
        cmfilter.render(str(tmp_path / "missing.json"))
    with pytest.raises(cmfilter.Error, match="unknown-key.json") as e:
        cmfilter.render(str(source_dir / "tests/cli/scenes/unknown-key.json"))
    assert e.value.kind == "bad_input"
    with pytest.raises(cmfilter.Error, match="method"):
        cmfilter.render(str(source_dir / "tests/cli/scenes/good.json"), method="magic")
    with pytest.raises(cmfilter.Error, match=r"RenderOptions::max_probes 65 is out of range") as e:
        cmfilter.render(str(source_dir / "tests/cli/scenes/good.json"), probes=65)
    assert e.value.field == "RenderOptions::max_probes"


def test_render_mixture_sub_footprints(cli, source_dir, tmp_path):
    # The command's mixture with 4 x 4 squares, pixel for pixel; with one
    # square, gaussian's image; and a bad count named by its field.
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        pytest.skip("oiiotool is not installed")
    scene = source_dir / "tests/cli/scenes/good.json"
    exr, tif = tmp_path / "mixture.exr", tmp_path / "mixture.tif"
    run(cli, "render", scene, "--method", "mixture", "--sub-footprints", "4", "--size", "16x9", "-o", exr, "--quiet")
    run(oiiotool, exr, "-d", "float", "--compression", "none", "-o", tif)
    mixture = cmfilter.render(str(scene), method="mixture", sub_footprints=4, size=(16, 9))
    np.testing.assert_array_equal(mixture, tifffile.imread(tif)[..., :3])
    one = cmfilter.render(str(scene), method="mixture", sub_footprints=1, size=(16, 9))
    np.testing.assert_array_equal(one, cmfilter.render(str(scene), method="gaussian", size=(16, 9)))
    assert np.abs(mixture - one).max() > 1e-3
    with pytest.raises(cmfilter.Error, match=r"SubFootprintOptions::max_cells 17 is out of range") as e:
        cmfilter.render(str(scene), method="mixture", sub_footprints=17)
    assert e.value.field == "SubFootprintOptions::max_cells"


def test_render_per_surface_choices_equal_the_commands_auto(cli, source_dir, tmp_path):
    # The bundled microsurface by the command's --method auto, and by the
    # module with the method and probe count that render recorded for it,
    # pixel for pixel; bad per-surface choices named by their fields.
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        pytest.skip("oiiotool is not installed")
    scene = source_dir / "examples/scenes/plane-microsurface-sand-snow.json"
    exr, tif = tmp_path / "auto.exr", tmp_path / "auto.tif"
    run(cli, "render", scene, "--method", "auto", "--tolerance", "1", "--size", "24x16", "-o", exr, "--quiet")
    info = run(oiiotool, "--info", "-v", exr).stdout
    method = re.search(r'cmfilter:microsurface_methods: "0: ([a-z-]+)"', info).group(1)
    probes = int(re.search(r'cmfilter:surface_probes: "0: ([0-9]+)"', info).group(1))
    run(oiiotool, exr, "-d", "float", "--compression", "none", "-o", tif)
    image = cmfilter.render(str(scene), method="gaussian", size=(24, 16), tolerance=1.0,
                            microsurface_methods=[method], surface_probes=[probes])
    np.testing.assert_array_equal(image, tifffile.imread(tif)[..., :3])
    with pytest.raises(cmfilter.Error, match=r"supersample for surface 0") as e:
        cmfilter.render(str(scene), size=(8, 8), microsurface_methods=["supersample"])
    assert e.value.field == "RenderOptions::microsurface_methods"
    with pytest.raises(cmfilter.Error, match=r"65 for surface 0") as e:
        cmfilter.render(str(scene), size=(8, 8), surface_probes=[65])
    assert e.value.field == "RenderOptions::surface_probes"
