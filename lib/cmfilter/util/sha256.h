// SPDX-License-Identifier: Apache-2.0
// SHA-256 message digests (FIPS 180-4, "Secure Hash Standard", NIST 2015),
// written from the specification. Used to record the provenance of input files;
// digests are returned as 64 lowercase hexadecimal characters.
#pragma once

#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>

namespace cmfilter {

// SHA-256 of size bytes at data (data may be null when size is 0).
std::string sha256_hex(const void* data, std::size_t size);

// SHA-256 of a file's bytes, read in chunks (never the whole file at once).
// An Io error naming the path if the file cannot be opened or read.
Expected<std::string> sha256_file_hex(const std::string& path);

namespace detail {
// For tests: the digest computed without the processor's SHA instructions, and
// which block computation sha256_hex uses ("x86-sha" or "portable").
std::string sha256_hex_portable(const void* data, std::size_t size);
const char* sha256_implementation();
}  // namespace detail

}  // namespace cmfilter
