// The saved state. Texture bindings are saved for every target on units 0-17 (rmsc binds units
// 0-17, and binding texture 0 to a unit clears all of its targets), buffer bindings for the
// indices rmsc's uniform and storage blocks use.
#include "gl/state_guard.hpp"

namespace rmsc::gl {
namespace {

constexpr GLenum kCapabilities[] = {
    GL_DEPTH_TEST,       GL_CULL_FACE,          GL_SCISSOR_TEST,
    GL_STENCIL_TEST,     GL_RASTERIZER_DISCARD, GL_POLYGON_OFFSET_FILL,
    GL_COLOR_LOGIC_OP,   GL_DEPTH_CLAMP,        GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_PRIMITIVE_RESTART};
// Capabilities rmsc's passes set or need off.
constexpr GLenum kOffDuringCall[] = {
    GL_SCISSOR_TEST,   GL_STENCIL_TEST, GL_RASTERIZER_DISCARD,      GL_POLYGON_OFFSET_FILL,
    GL_COLOR_LOGIC_OP, GL_DEPTH_CLAMP,  GL_SAMPLE_ALPHA_TO_COVERAGE};
constexpr GLenum kTextureTargets[][2] = {
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE},
    {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY}};
constexpr GLuint kTextureUnits = 18;
constexpr GLuint kUniformBufferIndices = 4;
constexpr GLuint kStorageBufferIndices = 8;
constexpr GLuint kDrawBuffers = 8;
constexpr GLenum kPixelStore[] = {
    GL_UNPACK_ALIGNMENT,    GL_UNPACK_ROW_LENGTH,  GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS,
    GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_PACK_ALIGNMENT,     GL_PACK_ROW_LENGTH};
constexpr GLint kPixelStoreDefaults[] = {4, 0, 0, 0, 0, 0, 4, 0};

GLint integer(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

} // namespace

StateGuard::StateGuard() {
    for (GLenum capability : kCapabilities)
        capabilities_.push_back({capability, glIsEnabled(capability)});
    blendEnabled_.resize(kDrawBuffers);
    colorMasks_.resize(kDrawBuffers);
    blend_.resize(kDrawBuffers);
    for (GLuint i = 0; i < kDrawBuffers; ++i) {
        blendEnabled_[i] = glIsEnabledi(GL_BLEND, i);
        glGetBooleani_v(GL_COLOR_WRITEMASK, i, colorMasks_[i].data());
        const GLenum names[] = {GL_BLEND_SRC_RGB,   GL_BLEND_DST_RGB,      GL_BLEND_SRC_ALPHA,
                                GL_BLEND_DST_ALPHA, GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA};
        for (int j = 0; j < 6; ++j)
            glGetIntegeri_v(names[j], i, &blend_[i][std::size_t(j)]);
    }
    drawFramebuffer_ = integer(GL_DRAW_FRAMEBUFFER_BINDING);
    readFramebuffer_ = integer(GL_READ_FRAMEBUFFER_BINDING);
    program_ = integer(GL_CURRENT_PROGRAM);
    vertexArray_ = integer(GL_VERTEX_ARRAY_BINDING);
    arrayBuffer_ = integer(GL_ARRAY_BUFFER_BINDING);
    uniformBuffer_ = integer(GL_UNIFORM_BUFFER_BINDING);
    storageBuffer_ = integer(GL_SHADER_STORAGE_BUFFER_BINDING);
    unpackBuffer_ = integer(GL_PIXEL_UNPACK_BUFFER_BINDING);
    packBuffer_ = integer(GL_PIXEL_PACK_BUFFER_BINDING);
    activeTexture_ = integer(GL_ACTIVE_TEXTURE);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox_.data());
    depthFunc_ = integer(GL_DEPTH_FUNC);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    cullFaceMode_ = integer(GL_CULL_FACE_MODE);
    frontFace_ = integer(GL_FRONT_FACE);
    polygonMode_[0] = polygonMode_[1] = GL_FILL;
    glGetIntegerv(GL_POLYGON_MODE, polygonMode_);
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &polygonOffsetFactor_);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &polygonOffsetUnits_);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor_);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clearDepth_);
    for (std::size_t i = 0; i < std::size(kPixelStore); ++i)
        pixelStore_[i] = integer(kPixelStore[i]);
    for (GLuint unit = 0; unit < kTextureUnits; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        for (const auto& target : kTextureTargets)
            textures_.push_back({target[0], unit, integer(target[1])});
        samplers_.push_back(integer(GL_SAMPLER_BINDING));
    }
    glActiveTexture(GLenum(activeTexture_));
    auto saveIndexed = [&](GLenum target, GLenum binding, GLenum start, GLenum size, GLuint count) {
        for (GLuint i = 0; i < count; ++i) {
            Binding saved{target, i, 0};
            glGetIntegeri_v(binding, i, &saved.name);
            glGetInteger64i_v(start, i, &saved.offset);
            glGetInteger64i_v(size, i, &saved.size);
            buffers_.push_back(saved);
        }
    };
    saveIndexed(GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
                GL_UNIFORM_BUFFER_SIZE, kUniformBufferIndices);
    saveIndexed(GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING,
                GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE,
                kStorageBufferIndices);

    // What the passes assume.
    for (GLenum capability : kOffDuringCall)
        glDisable(capability);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    for (std::size_t i = 0; i < std::size(kPixelStore); ++i)
        glPixelStorei(kPixelStore[i], kPixelStoreDefaults[i]);
}

StateGuard::~StateGuard() {
    for (const Capability& capability : capabilities_)
        capability.enabled ? glEnable(capability.name) : glDisable(capability.name);
    for (GLuint i = 0; i < kDrawBuffers; ++i) {
        blendEnabled_[i] ? glEnablei(GL_BLEND, i) : glDisablei(GL_BLEND, i);
        const auto& mask = colorMasks_[i];
        glColorMaski(i, mask[0], mask[1], mask[2], mask[3]);
        const auto& b = blend_[i];
        glBlendFuncSeparatei(i, GLenum(b[0]), GLenum(b[1]), GLenum(b[2]), GLenum(b[3]));
        glBlendEquationSeparatei(i, GLenum(b[4]), GLenum(b[5]));
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
    glUseProgram(GLuint(program_));
    glBindVertexArray(GLuint(vertexArray_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glScissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
    glDepthFunc(GLenum(depthFunc_));
    glDepthMask(depthMask_);
    glCullFace(GLenum(cullFaceMode_));
    glFrontFace(GLenum(frontFace_));
    glPolygonMode(GL_FRONT_AND_BACK, GLenum(polygonMode_[0]));
    glPolygonOffset(polygonOffsetFactor_, polygonOffsetUnits_);
    glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
    glClearDepth(clearDepth_);
    for (std::size_t i = 0; i < std::size(kPixelStore); ++i)
        glPixelStorei(kPixelStore[i], pixelStore_[i]);
    for (const Binding& texture : textures_) {
        glActiveTexture(GL_TEXTURE0 + texture.unitOrIndex);
        glBindTexture(texture.target, GLuint(texture.name));
    }
    for (GLuint unit = 0; unit < kTextureUnits; ++unit)
        glBindSampler(unit, GLuint(samplers_[unit]));
    glActiveTexture(GLenum(activeTexture_));
    for (const Binding& buffer : buffers_) {
        if (buffer.name != 0 && buffer.size > 0)
            glBindBufferRange(buffer.target, buffer.unitOrIndex, GLuint(buffer.name),
                              GLintptr(buffer.offset), GLsizeiptr(buffer.size));
        else
            glBindBufferBase(buffer.target, buffer.unitOrIndex, GLuint(buffer.name));
    }
    // The generic bindings last: binding an indexed one sets them too.
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
    glBindBuffer(GL_UNIFORM_BUFFER, GLuint(uniformBuffer_));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(storageBuffer_));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpackBuffer_));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer_));
}

} // namespace rmsc::gl
