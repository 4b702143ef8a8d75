// The camera of a frame drawn into a host program's framebuffer: built from the host's view
// and projection matrices instead of a scene camera, in one of the depth conventions rmsc
// supports (OpenGL's default clip space, glClipControl's zero-to-one, and reversed-Z with
// zero-to-one). Anything else is refused with the reason.
#pragma once

#include "render/frame.hpp"

#include <optional>
#include <string>

namespace rmsc {

struct HostView {
    glm::mat4 view{1.0f}; // world to eye: a rotation and a translation (OpenGL: looks down -z)
    glm::mat4 projection{1.0f}; // eye to clip: a perspective projection (w = -z_eye)
    int width = 0;              // the viewport's size in pixels
    int height = 0;
    bool zeroToOne = false; // clip depth in [0, w] (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE))
    bool reversedZ = false; // the projection maps the near plane to depth 1 and far to 0
};

// The frame camera of the host's view: its eye, forward axis, near and far planes (the far
// plane of an infinite projection is +infinity) and the frustum corners of its viewport.
// nullopt with `error` when the matrices are not a rigid view and a perspective projection, or
// the projection's depth runs the other way than `reversedZ` says, or reversed-Z is asked for
// without zero-to-one clip depth.
std::optional<FrameCamera> hostFrameCamera(const HostView& host, std::string& error);

// The window depth where the host has drawn nothing (its depth buffer's clear value).
inline float hostFarDepth(const HostView& host) {
    return host.reversedZ ? 0.0f : 1.0f;
}

} // namespace rmsc
