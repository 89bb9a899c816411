# SPDX-License-Identifier: Apache-2.0
# Relighting fits against NumPy: stacks made here from known models, the
# PTM polynomial (Malzbender et al. 2001, eq. 2) fitted by numpy.linalg.lstsq
# and evaluated here, Lafortune lobes evaluated here.
import numpy as np
import pytest

import cmfilter


def hemisphere(n, min_z=0.25):
    """n directions spread over the upper hemisphere (a Fibonacci spiral)."""
    k = np.arange(n) + 0.5
    z = 1 - (1 - min_z) * k / n
    phi = k * np.pi * (3 - np.sqrt(5))
    r = np.sqrt(1 - z * z)
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)


def ptm_basis(lights):
    u, v = lights[:, 0], lights[:, 1]
    return np.stack([u * u, v * v, u * v, u, v, np.ones_like(u)], axis=1)


def test_ptm_fit_is_least_squares_and_relights_the_polynomial():
    rng = np.random.default_rng(7)
    lights = hemisphere(16)
    h, w, c = 4, 5, 3
    truth = rng.uniform(-0.3, 0.6, (h, w, c, 6))
    images = np.einsum("nk,hwck->nhwc", ptm_basis(lights), truth) + rng.normal(0, 0.01, (16, h, w, c))
    fit = cmfilter.LinearFit.fit(images.astype(np.float32), lights, model="ptm-rgb", threads=1)
    assert (fit.width, fit.height, fit.channels, fit.terms) == (w, h, c, 6)
    # numpy's least squares on the same (float32) values.
    values = images.astype(np.float32).astype(np.float64).reshape(16, -1)
    solution, *_ = np.linalg.lstsq(ptm_basis(lights), values, rcond=None)
    expected = solution.T.reshape(h, w, c * 6)
    np.testing.assert_allclose(fit.coefficients, expected, atol=2e-5)
    new = hemisphere(5, min_z=0.5)[:, [1, 0, 2]]
    relit = fit.relight(new)
    assert relit.shape == (5, h, w, c) and relit.dtype == np.float32
    np.testing.assert_allclose(relit, np.einsum("nk,hwck->nhwc", ptm_basis(new), expected.reshape(h, w, c, 6)),
                               atol=2e-5)
    np.testing.assert_allclose(fit.relight(new[2]), relit[2])


def test_linear_fit_file_round_trip(tmp_path):
    lights = hemisphere(9)
    images = np.random.default_rng(1).uniform(0, 1, (9, 3, 2, 3)).astype(np.float32)
    fit = cmfilter.LinearFit.fit(images, lights, model="hsh2")
    fit.write(str(tmp_path / "fit.exr"))
    back = cmfilter.LinearFit.read(str(tmp_path / "fit.exr"))
    assert back.model == "hsh2"
    np.testing.assert_array_equal(back.coefficients, fit.coefficients)


def lafortune_image(lights, rho, axis, n):
    """uz (rho + max(0, axis . u)^n) per light and texel (one channel)."""
    dots = np.maximum(np.einsum("lk,hwk->lhw", lights, axis), 0)
    return lights[:, 2, None, None] * (rho + dots ** n)


def test_lafortune_lobe_is_recovered_and_relit(tmp_path):
    rng = np.random.default_rng(4)
    lights = hemisphere(48, min_z=0.1)
    h, w = 2, 3
    rho = rng.uniform(0.1, 0.3, (h, w))
    direction = np.stack([rng.uniform(-0.3, 0.3, (h, w)), rng.uniform(-0.3, 0.3, (h, w)), np.ones((h, w))], -1)
    axis = 0.95 * direction / np.linalg.norm(direction, axis=-1, keepdims=True)
    n = rng.uniform(4, 12, (h, w))
    images = lafortune_image(lights, rho[None], axis, n[None])[..., None].astype(np.float32)
    fit = cmfilter.LafortuneFit.fit(images, lights, variant="luminance", lobes=1, spacing_cap=0, threads=1)
    held_out = hemisphere(7, min_z=0.3)[:, [1, 0, 2]]
    expected = lafortune_image(held_out, rho[None], axis, n[None])[..., None]
    np.testing.assert_allclose(fit.relight(held_out), expected, rtol=0.02, atol=2e-3)
    fit.write(str(tmp_path / "lobes.exr"))
    back = cmfilter.LafortuneFit.read(str(tmp_path / "lobes.exr"))
    np.testing.assert_array_equal(back.parameters, fit.parameters)


def test_fit_errors():
    images = np.zeros((3, 2, 2, 3), np.float32)
    with pytest.raises(cmfilter.Error, match="LinearFitOptions::model") as e:
        cmfilter.LinearFit.fit(images, hemisphere(3), model="ptm-rgb")
    assert e.value.kind == "bad_input" and e.value.field == "LinearFitOptions::model"
    with pytest.raises(cmfilter.Error, match="lights"):
        cmfilter.LinearFit.fit(images, hemisphere(4))
    with pytest.raises(cmfilter.Error, match="no-such.lp"):
        cmfilter.LinearFit.fit_stack("no-such.lp")
