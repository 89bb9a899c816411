// SPDX-License-Identifier: Apache-2.0
// CIEDE2000 against the 34 published test pairs of Sharma, Wu & Dalal (2005)
// (tests/data/ciede2000-sharma.tsv), the linear Rec.709 -> L*a*b* conversion
// at white, black and mid grey, and the nearest-rank error summary.
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/color/error_summary.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

struct SharmaPair {
    Lab x, y;
    double expected = 0;
    int line = 0;
};

std::vector<SharmaPair> read_sharma_pairs()
{
    const std::string path = std::string(CMFILTER_TEST_DATA_DIR) + "/ciede2000-sharma.tsv";
    std::ifstream in(path);
    REQUIRE_MESSAGE(in, "cannot open " << path);
    std::vector<SharmaPair> pairs;
    std::string line;
    int line_number = 0;
    while (std::getline(in, line)) {
        ++line_number;
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        SharmaPair p;
        p.line = line_number;
        fields >> p.x.L >> p.x.a >> p.x.b >> p.y.L >> p.y.a >> p.y.b >> p.expected;
        REQUIRE_MESSAGE(!fields.fail(), "malformed line " << line_number << ": " << line);
        pairs.push_back(p);
    }
    return pairs;
}

}  // namespace

TEST_CASE("ciede2000 matches the Sharma et al. 2005 test data in both argument orders")
{
    const std::vector<SharmaPair> pairs = read_sharma_pairs();
    CHECK(pairs.size() == 34);  // the paper's Table 1 has 34 pairs
    for (const SharmaPair& p : pairs) {
        INFO("tsv line " << p.line);
        // Tolerance 1e-4: the published Delta E00 values are rounded to 4
        // decimals, so a correct implementation is within 0.5e-4 of them (plus
        // double rounding, ~1e-14). 1e-4 still catches the hue-angle mistakes
        // these pairs were designed to expose: the published values on either
        // side of each discontinuity (pairs 9-15) differ by 0.04 or more.
        CHECK(std::fabs(ciede2000(p.x, p.y) - p.expected) <= 1e-4);
        CHECK(std::fabs(ciede2000(p.y, p.x) - p.expected) <= 1e-4);
    }
}

TEST_CASE("ciede2000 of a colour with itself is zero")
{
    const Lab c{50.0, 2.5, -3.0};
    // Exact: every difference term (eqs. 8, 9, 10) is exactly 0.
    CHECK(ciede2000(c, c) == 0.0);
}

TEST_CASE("ciede2000: linear Rec.709 to L*a*b* at white, black and mid grey")
{
    // Tolerance 1e-9: the white is normalised by the row sums of the same
    // matrix, so the only error is rounding in a few multiplications and one
    // cube root (~1e-14 on values of order 100); 1e-9 leaves a wide margin while
    // still catching any wrong constant or white point (errors of 1e-4 or more).
    const Lab white = linear_rec709_to_lab({1.0, 1.0, 1.0});
    CHECK(std::fabs(white.L - 100.0) <= 1e-9);
    CHECK(std::fabs(white.a) <= 1e-9);
    CHECK(std::fabs(white.b) <= 1e-9);

    const Lab black = linear_rec709_to_lab({0.0, 0.0, 0.0});
    CHECK(std::fabs(black.L) <= 1e-9);  // same rounding argument as white
    CHECK(std::fabs(black.a) <= 1e-9);
    CHECK(std::fabs(black.b) <= 1e-9);

    // Mid grey 0.18 has Y/Yn = 0.18 > (6/29)^3, on the cube-root branch, so
    // L* = 116 * 0.18^(1/3) - 16, computed here independently with std::pow.
    // Tolerance 1e-9 as above (pow vs cbrt differ by ~1 ulp).
    const Lab grey = linear_rec709_to_lab({0.18, 0.18, 0.18});
    const double expected_L = 116.0 * std::pow(0.18, 1.0 / 3.0) - 16.0;
    CHECK(std::fabs(grey.L - expected_L) <= 1e-9);
    CHECK(std::fabs(grey.a) <= 1e-9);  // a neutral colour: a* = b* = 0 up to rounding
    CHECK(std::fabs(grey.b) <= 1e-9);
}

TEST_CASE("ciede2000: linear Rec.709 input is clipped to 0..1, NaN to 0")
{
    // Exact comparisons: clipping makes the inputs bit-identical, so the
    // outputs are bit-identical too.
    const Lab clipped = linear_rec709_to_lab({2.0, -1.0, std::nan("")});
    const Lab expected = linear_rec709_to_lab({1.0, 0.0, 0.0});
    CHECK(clipped.L == expected.L);
    CHECK(clipped.a == expected.a);
    CHECK(clipped.b == expected.b);
    CHECK(ciede2000_linear_rgb({2.0, -1.0, std::nan("")}, {1.0, 0.0, 0.0}) == 0.0);
}

TEST_CASE("ciede2000 error summary: mean, nearest-rank p95 and max of 1..100")
{
    std::vector<double> values;
    for (int i = 100; i >= 1; --i) values.push_back(i);  // unsorted on purpose
    const ErrorSummary s = summarize_errors(values);
    CHECK(s.count == 100);
    // Tolerance 1e-12: the sum 5050 of small integers is exact in double and
    // 5050 / 100 is correctly rounded, so mean is 50.5 to the last bit; the
    // tolerance only guards against a different summation order.
    CHECK(std::fabs(s.mean - 50.5) <= 1e-12);
    // Exact: p95 and max are elements of the input, not computed values.
    CHECK(s.p95 == 95.0);  // rank ceil(0.95 * 100) = 95
    CHECK(s.max == 100.0);
}

TEST_CASE("ciede2000 error summary: empty input and small samples")
{
    const ErrorSummary empty = summarize_errors({});
    CHECK(empty.count == 0);
    CHECK(empty.mean == 0.0);  // exact: defined as 0
    CHECK(empty.p95 == 0.0);
    CHECK(empty.max == 0.0);

    // n = 19: rank ceil(18.05) = 19, the maximum (exact: an element of the input).
    std::vector<double> nineteen;
    for (int i = 1; i <= 19; ++i) nineteen.push_back(i);
    CHECK(summarize_errors(nineteen).p95 == 19.0);
    // n = 20: rank ceil(19) = 19 (exact).
    nineteen.push_back(20);
    CHECK(summarize_errors(nineteen).p95 == 19.0);
}
