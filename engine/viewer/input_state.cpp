// Input state and the GLFW callbacks that fill it (see input_state.hpp).
#include "input_state.hpp"

#include <algorithm>

namespace rmsc::app {

void InputState::beginFrame() {
    wheel = 0.0f;
    characters.clear();
    drops.clear();
    pressedKeys.clear();
    clicked = {};
    released = {};
}

void InputState::finishEvents() {
    mouseDelta = haveLastMouse_ ? mouse - lastMouse_ : glm::vec2(0.0f);
    lastMouse_ = mouse;
    haveLastMouse_ = true;
}

void InputState::keyEvent(int key, bool down) {
    if (key < 0 || key > GLFW_KEY_LAST) return;
    if (down && !keys[std::size_t(key)]) pressedKeys.push_back(key);
    keys[std::size_t(key)] = down;
}

void InputState::buttonEvent(int button, bool down) {
    if (button < 0 || button > 2) return;
    if (down && !buttons[std::size_t(button)]) clicked[std::size_t(button)] = true;
    if (!down && buttons[std::size_t(button)]) released[std::size_t(button)] = true;
    buttons[std::size_t(button)] = down;
}

void InputState::moveMouse(glm::vec2 position) {
    mouse = position;
}

void InputState::apply(const editor::InputEvent& e) {
    using Kind = editor::InputEvent::Kind;
    switch (e.kind) {
    case Kind::Key:
        keyEvent(e.code, e.down);
        break;
    case Kind::Char:
        characters.push_back(unsigned(e.code));
        break;
    case Kind::Button:
        buttonEvent(e.code, e.down);
        break;
    case Kind::Scroll:
        wheel += e.value.y;
        break;
    case Kind::Cursor:
        moveMouse(e.value);
        break;
    case Kind::Drop:
        drops.push_back(e.path);
        return; // no modifiers of its own
    case Kind::Marker:
        return;
    }
    mods = e.mods;
}

bool InputState::pressed(int key) const {
    return std::find(pressedKeys.begin(), pressedKeys.end(), key) != pressedKeys.end();
}

int modifierBit(int key) {
    switch (key) {
    case GLFW_KEY_LEFT_SHIFT:
    case GLFW_KEY_RIGHT_SHIFT:
        return editor::kModShift;
    case GLFW_KEY_LEFT_CONTROL:
    case GLFW_KEY_RIGHT_CONTROL:
        return editor::kModCtrl;
    case GLFW_KEY_LEFT_ALT:
    case GLFW_KEY_RIGHT_ALT:
        return editor::kModAlt;
    case GLFW_KEY_LEFT_SUPER:
    case GLFW_KEY_RIGHT_SUPER:
        return editor::kModSuper;
    default:
        return 0;
    }
}

editor::InputEvent dropEvent(std::string path) {
    editor::InputEvent e;
    e.kind = editor::InputEvent::Kind::Drop;
    e.path = std::move(path);
    return e;
}

int modsAfterKey(int mods, int key, bool down) {
    const int bit = modifierBit(key);
    return down ? mods | bit : mods & ~bit;
}

namespace {

// What the callbacks of one window need: the queue, and the modifiers held at the last key
// event (characters, the wheel and the cursor carry no modifiers of their own in GLFW).
struct GlfwFeed {
    editor::InputQueue* queue = nullptr;
    int mods = 0;
};

GlfwFeed& feedOf(GLFWwindow* window) {
    return *static_cast<GlfwFeed*>(glfwGetWindowUserPointer(window));
}

int fromGlfwMods(int glfwMods) {
    return ((glfwMods & GLFW_MOD_SHIFT) ? editor::kModShift : 0) |
           ((glfwMods & GLFW_MOD_CONTROL) ? editor::kModCtrl : 0) |
           ((glfwMods & GLFW_MOD_ALT) ? editor::kModAlt : 0) |
           ((glfwMods & GLFW_MOD_SUPER) ? editor::kModSuper : 0);
}

void enqueue(GLFWwindow* window, editor::InputEvent e) {
    GlfwFeed& feed = feedOf(window);
    e.time = glfwGetTime();
    feed.queue->push(e);
}

} // namespace

void attachGlfwInput(GLFWwindow* window, editor::InputQueue* queue, bool dropsOnly) {
    using Kind = editor::InputEvent::Kind;
    static GlfwFeed feed; // one window takes real input
    feed = {queue, 0};
    glfwSetWindowUserPointer(window, &feed);
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        for (int i = 0; i < count; ++i)
            enqueue(w, dropEvent(paths[i]));
    });
    if (dropsOnly) return;
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int glfwMods) {
        if (action == GLFW_REPEAT || key < 0 || key > GLFW_KEY_LAST) return;
        const bool down = action == GLFW_PRESS;
        // X11 reports the modifiers as they were before the event; a modifier key's own bit
        // follows the key here.
        GlfwFeed& f = feedOf(w);
        f.mods = modsAfterKey(fromGlfwMods(glfwMods), key, down);
        enqueue(w, {Kind::Key, key, down, f.mods});
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned c) {
        enqueue(w, {Kind::Char, int(c), false, feedOf(w).mods});
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int glfwMods) {
        if (button < 0 || button > 2) return;
        GlfwFeed& f = feedOf(w);
        f.mods = fromGlfwMods(glfwMods);
        enqueue(w, {Kind::Button, button, action == GLFW_PRESS, f.mods});
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        enqueue(w, {Kind::Cursor, 0, false, feedOf(w).mods, glm::vec2(float(x), float(y))});
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
        enqueue(w, {Kind::Scroll, 0, false, feedOf(w).mods, glm::vec2(0.0f, float(dy))});
    });
}

} // namespace rmsc::app
