// SPDX-License-Identifier: Apache-2.0
// The pinhole camera of a scene and its ray differentials (Igehy 1999,
// "Tracing ray differentials"): for the ray through image point (px, py) (in
// pixels, y down, pixel centres at half-integers), the origin, the unit
// direction d and its derivatives dd/dpx, dd/dpy. With the unnormalised
// direction D = forward + (2 (px / W) - 1) a tan(fov/2) right
//                       - (2 (py / H) - 1) tan(fov/2) up   (a = W / H),
// d = D / |D| and dd/dpx = (|D|^2 dD/dpx - <D, dD/dpx> D) / |D|^3 (the same for y).
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/math/vec3.h"

namespace cmfilter {

struct CameraRay {
    Vec3 origin;
    Vec3 direction;       // unit
    Vec3 d_direction_dx;  // per pixel along x
    Vec3 d_direction_dy;  // per pixel along y (down the image)
};

class Camera {
public:
    // BadInput (naming the value) for a zero view direction, a zero up
    // vector, up parallel to the view direction, fov outside (0, 180), or a
    // resolution outside 1 .. kMaxImageSide / kMaxImagePixels.
    static Expected<Camera> create(const SceneCamera& camera);

    CameraRay ray(double px, double py) const;
    // The unnormalised direction of the header, D(px, py) = corner + px step_x
    // + py step_y: affine in the image point, so a plane through the eye
    // meets the image in a line and a cone about it in a conic.
    struct ImagePlane {
        Vec3 origin, corner, step_x, step_y;
    };
    ImagePlane image_plane() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    Camera() = default;
    Vec3 origin_, forward_, right_, up_;  // right_ and up_ scaled by the half-extents of the image plane at distance 1
    int width_ = 0, height_ = 0;
};

}  // namespace cmfilter
