// SPDX-License-Identifier: Apache-2.0
// SHA-256 (FIPS 180-4) against the NIST example digests, and the streamed file
// digest against the one-shot digest and the system sha256sum, across the
// padding boundaries.
#include "cmfilter/util/sha256.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace cmfilter;
namespace fs = std::filesystem;

namespace {

std::string sha256_of(const std::string& s) { return sha256_hex(s.data(), s.size()); }

// Runs a shell command and returns its standard output; empty if it failed.
std::string run_command(const std::string& command)
{
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return output;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    if (pclose(pipe) != 0) output.clear();
    return output;
}

bool have_sha256sum() { return !run_command("command -v sha256sum 2>/dev/null").empty(); }

}  // namespace

TEST_CASE("sha256: FIPS 180-4 example digests")
{
    // Digests from NIST's "Cryptographic Standards and Guidelines: Examples
    // with Intermediate Values" for SHA-256, and the FIPS 180-2 Appendix B
    // one-million-'a' example. Exact string comparisons.
    CHECK(sha256_of("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256_hex(nullptr, 0) == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256_of("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    CHECK(sha256_of("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    CHECK(sha256_of(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("sha256: the SHA-instruction and portable block computations agree")
{
    // sha256_hex uses the processor's SHA instructions where it has them; the
    // portable computation must give the same digests, in one call and fed in
    // pieces that split blocks anywhere (lengths across the padding boundary
    // and several blocks).
    MESSAGE("block computation in use: " << std::string(detail::sha256_implementation()));
    std::string bytes(4099, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 7919 + (i >> 5)) & 0xff);
    CHECK(detail::sha256_hex_portable("abc", 3) == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    for (std::size_t n : {0u, 1u, 55u, 56u, 63u, 64u, 65u, 127u, 128u, 129u, 1000u, 4099u}) {
        INFO("length " << n);
        CHECK(sha256_hex(bytes.data(), n) == detail::sha256_hex_portable(bytes.data(), n));
    }
}

TEST_CASE("sha256: file digests match the one-shot digest and the system sha256sum")
{
    // Lengths around the padding boundary (55 bytes still fit the 64-bit length
    // in the last block, 56 do not: FIPS 180-4, section 5.1.1), exact blocks,
    // and 200 001 bytes: more than three 64 KiB read chunks, not a multiple of
    // the 64-byte block.
    const bool system_tool = have_sha256sum();
    if (!system_tool) MESSAGE("sha256sum not found; skipping the comparison with the system tool");

    const fs::path dir = fs::temp_directory_path() / "cmfilter-test-sha256";
    fs::create_directories(dir);
    const fs::path file = dir / "data.bin";
    for (std::size_t n : {0u, 1u, 55u, 56u, 63u, 64u, 65u, 119u, 120u, 200001u}) {
        INFO("length " << n);
        std::string bytes(n, '\0');
        for (std::size_t i = 0; i < n; ++i) bytes[i] = static_cast<char>((i * 131 + i / 256) & 0xff);
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            REQUIRE(out.good());
        }
        const auto digest = sha256_file_hex(file.string());
        REQUIRE(digest.has_value());
        CHECK(*digest == sha256_of(bytes));  // exact: lowercase hex strings
        if (system_tool) {
            const std::string output = run_command("sha256sum '" + file.string() + "'");
            REQUIRE(output.size() >= 64);
            CHECK(*digest == output.substr(0, 64));  // exact: both are lowercase hex
        }
    }
    fs::remove_all(dir);
}

TEST_CASE("sha256: file digest of a missing file is an Io error naming it")
{
    const std::string path = (fs::temp_directory_path() / "cmfilter-test-sha256-no-such-file.bin").string();
    fs::remove(path);
    const auto digest = sha256_file_hex(path);
    REQUIRE_FALSE(digest.has_value());
    CHECK(digest.error().kind == ErrorKind::Io);
    CHECK(digest.error().message.find(path) != std::string::npos);
}
