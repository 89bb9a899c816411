// SPDX-License-Identifier: Apache-2.0
// What the .ptm (ptm_file.h) and HSH .rti (rti_file.h) readers and writers
// share: both files hold a 3-channel, display-encoded LinearFit quantised to
// one byte a coefficient behind a text header. Here: the check that a fit
// can be written in such a format (its model, channels, encoding, size and
// finite coefficients), a read position in a file's bytes that takes lines
// and whitespace-separated tokens off the header, the quoting of header
// text in messages, decimal integer tokens, and reading and atomically
// writing a file's bytes. Internal to the library (not installed).
#pragma once

#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>

namespace cmfilter {

// A quantised fit format, as check_writable_fit names it in messages.
struct QuantisedFitFormat {
    const char* name;            // ".ptm": "cannot write '<path>' as .ptm: ..."
    const char* holder;          // what holds the models and 3 channels: "a .ptm", "an HSH .rti"
    const char* encoded_holder;  // what holds display-encoded values: "a .ptm", "an .rti"
    LinearModel models[2];       // the two models the format holds
    int max_side;                // the largest width and height
};

// Ok when `fit` can be written to `path` in `format`: one of its models, 3
// channels, DisplayEncoded, each side within 1 .. max_side, as many
// coefficients as its size and model need, all finite. Otherwise BadInput
// "cannot write '<path>' as <name>: " and what is wrong (a non-finite
// coefficient naming its texel).
Status check_writable_fit(const std::string& path, const LinearFit& fit, const QuantisedFitFormat& format);

// A read position in a file's bytes.
struct ByteCursor {
    const std::string& bytes;
    std::size_t pos = 0;

    bool at_end() const { return pos >= bytes.size(); }
    // The rest of the line, without its "\n" and the spaces, tabs and "\r"
    // before it; false at the end.
    bool line(std::string& out);
    // The next whitespace-separated token (possibly on a later line); false
    // at the end.
    bool token(std::string& out);
    // Past the spaces, tabs, "\r" and the newline that end the current line;
    // false when something else comes first.
    bool end_of_line();
};

// Header text as it may be quoted in a message: in single quotes, its first
// 40 characters ("..." after them when there are more), each unprintable
// one as '?'.
std::string quoted_header(const std::string& text);

// A decimal integer that fills `token` and fits a long long.
bool parse_integer_token(const std::string& token, long long& value);

// The whole file. Io "cannot open '<path>' for reading" / "cannot read
// '<path>'".
Expected<std::string> read_file_bytes(const std::string& path);

// `bytes` written to `path` atomically (AtomicOutput: no file on failure).
Status write_file_bytes(const std::string& path, const std::string& bytes);

}  // namespace cmfilter
