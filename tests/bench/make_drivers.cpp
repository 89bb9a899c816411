// SPDX-License-Identifier: Apache-2.0
// Test drivers for the accuracy experiments of docs/apply.md, written as
// one-channel float32 OpenEXR files (drivers are data: no colour space).
//
//   cmfilter-make-drivers gaussian SIZE BLUR OUT.exr [SEED]
//       White Gaussian noise blurred with a Gaussian of standard deviation
//       BLUR texels (periodic, so no edge effects), then scaled to mean 0.5
//       and standard deviation 0.18: still exactly Gaussian, its 1st-99th
//       percentile range is 0.5 +- 2.326 x 0.18 = [0.081, 0.919], 84% of the
//       domain [0, 1].
//   cmfilter-make-drivers fbm SIZE H OUT.exr [SEED]
//       A sum of octaves of blurred white noise, octave o blurred with a
//       Gaussian of standard deviation 2^o texels (o = 0 .. log2(SIZE) - 2),
//       each scaled to standard deviation 2^(o H) before the sum: at every
//       scale finer octaves fill a footprint, as in fBm. Scaled like the
//       gaussian driver (mean 0.5, standard deviation 0.18); still Gaussian.
//   cmfilter-make-drivers quantise LEVELS IN.exr OUT.exr
//       The driver rounded to LEVELS evenly spaced values k / (LEVELS - 1) in
//       [0, 1] (clamped first): 2 levels give a binary (bimodal) pattern.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {

bool write(const std::string& path, int w, int h, const std::vector<float>& v)
{
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"Y"};
    spec.attribute("compression", "zip");
    return out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, v.data()) && out->close();
}

// Periodic 1-D Gaussian blur of n values with stride, kernel truncated at 5 sigma and normalised.
void blur_line(float* p, int n, std::size_t stride, const std::vector<double>& kernel, std::vector<double>& tmp)
{
    const int r = static_cast<int>(kernel.size()) / 2;
    tmp.assign(n, 0.0);
    for (int i = 0; i < n; ++i) {
        double acc = 0;
        for (int k = -r; k <= r; ++k)
            acc += kernel[k + r] * p[static_cast<std::size_t>(((i + k) % n + n) % n) * stride];
        tmp[i] = acc;
    }
    for (int i = 0; i < n; ++i) p[static_cast<std::size_t>(i) * stride] = static_cast<float>(tmp[i]);
}

// White Gaussian noise of `size`^2 texels blurred periodically with a
// Gaussian of standard deviation `blur` texels (none for blur <= 0).
std::vector<float> blurred_noise(int size, double blur, std::mt19937_64& rng)
{
    std::normal_distribution<double> normal;
    std::vector<float> f(static_cast<std::size_t>(size) * size);
    for (float& x : f) x = static_cast<float>(normal(rng));
    if (blur <= 0) return f;
    const int r = std::min(size / 2, static_cast<int>(std::ceil(5 * blur)));
    std::vector<double> kernel(2 * r + 1), tmp;
    double sum = 0;
    for (int k = -r; k <= r; ++k) sum += kernel[k + r] = std::exp(-0.5 * k * k / (blur * blur));
    for (double& k : kernel) k /= sum;
    for (int y = 0; y < size; ++y) blur_line(f.data() + static_cast<std::size_t>(y) * size, size, 1, kernel, tmp);
    for (int x = 0; x < size; ++x) blur_line(f.data() + x, size, size, kernel, tmp);
    return f;
}

// Scales f to mean `mean` and standard deviation `sd` (measured in double).
void standardise(std::vector<float>& f, double mean_to, double sd_to)
{
    double mean = 0, sq = 0;
    for (float x : f) mean += x;
    mean /= f.size();
    for (float x : f) sq += (x - mean) * (x - mean);
    const double scale = sd_to / std::sqrt(sq / f.size());
    for (float& x : f) x = static_cast<float>(mean_to + (x - mean) * scale);
}

int gaussian(int size, double blur, const std::string& out, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::vector<float> f = blurred_noise(size, blur, rng);
    standardise(f, 0.5, 0.18);
    return write(out, size, size, f) ? 0 : 1;
}

int fbm(int size, double h, const std::string& out, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::vector<double> sum(static_cast<std::size_t>(size) * size, 0.0);
    for (int o = 0; (4 << o) <= size; ++o) {
        std::vector<float> octave = blurred_noise(size, o == 0 ? 0.0 : std::ldexp(1.0, o), rng);
        standardise(octave, 0.0, std::pow(2.0, o * h));
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += octave[i];
    }
    std::vector<float> f(sum.begin(), sum.end());
    standardise(f, 0.5, 0.18);
    return write(out, size, size, f) ? 0 : 1;
}

int quantise(int levels, const std::string& in_path, const std::string& out)
{
    auto in = OIIO::ImageInput::open(in_path);
    if (!in) return 1;
    const OIIO::ImageSpec spec = in->spec();
    std::vector<float> f(static_cast<std::size_t>(spec.width) * spec.height);
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, f.data())) return 1;
    for (float& x : f) x = static_cast<float>(std::round(std::clamp(x, 0.0f, 1.0f) * (levels - 1)) / (levels - 1));
    return write(out, spec.width, spec.height, f) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv)
{
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "gaussian" && (argc == 5 || argc == 6))
        return gaussian(std::atoi(argv[2]), std::atof(argv[3]), argv[4], argc == 6 ? std::atoi(argv[5]) : 1);
    if (mode == "fbm" && (argc == 5 || argc == 6))
        return fbm(std::atoi(argv[2]), std::atof(argv[3]), argv[4], argc == 6 ? std::atoi(argv[5]) : 1);
    if (mode == "quantise" && argc == 5) return quantise(std::atoi(argv[2]), argv[3], argv[4]);
    std::cerr << "usage: cmfilter-make-drivers gaussian SIZE BLUR OUT.exr [SEED]\n"
                 "       cmfilter-make-drivers fbm SIZE H OUT.exr [SEED]\n"
                 "       cmfilter-make-drivers quantise LEVELS IN.exr OUT.exr\n";
    return 1;
}
