// Widgets the panels share (see panel_widgets.hpp).
#include "panel_widgets.hpp"

#include "core/srgb.hpp"
#include "core/transform.hpp"
#include "editor/param_fields.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace rmsc::app {

void helpTooltip(std::string_view text) {
    if (!text.empty() && ImGui::IsItemHovered())
        ImGui::SetTooltip("%.*s", int(text.size()), text.data());
}

namespace {

// Where a field keeps when it last clamped a value: the window's state storage, under a key of
// its own beside the widget's id (ImGui keeps a tree node's state the same way).
ImGuiID clampKey(const char* label) {
    ImGui::PushID(label);
    const ImGuiID key = ImGui::GetID("clamped at");
    ImGui::PopID();
    return key;
}

const ImVec4 kClampNoticeColour{1.0f, 0.72f, 0.25f, 1.0f};

// After the widget: the clamp's time kept, the tooltip, and the notice while it shows, under the
// field and at the top of its tooltip too (a tooltip placed below the pointer covers the line
// under the field).
void finishNumberField(const char* label, bool changed, bool clamped, const ParamRange& range,
                       std::string_view help) {
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID key = clampKey(label);
    if (clamped)
        storage->SetFloat(key, float(ImGui::GetTime()));
    else if (changed)
        storage->SetFloat(key, -1.0f); // a value within the range: the notice goes
    const bool noticeShown =
        editor::clampNoticeShown(double(storage->GetFloat(key, -1.0f)), ImGui::GetTime());
    const std::string notice = noticeShown ? editor::clampNotice(range) : std::string();
    if (ImGui::IsItemHovered()) { // (still the field: nothing has been drawn after it)
        const std::string text = editor::fieldHelp(help, range);
        ImGui::BeginTooltip();
        if (noticeShown) ImGui::TextColored(kClampNoticeColour, "%s", notice.c_str());
        ImGui::TextUnformatted(text.c_str());
        ImGui::EndTooltip();
    }
    if (noticeShown) ImGui::TextColored(kClampNoticeColour, "%s", notice.c_str());
}

} // namespace

bool numberField(const char* label, float* values, int components, float step,
                 const ParamRange& range, std::string_view help, const NumberFieldStyle& style) {
    const editor::FloatFieldRange valid = editor::floatFieldRange(range);
    const editor::FloatFieldRange drag = style.drag.value_or(valid);
    const int flags = style.flags & ~ImGuiSliderFlags_AlwaysClamp;
    const bool changed =
        style.slider && components == 1
            ? ImGui::SliderFloat(label, values, drag.min, drag.max, style.format, flags)
            : ImGui::DragScalarN(label, ImGuiDataType_Float, values, components, step, &drag.min,
                                 &drag.max, style.format, flags);
    bool clamped = false;
    if (changed) {
        for (int c = 0; c < components; ++c) {
            const editor::ClampedValue v = editor::clampToField(values[c], valid);
            values[c] = v.value;
            clamped |= v.clamped;
        }
    }
    finishNumberField(label, changed, clamped, range, help);
    return changed;
}

bool numberField(const char* label, int* values, int components, float step,
                 const ParamRange& range, std::string_view help) {
    const editor::IntFieldRange valid = editor::intFieldRange(range);
    const bool changed = ImGui::DragScalarN(label, ImGuiDataType_S32, values, components, step,
                                            &valid.min, &valid.max, "%d");
    bool clamped = false;
    if (changed) {
        for (int c = 0; c < components; ++c) {
            const editor::ClampedInt v = editor::clampToField(values[c], valid);
            values[c] = v.value;
            clamped |= v.clamped;
        }
    }
    finishNumberField(label, changed, clamped, range, help);
    return changed;
}

float stepFor(float size) {
    return std::max(0.001f, std::abs(size) * 0.01f);
}

bool editTransform(Transform& t, bool world, const glm::mat4& parentWorld, float size) {
    bool changed = false;
    glm::vec3 position = world ? glm::vec3(parentWorld * glm::vec4(t.position, 1.0f)) : t.position;
    if (numberField("position", &position.x, 3, stepFor(size), unboundedRange(Unit::Metres),
                    world ? "Where the object's origin is, in world coordinates."
                          : "Where the object's origin is, in its parent's frame.")) {
        t.position =
            world ? glm::vec3(glm::inverse(parentWorld) * glm::vec4(position, 1.0f)) : position;
        changed = true;
    }
    // The degrees the file has (or would write) where there are such, so what was typed shows
    // and a value typed here is saved as typed (shownEulerDegrees).
    glm::vec3 euler = shownEulerDegrees(t.rotation);
    if (numberField("rotation", &euler.x, 3, 0.5f, closedRange(-360.0, 360.0, Unit::Degrees),
                    "Turns about x, then y, then z (Euler angles; the file keeps them where short "
                    "ones give exactly this rotation, else a quaternion).",
                    {.format = "%.1f°"})) {
        t.rotation = eulerDegreesToQuaternion(euler);
        changed = true;
    }
    // The reader takes any scale > 0; the inspector keeps to three orders of magnitude each way.
    if (numberField("scale", &t.scale.x, 3, 0.005f, closedRange(0.001, 1000.0, Unit::Ratio),
                    "Scale along the object's own x, y, z (1 = unchanged)."))
        changed = true;
    return changed;
}

bool editColor(const char* label, glm::vec3& linear, int flags) {
    glm::vec3 shown = linearToSrgb(linear);
    if (!ImGui::ColorEdit3(label, &shown.x, flags)) return false;
    linear = srgbToLinear(shown);
    return true;
}

void drawDuplicateDeleteButtons(ViewerCommands& commands) {
    if (ImGui::Button("Duplicate")) commands.push_back(ViewerCommand::Duplicate);
    ImGui::SameLine();
    if (ImGui::Button("Delete")) commands.push_back(ViewerCommand::Delete);
}

} // namespace rmsc::app
