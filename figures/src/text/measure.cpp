// Labels measured as the painter sets them (see measure.hpp).
#include "measure.hpp"

#include "rich_text.hpp"

#include <mutex>

namespace splinefig::figures::detail {

render::TextStyle plain_style(double size, const Font& f, bool italic) {
  render::TextStyle t;
  t.size = size;
  t.color = f.color;
  t.weight = f.bold ? render::FontWeight::Bold : render::FontWeight::Normal;
  t.family = f.family.value_or(render::FontFamily::Sans);
  t.italic = italic;
  return t;
}

render::TextExtent measure_plain(const std::string& text, double size, const Font& f, bool italic) {
  static std::mutex mutex;
  static std::map<std::tuple<std::string, double, int, int>, render::TextExtent> cache;
  const int face = static_cast<int>(f.family.value_or(render::FontFamily::Sans)) * 4 + (f.bold ? 2 : 0) + (italic ? 1 : 0);
  auto key = std::make_tuple(text, size, face, 0);
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  render::TextExtent e = render::measure_text(text, plain_style(size, f, italic));
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() > 100000) cache.clear();
  cache[key] = e;
  return e;
}

Font TextMeasure::resolved(const Font& f) const {
  Font r = f;
  if (!r.family) r.family = family_;
  return r;
}

render::TextExtent TextMeasure::measure(const std::string& s, const Font& font) const {
  const Font f = resolved(font);
  auto key = std::make_tuple(s, f.size, f.bold, static_cast<int>(*f.family));
  if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  // Measured at 1x whatever the output scale, so that the layout (and every pixel box)
  // scales exactly; drawing aligns each label with its extent at the output size.
  RichText rt = set_text(s, f.size, [&](const std::string& t, double size, bool italic) { return measure_plain(t, size, f, italic); });
  render::TextExtent e{rt.width, rt.ascent, rt.descent};
  cache_[key] = e;
  return e;
}

}  // namespace splinefig::figures::detail
