// SPDX-License-Identifier: Apache-2.0
// JSON text parsed into a document for the library's JSON file formats, with
// errors a user can act on: BadInput naming the file and, for malformed text,
// the line and column (and byte offset) where the parser stopped. A key given
// twice in one object is an error too (nlohmann-json would silently keep the
// last), named by its JSON pointer.
#pragma once

#include "cmfilter/util/error.h"

#include <nlohmann/json.hpp>

#include <string>

namespace cmfilter {

// `file` names the text in messages: "<file>: malformed JSON at line L,
// column C (byte B): <what the parser expected>".
Expected<nlohmann::json> parse_json_document(const std::string& text, const std::string& file);

}  // namespace cmfilter
