// The image type's constructors and channel-name defaults (see image.hpp).
#include <splinefig/image/image.hpp>

#include <algorithm>

namespace splinefig {

std::vector<std::string> default_channel_names(int channels) {
  switch (channels) {
    case 1: return {"Y"};
    case 2: return {"Y", "A"};
    case 3: return {"R", "G", "B"};
    case 4: return {"R", "G", "B", "A"};
    default: break;
  }
  std::vector<std::string> names;
  for (int c = 0; c < channels; ++c) names.push_back("channel" + std::to_string(c));
  return names;
}

int default_alpha_channel(int channels) { return (channels == 2 || channels == 4) ? channels - 1 : -1; }

Image::Image(int w, int h, int c, Encoding e)
    : width(w), height(h), channels(c), channel_names(default_channel_names(c)),
      alpha_channel(default_alpha_channel(c)), encoding(e) {
  pixels.resize(std::size_t(w) * std::size_t(h) * std::size_t(c));
}

Image Image::zeros(int w, int h, int c, Encoding e) {
  Image im(w, h, c, e);
  std::fill(im.pixels.begin(), im.pixels.end(), 0.0f);
  return im;
}

void Image::copy_metadata_from(const Image& other) {
  x = other.x;
  y = other.y;
  encoding = other.encoding;
  if (other.channels == channels) {
    channel_names = other.channel_names;
    alpha_channel = other.alpha_channel;
  }
}

}  // namespace splinefig
