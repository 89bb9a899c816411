// SPDX-License-Identifier: Apache-2.0
// Checked reading of a parsed JSON document (json_document.h), key by key:
// every value carries the file and the JSON pointer that name it, so each
// error (BadInput) reads "<file>: <pointer>: <what was expected>, got <what
// was found>", e.g. "scene.json: /surfaces/1/radius: expected a number > 0,
// got -2". Objects are checked for unknown keys before their values are read.
#pragma once

#include "cmfilter/util/error.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

// A value inside a document. Refers to the document, which must outlive it.
class JsonValue {
public:
    // The document's root.
    JsonValue(const nlohmann::json& document, std::string file);

    const nlohmann::json& json() const { return *value_; }
    const std::string& file() const { return file_; }
    // "/surfaces/1/radius" ("(root)" for the whole document).
    std::string pointer_text() const;

    // The member or element; the caller has checked that it exists.
    JsonValue member(const std::string& key) const;
    JsonValue element(std::size_t index) const;

    // "<file>: <pointer>: <what>".
    Error error(const std::string& what) const;
    // "<file>: <pointer>: expected <expectation>, got <the value, shortened>".
    Error expected(const std::string& expectation) const;
    // "<file>: <pointer>/<key>: <what>", for a member that may be absent
    // (missing, or a default that does not fit).
    Error member_error(const std::string& key, const std::string& what) const;

private:
    JsonValue(const nlohmann::json& value, std::string file, nlohmann::json::json_pointer pointer);

    const nlohmann::json* value_;
    std::string file_;
    nlohmann::json::json_pointer pointer_;
};

// A JSON object whose keys are among those its format allows.
class JsonObject {
public:
    // BadInput unless `value` is an object.
    static Expected<JsonObject> read(const JsonValue& value);
    // BadInput unless `value` is an object with no key outside `allowed`.
    static Expected<JsonObject> read(const JsonValue& value, const std::vector<std::string>& allowed);

    // BadInput naming the first key outside `allowed` and listing `allowed`.
    Status allow_only(const std::vector<std::string>& allowed) const;

    const JsonValue& value() const { return value_; }
    bool has(const std::string& key) const { return value_.json().contains(key); }
    std::optional<JsonValue> find(const std::string& key) const;
    // BadInput "<file>: <pointer>/<key>: required key is missing" when absent.
    Expected<JsonValue> require(const std::string& key) const;

    // BadInput at the object unless exactly one of `keys` is present:
    // "expected exactly one of a, b or c, got none" (or "got a and c").
    Status require_one_of(const std::vector<std::string>& keys) const;
    // BadInput "<pointer>/<key>: <why>" for the first of `keys` present.
    Status reject_any_of(const std::vector<std::string>& keys, const std::string& why) const;

    // Reads a member with `read_value` (a function JsonValue -> Expected<T>) into
    // `out`; an absent optional member leaves `out` (its default) unchanged.
    template <typename T, typename Read>
    Status read_optional(const std::string& key, T& out, Read read_value) const
    {
        const auto member = find(key);
        return member ? store(read_value(*member), out) : ok();
    }
    template <typename T, typename Read>
    Status read_required(const std::string& key, T& out, Read read_value) const
    {
        const auto member = require(key);
        return member ? store(read_value(*member), out) : Status(member.error());
    }

private:
    explicit JsonObject(JsonValue value) : value_(std::move(value)) {}

    template <typename T, typename U>
    static Status store(Expected<U> result, T& out)
    {
        if (!result) return result.error();
        out = std::move(*result);
        return ok();
    }

    JsonValue value_;
};

// A JSON number, as a double (JSON has no NaN or infinity).
Expected<double> read_number(const JsonValue& value);
// A JSON string.
Expected<std::string> read_string(const JsonValue& value);
// The index in `words` of the string `value` holds; BadInput
// 'expected "a", "b" or "c", got ...' for anything else.
Expected<std::size_t> read_choice_index(const JsonValue& value, const std::vector<std::string>& words);
// The same, giving the value paired with the word.
template <typename T>
Expected<T> read_choice(const JsonValue& value, const std::vector<std::pair<std::string, T>>& choices)
{
    std::vector<std::string> words;
    for (const auto& choice : choices) words.push_back(choice.first);
    auto index = read_choice_index(value, words);
    if (!index) return index.error();
    return choices[*index].second;
}
// An array of exactly `count` numbers; an element of another type is named
// by its own pointer.
Expected<std::vector<double>> read_numbers(const JsonValue& value, std::size_t count);

}  // namespace cmfilter
