// The viewer's display pass: draws the last rendered frame into the window's viewport
// rectangle (scaling it up when it was rendered at a lower resolution), or only its bottom rows,
// as colour, normals, depth or object ids, with the selection outlined. Program:
// shaders/passes/viewer_display.*.
#pragma once

#include "gl/program.hpp"
#include "render/renderer.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rmsc::app {

enum class ViewMode { Color = 0, Normals = 1, Depth = 2, ObjectId = 3, MarchSteps = 4 };

// How many id ranges the display pass outlines (the shader's uSelected array): the objects of a
// selection beyond these are not outlined.
constexpr int kOutlinedRanges = 32;

struct DisplayInput {
    const FrameTargets* frame = nullptr;
    GLuint framebuffer = 0; // drawn into (0: the window's)
    ViewMode mode = ViewMode::Color;
    // Ids [first, last) to outline, one range per selected object (kOutlinedRanges at most).
    std::vector<std::pair<unsigned, unsigned>> selected;
    float nearPlane = 0.05f, farPlane = 200.0f;
    int maxSteps = 256;                      // the march-steps heatmap reaches red here
    int x = 0, y = 0, width = 1, height = 1; // viewport in framebuffer pixels, y from the bottom
    int rows = -1; // draw only the viewport's bottom `rows` rows (a partly refined frame); -1: all
};

class DisplayPass {
  public:
    static std::optional<DisplayPass> create(const ShaderFiles& files, std::string& error);
    void draw(const DisplayInput& input) const; // into input.framebuffer

  private:
    // One program per view mode, with and without the outline: llvmpipe runs the untaken
    // branches of a shader that chooses at run time (the colour view cost 11 ms a frame at
    // 670x701 instead of 2).
    struct Variant {
        gl::Program program;
        GLint selected = -1, selectedCount = -1, depthRange = -1, viewportSize = -1, maxSteps = -1;
    };
    static constexpr int kModes = 5;
    std::vector<Variant> variants_; // [2 * mode + outlined]
    gl::VertexArray emptyVertexArray_;
    gl::Sampler linear_; // the colour's filtering (the render targets' own is nearest)
};

} // namespace rmsc::app
