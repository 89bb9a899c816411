// SPDX-License-Identifier: Apache-2.0
// The bundled ground plane rendered in real time by the shaders of shaders/
// (docs/shaders.md): a fragment shader over `cmfilter render`'s camera,
// filtering the plane's texture driver by the naive or the gaussian method,
// drawn headlessly into a float framebuffer and written as a scene-linear
// OpenEXR image, with the frame time.
//   realtime_plane SCENE.json --method naive|gaussian --size WxH -o OUT.exr [--frames N]
// The scene must hold one plane with a planar mapping and a texture driver
// (examples/scenes/plane-image-terrain.json). Its material is prepared by the
// library as `render` prepares it (the moment pyramid baked, the colour
// table chosen), then uploaded as textures.
#include "artefact_textures.h"
#include "headless_gl.h"

#include "cmfilter/color/color_config.h"
#include "cmfilter/scene/camera.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

int usage()
{
    std::fprintf(stderr, "usage: realtime_plane SCENE.json --method naive|gaussian --size WxH -o OUT.exr "
                         "[--frames N]\n");
    return 2;
}

void put(std::vector<float>& block, const Vec3& v, float w = 0)
{
    block.insert(block.end(), {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), w});
}

void put(std::vector<float>& block, const Rgb& c)
{
    block.insert(block.end(), {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), 0});
}

int run(int argc, char** argv)
{
    std::string scene_path, method, output;
    int width = 0, height = 0, frames = 10;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--method" && has_value) method = argv[++i];
        else if (a == "--size" && has_value) {
            if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2) return usage();
        } else if (a == "-o" && has_value) output = argv[++i];
        else if (a == "--frames" && has_value) frames = std::stoi(argv[++i]);
        else if (scene_path.empty() && a[0] != '-') scene_path = a;
        else return usage();
    }
    if (scene_path.empty() || output.empty() || (method != "naive" && method != "gaussian") || width < 1 ||
        height < 1 || frames < 1)
        return usage();

    auto scene = load_scene(scene_path);
    if (!scene) throw std::runtime_error(scene.error().message);
    scene->camera.width = width;
    scene->camera.height = height;
    if (scene->surfaces.size() != 1 || scene->surfaces[0].kind != SurfaceKind::Plane ||
        scene->surfaces[0].mapping.kind != MappingKind::Planar)
        throw std::runtime_error(scene_path + ": expected one plane with a planar mapping");
    auto config = ColorConfig::load("");
    if (!config) throw std::runtime_error(config.error().message);
    auto materials = prepare_materials(*scene, *config, {});
    if (!materials) throw std::runtime_error(materials.error().message);
    const Material& material = (*materials)[0];
    const auto* driver = std::get_if<TextureDriver>(&material.driver);
    if (!driver) throw std::runtime_error(scene_path + ": the plane's driver is not a texture");
    auto camera = Camera::create(scene->camera);
    if (!camera) throw std::runtime_error(camera.error().message);

    cmfilter_gl::GlContext gl;
    std::printf("OpenGL renderer: %s\n", gl.renderer().c_str());

    // The moment pyramid's levels, as its file holds them (periodic: render
    // bakes texture drivers with --wrap periodic).
    const MomentTexture& moments = driver->texture.moments();
    const cmfilter_gl::MomentLevels levels = cmfilter_gl::read_moment_levels(moments.path());
    if (static_cast<int>(levels.levels.size()) != moments.info().levels)
        throw std::runtime_error(moments.path() + ": the file's MIP levels disagree with cmfilter:levels");
    const GLenum wrap = moments.info().wrap == TextureWrap::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    GLuint textures[3];
    textures[0] = cmfilter_gl::float_texture(0, levels.levels, 2, wrap, wrap, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    // The colour table render chose for the material, and the map C0.
    const GaussianColorTable& table = material.color.table;
    const TableAxes& ax = table.axes();
    textures[1] = cmfilter_gl::float_texture(1, {{ax.values, ax.sigmas, table.data().data()}}, 3,
                                             ax.wrap == WrapMode::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE,
                                             GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR);
    std::vector<float> map;
    for (const Rgb& c : material.color.map.texels) put(map, c);
    const ColorMap& c0 = material.color.map;
    textures[2] = cmfilter_gl::float_texture(2, {{static_cast<int>(c0.texels.size()), 1, map.data()}}, 4,
                                             cmfilter_gl::color_map_wrap(c0.wrap), GL_CLAMP_TO_EDGE, GL_LINEAR,
                                             GL_LINEAR);

    // The uniform blocks (std140: vec4s, then the scalars packed).
    const Camera::ImagePlane plane = camera->image_plane();
    const Vec3 right = (0.5 * width) * plane.step_x, up = (-0.5 * height) * plane.step_y;
    const Vec3 forward = plane.corner + right - up;
    const Surface& surface = scene->surfaces[0];
    std::vector<float> frame;
    put(frame, plane.origin);
    put(frame, forward);
    put(frame, right);
    put(frame, up);
    put(frame, surface.point);
    put(frame, surface.normal);
    put(frame, surface.mapping.u_axis);
    put(frame, surface.mapping.v_axis);
    put(frame, surface.mapping.origin);
    put(frame, scene->light.direction);
    put(frame, scene->light.radiance);
    put(frame, scene->light.ambient);
    put(frame, scene->background);
    frame.insert(frame.end(), {static_cast<float>(width), static_cast<float>(height)});
    const std::int32_t ints[2] = {method == "naive" ? 0 : 1, 16};
    frame.insert(frame.end(), 2, 0.0f);
    std::memcpy(&frame[frame.size() - 2], ints, sizeof ints);
    frame.push_back(static_cast<float>(moments.info().width));
    frame.resize((frame.size() + 3) / 4 * 4);
    // Material: CmfColorTable, then CmfMomentPyramid at the next multiple
    // of 16 (std140 aligns a struct member to 16).
    const cmfilter_gl::ColorTableBlock table_block = cmfilter_gl::color_table_block(ax);
    const float reference = static_cast<float>(moments.reference());
    const std::int32_t level_count = moments.info().levels;
    std::vector<char> material_bytes(64, 0);
    std::memcpy(material_bytes.data(), &table_block, sizeof table_block);
    std::memcpy(material_bytes.data() + 48, &reference, 4);
    std::memcpy(material_bytes.data() + 52, &level_count, 4);
    GLuint blocks[2];
    glCreateBuffers(2, blocks);
    glNamedBufferStorage(blocks[0], static_cast<GLsizeiptr>(frame.size() * sizeof(float)), frame.data(), 0);
    glNamedBufferStorage(blocks[1], static_cast<GLsizeiptr>(material_bytes.size()), material_bytes.data(), 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, blocks[0]);
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, blocks[1]);

    const std::string vertex = "#version 450\n"
                               "void main() {\n"
                               "    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                               "    gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);\n"
                               "}\n";
    const GLuint program = cmfilter_gl::build_program(
        {{GL_VERTEX_SHADER, vertex},
         {GL_FRAGMENT_SHADER, cmfilter_gl::expand_includes(std::string(CMFILTER_EXAMPLE_DIR) + "/plane_filter.frag",
                                                           CMFILTER_SHADER_DIR)}});

    GLuint target = 0, framebuffer = 0, vao = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &target);
    glTextureStorage2D(target, 1, GL_RGBA32F, width, height);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, target, 0);
    if (glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the RGBA32F framebuffer is incomplete");
    glCreateVertexArrays(1, &vao);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    glUseProgram(program);
    glBindVertexArray(vao);
    auto draw = [] {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
    };
    draw();  // the first frame compiles the shader for the driver
    const auto start = std::chrono::steady_clock::now();
    for (int f = 0; f < frames; ++f) draw();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
                      frames;
    std::printf("%s %dx%d: %.2f ms a frame (mean of %d)\n", method.c_str(), width, height, ms, frames);

    std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &target);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
    glDeleteBuffers(2, blocks);
    glDeleteTextures(3, textures);
    // GL's row 0 is the bottom one: the image's rows top first, RGB.
    std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(static_cast<std::size_t>(y) * width + x) * 3 + c] =
                    rgba[(static_cast<std::size_t>(height - 1 - y) * width + x) * 4 + c];
    auto out = OIIO::ImageOutput::create(output);
    if (!out) throw std::runtime_error("cannot write '" + output + "'");
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    if (!out->open(output, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close())
        throw std::runtime_error("cannot write '" + output + "': " + out->geterror());
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "realtime_plane: %s\n", e.what());
        return 1;
    }
}
