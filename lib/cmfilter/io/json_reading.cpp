// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/json_reading.h"

#include <algorithm>
#include <utility>

namespace cmfilter {

namespace {

// The value as JSON text, cut short when long (a whole object, say).
std::string shortened_text(const nlohmann::json& value)
{
    constexpr std::size_t kMaxChars = 60;
    const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return text.size() <= kMaxChars ? text : text.substr(0, kMaxChars - 3) + "...";
}

// "a, b, c" (separator ", ") or "a, b or c" (last_separator " or ").
std::string joined(const std::vector<std::string>& words, const std::string& last_separator = ", ")
{
    std::string out;
    for (std::size_t i = 0; i < words.size(); ++i)
        out += (i == 0 ? "" : i + 1 == words.size() ? last_separator : ", ") + words[i];
    return out;
}

}  // namespace

JsonValue::JsonValue(const nlohmann::json& document, std::string file)
    : JsonValue(document, std::move(file), nlohmann::json::json_pointer())
{
}

JsonValue::JsonValue(const nlohmann::json& value, std::string file, nlohmann::json::json_pointer pointer)
    : value_(&value), file_(std::move(file)), pointer_(std::move(pointer))
{
}

std::string JsonValue::pointer_text() const
{
    const std::string text = pointer_.to_string();
    return text.empty() ? "(root)" : text;
}

JsonValue JsonValue::member(const std::string& key) const { return JsonValue(value_->at(key), file_, pointer_ / key); }

JsonValue JsonValue::element(std::size_t index) const { return JsonValue(value_->at(index), file_, pointer_ / index); }

Error JsonValue::error(const std::string& what) const { return bad_input(file_ + ": " + pointer_text() + ": " + what); }

Error JsonValue::member_error(const std::string& key, const std::string& what) const
{
    return bad_input(file_ + ": " + (pointer_ / key).to_string() + ": " + what);
}

Error JsonValue::expected(const std::string& expectation) const
{
    return error("expected " + expectation + ", got " + shortened_text(*value_));
}

Expected<JsonObject> JsonObject::read(const JsonValue& value)
{
    if (!value.json().is_object()) return value.expected("an object");
    return JsonObject(value);
}

Expected<JsonObject> JsonObject::read(const JsonValue& value, const std::vector<std::string>& allowed)
{
    auto object = read(value);
    if (!object) return object;
    if (auto allowed_only = object->allow_only(allowed); !allowed_only) return allowed_only.error();
    return object;
}

Status JsonObject::allow_only(const std::vector<std::string>& allowed) const
{
    for (const auto& [key, member] : value_.json().items())
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
            return value_.member(key).error("unknown key (expected one of " + joined(allowed) + ")");
    return ok();
}

Status JsonObject::require_one_of(const std::vector<std::string>& keys) const
{
    std::vector<std::string> present;
    for (const std::string& key : keys)
        if (has(key)) present.push_back(key);
    if (present.size() == 1) return ok();
    return value_.error("expected exactly one of " + joined(keys, " or ") + ", got " +
                        (present.empty() ? std::string("none") : joined(present, " and ")));
}

Status JsonObject::reject_any_of(const std::vector<std::string>& keys, const std::string& why) const
{
    for (const std::string& key : keys)
        if (has(key)) return value_.member(key).error(why);
    return ok();
}

std::optional<JsonValue> JsonObject::find(const std::string& key) const
{
    if (!has(key)) return std::nullopt;
    return value_.member(key);
}

Expected<JsonValue> JsonObject::require(const std::string& key) const
{
    if (!has(key)) return value_.member_error(key, "required key is missing");
    return value_.member(key);
}

Expected<double> read_number(const JsonValue& value)
{
    if (!value.json().is_number()) return value.expected("a number");
    return value.json().get<double>();
}

Expected<std::string> read_string(const JsonValue& value)
{
    if (!value.json().is_string()) return value.expected("a string");
    return value.json().get<std::string>();
}

Expected<std::size_t> read_choice_index(const JsonValue& value, const std::vector<std::string>& words)
{
    if (value.json().is_string()) {
        const auto found = std::find(words.begin(), words.end(), value.json().get<std::string>());
        if (found != words.end()) return static_cast<std::size_t>(found - words.begin());
    }
    std::vector<std::string> quoted;
    for (const std::string& word : words) quoted.push_back(nlohmann::json(word).dump());
    return value.expected(joined(quoted, " or "));
}

Expected<std::vector<double>> read_numbers(const JsonValue& value, std::size_t count)
{
    const std::string expectation = "an array of " + std::to_string(count) + " numbers";
    if (!value.json().is_array() || value.json().size() != count) return value.expected(expectation);
    std::vector<double> numbers;
    for (std::size_t i = 0; i < count; ++i) {
        auto number = read_number(value.element(i));
        if (!number) return number.error();
        numbers.push_back(*number);
    }
    return numbers;
}

}  // namespace cmfilter
