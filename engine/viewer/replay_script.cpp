// Replay scripts (see replay_script.hpp).
#include "replay_script.hpp"

#include "key_names.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace rmsc::app {
namespace {

int keyCode(const std::string& name) {
    return glfwKeyNamed(name);
}

int buttonCode(const std::string& name) {
    if (name == "left") return 0;
    if (name == "right") return 1;
    if (name == "middle") return 2;
    return -1;
}

} // namespace

std::optional<Script> parseScript(const std::string& text, const std::string& file,
                                  std::string& error) {
    Script script;
    std::istringstream lines(text);
    std::string line;
    int lineNumber = 0;
    auto fail = [&](const std::string& message) {
        error = file + ":" + std::to_string(lineNumber) + ": " + message;
        return std::nullopt;
    };
    while (std::getline(lines, line)) {
        ++lineNumber;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream in(line);
        std::string frameText, verb;
        if (!(in >> frameText)) continue;
        int frame = 0;
        try {
            std::size_t used = 0;
            frame = std::stoi(frameText, &used);
            if (used != frameText.size() || frame < 0) throw std::invalid_argument("frame");
        } catch (const std::exception&) {
            return fail("expected a frame number >= 0, got '" + frameText + "'");
        }
        if (!(in >> verb)) return fail("expected an event after the frame number");
        ScriptEvent e;
        e.frame = frame;
        e.line = lineNumber;
        using K = ScriptEvent::Kind;
        if (verb == "key" || verb == "hold") {
            std::string keys;
            in >> keys;
            int frames = 1;
            if (verb == "hold" && !(in >> frames)) return fail("expected: hold KEY FRAMES");
            std::vector<int> codes;
            std::stringstream parts(keys);
            std::string part;
            while (std::getline(parts, part, '+')) {
                const int code = keyCode(part);
                if (code < 0) return fail("unknown key '" + part + "'");
                codes.push_back(code);
            }
            if (codes.empty()) return fail("expected a key");
            for (int code : codes)
                script.events.push_back({frame, K::KeyDown, code, {}, {}, lineNumber});
            for (int code : codes)
                script.events.push_back({frame + frames, K::KeyUp, code, {}, {}, lineNumber});
        } else if (verb == "move" || verb == "click") {
            float x = 0, y = 0;
            if (!(in >> x >> y)) return fail("expected: " + verb + " X Y");
            script.events.push_back({frame, K::MouseMove, 0, {x, y}, {}, lineNumber});
            if (verb == "click") {
                script.events.push_back({frame, K::ButtonDown, 0, {}, {}, lineNumber});
                script.events.push_back({frame + 1, K::ButtonUp, 0, {}, {}, lineNumber});
            }
        } else if (verb == "down" || verb == "up") {
            std::string name;
            in >> name;
            const int button = buttonCode(name);
            if (button < 0) return fail("expected left, right or middle, got '" + name + "'");
            script.events.push_back(
                {frame, verb == "down" ? K::ButtonDown : K::ButtonUp, button, {}, {}, lineNumber});
        } else if (verb == "wheel") {
            float dy = 0;
            if (!(in >> dy)) return fail("expected: wheel DY");
            script.events.push_back({frame, K::Wheel, 0, {0.0f, dy}, {}, lineNumber});
        } else if (verb == "text" || verb == "drop" || verb == "screenshot" ||
                   verb == "window-shot") {
            std::string rest;
            std::getline(in >> std::ws, rest);
            while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\r'))
                rest.pop_back();
            if (rest.empty()) return fail("expected text or a path after '" + verb + "'");
            const K kind = verb == "text"         ? K::Text
                           : verb == "drop"       ? K::Drop
                           : verb == "screenshot" ? K::Screenshot
                                                  : K::WindowShot;
            script.events.push_back({frame, kind, 0, {}, rest, lineNumber});
        } else if (verb == "quit" || verb == "wait-shaders" || verb == "wait-view" ||
                   verb == "wait-refined" || verb == "wait-export") {
            const K kind = verb == "quit"           ? K::Quit
                           : verb == "wait-shaders" ? K::WaitShaders
                           : verb == "wait-view"    ? K::WaitView
                           : verb == "wait-export"  ? K::WaitExport
                                                    : K::WaitRefined;
            script.events.push_back({frame, kind, 0, {}, {}, lineNumber});
        } else {
            return fail("unknown event '" + verb + "'");
        }
    }
    std::stable_sort(script.events.begin(), script.events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return script;
}

std::optional<Script> loadScript(const std::filesystem::path& path, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path.string() + ": cannot read the script";
        return std::nullopt;
    }
    std::stringstream text;
    text << in.rdbuf();
    return parseScript(text.str(), path.string(), error);
}

void playScriptFrame(const Script& script, int frame, double time, editor::InputQueue& queue,
                     int& mods) {
    using K = ScriptEvent::Kind;
    using E = editor::InputEvent::Kind;
    for (std::size_t i = 0; i < script.events.size(); ++i) {
        const ScriptEvent& e = script.events[i];
        if (e.frame != frame) continue;
        editor::InputEvent event;
        event.time = time;
        switch (e.kind) {
        case K::KeyDown:
        case K::KeyUp:
            mods = modsAfterKey(mods, e.code, e.kind == K::KeyDown);
            event.kind = E::Key;
            event.code = e.code;
            event.down = e.kind == K::KeyDown;
            break;
        case K::MouseMove:
            event.kind = E::Cursor;
            event.value = e.value;
            break;
        case K::ButtonDown:
        case K::ButtonUp:
            event.kind = E::Button;
            event.code = e.code;
            event.down = e.kind == K::ButtonDown;
            break;
        case K::Wheel:
            event.kind = E::Scroll;
            event.value = e.value;
            break;
        case K::Drop:
            event = dropEvent(e.text);
            event.time = time;
            queue.push(event);
            continue;
        case K::Text:
            event.kind = E::Char;
            event.mods = mods;
            for (unsigned char c : e.text) {
                event.code = c;
                queue.push(event);
            }
            continue;
        default:
            event.kind = E::Marker;
            event.code = int(i);
            break;
        }
        event.mods = mods;
        queue.push(event);
    }
}

ScriptActions scriptActions(const Script& script, const std::vector<editor::InputEvent>& taken) {
    ScriptActions actions;
    using K = ScriptEvent::Kind;
    for (const editor::InputEvent& marker : taken) {
        if (marker.kind != editor::InputEvent::Kind::Marker) continue;
        const ScriptEvent& e = script.events.at(std::size_t(marker.code));
        switch (e.kind) {
        case K::Screenshot:
            actions.screenshots.push_back(e.text);
            break;
        case K::WindowShot:
            actions.windowShots.push_back(e.text);
            break;
        case K::WaitShaders:
            actions.waitShaders = true;
            break;
        case K::WaitView:
            actions.waitView = true;
            break;
        case K::WaitRefined:
            actions.waitRefined = true;
            break;
        case K::WaitExport:
            actions.waitExport = true;
            break;
        case K::Quit:
            actions.quit = true;
            break;
        default:
            break;
        }
    }
    return actions;
}

} // namespace rmsc::app
