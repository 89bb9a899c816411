// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/json_document.h"

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

namespace cmfilter {

namespace {

using json = nlohmann::json;

// nlohmann's message without its "[json.exception.parse_error.101] " tag and
// without its own "parse error at line L, column C: " (we say where ourselves).
std::string parser_description(const std::string& what)
{
    std::string text = what;
    if (const auto tag_end = text.find("] "); !text.empty() && text[0] == '[' && tag_end != std::string::npos)
        text = text.substr(tag_end + 2);
    if (text.rfind("parse error", 0) == 0)
        if (const auto colon = text.find(": "); colon != std::string::npos) text = text.substr(colon + 2);
    return text;
}

// Line and column (both from 1) of the character at `index` (from 0) in `text`;
// index == text.size() is the end of the input.
std::string line_and_column(const std::string& text, std::size_t index)
{
    index = std::min(index, text.size());
    const auto begin = text.begin(), at = begin + static_cast<std::ptrdiff_t>(index);
    const auto line = 1 + std::count(begin, at, '\n');
    std::size_t column = index + 1;
    if (index > 0)
        if (const auto newline = text.rfind('\n', index - 1); newline != std::string::npos) column = index - newline;
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Watches the parser's events to find the first key given twice in one
// object, and the JSON pointer it stands at.
class DuplicateKeyFinder {
public:
    bool operator()(int /*depth*/, json::parse_event_t event, json& parsed)
    {
        switch (event) {
        case json::parse_event_t::object_start:
        case json::parse_event_t::array_start:
            count_element();
            frames_.push_back({event == json::parse_event_t::object_start, {}, {}, 0});
            break;
        case json::parse_event_t::object_end:
        case json::parse_event_t::array_end: frames_.pop_back(); break;
        case json::parse_event_t::key: {
            Frame& object = frames_.back();
            object.key = parsed.get<std::string>();
            if (!object.keys.insert(object.key).second && !duplicate_) duplicate_ = current_pointer();
            break;
        }
        case json::parse_event_t::value: count_element(); break;
        }
        return true;
    }

    const std::optional<std::string>& duplicate() const { return duplicate_; }

private:
    struct Frame {
        bool is_object;
        std::set<std::string> keys;  // objects: the keys so far
        std::string key;             // objects: the key being read
        std::size_t elements;        // arrays: the elements started so far
    };

    void count_element()
    {
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().elements;
    }

    std::string current_pointer() const
    {
        json::json_pointer pointer;
        for (const Frame& frame : frames_)
            pointer = frame.is_object ? pointer / frame.key : pointer / (frame.elements - 1);
        return pointer.to_string();
    }

    std::vector<Frame> frames_;
    std::optional<std::string> duplicate_;
};

}  // namespace

Expected<nlohmann::json> parse_json_document(const std::string& text, const std::string& file)
{
    DuplicateKeyFinder finder;
    json document;
    try {
        document = json::parse(text, std::ref(finder));
    } catch (const json::parse_error& e) {
        // e.byte counts from 1 and is the last character the parser read.
        const std::size_t index = e.byte == 0 ? 0 : e.byte - 1;
        return bad_input(file + ": malformed JSON at " + line_and_column(text, index) + " (byte " +
                         std::to_string(e.byte) + "): " + parser_description(e.what()));
    } catch (const json::exception& e) {  // a number too large for a double
        return bad_input(file + ": malformed JSON: " + parser_description(e.what()));
    }
    if (finder.duplicate()) return bad_input(file + ": " + *finder.duplicate() + ": key given twice in one object");
    return document;
}

}  // namespace cmfilter
