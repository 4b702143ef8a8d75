// The file browser's window (see file_browser_dialog.hpp).
#include "file_browser_dialog.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>
#include <cstdlib>

namespace rmsc::app {
namespace {

constexpr const char* kPopupId = "###file browser";

// "12.3 KiB" for a listing.
std::string sizeText(std::uintmax_t bytes) {
    char text[32];
    if (bytes < 1024)
        std::snprintf(text, sizeof text, "%ju B", bytes);
    else if (bytes < 1024 * 1024)
        std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    else
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

std::filesystem::path homeFolder() {
    const char* home = std::getenv("HOME");
    return home ? std::filesystem::path(home) : std::filesystem::path();
}

void goInto(FileBrowser& browser, const std::filesystem::path& folder) {
    browser.folder = folder.lexically_normal();
    browser.stale = true;
    browser.error.clear();
}

// What the name field (or a double-clicked entry) stands for: a folder is gone into, a file
// chosen. Returns the chosen file.
std::optional<std::filesystem::path> take(FileBrowser& browser, const std::string& typed) {
    if (typed.empty()) return std::nullopt;
    const std::filesystem::path path = editor::typedPath(browser.folder, typed, homeFolder());
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        goInto(browser, path);
        browser.name.clear();
        return std::nullopt;
    }
    if (!browser.saving && !std::filesystem::exists(path, ec)) {
        browser.error = path.string() + ": no such file";
        return std::nullopt;
    }
    return path;
}

} // namespace

void FileBrowser::open(std::string newTitle, editor::FileKind newKind, bool newSaving,
                       const std::filesystem::path& start) {
    ask = true;
    title = std::move(newTitle);
    kind = newKind;
    saving = newSaving;
    std::error_code ec;
    if (!start.empty() && std::filesystem::is_directory(start, ec)) {
        folder = start;
        name.clear();
    } else if (!start.empty()) {
        folder = start.parent_path();
        name = start.filename().string();
    }
    if (folder.empty() || !std::filesystem::is_directory(folder, ec))
        folder = std::filesystem::current_path(ec);
    folder = std::filesystem::absolute(folder, ec).lexically_normal();
    stale = true;
    error.clear();
}

std::optional<std::filesystem::path> drawFileBrowser(FileBrowser& browser) {
    const std::string id = browser.title + kPopupId;
    if (browser.ask) {
        ImGui::OpenPopup(id.c_str());
        browser.ask = false;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(
        ImVec2(std::min(display.x - 20.0f, 40 * em), std::min(display.y - 20.0f, 28 * em)),
        ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(id.c_str(), nullptr, ImGuiWindowFlags_NoSavedSettings))
        return std::nullopt;
    if (browser.stale) {
        browser.listing = editor::listDirectory(browser.folder, browser.kind, browser.allFiles);
        browser.stale = false;
    }
    std::optional<std::filesystem::path> chosen;
    if (ImGui::SmallButton("Up")) goInto(browser, browser.folder.parent_path());
    ImGui::SameLine();
    ImGui::TextUnformatted(browser.folder.string().c_str());

    // The listing: what is left after the name field, the filter and the buttons.
    const float below = ImGui::GetFrameHeightWithSpacing() * 3.0f + ImGui::GetTextLineHeight();
    ImGui::BeginChild("listing", ImVec2(0, -below), true);
    if (!browser.listing.error.empty()) ImGui::TextDisabled("%s", browser.listing.error.c_str());
    for (const editor::DirectoryEntry& entry : browser.listing.entries) {
        const std::string label = entry.folder ? entry.name + "/" : entry.name;
        if (ImGui::Selectable(label.c_str(), !entry.folder && entry.name == browser.name,
                              ImGuiSelectableFlags_AllowDoubleClick |
                                  ImGuiSelectableFlags_DontClosePopups)) {
            if (entry.folder) {
                if (ImGui::IsMouseDoubleClicked(0)) {
                    goInto(browser, browser.folder / entry.name);
                    break; // the listing is stale now
                }
            } else {
                browser.name = entry.name;
                browser.error.clear();
                if (ImGui::IsMouseDoubleClicked(0)) chosen = take(browser, entry.name);
            }
        }
        if (!entry.folder) {
            ImGui::SameLine(ImGui::GetContentRegionMax().x - 6 * em);
            ImGui::TextDisabled("%s", sizeText(entry.bytes).c_str());
        }
    }
    ImGui::EndChild();

    ImGui::TextDisabled("%.*s", int(editor::fileKindLabel(browser.kind).size()),
                        editor::fileKindLabel(browser.kind).data());
    ImGui::SameLine();
    if (ImGui::Checkbox("all files", &browser.allFiles)) browser.stale = true;
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1);
    const bool entered = ImGui::InputTextWithHint(
        "##name", "file name, or a path (relative to this folder, or absolute)", &browser.name,
        ImGuiInputTextFlags_EnterReturnsTrue);
    if (!browser.error.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", browser.error.c_str());
    if (ImGui::Button(browser.saving ? "Save" : "OK") || entered)
        chosen = take(browser, browser.name);
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    if (chosen) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return chosen;
}

} // namespace rmsc::app
