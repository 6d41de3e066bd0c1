// Generated elements: dispatch, and their paths sampled (see generated.hpp).
#include "generated.hpp"

#include <cmath>
#include <type_traits>

namespace splinefig::figures::detail {

namespace {

// The element kinds that have a parts_of().
template <class T>
concept Generated = requires(const T& e) { parts_of(e); };

}  // namespace

bool is_generated(const PlotElement& e) {
  return std::visit([](const auto& x) { return Generated<std::decay_t<decltype(x)>>; }, e);
}

std::vector<GeneratedPart> generate(const PlotElement& e) {
  return std::visit(
      [](const auto& x) -> std::vector<GeneratedPart> {
        if constexpr (Generated<std::decay_t<decltype(x)>>) return parts_of(x);
        else return {};
      },
      e);
}

namespace {

Vec2 left_end(const Path& p, double t) { return p.before ? p.before(t) : p.at(t); }

void append_unique(std::vector<Vec2>& out, Vec2 q) {
  if (out.empty() || out.back().x != q.x || out.back().y != q.y) out.push_back(q);
}

}  // namespace

std::vector<Vec2> rough_points(const Path& p) {
  std::vector<Vec2> out;
  if (p.before && !p.breaks.empty()) out.push_back(p.before(p.breaks.front()));
  for (size_t i = 0; i + 1 < p.breaks.size(); ++i) {
    const double a = p.breaks[i], b = p.breaks[i + 1];
    for (int j = 0; j < 32; ++j) out.push_back(p.at(a + (b - a) * j / 32));
    out.push_back(left_end(p, b));
  }
  if (p.breaks.size() == 1 || (p.breaks.size() == 2 && p.breaks[0] == p.breaks[1])) out.push_back(p.at(p.breaks[0]));
  return out;
}

std::vector<Vec2> sample_path(const Path& p, const PixelMap& map, double tolerance) {
  std::vector<Vec2> out;
  // The limit from the left at the first break, when the path starts at a jump (the box's
  // left edge on its support), so the jump is drawn upright as at every other break.
  if (p.before && !p.breaks.empty()) {
    const Vec2 l = p.before(p.breaks.front()), r = p.at(p.breaks.front());
    const Vec2 pl = map(l), pr = map(r);
    if (std::hypot(pl.x - pr.x, pl.y - pr.y) > tolerance) out.push_back(l);
  }
  for (size_t i = 0; i + 1 < p.breaks.size(); ++i) {
    const double a = p.breaks[i], b = p.breaks[i + 1];
    append_unique(out, p.at(a));
    if (!(b > a)) continue;
    // The piece's right end is its limit from the left; a jump to the value there follows.
    auto pixel = [&](double t) { return map(t < b ? p.at(t) : left_end(p, b)); };
    for (double t : flat_parameters(pixel, a, b, tolerance, 3)) append_unique(out, t < b ? p.at(t) : left_end(p, b));
  }
  // The value at the last break itself, after its limit from the left (the box's right edge).
  if (!p.breaks.empty()) append_unique(out, p.at(p.breaks.back()));
  if (p.closed && out.size() > 1) out.back() = out.front();
  return out;
}

}  // namespace splinefig::figures::detail
