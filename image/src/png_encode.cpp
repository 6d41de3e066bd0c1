#include "png_encode.hpp"

#include <png.h>

#include <bit>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace splinefig::detail {
namespace {

// Where libpng's output goes; a failed append is remembered (libpng must not be left by an
// exception) and reported after the write.
struct Sink {
  std::vector<unsigned char>* file;
  bool failed = false;
};

void append(png_structp png, png_bytep data, png_size_t n) {
  Sink* sink = static_cast<Sink*>(png_get_io_ptr(png));
  if (sink->failed) return;
  try {
    sink->file->insert(sink->file->end(), data, data + n);
  } catch (...) {
    sink->failed = true;
  }
}

void flush(png_structp) {}

struct Message {
  char text[256] = "";
};

[[noreturn]] void on_error(png_structp png, png_const_charp text) {
  Message* m = static_cast<Message*>(png_get_error_ptr(png));
  std::snprintf(m->text, sizeof m->text, "%s", text);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// Everything the write needs, prepared before it: the libpng calls below run under setjmp,
// where only plain data may live.
struct Plan {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 8, color_type = PNG_COLOR_TYPE_RGBA;
  png_text text[2]{};
  int texts = 0;
  bool srgb = false;
  png_uint_32 ppm_x = 0, ppm_y = 0;  // pixels per metre; none when 0
  png_int_32 x = 0, y = 0;
  int level = 6, filter = PNG_ALL_FILTERS;
  png_bytepp rows = nullptr;
};

bool write_all(png_structp png, png_infop info, const Plan& p) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, p.width, p.height, p.bit_depth, p.color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (p.srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (p.texts > 0) png_set_text(png, info, const_cast<png_textp>(p.text), p.texts);
  if (p.ppm_x > 0 && p.ppm_y > 0) png_set_pHYs(png, info, p.ppm_x, p.ppm_y, PNG_RESOLUTION_METER);
  if (p.x != 0 || p.y != 0) png_set_oFFs(png, info, p.x, p.y, PNG_OFFSET_PIXEL);
  png_set_compression_level(png, p.level);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, p.filter);
  png_write_info(png, info);
  if (p.bit_depth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
  png_write_image(png, p.rows);
  png_write_end(png, nullptr);
  return true;
}

const std::string* string_attribute(const CodecImage& im, const char* name) {
  for (const auto& [key, value] : im.string_attributes)
    if (key == name) return &value;
  return nullptr;
}

// Pixels per metre for a resolution in pixels per inch; 0 when there is none or it is out of range.
png_uint_32 per_metre(const CodecImage& im, const char* name) {
  for (const auto& [key, value] : im.float_attributes)
    if (key == name && value > 0 && value < 1e6f) return static_cast<png_uint_32>(std::lround(value / 0.0254));
  return 0;
}

}  // namespace

bool encode_png(const CodecImage& im, std::vector<unsigned char>& file, std::string& error) noexcept {
  if (im.channels < 1 || im.channels > 4 || im.type == CodecType::f32 || im.width <= 0 || im.height <= 0 || !im.data) {
    error = "PNG holds 1 to 4 channels of 8 or 16 bits";
    return false;
  }
  try {
    Plan p;
    p.width = static_cast<png_uint_32>(im.width);
    p.height = static_cast<png_uint_32>(im.height);
    p.bit_depth = im.type == CodecType::u16 ? 16 : 8;
    static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                          PNG_COLOR_TYPE_RGBA};
    p.color_type = kColorTypes[im.channels - 1];
    const std::string* software = string_attribute(im, "Software");
    const std::string* description = string_attribute(im, "ImageDescription");
    // tEXt holds Latin-1; a description with other characters goes into iTXt (UTF-8) instead.
    auto add_text = [&](const char* key, const std::string* value) {
      if (!value || value->empty()) return;
      png_text& t = p.text[p.texts++];
      t.key = const_cast<char*>(key);
      t.text = const_cast<char*>(value->c_str());
      t.text_length = value->size();
      bool ascii = true;
      for (unsigned char c : *value) ascii = ascii && c < 0x80;
      t.compression = ascii ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
    };
    add_text("Software", software);
    add_text("Description", description);
    const std::string* space = string_attribute(im, "oiio:ColorSpace");
    p.srgb = space && *space == "sRGB";
    p.ppm_x = per_metre(im, "XResolution");
    p.ppm_y = per_metre(im, "YResolution");
    p.x = im.x;
    p.y = im.y;
    for (const auto& [key, value] : im.int_attributes) {
      if (key == "png:compressionLevel") p.level = value;
      if (key == "png:filter") p.filter = value;
    }
    const std::size_t row_bytes =
        static_cast<std::size_t>(im.width) * static_cast<std::size_t>(im.channels) * (p.bit_depth / 8);
    std::vector<png_bytep> rows(static_cast<std::size_t>(im.height));
    auto* base = static_cast<png_bytep>(const_cast<void*>(im.data));
    for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = base + r * row_bytes;
    p.rows = rows.data();

    Message message;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
    if (!png) {
      error = "cannot start the PNG encoder";
      return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info) {
      png_destroy_write_struct(&png, nullptr);
      error = "cannot start the PNG encoder";
      return false;
    }
    Sink sink{&file};
    file.clear();
    png_set_write_fn(png, &sink, append, flush);
    const bool ok = write_all(png, info, p);
    png_destroy_write_struct(&png, &info);
    if (!ok) {
      error = message.text[0] ? message.text : "the PNG encoder failed";
      return false;
    }
    if (sink.failed) {
      error = "out of memory while encoding PNG";
      return false;
    }
    return true;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

}  // namespace splinefig::detail
