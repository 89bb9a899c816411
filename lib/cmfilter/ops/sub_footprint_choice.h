// SPDX-License-Identifier: Apache-2.0
// The fewest sub-footprints (noise/noise_sub_footprints.h) a noise material
// needs for a colour-difference tolerance, by measurement, as
// docs/noise-accuracy.md measures: at each measured LOD L, square footprints
// of width p_0 2^L at `footprints` centres uniform over [0, 256 p_0)^2 are
// coloured by the mixture with each candidate's max_cells (1: sec. 4.2's one
// Gaussian) through the material's colour of a Gaussian (its table lookup,
// as the renderer makes it for each square; the renderer's small-sigma
// shortcut of a whole footprint is not applied here), and compared with the
// reference,
// the mean of C0(f) over strata x strata jittered-stratified points of the
// footprint; the error at L is the mean CIEDE2000 over the footprints, a
// candidate's error overall the worst over the LODs. Candidates are tried
// fewest squares first; the choice is the first that meets the tolerance at
// every LOD, none when none does (the caller says so).
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/noise/noise_sub_footprints.h"
#include "cmfilter/util/error.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace cmfilter {

// The integer LODs that cover a view's footprints from LOD `first` to `last`
// (surface_lods.h): floor(first) to ceil(last), each kept within the integer
// LODs of the noise's sigma table (which sub-footprints are measured over);
// at least one (the table's first LOD where it spans no integer).
std::vector<double> sub_footprint_lods_between(const NoiseSigmaTable& table, double first, double last);

struct SubFootprintChoiceOptions {
    double tolerance = 1.0;  // mean CIEDE2000 at every measured LOD; finite and > 0
    // The LODs measured (log2 of the width over the base period), each
    // finite; empty: every integer LOD of the noise's sigma table.
    std::vector<double> lods;
    // SubFootprintOptions::max_cells candidates, each 1 .. 16; empty: 1, 2,
    // 4, 8, 16. Tried in increasing order.
    std::vector<int> candidates;
    int footprints = 256;  // per LOD, >= 1
    int strata = 32;       // reference points per axis, >= 1 (32: as docs/noise-accuracy.md)
    std::uint64_t seed = 0;
    int threads = 0;  // 0: all cores
};

struct SubFootprintTrial {
    int max_cells = 1;
    std::vector<double> errors;  // mean CIEDE2000 per measured LOD
    double worst = 0;
    double worst_lod = 0;
    bool meets = false;
};

struct SubFootprintChoice {
    double tolerance = 0;
    std::vector<double> lods;
    std::vector<SubFootprintTrial> trials;  // fewest squares first
    std::optional<std::size_t> chosen;      // the first that meets; none when none does

    const SubFootprintTrial* choice() const { return chosen ? &trials[*chosen] : nullptr; }
    const SubFootprintTrial* best() const;  // the lowest worst error
};

// BadInput naming SubFootprintChoiceOptions' field for a tolerance, LOD,
// candidate, footprint or strata count out of range.
// `gaussian_colour(mean, sigma)` is the material's colour of N(mean,
// sigma^2), `map` its C0; both are called from several threads.
Expected<SubFootprintChoice> choose_sub_footprints(const FilteredNoise& noise, const ColorMap& map,
                                                   const std::function<Rgb(double, double)>& gaussian_colour,
                                                   const SubFootprintChoiceOptions& options);

}  // namespace cmfilter
