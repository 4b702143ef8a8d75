// Move-only RAII owners for GL objects: each owns one name and deletes it when destroyed.
// Create them with the named factory functions (DSA, GL 4.5).
#pragma once

#include "gl/gl.hpp"

#include <utility>

namespace rmsc::gl {

template <class Traits> class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Traits::destroy(id_);
        id_ = 0;
    }

  private:
    GLuint id_ = 0;
};

struct BufferTraits {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct TextureTraits {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferTraits {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayTraits {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct ShaderTraits {
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct ProgramTraits {
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct QueryTraits {
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct SamplerTraits {
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};

using Buffer = Handle<BufferTraits>;
using Texture = Handle<TextureTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Shader = Handle<ShaderTraits>;
using Program = Handle<ProgramTraits>;
using Query = Handle<QueryTraits>;
using Sampler = Handle<SamplerTraits>;

inline Buffer createBuffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return Buffer(id);
}
inline Texture createTexture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(id);
}
inline Framebuffer createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(id);
}
inline VertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id);
}
inline Query createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id);
}

inline Sampler createSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return Sampler(id);
}

// A buffer holding `size` bytes of `data`, updatable with glNamedBufferSubData.
inline Buffer createBufferWithData(GLsizeiptr size, const void* data) {
    Buffer buffer = createBuffer();
    // GL refuses empty storage: an empty buffer still gets 16 (zeroed) bytes.
    if (size > 0)
        glNamedBufferStorage(buffer.id(), size, data, GL_DYNAMIC_STORAGE_BIT);
    else
        glNamedBufferStorage(buffer.id(), 16, nullptr, GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

} // namespace rmsc::gl
