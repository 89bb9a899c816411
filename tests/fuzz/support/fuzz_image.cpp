// SPDX-License-Identifier: Apache-2.0
#include "fuzz_image.h"

#include <OpenImageIO/half.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>

namespace cmfilter::fuzz {

namespace {

class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
    std::uint32_t u32()
    {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(u8()) << (8 * i);
        return v;
    }
    std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | (u8() << 8)); }
    float f32()
    {
        const std::uint32_t bits = u32();
        float v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    std::string text()
    {
        const std::size_t n = std::min<std::size_t>(u8(), size_ - std::min(pos_, size_));
        std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
        pos_ += n;
        return s;
    }
    bool done() const { return pos_ >= size_; }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

class ByteWriter {
public:
    void u8(unsigned v) { out_.push_back(static_cast<char>(v & 0xff)); }
    void u32(std::uint32_t v)
    {
        for (int i = 0; i < 4; ++i) u8(v >> (8 * i));
    }
    void u16(unsigned v)
    {
        u8(v);
        u8(v >> 8);
    }
    void f32(float v)
    {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    void text(const std::string& s)
    {
        const std::size_t n = std::min<std::size_t>(s.size(), 255);
        u8(static_cast<unsigned>(n));
        out_.append(s, 0, n);
    }
    std::string take() { return std::move(out_); }

private:
    std::string out_;
};

OIIO::TypeDesc pixel_type(int type)
{
    switch (type) {
    case 1: return OIIO::TypeDesc::HALF;
    case 2: return OIIO::TypeDesc::UINT8;
    case 3: return OIIO::TypeDesc::UINT16;
    default: return OIIO::TypeDesc::FLOAT;
    }
}

// Serves a FuzzImage, read from the file's bytes, as an image.
class FuzzImageInput final : public OIIO::ImageInput {
public:
    const char* format_name() const override { return "cmfuzz"; }
    int supports(OIIO::string_view feature) const override
    {
        return feature == "multiimage" || feature == "mipmap" || feature == "arbitrary_metadata";
    }
    bool valid_file(const std::string&) const override { return true; }

    bool open(const std::string& name, OIIO::ImageSpec& newspec) override
    {
        std::ifstream in(name, std::ios::binary);
        if (!in) {
            errorf("cannot open %s", name);
            return false;
        }
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        image_ = decode_fuzz_image(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        if (!seek_subimage(0, 0)) return false;
        newspec = spec();
        return true;
    }
    bool close() override
    {
        image_ = {};
        return true;
    }
    bool seek_subimage(int subimage, int miplevel) override
    {
        if (subimage < 0 || subimage >= static_cast<int>(image_.subimages.size())) return false;
        const FuzzSubimage& sub = image_.subimages[static_cast<std::size_t>(subimage)];
        if (miplevel < 0 || miplevel >= sub.levels) return false;
        if (subimage == current_subimage() && miplevel == current_miplevel()) return true;
        m_spec = fuzz_image_spec(sub, miplevel);
        subimage_ = subimage;
        level_ = miplevel;
        return true;
    }
    int current_subimage() const override { return subimage_; }
    int current_miplevel() const override { return level_; }

    bool read_native_scanline(int subimage, int miplevel, int y, int /*z*/, void* data) override
    {
        std::lock_guard<OIIO::ImageInput> lock(*this);
        if (!seek_subimage(subimage, miplevel)) return false;
        fill(static_cast<std::uint64_t>(y - m_spec.y) * std::uint64_t(m_spec.width), std::uint64_t(m_spec.width), data);
        return true;
    }
    bool read_native_tile(int subimage, int miplevel, int x, int y, int /*z*/, void* data) override
    {
        std::lock_guard<OIIO::ImageInput> lock(*this);
        if (!seek_subimage(subimage, miplevel)) return false;
        const int tw = m_spec.tile_width, th = m_spec.tile_height;
        const std::size_t px = m_spec.pixel_bytes(true);
        for (int row = 0; row < th; ++row) {
            const int yy = y - m_spec.y + row, xx = x - m_spec.x;
            const std::uint64_t first = std::uint64_t(std::max(yy, 0)) * std::uint64_t(m_spec.width) +
                                        std::uint64_t(std::max(xx, 0));
            fill(first, std::uint64_t(tw), static_cast<char*>(data) + std::size_t(row) * std::size_t(tw) * px);
        }
        return true;
    }

private:
    // `count` pixels from pixel index `first` of the current level, in its
    // type. Not instrumented for coverage: the pixels are the fuzzer's own
    // input, repeated, and instrumenting their copy only slowed large images.
    // (The harnesses are clang's alone.)
    __attribute__((no_sanitize("coverage"))) void fill(std::uint64_t first, std::uint64_t count, void* data) const
    {
        const FuzzSubimage& sub = image_.subimages[static_cast<std::size_t>(subimage_)];
        const std::uint64_t nch = std::uint64_t(m_spec.nchannels);
        std::vector<float>& values = values_;  // reused: a tile row of tiny tiles is many calls
        values.resize(static_cast<std::size_t>(count * nch));
        for (std::uint64_t i = 0; i < count * nch; ++i)
            values[i] = sub.values.empty() ? 0.0f : sub.values[(first * nch + i) % sub.values.size()];
        OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, values.data(), m_spec.format, data,
                                   static_cast<int>(values.size()));
    }

    FuzzImage image_;
    int subimage_ = -1;
    int level_ = -1;
    mutable std::vector<float> values_;
};

OIIO::ImageInput* create_fuzz_image_input() { return new FuzzImageInput; }

}  // namespace

FuzzImage decode_fuzz_image(const std::uint8_t* data, std::size_t size)
{
    ByteReader in(data, size);
    FuzzImage image;
    const int subimages = 1 + in.u8() % 4;
    for (int s = 0; s < subimages; ++s) {
        FuzzSubimage sub;
        sub.levels = 1 + in.u8() % 8;
        sub.width = static_cast<std::int32_t>(in.u32());
        sub.height = static_cast<std::int32_t>(in.u32());
        const int channels = in.u8() % 16;
        sub.type = in.u8() % 4;
        sub.tiled = in.u8() % 2 == 1;
        for (int c = 0; c < channels; ++c) sub.channel_names.push_back(in.text());
        const int attributes = in.u8();
        for (int a = 0; a < attributes && !in.done(); ++a) {
            FuzzAttribute attr;
            attr.name = in.text();
            attr.kind = in.u8() % 3;
            if (attr.kind == 0) attr.int_value = static_cast<std::int32_t>(in.u32());
            else if (attr.kind == 1) attr.float_value = in.f32();
            else attr.string_value = in.text();
            sub.attributes.push_back(std::move(attr));
        }
        const int values = in.u16();
        for (int v = 0; v < values && !in.done(); ++v) sub.values.push_back(in.f32());
        image.subimages.push_back(std::move(sub));
    }
    return image;
}

std::string encode_fuzz_image(const FuzzImage& image)
{
    ByteWriter out;
    out.u8(static_cast<unsigned>(std::max<std::size_t>(image.subimages.size(), 1) - 1));
    for (const FuzzSubimage& sub : image.subimages) {
        out.u8(static_cast<unsigned>(std::max(sub.levels, 1) - 1));
        out.u32(static_cast<std::uint32_t>(sub.width));
        out.u32(static_cast<std::uint32_t>(sub.height));
        out.u8(static_cast<unsigned>(sub.channel_names.size()));
        out.u8(static_cast<unsigned>(sub.type));
        out.u8(sub.tiled ? 1 : 0);
        for (const std::string& name : sub.channel_names) out.text(name);
        out.u8(static_cast<unsigned>(std::min<std::size_t>(sub.attributes.size(), 255)));
        for (std::size_t a = 0; a < std::min<std::size_t>(sub.attributes.size(), 255); ++a) {
            const FuzzAttribute& attr = sub.attributes[a];
            out.text(attr.name);
            out.u8(static_cast<unsigned>(attr.kind));
            if (attr.kind == 0) out.u32(static_cast<std::uint32_t>(attr.int_value));
            else if (attr.kind == 1) out.f32(attr.float_value);
            else out.text(attr.string_value);
        }
        const std::size_t values = std::min<std::size_t>(sub.values.size(), 65535);
        out.u16(static_cast<unsigned>(values));
        for (std::size_t v = 0; v < values; ++v) out.f32(sub.values[v]);
    }
    return out.take();
}

OIIO::ImageSpec fuzz_image_spec(const FuzzSubimage& sub, int level)
{
    const int nch = static_cast<int>(sub.channel_names.size());
    const int w = level == 0 ? sub.width : std::max(1, sub.width >> std::min(level, 30));
    const int h = level == 0 ? sub.height : std::max(1, sub.height >> std::min(level, 30));
    OIIO::ImageSpec spec(w, h, nch, pixel_type(sub.type));
    spec.channelnames = sub.channel_names;
    if (sub.tiled) {
        spec.tile_width = 64;
        spec.tile_height = 64;
        spec.tile_depth = 1;
    }
    for (const FuzzAttribute& attr : sub.attributes) {
        if (attr.name.empty()) continue;
        if (attr.kind == 0) spec.attribute(attr.name, static_cast<int>(attr.int_value));
        else if (attr.kind == 1) spec.attribute(attr.name, attr.float_value);
        else spec.attribute(attr.name, attr.string_value);
    }
    return spec;
}

void register_fuzz_image_format()
{
    static std::once_flag once;
    std::call_once(once, [] {
        static const char* extensions[] = {"cmfuzz", nullptr};
        OIIO::declare_imageio_format("cmfuzz", &create_fuzz_image_input, extensions, nullptr, nullptr, "1");
    });
}

}  // namespace cmfilter::fuzz
