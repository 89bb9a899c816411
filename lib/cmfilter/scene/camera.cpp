// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/camera.h"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Below this sine of the angle between up and the view direction, up counts
// as parallel: the image's right axis would be mostly rounding error.
constexpr double kMinUpSine = 1e-9;

std::string format(const Vec3& v)
{
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

Error bad_camera_vector(const std::string& name, const Vec3& v, const std::string& problem)
{
    return bad_input("camera: " + name + " " + format(v) + " " + problem);
}

}  // namespace

Expected<Camera> Camera::create(const SceneCamera& camera)
{
    if (!is_finite(camera.position)) return bad_camera_vector("position", camera.position, "is not finite");
    if (!is_finite(camera.look_at)) return bad_camera_vector("look_at", camera.look_at, "is not finite");
    if (!is_finite(camera.up)) return bad_camera_vector("up", camera.up, "is not finite");
    const Vec3 view = camera.look_at - camera.position;
    if (!(length(view) > 0))
        return bad_input("camera: the view direction look_at " + format(camera.look_at) + " - position " +
                         format(camera.position) + " is zero");
    if (!(length(camera.up) > 0)) return bad_camera_vector("up", camera.up, "is zero");
    const Vec3 forward = normalize(view);
    const Vec3 forward_cross_up = cross(forward, normalize(camera.up));  // length: the sine of their angle
    if (!(length(forward_cross_up) > kMinUpSine))
        return bad_camera_vector("up", camera.up, "is parallel to the view direction " + format(view));
    if (!(camera.fov_degrees > 0 && camera.fov_degrees < 180)) {
        std::ostringstream msg;
        msg << "camera: fov_degrees " << camera.fov_degrees << " is outside (0, 180)";
        return bad_input(msg.str());
    }
    for (const auto& [name, extent] : {std::pair{"width", camera.width}, std::pair{"height", camera.height}})
        if (extent < 1 || extent > kMaxImageSide)
            return bad_input(std::string("camera: ") + name + " " + std::to_string(extent) + " is outside 1 .. " +
                             std::to_string(kMaxImageSide));
    const long long pixels = static_cast<long long>(camera.width) * camera.height;
    if (pixels > kMaxImagePixels)
        return bad_input("camera: width x height " + std::to_string(camera.width) + " x " +
                         std::to_string(camera.height) + " = " + std::to_string(pixels) + " pixels is above " +
                         std::to_string(kMaxImagePixels));

    const double half_height = std::tan(0.5 * camera.fov_degrees * kPi / 180.0);
    const double aspect = static_cast<double>(camera.width) / camera.height;
    const Vec3 right = normalize(forward_cross_up);
    Camera c;
    c.origin_ = camera.position;
    c.forward_ = forward;
    c.right_ = aspect * half_height * right;
    c.up_ = half_height * cross(right, forward);
    c.width_ = camera.width;
    c.height_ = camera.height;
    return c;
}

Camera::ImagePlane Camera::image_plane() const
{
    return {origin_, forward_ - right_ + up_, (2.0 / width_) * right_, (-2.0 / height_) * up_};
}

CameraRay Camera::ray(double px, double py) const
{
    const Vec3 D = forward_ + (2.0 * px / width_ - 1.0) * right_ - (2.0 * py / height_ - 1.0) * up_;
    const Vec3 dD_dx = (2.0 / width_) * right_;
    const Vec3 dD_dy = (-2.0 / height_) * up_;
    CameraRay r;
    r.origin = origin_;
    r.direction = normalize(D);
    // Igehy 1999's eye-ray differential: the derivative of the normalised D.
    r.d_direction_dx = normalize_derivative(D, dD_dx);
    r.d_direction_dy = normalize_derivative(D, dD_dy);
    return r;
}

}  // namespace cmfilter
