// rasterize(): items become exact geometry (prepare.hpp), then the canvas is processed in
// horizontal bands of rows, each band by one thread, every item composited in order with
// Porter-Duff over (compositor.hpp). A band's pixels depend only on the geometry and its own rows, never on
// which thread ran it or on the other bands, so any thread count gives identical bytes.
#include "box_coverage.hpp"
#include "filter_coverage.hpp"
#include <splinefig/base/huge_pages.hpp>
#include "raster_item.hpp"
#include "prepare.hpp"
#include "work_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "splinefig/base/parallel.hpp"

namespace splinefig::render {
namespace detail {
namespace {

constexpr int kBandRows = 16;

// The item's rows in [r0, r1), one band of kBandRows rows at a time: the band is one strip of
// the scan converter (its union resolved once for all its rows), then each row is summed and
// composited. Strips are aligned to multiples of their height whatever r0 is, so a row's
// coverage is the same for any thread count.
void render_box(const Geometry& g, const Prepared& p, Image& img, int r0, int r1, BoxBand& band, StripSweep& sweep) {
  sweep.reset(g, p.shape);
  const int y_begin = std::max(r0, p.row0), y_end = std::min(r1, p.row1);
  for (int b0 = y_begin - y_begin % kBandRows; b0 < y_end; b0 += kBandRows) {
    const int b1 = std::min(b0 + kBandRows, img.height);
    band.begin(b0, b1 - b0);
    const bool more = sweep.strip(static_cast<double>(b0), static_cast<double>(b1), band);
    if (sweep.over()) return;  // stopped at the work limit: the item is refused
    for (int y = b0; y < b1; ++y) {
      BoxRow& row = band.row(y);
      if (row.cmax < row.cmin) continue;
      if (y < y_begin || y >= y_end) {  // nothing is drawn there; keep the accumulator zero
        std::fill(row.acc.begin(), row.acc.end(), 0.0);
        continue;
      }
      // The canvas (16 bytes a pixel) rarely stays in cache across thousands of small items:
      // ask for the pixels two rows ahead, whose columns are close to this row's.
      if (y + 2 < y_end) {
        const int x0 = std::max(0, row.cmin - 4), x1 = std::min(img.width - 1, row.cmax + 5);
        for (int x = x0; x <= x1; x += 4) __builtin_prefetch(img.pixel(x, y + 2), 1);
        __builtin_prefetch(img.pixel(x1, y + 2), 1);
      }
      double cov = 0;
      const int xe = std::min(row.cmax + 1, img.width - 1);
      float* px = img.pixel(0, y);
      for (int x = row.cmin; x <= xe; ++x) {
        cov += row.acc[static_cast<std::size_t>(x)];
        row.acc[static_cast<std::size_t>(x)] = 0;
        const double c = cov;
        if (c > 1e-9) over(px + 4 * static_cast<std::size_t>(x), p.paint, static_cast<float>(std::min(c, 1.0)));
      }
      for (int x = xe + 1; x <= std::min(row.cmax + 1, img.width + 1); ++x) row.acc[static_cast<std::size_t>(x)] = 0;
    }
    if (!more) break;
  }
}

const char* kind_name(Scene::Item::Kind k) {
  using K = Scene::Item::Kind;
  switch (k) {
    case K::Stroke: return "stroked polyline";
    case K::Fill: return "filled polygon";
    case K::Disk: return "disk";
    case K::Ring: return "stroked circle";
    case K::Marker: return "marker";
    case K::Text: return "text";
    case K::Image: return "image";
    case K::PathFill: return "filled path";
    case K::PathStroke: return "stroked path";
  }
  return "item";
}

// How far the exact sweep of the item's shape would go past `limit` crossings: a lower bound on
// its crossings once it reaches the limit (work_estimate.hpp), else 0. A shape of E edges has at
// most E (E - 1) / 2 crossings, so only large shapes are looked at.
double excess_crossings(const Geometry& g, const Prepared& p, double limit) {
  if (p.raster || p.shape.simple || p.shape.empty()) return 0;
  double edges = 0;
  for (std::size_t c = p.shape.chain_begin; c < p.shape.chain_end; ++c)
    edges += static_cast<double>(g.chains[c].last - g.chains[c].first);
  if (edges * (edges - 1) / 2 < limit) return 0;
  const int y0 = static_cast<int>(std::floor(p.shape.ymin)), y1 = static_cast<int>(std::ceil(p.shape.ymax));
  const double found = crossings_lower_bound(g, p.shape, y0, y1, kBandRows, limit);
  return found >= limit ? found : 0;
}

// The work limit as the sweep's budget in units (StripSweep::work()).
std::uint64_t work_budget(double limit) {
  return limit >= 0x1p63 ? ~std::uint64_t{0} : static_cast<std::uint64_t>(limit);
}

// An item whose sweep went past the limit although the bound before it did not reach it: its
// chains cross mostly where they begin or end (the bound counts only chains through a whole
// band), as at the turns of a dense zigzag.
[[noreturn]] void refuse_sweep(const Scene::Item& item, std::size_t index, double limit) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "item %zu (%s): its exact union was stopped at the work limit of the sweep, %.3g events "
                "(crossings and turns of its outline, about 0.2 to 2 us each)",
                index + 1, kind_name(item.kind), limit);
  throw std::length_error(buf);
}

[[noreturn]] void refuse_work(const Scene::Item& item, std::size_t index, double crossings, double limit) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "item %zu (%s): its outline crosses itself at least %.3g times on the canvas; the exact union is "
                "refused past %.3g crossings (work limit of the sweep, about 0.2 us each)",
                index + 1, kind_name(item.kind), crossings, limit);
  throw std::length_error(buf);
}

}  // namespace
}  // namespace detail

Image rasterize(const Scene& scene, int threads) {
  using namespace detail;
  const int W = scene.width(), H = scene.height();
  const Compositor comp(scene.blend_);
  Image img(0, 0, 4);  // RGBA; the pixels get huge-page advice before they are first written
  img.width = W;
  img.height = H;
  img.encoding = comp.encoding();
  reserve_huge(img.pixels, static_cast<std::size_t>(W) * H * 4);
  img.pixels.resize(static_cast<std::size_t>(W) * H * 4);
  const Paint bg = comp.paint(scene.background_);
  auto clear_rows = [&](int r0, int r1) {  // to the background
    const std::size_t end = static_cast<std::size_t>(r1) * W * 4;
    for (std::size_t i = static_cast<std::size_t>(r0) * W * 4; i < end; i += 4) std::copy_n(bg.v, 4, &img.pixels[i]);
  };

  const bool box = exact_area(scene.filter_);
  const std::uint64_t budget = work_budget(scene.max_crossings_);
  FilterGrid grid = box ? FilterGrid{} : make_filter_grid(scene.filter_, W, H);
  Box clip = box ? Box{0, 0, static_cast<double>(W), static_cast<double>(H)} : grid.clip;
  Vec2 shift = box ? Vec2{0, 0} : Vec2{grid.delta, grid.delta};

  Geometry geom;
  const auto& items = scene.items();
  auto prepare = [&](std::size_t i, Prepared& p, Geometry& into, int item_threads) {
    prepare_item(items[i], comp, shift, clip, into, p, H, item_threads);
    if (p.raster || p.shape.empty()) return;
    if (box) {
      p.row0 = std::max(0, static_cast<int>(std::floor(p.shape.ymin)));
      p.row1 = std::min(H, static_cast<int>(std::ceil(p.shape.ymax)));
    } else {
      grid.rows_of(p.shape, p.row0, p.row1);
    }
  };
  const int bands = (H + kBandRows - 1) / kBandRows;
  const int nthreads = std::min(worker_count(threads), bands);

  if (nthreads <= 1) {
    // One thread: each item is built, drawn and dropped in turn, so its geometry is still in
    // cache and memory holds one item at a time. Every row is computed exactly as in the band
    // schedule below (a strip's result does not depend on where its band starts, and filtered
    // items are drawn band by band with the same band boundaries): identical bytes.
    clear_rows(0, H);
    BoxBand band;
    band.reset(W, kBandRows);
    FilterScratch fs;
    StripSweep sweep;
    Prepared p;
    for (std::size_t i = 0; i < items.size(); ++i) {
      geom.verts.clear();
      geom.chains.clear();
      p = Prepared{};
      prepare(i, p, geom, 1);
      if (p.row1 <= p.row0) continue;
      if (const double n = excess_crossings(geom, p, scene.max_crossings_)) refuse_work(items[i], i, n, scene.max_crossings_);
      if (p.raster) {
        composite_raster(*p.raster, comp, img, 0, H);
        continue;
      }
      if (box) {
        sweep.set_budget(budget);
        render_box(geom, p, img, p.row0, p.row1, band, sweep);
      } else {
        std::uint64_t spent = 0;
        for (int b = p.row0 / kBandRows; b <= (p.row1 - 1) / kBandRows && !sweep.over(); ++b) {
          sweep.set_budget(budget - spent);
          render_filtered(geom, p, grid, img, b * kBandRows, std::min(H, (b + 1) * kBandRows), fs, sweep);
          spent += std::min(sweep.work(), budget - spent);
        }
      }
      if (sweep.over()) refuse_sweep(items[i], i, scene.max_crossings_);
    }
    return img;
  }

  // Items are prepared by the threads too: in runs of consecutive items, each run into a
  // geometry of its own. An item's chains and vertices are the same in any run (they are
  // appended in order and only their relative order matters), so the bytes do not depend on
  // how items fall into runs. A long stroke's outline is built in pieces by its preparer and
  // helper threads it starts (prepare.hpp); while other runs are being prepared too, the
  // threads outnumber the cores for that while, which costs a little time and no bytes.
  std::vector<Prepared> prep;
  reserve_huge(prep, items.size());
  prep.resize(items.size());
  const std::size_t runs = std::min<std::size_t>(items.size(), static_cast<std::size_t>(nthreads) * 8);
  std::vector<Geometry> geoms(runs);
  std::vector<std::uint32_t> run_of(items.size());
  {
    auto run_begin = [&](std::size_t r) { return r * items.size() / runs; };
    for (std::size_t r = 0; r < runs; ++r)
      for (std::size_t i = run_begin(r); i < run_begin(r + 1); ++i) run_of[i] = static_cast<std::uint32_t>(r);
    std::vector<double> excess(items.size(), 0.0);
    parallel_for(runs, nthreads, [&](std::size_t r, int) {
      for (std::size_t i = run_begin(r); i < run_begin(r + 1); ++i) {
        prepare(i, prep[i], geoms[r], nthreads);
        if (prep[i].row1 > prep[i].row0) excess[i] = excess_crossings(geoms[r], prep[i], scene.max_crossings_);
      }
    });
    // The first item over the limit, whichever thread found it: the same message on any count.
    for (std::size_t i = 0; i < items.size(); ++i)
      if (excess[i] > 0) refuse_work(items[i], i, excess[i], scene.max_crossings_);
  }
  // Each swept item's work over all bands, against the one limit: an item is refused exactly
  // when its total passes the limit, whichever bands and threads counted it (a band stops once
  // the total, with its own share, passes it; the totals of items drawn in full do not depend
  // on the order). The first refused item is the one named: once an item is refused, later
  // items are skipped, earlier ones still drawn in full, so the lowest index left is the first
  // item over the limit on any thread count.
  std::uint32_t slots = 0;
  for (Prepared& p : prep)
    if (!p.raster && !p.shape.simple && !p.shape.empty() && p.row1 > p.row0) p.work_slot = slots++;
  std::vector<std::atomic<std::uint64_t>> spent(slots);
  std::atomic<std::size_t> first_over{items.size()};
  auto note_over = [&](std::size_t i) {
    std::size_t cur = first_over.load();
    while (i < cur && !first_over.compare_exchange_weak(cur, i)) {}
  };
  // Which items touch which band, in item order.
  std::vector<std::vector<std::uint32_t>> band_items(static_cast<std::size_t>(bands));
  for (std::uint32_t i = 0; i < prep.size(); ++i) {
    if (prep[i].row1 <= prep[i].row0) continue;
    for (int b = prep[i].row0 / kBandRows; b <= (prep[i].row1 - 1) / kBandRows; ++b)
      band_items[static_cast<std::size_t>(b)].push_back(i);
  }

  // Each thread keeps its scratch (a band's accumulators, the sweep's and the filter's state)
  // across the bands it draws; a band is drawn the same whichever thread draws it.
  struct Scratch {
    BoxBand band;
    FilterScratch fs;
    StripSweep sweep;
  };
  std::vector<std::unique_ptr<Scratch>> scratch(static_cast<std::size_t>(nthreads));
  parallel_for(static_cast<std::size_t>(bands), nthreads, [&](std::size_t b, int worker) {
    auto& s = scratch[static_cast<std::size_t>(worker)];
    if (!s) {
      s = std::make_unique<Scratch>();
      s->band.reset(W, kBandRows);
    }
    const int r0 = static_cast<int>(b) * kBandRows, r1 = std::min(H, r0 + kBandRows);
    clear_rows(r0, r1);  // by the band's thread, like everything else in its rows
    for (std::uint32_t i : band_items[b]) {
      if (i >= first_over.load(std::memory_order_relaxed)) break;
      const Prepared& p = prep[i];
      const Geometry& g = geoms[run_of[i]];
      if (p.raster) {
        composite_raster(*p.raster, comp, img, r0, r1);
        continue;
      }
      std::atomic<std::uint64_t>* total = p.work_slot == Prepared::kNoWorkSlot ? nullptr : &spent[p.work_slot];
      const std::uint64_t used = total ? total->load() : 0;
      if (used > budget) {
        note_over(i);
        break;
      }
      s->sweep.set_budget(budget - used);
      if (box) render_box(g, p, img, r0, r1, s->band, s->sweep);
      else render_filtered(g, p, grid, img, r0, r1, s->fs, s->sweep);
      if (total && (s->sweep.over() || total->fetch_add(s->sweep.work()) + s->sweep.work() > budget)) {
        note_over(i);
        break;
      }
    }
  });
  if (first_over.load() < items.size()) refuse_sweep(items[first_over.load()], first_over.load(), scene.max_crossings_);
  return img;
}

}  // namespace splinefig::render
