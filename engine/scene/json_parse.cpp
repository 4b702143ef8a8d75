// Parsing JSON text for the scene reader. nlohmann's DOM parser keeps the last of duplicate
// keys, stops at 1e999 without saying where in the document it was, and accepts any nesting.
// This SAX handler builds the same document while following the JSON pointer of every value,
// so it reports duplicates and overflowing numbers at their pointers and stops nesting at
// kMaxJsonDepth. (nlohmann's parser-callback variant could do the same, but it rescans the
// enclosing array after every object, which takes seconds for 100000 SDF nodes.)
#include "json_reader.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>

namespace rmsc {
namespace {

// 1-based line and column of the byte nlohmann reports (the last one it read), counted the way
// nlohmann counts: a newline ends a line, the column is the byte's position on its line, and
// the end of the input counts as one byte past the last.
std::string lineAndColumn(std::string_view text, std::size_t byte) {
    const std::size_t end = std::min(byte, text.size());
    std::size_t line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(byte - lineStart);
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1,
// column 2: " prefix, which the diagnostic's location replaces.
std::string syntaxErrorMessage(const Json::exception& e) {
    std::string message = e.what();
    const std::size_t bracket = message.find("] ");
    if (message.starts_with("[json.exception") && bracket != std::string::npos)
        message.erase(0, bracket + 2);
    const std::size_t column = message.find(", column ");
    if (column != std::string::npos) {
        const std::size_t colon = message.find(": ", column);
        if (colon != std::string::npos) message = "JSON " + message.substr(colon + 2);
    }
    return message;
}

// nlohmann's exception id for "number overflow parsing '1e999'".
constexpr int kNumberOverflowId = 406;

// Receives nlohmann's parse events (the SAX interface) and builds the document.
class DocumentBuilder {
  public:
    DocumentBuilder(std::string_view text, const JsonReader& reader)
        : text_(text), reader_(reader) {}

    Json& document() { return document_; }

    bool null() { return addValue(nullptr); }
    bool boolean(bool value) { return addValue(value); }
    bool number_integer(Json::number_integer_t value) { return addValue(value); }
    bool number_unsigned(Json::number_unsigned_t value) { return addValue(value); }
    bool number_float(Json::number_float_t value, const Json::string_t& text) {
        // nlohmann 3.11 reports these as overflow errors itself; checked here too so that no
        // version lets a non-finite number reach the readers, which count on it.
        if (!std::isfinite(value)) {
            reader_.error(pendingPointer(), "expected a finite number, got " + text);
            return false;
        }
        return addValue(value);
    }
    bool string(Json::string_t& value) { return addValue(std::move(value)); }
    bool binary(Json::binary_t& value) { return addValue(Json::binary(std::move(value))); }

    bool start_object(std::size_t) { return openContainer(Json::object()); }
    bool start_array(std::size_t) { return openContainer(Json::array()); }
    bool end_object() { return closeContainer(); }
    bool end_array() { return closeContainer(); }

    bool key(Json::string_t& key) {
        Frame& frame = frames_.back();
        frame.key = key;
        const auto [it, added] = frame.keys.try_emplace(key, frame.keys.size());
        frame.keyIndex = it->second;
        if (!added) {
            reader_.error(childPointer(frame.pointer, key),
                          "duplicate key \"" + key + "\"; each key may appear once in an object");
        }
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const Json::exception& e) {
        if (e.id == kNumberOverflowId) {
            reader_.error(pendingPointer(), "expected a finite number, got " + lastToken +
                                                ", which is too large to represent");
        } else {
            reader_.error(lineAndColumn(text_, position), syntaxErrorMessage(e));
        }
        return false;
    }

  private:
    struct Frame {
        Json* container = nullptr;
        std::string pointer;
        // Objects: each key seen so far and its place in the object, so that adding a member
        // takes constant time (nlohmann's ordered object finds keys by a linear search, which
        // made an object of n keys take n * n / 2 comparisons).
        std::unordered_map<std::string, std::size_t> keys;
        std::string key;          // objects: the key of the value being parsed
        std::size_t keyIndex = 0; // objects: its place in the object
        std::size_t count = 0;    // arrays: elements added so far
    };

    // The pointer of the value being parsed now, before it is added.
    std::string pendingPointer() const {
        if (frames_.empty()) return "";
        const Frame& frame = frames_.back();
        if (frame.container->is_object()) return childPointer(frame.pointer, frame.key);
        return childPointer(frame.pointer, frame.count);
    }

    // Adds a value to the open container (objects: under the last key, replacing an earlier
    // value of a duplicate key as nlohmann does) and returns where it now lives. The open
    // containers' addresses stay valid: only the innermost one grows.
    Json* add(Json&& value) {
        if (frames_.empty()) {
            document_ = std::move(value);
            return &document_;
        }
        Frame& frame = frames_.back();
        if (frame.container->is_object()) {
            auto& members = frame.container->get_ref<Json::object_t&>();
            if (frame.keyIndex < members.size()) // a duplicate key: replace the earlier value
                return &((members.begin() + std::ptrdiff_t(frame.keyIndex))->second =
                             std::move(value));
            members.emplace_back(frame.key, std::move(value));
            return &members.back().second;
        }
        ++frame.count;
        frame.container->push_back(std::move(value));
        return &frame.container->back();
    }

    bool addValue(Json&& value) {
        add(std::move(value));
        return true;
    }

    bool openContainer(Json&& empty) {
        std::string pointer = pendingPointer();
        if (frames_.size() >= std::size_t(kMaxJsonDepth)) {
            reader_.error(pointer, "arrays and objects are nested more than " +
                                       std::to_string(kMaxJsonDepth) +
                                       " levels deep (the limit); this is not a scene file");
            return false;
        }
        Json* container = add(std::move(empty));
        frames_.push_back({container, std::move(pointer), {}, {}, 0, 0});
        return true;
    }

    bool closeContainer() {
        frames_.pop_back();
        return true;
    }

    std::string_view text_;
    const JsonReader& reader_;
    Json document_;
    std::vector<Frame> frames_;
};

} // namespace

std::optional<Json> parseJsonText(std::string_view text, const JsonReader& reader) {
    DocumentBuilder builder(text, reader);
    try {
        if (!Json::sax_parse(text.begin(), text.end(), &builder, Json::input_format_t::json,
                             /*strict=*/true, /*ignore_comments=*/false))
            return std::nullopt; // the builder reported why
    } catch (const Json::exception& e) {
        reader.error("", std::string("cannot parse JSON: ") + e.what());
        return std::nullopt;
    }
    return std::move(builder.document());
}

} // namespace rmsc
