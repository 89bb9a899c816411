// SPDX-License-Identifier: Apache-2.0
// A headless OpenGL 4.5 core context through EGL (Mesa's surfaceless
// platform: llvmpipe on a machine without a GPU) and the little the
// real-time example and the checks of shaders/ (tests/shaders/) need:
// programs built from GLSL whose #include lines name files of shaders/,
// storage buffers, float textures.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

namespace cmfilter_gl {

class GlContext {
public:
    // Throws std::runtime_error naming the EGL call that failed.
    GlContext();
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;
    std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

// The source of `path` with each `#include "name"` replaced by the text of
// include_dir/name (once; nested includes expanded too) and the
// GL_GOOGLE_include_directive #extension line removed: what glslangValidator
// compiles with -I include_dir. Throws naming a file it cannot read.
std::string expand_includes(const std::string& path, const std::string& include_dir);

// Compiles and links a shader of `stage` (GL_COMPUTE_SHADER, GL_VERTEX_SHADER,
// GL_FRAGMENT_SHADER) sources into a program; throws with the info log.
GLuint build_program(const std::vector<std::pair<GLenum, std::string>>& stages);

// A shader storage buffer bound at `binding`, holding `bytes` of `data`
// (zeros when data is null).
GLuint storage_buffer(GLuint binding, std::size_t bytes, const void* data);
std::vector<float> read_storage_buffer(GLuint buffer, std::size_t floats);

// Runs `program` over `count` invocations in groups of 64, then waits for
// its writes to storage buffers.
void dispatch(GLuint program, std::size_t count);

// Runs a compute kernel of shaders/kernels/ once: `points` in the storage
// buffer at binding 0, `result_floats` zeros at binding 1, the parameter
// block at binding 2, over `invocations` invocations; returns binding 1's
// floats and deletes the three buffers.
std::vector<float> run_kernel(GLuint program, const std::vector<float>& points, std::size_t invocations,
                              std::size_t result_floats, const void* parameters, std::size_t parameter_bytes);

struct TextureLevel {
    int width = 0, height = 0;
    const float* texels = nullptr;  // width * height * channels, rows in file order
};

// A 2-D float texture with the given levels (GL_TEXTURE_MAX_LEVEL = levels - 1),
// `channels` 1..4 (R32F .. RGBA32F), wrap S and T, min and mag filters, bound
// to texture unit `unit`.
GLuint float_texture(GLuint unit, const std::vector<TextureLevel>& levels, int channels, GLenum wrap_s, GLenum wrap_t,
                     GLenum min_filter, GLenum mag_filter);
// A GL_RGBA32F GL_TEXTURE_2D_ARRAY: layers[j][k] is MIP level k of layer j
// (four channels a texel; every layer the same sizes), bound to `unit`.
GLuint float_texture_array(GLuint unit, const std::vector<std::vector<TextureLevel>>& layers, GLenum wrap,
                           GLenum min_filter, GLenum mag_filter);

}  // namespace cmfilter_gl
