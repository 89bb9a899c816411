// SPDX-License-Identifier: Apache-2.0
// The bundled ground plane (examples/scenes/plane-image-terrain.json) as a
// renderer's fragment shader draws it with shaders/: one ray per pixel
// centre through `cmfilter render`'s pinhole camera, its hit on the plane,
// the pixel's footprint in texture space from the ray differentials (Igehy
// 1999), cut into up to 16 square probes along its major axis as `render`
// does (texture_footprint.h), each probe's mean and sigma of the driver from
// the moment pyramid (sec. 4.2) and its colour by the naive method C0(mean)
// or the gaussian one T(mean, sigma) (eq. 10), shaded
// albedo (radiance max(0, <n, l>) + ambient).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "cmfilter_color_table.glsl"
#include "cmfilter_moments.glsl"

layout(binding = 0) uniform sampler2D moments;      // the driver's moment pyramid, periodic
layout(binding = 1) uniform sampler2D color_table;  // T(v, sigma) of the material
layout(binding = 2) uniform sampler2D color_map;    // C0, n x 1
layout(std140, binding = 0) uniform Frame {
    vec4 origin;         // camera position
    vec4 forward;        // unit view direction
    vec4 right;          // aspect tan(fov / 2) times the unit right axis
    vec4 up;             // tan(fov / 2) times the unit up axis
    vec4 plane_point;    // a point of the plane
    vec4 plane_normal;   // its unit normal
    vec4 u_axis;         // planar mapping: u = <p - origin, u_axis>
    vec4 v_axis;         //                 v = <p - origin, v_axis>
    vec4 mapping_origin;
    vec4 light;          // unit direction towards the light
    vec4 radiance;
    vec4 ambient;
    vec4 background;
    vec2 size;           // pixels
    int method;          // 0 naive, 1 gaussian
    int max_probes;      // render's --probes (16)
    float texture_width; // the driver's level-0 width, texels
} frame;
layout(std140, binding = 1) uniform Material {
    CmfColorTable table;       // the table's cmfilter:* axes
    CmfMomentPyramid pyramid;  // cmfilter:reference, cmfilter:levels
} material;

layout(location = 0) out vec4 colour;

// The derivative of normalize(D) along dD.
vec3 normalize_derivative(vec3 D, vec3 dD)
{
    float len = length(D);
    vec3 d = D / len;
    return (dD - d * dot(d, dD)) / len;
}

void main()
{
    // Pixel (x, y), row 0 at the top: px = x + 0.5, py = y + 0.5.
    float px = gl_FragCoord.x, py = frame.size.y - gl_FragCoord.y;
    vec3 D = frame.forward.xyz + (2.0 * px / frame.size.x - 1.0) * frame.right.xyz -
             (2.0 * py / frame.size.y - 1.0) * frame.up.xyz;
    vec3 d = normalize(D);
    vec3 dd_dx = normalize_derivative(D, (2.0 / frame.size.x) * frame.right.xyz);
    vec3 dd_dy = normalize_derivative(D, (-2.0 / frame.size.y) * frame.up.xyz);
    vec3 n = frame.plane_normal.xyz;
    float dn = dot(d, n);
    float t = dn != 0.0 ? dot(frame.plane_point.xyz - frame.origin.xyz, n) / dn : -1.0;
    if (!(t > 0.0)) {
        colour = vec4(frame.background.rgb, 1.0);
        return;
    }
    vec3 p = frame.origin.xyz + t * d;
    // The hit's differentials: dp = t dd + dt d, dt = -t <dd, n> / <d, n>.
    vec3 dp_dx = t * dd_dx - (t * dot(dd_dx, n) / dn) * d;
    vec3 dp_dy = t * dd_dy - (t * dot(dd_dy, n) / dn) * d;
    vec2 uv = vec2(dot(p - frame.mapping_origin.xyz, frame.u_axis.xyz),
                   dot(p - frame.mapping_origin.xyz, frame.v_axis.xyz));
    vec2 e1 = vec2(dot(dp_dx, frame.u_axis.xyz), dot(dp_dx, frame.v_axis.xyz));
    vec2 e2 = vec2(dot(dp_dy, frame.u_axis.xyz), dot(dp_dy, frame.v_axis.xyz));

    // Probes along the major edge (anisotropic_probes.h), each a square of
    // the rms width of its share of the footprint (footprint_width.h).
    float l1 = length(e1), l2 = length(e2);
    vec2 major = l1 >= l2 ? e1 : e2, minor = l1 >= l2 ? e2 : e1;
    float lmajor = max(l1, l2), lminor = min(l1, l2);
    int count = 1;
    if (frame.max_probes > 1 && lmajor > lminor)
        count = int(min(float(frame.max_probes), lminor > 0.0 ? ceil(lmajor / lminor) : float(frame.max_probes)));
    vec2 share = major / float(count);
    float width = sqrt(0.5 * (dot(share, share) + dot(minor, minor)));
    // The trilinear LOD whose kernel has the box's variance (texture_lod.h).
    float lod = log2(width * frame.texture_width) - log2(sqrt(3.0));
    vec3 albedo = vec3(0.0);
    for (int j = 0; j < count; ++j) {
        vec2 q = uv + ((float(j) + 0.5) / float(count) - 0.5) * major;
        CmfMomentSample f = cmf_moment_pyramid(moments, material.pyramid, fract(q), lod);
        if (frame.method == 0)
            albedo += cmf_color_map(color_map, material.table.domain_min, material.table.domain_max, f.mean);
        else
            albedo += cmf_color_table(color_table, material.table, f.mean, f.sigma);
    }
    albedo /= float(count);
    vec3 facing = dn < 0.0 ? n : -n;
    colour = vec4(albedo * (frame.radiance.rgb * max(0.0, dot(facing, frame.light.xyz)) + frame.ambient.rgb), 1.0);
}
