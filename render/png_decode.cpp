#include "png_decode.hpp"

#include <png.h>

#include <csetjmp>
#include <cstring>

namespace plastica::render {

namespace {

struct Source {
    const std::string* bytes;
    std::size_t at;
};

void read_from(png_structp png, png_bytep out, png_size_t length) {
    auto* source = static_cast<Source*>(png_get_io_ptr(png));
    if (length > source->bytes->size() - source->at) png_error(png, "the file ends inside the picture (truncated)");
    std::memcpy(out, source->bytes->data() + source->at, length);
    source->at += length;
}

// libpng's own message, kept for the caller (its default handler would print it).
void on_error(png_structp png, png_const_charp message) {
    auto* why = static_cast<std::string*>(png_get_error_ptr(png));
    *why = message;
    png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp back here, so the objects with destructors live in the
// caller; the pixel rows are sized only once the header has been checked against the bounds.
bool decode(png_structp png, png_infop info, Source* source, DecodedPng* out, std::vector<png_bytep>* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_read_fn(png, source, read_from);
    png_set_user_limits(png, max_png_side, max_png_side);
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    out->width = static_cast<int>(width);
    out->height = static_cast<int>(height);
    // Said by the caller: no string is built in a frame that longjmp may leave.
    if (static_cast<std::size_t>(width) * height > max_png_pixels) return false;
    // Every kind of PNG to 8 bits a channel: palettes expanded, 16 bits cut, low grey bits widened.
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    out->channels = png_get_channels(png, info);
    const std::size_t row_bytes = png_get_rowbytes(png, info);
    if (out->channels < 1 || out->channels > 4 || row_bytes != static_cast<std::size_t>(width) * out->channels) return false;
    out->pixels.resize(row_bytes * height);
    rows->resize(height);
    for (std::size_t y = 0; y < height; ++y) (*rows)[y] = out->pixels.data() + y * row_bytes;
    png_read_image(png, rows->data());
    png_read_end(png, nullptr);
    return true;
}

} // namespace

std::optional<DecodedPng> decode_png(const std::string& bytes, std::string& why) {
    if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0) {
        why = "not a PNG image";
        return std::nullopt;
    }
    DecodedPng out;
    std::vector<png_bytep> rows;
    Source source{&bytes, 0};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &why, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    const bool decoded = info && decode(png, info, &source, &out, &rows);
    png_destroy_read_struct(&png, &info, nullptr);
    if (!decoded) {
        if (why.empty() && static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) > max_png_pixels)
            why = std::to_string(out.width) + " × " + std::to_string(out.height) + " pixels, more than the " +
                  std::to_string(max_png_pixels) + " a picture read may have";
        if (why.empty() && out.channels != 0) why = "an unsupported pixel layout";
        if (why.empty()) why = "unreadable PNG";
        if (why == "Invalid IHDR data")
            why = "a bad header (IHDR): a picture read has 1 to " + std::to_string(max_png_side) + " pixels a side and a PNG pixel format";
        return std::nullopt;
    }
    return out;
}

} // namespace plastica::render
