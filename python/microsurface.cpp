// SPDX-License-Identifier: Apache-2.0
// The functions of a Gaussian microsurface that `render` colours it with
// (Heitz et al. 2013, sec. 5.1): Smith's Lambda (eq. 3), the mean visibility
// (eq. 13) and the Lambda sum it weights heights by, and the moments of the
// height filtering distribution D_h (eqs. 15-16) with the paper's fit of
// them (eqs. 17-18), on arrays that broadcast.
#include "bindings.h"

#include "cmfilter/microsurface/height_filtering.h"

namespace cmfilter::python {

MaskingShadowing parse_masking(const std::string& name, const char* what)
{
    if (name == "uncorrelated") return MaskingShadowing::Uncorrelated;
    if (name == "correlated") return MaskingShadowing::DirectionCorrelated;
    bad_argument(std::string(what) + " '" + name + "' is unknown (expected uncorrelated or correlated)");
}

namespace {

// f(the broadcast values at i) for every element: an array of the broadcast shape.
template <typename F>
py::array_t<double> per_element(const std::vector<py::object>& values, F&& f)
{
    Broadcast b = broadcast(values);
    std::vector<double> out(b.size);
    for (std::size_t i = 0; i < b.size; ++i) out[i] = f(b, i);
    return owning_array(std::move(out), b.shape);
}

double at(const Broadcast& b, std::size_t k, std::size_t i) { return b.arrays[k].data()[i]; }

void check_nonnegative(const py::object& value, const char* what)
{
    const DoubleArray a = py::cast<DoubleArray>(value);
    for (py::ssize_t i = 0; i < a.size(); ++i)
        if (!(a.data()[i] >= 0))
            bad_argument(std::string(what) + " " + std::to_string(a.data()[i]) + " is invalid (expected >= 0)");
}

}  // namespace

void bind_microsurface(py::module_& m)
{
    m.def(
        "smith_lambda",
        [](const py::object& theta, const py::object& sigma_s) {
        check_nonnegative(sigma_s, "sigma_s");
        return per_element({theta, sigma_s}, [](const Broadcast& b, std::size_t i) {
            return smith_lambda_gaussian(at(b, 0, i), at(b, 1, i));
        });
        },
        py::arg("theta"), py::arg("sigma_s"),
        "Smith's Lambda (eq. 3) of Gaussian slopes of standard deviation sigma_s along the direction's azimuth, at "
        "theta radians from the mean normal (clamped to pi/2; +inf there, where only the highest points are seen).");

    // lambda_sum and mean_visibility: the same arguments.
    using LambdaFunction = double (*)(double, double, double, MaskingShadowing);
    const auto bind_lambda_function = [&m](const char* name, LambdaFunction f, const char* doc) {
        m.def(
            name,
            [f](const py::object& lambda_o, const py::object& lambda_i, const py::object& azimuth_difference,
                const std::string& masking) {
            const MaskingShadowing mode = parse_masking(masking, "masking");
            return per_element({lambda_o, lambda_i, azimuth_difference}, [&](const Broadcast& b, std::size_t i) {
                return f(at(b, 0, i), at(b, 1, i), at(b, 2, i), mode);
            });
            },
            py::arg("lambda_o"), py::arg("lambda_i"), py::arg("azimuth_difference") = 0.0, py::kw_only(),
            py::arg("masking") = "uncorrelated", doc);
    };
    bind_lambda_function(
        "lambda_sum", &lambda_sum,
        "The Lambda sum L that weights the heights seen lit by P_h^L (eq. 16): Lambda_o + Lambda_i (uncorrelated), "
        "or max + lambda(phi) min with lambda(phi) = 4.41 phi / (4.41 phi + 1) (correlated by the azimuth "
        "difference phi, radians).");
    bind_lambda_function(
        "mean_visibility", static_cast<LambdaFunction>(&mean_visibility),
        "The share of the viewed microsurface that is lit, (1 + Lambda_o) / (1 + L) with L lambda_sum's (eq. 13 "
        "when uncorrelated), in [0, 1], its limits taken where a Lambda is infinite.");

    m.def(
        "height_moments",
        [](const py::object& lambda_sum, const py::object& sigma_h, const std::string& fit) {
        if (fit != "exact" && fit != "paper") bad_argument("fit '" + fit + "' is unknown (expected exact or paper)");
        check_nonnegative(sigma_h, "sigma_h");
        Broadcast b = broadcast({lambda_sum, sigma_h});
        std::vector<double> mean(b.size), sigma(b.size);
        for (std::size_t i = 0; i < b.size; ++i) {
            const HeightMoments h = fit == "exact" ? exact_height_moments(at(b, 0, i), at(b, 1, i))
                                                   : paper_height_fit(at(b, 0, i), at(b, 1, i));
            mean[i] = h.mean;
            sigma[i] = h.sigma;
        }
        return py::make_tuple(owning_array(std::move(mean), b.shape), owning_array(std::move(sigma), b.shape));
        },
        py::arg("lambda_sum"), py::arg("sigma_h"), py::kw_only(), py::arg("fit") = "exact",
        "The mean and central standard deviation of the heights seen lit, D_h(h) proportional to P_h(h)^L p_h(h) "
        "for heights N(0, sigma_h^2) (eqs. 15-16): exact (quadrature), or the paper's fit (eqs. 17-18). "
        "(mean, sigma) float64 arrays.");
}

}  // namespace cmfilter::python
