// SPDX-License-Identifier: Apache-2.0
#include "headless_gl.h"

#include <EGL/eglext.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cmfilter_gl {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

std::string egl_error(const char* call)
{
    std::ostringstream msg;
    msg << call << " failed (EGL error 0x" << std::hex << eglGetError() << ")";
    return msg.str();
}

}  // namespace

GlContext::GlContext()
{
    // The surfaceless platform needs no window system and no GPU: Mesa picks
    // its software rasteriser when there is no device to drive.
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) fail("eglGetPlatformDisplayEXT is not available (EGL_EXT_platform_base)");
    display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) fail(egl_error("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)"));
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) fail(egl_error("eglInitialize"));
    if (!eglBindAPI(EGL_OPENGL_API)) fail(egl_error("eglBindAPI(EGL_OPENGL_API)"));
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    // No config: the context renders to framebuffer objects only
    // (EGL_KHR_no_config_context).
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) fail(egl_error("eglCreateContext(OpenGL 4.5 core)"));
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail(egl_error("eglMakeCurrent"));
}

GlContext::~GlContext()
{
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    // The display stays initialised for the process: eglTerminate unloads
    // Mesa's driver, and LeakSanitizer then reports two 56-byte blocks its
    // draw path keeps (stacks in an unloaded module, which no suppression can
    // name). Loaded, they are still reachable and nothing is reported.
    eglReleaseThread();
}

std::string GlContext::renderer() const
{
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "";
}

std::string expand_includes(const std::string& path, const std::string& include_dir)
{
    std::ifstream in(path);
    if (!in) fail("cannot read shader '" + path + "'");
    std::ostringstream out;
    std::string line;
    const std::string include = "#include \"";
    while (std::getline(in, line)) {
        if (line.rfind("#extension GL_GOOGLE_include_directive", 0) == 0) continue;
        if (line.rfind(include, 0) == 0) {
            const std::string name = line.substr(include.size(), line.find('"', include.size()) - include.size());
            out << expand_includes(include_dir + "/" + name, include_dir) << "\n";
            continue;
        }
        out << line << "\n";
    }
    return out.str();
}

GLuint build_program(const std::vector<std::pair<GLenum, std::string>>& stages)
{
    const GLuint program = glCreateProgram();
    std::vector<GLuint> shaders;
    for (const auto& [stage, source] : stages) {
        const GLuint shader = glCreateShader(stage);
        const char* text = source.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[8192] = {};
            glGetShaderInfoLog(shader, sizeof log, nullptr, log);
            fail(std::string("shader compilation failed: ") + log);
        }
        glAttachShader(program, shader);
        shaders.push_back(shader);
    }
    glLinkProgram(program);
    for (GLuint shader : shaders) glDeleteShader(shader);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[8192] = {};
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        fail(std::string("program link failed: ") + log);
    }
    return program;
}

GLuint storage_buffer(GLuint binding, std::size_t bytes, const void* data)
{
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    std::vector<char> zeros;
    if (!data) {
        zeros.assign(bytes, 0);
        data = zeros.data();
    }
    glNamedBufferStorage(buffer, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
    return buffer;
}

std::vector<float> read_storage_buffer(GLuint buffer, std::size_t floats)
{
    std::vector<float> out(floats);
    glGetNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(floats * sizeof(float)), out.data());
    return out;
}

void dispatch(GLuint program, std::size_t count)
{
    glUseProgram(program);
    glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glFinish();
}

std::vector<float> run_kernel(GLuint program, const std::vector<float>& points, std::size_t invocations,
                              std::size_t result_floats, const void* parameters, std::size_t parameter_bytes)
{
    const GLuint buffers[3] = {storage_buffer(0, points.size() * sizeof(float), points.data()),
                               storage_buffer(1, result_floats * sizeof(float), nullptr),
                               storage_buffer(2, parameter_bytes, parameters)};
    dispatch(program, invocations);
    std::vector<float> result = read_storage_buffer(buffers[1], result_floats);
    glDeleteBuffers(3, buffers);
    return result;
}

namespace {

// The MIP range (levels 0 .. levels - 1), wrap, filters and a black border
// of a texture whose levels are uploaded, bound to `unit`.
GLuint sampled_texture(GLuint texture, GLuint unit, std::size_t levels, GLenum wrap_s, GLenum wrap_t, GLenum min_filter,
                       GLenum mag_filter)
{
    glTextureParameteri(texture, GL_TEXTURE_BASE_LEVEL, 0);
    glTextureParameteri(texture, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels) - 1);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap_s));
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap_t));
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min_filter));
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag_filter));
    const float border[4] = {0, 0, 0, 0};
    glTextureParameterfv(texture, GL_TEXTURE_BORDER_COLOR, border);
    glBindTextureUnit(unit, texture);
    return texture;
}

}  // namespace

GLuint float_texture(GLuint unit, const std::vector<TextureLevel>& levels, int channels, GLenum wrap_s, GLenum wrap_t,
                     GLenum min_filter, GLenum mag_filter)
{
    static const GLenum internal[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
    static const GLenum format[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, static_cast<GLsizei>(levels.size()), internal[channels - 1], levels[0].width,
                       levels[0].height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t k = 0; k < levels.size(); ++k)
        glTextureSubImage2D(texture, static_cast<GLint>(k), 0, 0, levels[k].width, levels[k].height,
                            format[channels - 1], GL_FLOAT, levels[k].texels);
    return sampled_texture(texture, unit, levels.size(), wrap_s, wrap_t, min_filter, mag_filter);
}

GLuint float_texture_array(GLuint unit, const std::vector<std::vector<TextureLevel>>& layers, GLenum wrap,
                           GLenum min_filter, GLenum mag_filter)
{
    const std::vector<TextureLevel>& first = layers.front();
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture);
    glTextureStorage3D(texture, static_cast<GLsizei>(first.size()), GL_RGBA32F, first[0].width, first[0].height,
                       static_cast<GLsizei>(layers.size()));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t j = 0; j < layers.size(); ++j)
        for (std::size_t k = 0; k < first.size(); ++k)
            glTextureSubImage3D(texture, static_cast<GLint>(k), 0, 0, static_cast<GLint>(j), layers[j][k].width,
                                layers[j][k].height, 1, GL_RGBA, GL_FLOAT, layers[j][k].texels);
    return sampled_texture(texture, unit, first.size(), wrap, wrap, min_filter, mag_filter);
}

}  // namespace cmfilter_gl
