// SPDX-License-Identifier: Apache-2.0
// One ray of the ray-traced ground truth for a microsurface plane (scene.h,
// MaterialSource::microsurface): the plane displaced along its normal (the side
// facing the camera) by the microsurface's heights, a tabulated heightfield
// (heightfield_tracer.h) traced exactly, and a shadow ray from the hit to the
// light. The frame: x = <p - mapping origin, u_axis>, y = <p - mapping
// origin, v_axis>, z = k <p - plane point, n> for the mapping's axis length k,
// so texture units on all three axes (the mapping is a scaled isometry).
#pragma once

#include "cmfilter/microsurface/heightfield_tracer.h"
#include "cmfilter/scene/scene.h"

#include <optional>

namespace cmfilter {

struct DisplacedPlaneSample {
    double t = 0;             // scene distance along the unit ray direction
    double height = 0;        // of the hit, texture units: C_h's argument
    bool lit = false;         // the shadow ray reaches the light
    double light_cosine = 0;  // max(0, <m, l>) for the hit's micro-normal m
    double x = 0, y = 0;      // the hit's texture coordinates (u, v)
    // The microsurface's slopes (dh/du, dh/dv) at the hit: the heightfield's
    // tabulated ones (HeightfieldOptions::slopes), else its bilinear patch's.
    double slope_x = 0, slope_y = 0;
};

// The ray (unit direction) against the displaced plane seen from the side
// the ray comes from; none when it never meets the heightfield (a ray parallel
// to the plane or leaving it).
// `shift`: the heightfield's (x, y) are the texture's (u - shift, v - shift)
// (a displacement texture's half texel, DisplacementTexture::heightfield_xy;
// 0 for a Gaussian microsurface).
std::optional<DisplacedPlaneSample> trace_displaced_plane(const Surface& plane, const Heightfield& heightfield,
                                                          const Vec3& origin, const Vec3& direction,
                                                          const Vec3& to_light, double shift = 0);

}  // namespace cmfilter
