// SHA-256 written from FIPS 180-4 (NIST, August 2015): the functions of
// section 4.1.2, the constants of section 4.2.2, the padding of section 5.1.1,
// the initial hash value of section 5.3.3 and the hash computation of section
// 6.2.2. A small streaming hasher lets files be digested chunk by chunk.
#include "cmfilter/sha256.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

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

class Sha256 {
public:
    void update(const unsigned char* data, std::size_t size)
    {
        total_bytes_ += size;
        while (size > 0) {
            const std::size_t take = std::min(size, block_.size() - fill_);
            std::memcpy(block_.data() + fill_, data, take);
            fill_ += take;
            data += take;
            size -= take;
            if (fill_ == block_.size()) {
                compress(block_.data());
                fill_ = 0;
            }
        }
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
            compress(block_.data());
            fill_ = 0;
        }
        std::fill(block_.begin() + fill_, block_.begin() + 56, 0);
        for (int i = 0; i < 8; ++i)
            block_[56 + i] = static_cast<unsigned char>(bit_length >> (56 - 8 * i));
        compress(block_.data());
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
    // FIPS 180-4, section 6.2.2: process one 512-bit block M(i).
    void compress(const unsigned char* m)
    {
        // Step 1: prepare the message schedule W_t.
        std::array<std::uint32_t, 64> w{};
        for (int t = 0; t < 16; ++t)
            w[t] = (std::uint32_t{m[4 * t]} << 24) | (std::uint32_t{m[4 * t + 1]} << 16) |
                   (std::uint32_t{m[4 * t + 2]} << 8) | std::uint32_t{m[4 * t + 3]};
        for (int t = 16; t < 64; ++t)
            w[t] = small_sigma1(w[t - 2]) + w[t - 7] + small_sigma0(w[t - 15]) + w[t - 16];

        // Step 2: initialise the working variables a..h from H(i-1).
        std::uint32_t a = hash_[0], b = hash_[1], c = hash_[2], d = hash_[3];
        std::uint32_t e = hash_[4], f = hash_[5], g = hash_[6], h = hash_[7];

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
        hash_[0] += a; hash_[1] += b; hash_[2] += c; hash_[3] += d;
        hash_[4] += e; hash_[5] += f; hash_[6] += g; hash_[7] += h;
    }

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

Expected<std::string> sha256_file_hex(const std::string& path)
{
    // A directory opens as a stream on some platforms and then reads as empty;
    // refuse it rather than hash nothing.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return io_error("cannot read '" + path + "': it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) return io_error("cannot read '" + path + "': cannot open the file to hash it");
    Sha256 hasher;
    std::vector<char> chunk(1 << 16);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const std::streamsize got = in.gcount();
        if (got > 0)
            hasher.update(reinterpret_cast<const unsigned char*>(chunk.data()),
                          static_cast<std::size_t>(got));
    }
    if (in.bad()) return io_error("cannot read '" + path + "': a read failed while hashing it");
    return hasher.finish_hex();
}

}  // namespace cmfilter
