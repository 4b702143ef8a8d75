// Dear ImGui's platform side for the viewer, fed from an InputState (input_state.hpp) instead of
// imgui_impl_glfw, which would read the real devices: scripted and real input look the same to
// the panels.
#pragma once

#include "input_state.hpp"

namespace rmsc::app {

// Names the platform back end and sets the key map; once, after ImGui::CreateContext.
void setupImGuiInput();
// This frame's display size, time step, mouse, keys, modifiers (those of the frame's events)
// and characters.
void feedImGui(const InputState& input, int windowWidth, int windowHeight, int framebufferWidth,
               int framebufferHeight, float seconds);
// The panels do not want the keyboard and Ctrl is up: plain keys are the view's (camera,
// gestures, F, Delete).
bool keyboardFree(const InputState& input);

} // namespace rmsc::app
