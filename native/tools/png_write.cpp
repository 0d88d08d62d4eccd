#include "png_write.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace el_tools {
namespace {

unsigned char srgb8(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<unsigned char>(std::lround(s * 255.0f));
}

}  // namespace

void write_png(const std::string& path, const std::vector<float>& rgba, int width, int height) {
    if (rgba.size() != size_t(width) * size_t(height) * 4) throw std::invalid_argument("write_png: size mismatch");
    std::vector<unsigned char> rows(size_t(width) * size_t(height) * 4);
    for (int y = 0; y < height; ++y) {
        const float* src = &rgba[size_t(height - 1 - y) * size_t(width) * 4];  // PNG rows run top-down
        unsigned char* dst = &rows[size_t(y) * size_t(width) * 4];
        for (int x = 0; x < width; ++x) {
            for (int k = 0; k < 3; ++k) dst[4 * x + k] = srgb8(src[4 * x + k]);
            dst[4 * x + 3] = static_cast<unsigned char>(std::lround(std::clamp(src[4 * x + 3], 0.0f, 1.0f) * 255.0f));
        }
    }
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "wb"), std::fclose);
    if (!f) throw std::runtime_error("cannot write " + path);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw std::runtime_error("libpng: out of memory");
    }
    if (setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng could not write " + path);
    }
    png_init_io(png, f.get());
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) png_write_row(png, &rows[size_t(y) * size_t(width) * 4]);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
}

}  // namespace el_tools
