// SPDX-License-Identifier: Apache-2.0
// SHA-256 written from FIPS 180-4 (NIST, August 2015): the functions of
// section 4.1.2, the constants of section 4.2.2, the padding of section 5.1.1,
// the initial hash value of section 5.3.3 and the hash computation of section
// 6.2.2. A small streaming hasher lets files be digested chunk by chunk.
// On x86-64 processors with the SHA extensions (SHA256RNDS2, SHA256MSG1/2:
// Intel 64 and IA-32 Architectures Software Developer's Manual, vol. 2) the
// same block computation runs on those instructions, several times faster;
// the choice is made once, at run time, from CPUID.
#include "cmfilter/util/sha256.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CMFILTER_SHA256_X86_SHA 1
#include <cpuid.h>
#include <immintrin.h>
#endif

namespace cmfilter {

namespace {

// FIPS 180-4, section 4.2.2: the first 32 bits of the fractional parts of the
// cube roots of the first 64 primes.
constexpr std::array<std::uint32_t, 64> kRoundConstants = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
};

// FIPS 180-4, section 5.3.3: the first 32 bits of the fractional parts of the
// square roots of the first 8 primes.
constexpr std::array<std::uint32_t, 8> kInitialHash = {
    0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19,
};

// FIPS 180-4, section 3.2: ROTR^n(x), a circular right shift (0 < n < 32).
constexpr std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

// FIPS 180-4, section 4.1.2, eqs. 4.2-4.7.
constexpr std::uint32_t ch(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return (x & y) ^ (~x & z); }
constexpr std::uint32_t maj(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return (x & y) ^ (x & z) ^ (y & z); }
constexpr std::uint32_t big_sigma0(std::uint32_t x) { return rotr(x, 2) ^ rotr(x, 13) ^ rotr(x, 22); }
constexpr std::uint32_t big_sigma1(std::uint32_t x) { return rotr(x, 6) ^ rotr(x, 11) ^ rotr(x, 25); }
constexpr std::uint32_t small_sigma0(std::uint32_t x) { return rotr(x, 7) ^ rotr(x, 18) ^ (x >> 3); }
constexpr std::uint32_t small_sigma1(std::uint32_t x) { return rotr(x, 17) ^ rotr(x, 19) ^ (x >> 10); }

// FIPS 180-4, section 6.2.2: process `blocks` consecutive 512-bit blocks M(i)
// into the hash value H.
void compress_portable(std::uint32_t* hash, const unsigned char* m, std::size_t blocks)
{
    for (; blocks > 0; --blocks, m += 64) {
        // Step 1: prepare the message schedule W_t.
        std::array<std::uint32_t, 64> w{};
        for (int t = 0; t < 16; ++t)
            w[t] = (std::uint32_t{m[4 * t]} << 24) | (std::uint32_t{m[4 * t + 1]} << 16) |
                   (std::uint32_t{m[4 * t + 2]} << 8) | std::uint32_t{m[4 * t + 3]};
        for (int t = 16; t < 64; ++t) w[t] = small_sigma1(w[t - 2]) + w[t - 7] + small_sigma0(w[t - 15]) + w[t - 16];

        // Step 2: initialise the working variables a..h from H(i-1).
        std::uint32_t a = hash[0], b = hash[1], c = hash[2], d = hash[3];
        std::uint32_t e = hash[4], f = hash[5], g = hash[6], h = hash[7];

        // Step 3: 64 rounds (all additions modulo 2^32).
        for (int t = 0; t < 64; ++t) {
            const std::uint32_t t1 = h + big_sigma1(e) + ch(e, f, g) + kRoundConstants[t] + w[t];
            const std::uint32_t t2 = big_sigma0(a) + maj(a, b, c);
            h = g;
            g = f;
            f = e;
            e = d + t1;
            d = c;
            c = b;
            b = a;
            a = t1 + t2;
        }

        // Step 4: the intermediate hash value H(i).
        hash[0] += a;
        hash[1] += b;
        hash[2] += c;
        hash[3] += d;
        hash[4] += e;
        hash[5] += f;
        hash[6] += g;
        hash[7] += h;
    }
}

#ifdef CMFILTER_SHA256_X86_SHA
// The same computation on the SHA extensions. The working variables live in
// two registers as (A, B, E, F) and (C, D, G, H); SHA256RNDS2 does two rounds
// with W_t + K_t taken from the low 64 bits of its third operand, SHA256MSG1
// and SHA256MSG2 compute the message schedule (section 6.2.2, step 1) four
// words at a time.
__attribute__((target("sha,sse4.1,ssse3"))) void compress_x86_sha(std::uint32_t* hash, const unsigned char* m,
                                                                  std::size_t blocks)
{
    const __m128i byte_swap = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);
    __m128i dcba = _mm_loadu_si128(reinterpret_cast<const __m128i*>(hash));
    __m128i hgfe = _mm_loadu_si128(reinterpret_cast<const __m128i*>(hash + 4));
    const __m128i cdab = _mm_shuffle_epi32(dcba, 0xB1);
    const __m128i efgh = _mm_shuffle_epi32(hgfe, 0x1B);
    __m128i abef = _mm_alignr_epi8(cdab, efgh, 8);
    __m128i cdgh = _mm_blend_epi16(efgh, cdab, 0xF0);

    for (; blocks > 0; --blocks, m += 64) {
        const __m128i abef_in = abef, cdgh_in = cdgh;
        __m128i w[4];  // W_{4g}..W_{4g+3} for the group g of four rounds, in w[g % 4]
        for (int g = 0; g < 16; ++g) {
            __m128i& cur = w[g % 4];
            if (g < 4) cur = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(m + 16 * g)), byte_swap);
            __m128i wk =
                _mm_add_epi32(cur, _mm_loadu_si128(reinterpret_cast<const __m128i*>(kRoundConstants.data() + 4 * g)));
            cdgh = _mm_sha256rnds2_epu32(cdgh, abef, wk);
            if (g >= 3 && g < 15) {  // finish W for group g + 1 (its MSG1 part was done at g - 1)
                __m128i& next = w[(g + 1) % 4];
                next = _mm_add_epi32(next, _mm_alignr_epi8(cur, w[(g + 3) % 4], 4));
                next = _mm_sha256msg2_epu32(next, cur);
            }
            wk = _mm_shuffle_epi32(wk, 0x0E);
            abef = _mm_sha256rnds2_epu32(abef, cdgh, wk);
            if (g >= 1 && g < 13) w[(g + 3) % 4] = _mm_sha256msg1_epu32(w[(g + 3) % 4], cur);
        }
        abef = _mm_add_epi32(abef, abef_in);
        cdgh = _mm_add_epi32(cdgh, cdgh_in);
    }

    const __m128i feba = _mm_shuffle_epi32(abef, 0x1B);
    const __m128i dchg = _mm_shuffle_epi32(cdgh, 0xB1);
    dcba = _mm_blend_epi16(feba, dchg, 0xF0);
    hgfe = _mm_alignr_epi8(dchg, feba, 8);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(hash), dcba);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(hash + 4), hgfe);
}

bool cpu_has_x86_sha()
{
    unsigned a = 0, b = 0, c = 0, d = 0;
    if (!__get_cpuid(1, &a, &b, &c, &d)) return false;
    const bool ssse3 = c & (1u << 9), sse41 = c & (1u << 19);
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return false;
    return ssse3 && sse41 && (b & (1u << 29));
}
#endif

using CompressFn = void (*)(std::uint32_t*, const unsigned char*, std::size_t);

CompressFn select_compress()
{
#ifdef CMFILTER_SHA256_X86_SHA
    if (cpu_has_x86_sha()) return compress_x86_sha;
#endif
    return compress_portable;
}

const CompressFn compress_blocks = select_compress();

class Sha256 {
public:
    explicit Sha256(CompressFn compress = compress_blocks) : compress_(compress) {}

    void update(const unsigned char* data, std::size_t size)
    {
        total_bytes_ += size;
        if (fill_ > 0) {  // complete the pending block first
            const std::size_t take = std::min(size, block_.size() - fill_);
            std::memcpy(block_.data() + fill_, data, take);
            fill_ += take;
            data += take;
            size -= take;
            if (fill_ < block_.size()) return;
            compress_(hash_.data(), block_.data(), 1);
            fill_ = 0;
        }
        const std::size_t whole = size / block_.size();
        if (whole > 0) compress_(hash_.data(), data, whole);
        data += whole * block_.size();
        size -= whole * block_.size();
        std::memcpy(block_.data(), data, size);
        fill_ = size;
    }

    std::string finish_hex()
    {
        // FIPS 180-4, section 5.1.1: append the bit 1, then k zero bits so the
        // length is 448 mod 512, then the message length in bits as a 64-bit
        // big-endian integer.
        const std::uint64_t bit_length = total_bytes_ * 8;
        block_[fill_++] = 0x80;
        if (fill_ > 56) {
            std::fill(block_.begin() + fill_, block_.end(), 0);
            compress_(hash_.data(), block_.data(), 1);
            fill_ = 0;
        }
        std::fill(block_.begin() + fill_, block_.begin() + 56, 0);
        for (int i = 0; i < 8; ++i) block_[56 + i] = static_cast<unsigned char>(bit_length >> (56 - 8 * i));
        compress_(hash_.data(), block_.data(), 1);
        fill_ = 0;

        // Section 6.2.2, final step: H(N) = H0 || ... || H7, big-endian.
        static const char digits[] = "0123456789abcdef";
        std::string hex;
        hex.reserve(64);
        for (std::uint32_t word : hash_)
            for (int shift = 28; shift >= 0; shift -= 4) hex.push_back(digits[(word >> shift) & 0xf]);
        return hex;
    }

private:
    CompressFn compress_;
    std::array<std::uint32_t, 8> hash_ = kInitialHash;
    std::array<unsigned char, 64> block_{};
    std::size_t fill_ = 0;
    std::uint64_t total_bytes_ = 0;
};

}  // namespace

std::string sha256_hex(const void* data, std::size_t size)
{
    Sha256 hasher;
    if (size > 0) hasher.update(static_cast<const unsigned char*>(data), size);
    return hasher.finish_hex();
}

namespace detail {

std::string sha256_hex_portable(const void* data, std::size_t size)
{
    Sha256 hasher(compress_portable);
    if (size > 0) hasher.update(static_cast<const unsigned char*>(data), size);
    return hasher.finish_hex();
}

const char* sha256_implementation() { return compress_blocks == compress_portable ? "portable" : "x86-sha"; }

}  // namespace detail

Expected<std::string> sha256_file_hex(const std::string& path)
{
    // A directory opens as a stream on some platforms and then reads as empty;
    // refuse it rather than hash nothing.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return io_error("cannot read '" + path + "': it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) return io_error("cannot read '" + path + "': cannot open the file to hash it");
    Sha256 hasher;
    std::vector<char> chunk(1 << 16);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const std::streamsize got = in.gcount();
        if (got > 0) hasher.update(reinterpret_cast<const unsigned char*>(chunk.data()), static_cast<std::size_t>(got));
    }
    if (in.bad()) return io_error("cannot read '" + path + "': a read failed while hashing it");
    return hasher.finish_hex();
}

}  // namespace cmfilter
