// rasterize(): items become exact geometry (prepare.hpp), then the canvas is processed in
// horizontal bands of rows (on several threads, blocks of bands, each by one thread), every
// item composited in order with Porter-Duff over (compositor.hpp). A band's pixels depend only
// on the geometry and its own rows, never on which thread ran it or on the other bands, so any
// thread count gives identical bytes.
#include "box_coverage.hpp"
#include "filter_coverage.hpp"
#include "item_reach.hpp"
#include <splinefig/base/huge_pages.hpp>
#include "raster_item.hpp"
#include "piece_coverage.hpp"
#include "prepare.hpp"
#include "stroke.hpp"
#include "work_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "splinefig/base/parallel.hpp"

namespace splinefig::render {
namespace detail {
namespace {

constexpr int kBandRows = 16;

// Under a coverage tolerance above 0, a band of a solid stroke is resolved from the stroke's
// pieces when its outline's chains cross each other at least kPieceRatio times per chain meeting
// the band (the lower bound of work_estimate.hpp, found before sweeping), or when its sweep
// passes kStripRatio units per chain edge and span (StripSweep::set_strip_ratio: the crossings
// the bound cannot see, as at the turns of a dense zigzag). Measured on uniformly random
// polylines on 1024^2: 10^3 points (about 9 crossings per chain and band) sweep faster, 10^4
// (about 90) draw five times faster from their pieces.
// Only where the ink covers the band kMinCover times over on average: below that most pixels
// are neither solid nor empty, and resolving them from the pieces costs more than the sweep
// (a random walk of 10^5 steps, width 1, on 1024^2 covers it 0.8 times over: twice as slow).
constexpr double kPieceRatio = 32;
constexpr double kStripRatio = 64;
constexpr double kMinCover = 2;

// How a band of an item that may be drawn from its pieces is resolved. A stroke whose ink on the
// whole canvas (Shape::ink) is under half what one band needs is swept in every band without
// looking at its chains there: its winding is >= 0, so no band holds more than the whole, and
// the margin of half is far beyond the rounding of either sum (about 1e-8 of it even for a
// million vertices). So A1's and A3's 100,000 segments skip the test, and so does B's curve (about
// 15,300 px^2 of ink against the 16,384 of half a band of 1024 x 16 covered twice) where its
// outline is built whole (several threads); built band by band its ink is not known beforehand.
enum class BandPlan { Sweep, SweepOrPieces, Pieces };
BandPlan plan_band(const Geometry& g, const Shape& s, int b0, int b1, int width) {
  const double need = kMinCover * width * (b1 - b0);
  if (s.ink < 0.5 * need || !(winding_area(g, s, b0, b1) >= need)) return BandPlan::Sweep;
  std::size_t chains = 0;
  const double crossings = crossings_lower_bound(g, s, b0, b1, kBandRows, INFINITY, &chains);
  return crossings > kPieceRatio * static_cast<double>(chains) + static_cast<double>(StripSweep::kStripSlack)
             ? BandPlan::Pieces
             : BandPlan::SweepOrPieces;
}

// Whether the item may be resolved from its pieces in bands where its sweep costs too much.
bool piece_eligible(const DrawItem& it, const ClipRegion* clip, bool box, double tolerance) {
  const StrokeStyle* style = nullptr;
  if (const auto* st = std::get_if<StrokeItem>(&it)) style = &st->style;
  if (const auto* ps = std::get_if<PathStrokeItem>(&it)) style = &ps->style;
  return box && tolerance > 0 && !clip && style && style->dashes.empty();
}

// An item's pieces (piece_coverage.hpp), built when one of its bands first needs them, by
// whichever thread gets there first: they depend only on the item. Null if the stroke has a
// part that is a single point (its dot is not a piece).
class LazyPieces {
 public:
  const PieceCoverage* get(const DrawItem& it, int width, int height) {
    std::call_once(once_, [&] {
      ConvexPieces cp;
      const Box clip{0, 0, static_cast<double>(width), static_cast<double>(height)};
      bool ok = true;
      if (const auto* st = std::get_if<StrokeItem>(&it)) {
        ok = stroke_pieces(st->points, st->closed, st->style, clip, cp);
      } else {
        const auto& ps = std::get<PathStrokeItem>(it);
        const Path::Flat flat = ps.path->flatten(kArcTolerance);
        for (std::size_t i = 0; i < flat.contours.size() && ok; ++i)
          ok = stroke_pieces(flat.contours[i], flat.closed[i], ps.style, clip, cp);
      }
      if (ok) cov_ = std::make_unique<PieceCoverage>(std::move(cp), width, height, kBandRows);
    });
    return cov_.get();
  }

 private:
  std::once_flag once_;
  std::unique_ptr<PieceCoverage> cov_;
};

// What drawing an item's rows cost (in StripSweep::work() units) and how.
struct BandWork {
  std::uint64_t work = 0;
  bool over = false;    // past the budget: the rows are incomplete, the item is refused
  int piece_bands = 0;  // bands resolved from the pieces
};

// The item's rows in [r0, r1), one band of kBandRows rows at a time: the band is one strip of
// the scan converter (its union resolved once for all its rows), then each row is summed and
// composited. Strips are aligned to multiples of their height whatever r0 is, so a row's
// coverage is the same for any thread count. With `pieces`, a dense band (kPieceRatio, before
// sweeping, or kStripRatio, while sweeping: then the band is cleared first) is drawn from the
// pieces instead, and the sweep restarts below it: the verdict depends on the band alone, so
// the bytes do not depend on the threads. With `stream`, the item's outline is built band by band
// (outline_stream.hpp) into g and p's shape.
BandWork render_box(const Geometry& g, const Prepared& p, const DrawItem& item, LazyPieces* pieces, Image& img,
                    int r0, int r1, BoxBand& band, StripSweep& sweep, PieceCoverage::Scratch& ps, std::uint64_t budget,
                    OutlineStream* stream = nullptr) {
  BandWork out;
  std::uint64_t base = 0;  // work before the sweep's last restart
  auto restart = [&] {
    sweep.reset(g, p.shape);
    sweep.set_budget(budget - std::min(budget, base));
  };
  restart();
  const int y_begin = std::max(r0, p.row0), y_end = std::min(r1, p.row1);
  for (int b0 = y_begin - y_begin % kBandRows; b0 < y_end; b0 += kBandRows) {
    const int b1 = std::min(b0 + kBandRows, img.height);
    band.begin(b0, b1 - b0);
    if (stream) stream->advance(static_cast<double>(b0), static_cast<double>(b1));
    const BandPlan plan = pieces ? plan_band(g, p.shape, b0, b1, img.width) : BandPlan::Sweep;
    const bool dense = plan == BandPlan::Pieces;
    sweep.set_strip_ratio(plan == BandPlan::SweepOrPieces ? kStripRatio : 0);
    bool more = dense || sweep.strip(static_cast<double>(b0), static_cast<double>(b1), band);
    if (dense || sweep.over()) {
      base += sweep.work();
      const bool strip_over = dense || sweep.strip_over();
      if (!strip_over) {  // stopped at the work limit: the item is refused
        out.work = base;
        out.over = true;
        return out;
      }
      band.clear();
      const PieceCoverage* pc = pieces->get(item, img.width, img.height);
      restart();
      if (pc) {
        base += pc->draw(b0 / kBandRows, b0, b1, band, ps, budget - std::min(budget, base));
        ++out.piece_bands;
        more = true;
        restart();
      } else {
        more = sweep.strip(static_cast<double>(b0), static_cast<double>(b1), band);
      }
      if (base > budget || sweep.over()) {
        out.work = base + sweep.work();
        out.over = true;
        return out;
      }
    }
    // The canvas (16 bytes a pixel) rarely stays in cache across thousands of small items: ask
    // for every pixel the band's rows composite before compositing any, so that their cache
    // misses overlap instead of coming one or two rows at a time.
    for (int y = std::max(b0, y_begin); y < std::min(b1, y_end); ++y) {
      const BoxRow& row = band.row(y);
      if (row.cmax < row.cmin) continue;
      const float* first = img.pixel(row.cmin, y);
      const float* last = img.pixel(std::min(row.cmax + 1, img.width - 1), y);
      for (const float* q = first; q < last; q += 16) __builtin_prefetch(q, 1);  // 64-byte lines
      __builtin_prefetch(last, 1);
    }
    for (int y = b0; y < b1; ++y) {
      BoxRow& row = band.row(y);
      if (row.cmax < row.cmin) continue;
      if (y < y_begin || y >= y_end) {  // nothing is drawn there; keep the accumulator zero
        std::fill(row.acc.begin(), row.acc.end(), 0.0);
        continue;
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
    if (!more && !(stream && stream->pending())) break;
  }
  out.work = base + sweep.work();
  return out;
}

const char* kind_name(const DrawItem& item) {
  // In the order of DrawItem's alternatives.
  static constexpr const char* names[] = {"stroked polyline", "filled polygon", "filled path", "stroked path", "disk",
                                          "stroked circle",   "marker",         "text",        "image"};
  static_assert(std::size(names) == std::variant_size_v<DrawItem>);
  return names[item.index()];
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
[[noreturn]] void refuse_sweep(const DrawItem& item, std::size_t index, double limit) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "item %zu (%s): its exact union was stopped at the work limit of the sweep, %.3g events "
                "(crossings and turns of its outline, about 0.2 to 2 us each)",
                index + 1, kind_name(item), limit);
  throw std::length_error(buf);
}

[[noreturn]] void refuse_work(const DrawItem& item, std::size_t index, double crossings, double limit) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "item %zu (%s): its outline crosses itself at least %.3g times on the canvas; the exact union is "
                "refused past %.3g crossings (work limit of the sweep, about 0.2 us each)",
                index + 1, kind_name(item), crossings, limit);
  throw std::length_error(buf);
}

}  // namespace
}  // namespace detail

Image rasterize(const Scene& scene, int threads, RasterReport* report) {
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
  const double tolerance = scene.tolerance_;
  auto eligible = [&](std::size_t i) { return piece_eligible(scene.items()[i], scene.clip_of(i), box, tolerance); };
  std::vector<int> piece_bands(report ? scene.items().size() : 0, 0), item_bands(piece_bands.size(), 0);
  auto note_bands = [&](std::size_t i, const Prepared& p, int pieces) {
    if (!report || pieces == 0) return;
    piece_bands[i] = pieces;
    item_bands[i] = (p.row1 - 1) / kBandRows - p.row0 / kBandRows + 1;
  };
  auto finish = [&] {
    if (!report) return;
    *report = RasterReport{};
    report->tolerance = tolerance;
    report->band_rows = kBandRows;
    for (std::size_t i = 0; i < piece_bands.size(); ++i) {
      if (piece_bands[i] > 0) report->items.push_back({i, item_bands[i], piece_bands[i]});
    }
  };
  const std::uint64_t budget = work_budget(scene.max_crossings_);
  FilterGrid grid = box ? FilterGrid{} : make_filter_grid(scene.filter_, W, H);
  Box clip = box ? Box{0, 0, static_cast<double>(W), static_cast<double>(H)} : grid.clip;
  Vec2 shift = box ? Vec2{0, 0} : Vec2{grid.delta, grid.delta};

  Geometry geom;
  const auto& items = scene.items();
  auto prepare = [&](std::size_t i, Prepared& p, Geometry& into, int item_threads) {
    prepare_item(items[i], scene.clip_of(i), comp, shift, clip, into, p, H, item_threads);
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
    PieceCoverage::Scratch ps;
    Prepared p;
    for (std::size_t i = 0; i < items.size(); ++i) {
      geom.verts.clear();
      geom.chains.clear();
      p = Prepared{};
      // A long stroke's outline is built as its bands come and given back behind them.
      OutlineStream stream;
      const bool streamed = box && eligible(i) && prepare_streamed(items[i], comp, clip, geom, p, H, stream);
      if (!streamed) prepare(i, p, geom, 1);
      if (p.row1 <= p.row0) continue;
      if (!eligible(i))
        if (const double n = excess_crossings(geom, p, scene.max_crossings_)) refuse_work(items[i], i, n, scene.max_crossings_);
      if (p.raster) {
        composite_raster(*p.raster, comp, img, 0, H);
        continue;
      }
      if (box) {
        LazyPieces pieces;
        const BandWork w = render_box(geom, p, items[i], eligible(i) ? &pieces : nullptr, img, p.row0, p.row1, band,
                                      sweep, ps, budget, streamed ? &stream : nullptr);
        if (w.over) refuse_sweep(items[i], i, scene.max_crossings_);
        if (streamed && w.piece_bands > 0) {  // the rows prepare_item gives, for the report
          p.row0 = std::max(0, static_cast<int>(std::floor(stream.chains_ymin())));
          p.row1 = std::min(H, static_cast<int>(std::ceil(stream.chains_ymax())));
        }
        note_bands(i, p, w.piece_bands);
        continue;
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
    finish();
    return img;
  }

  // Several threads: the canvas is cut into blocks of whole bands, each block drawn by one
  // thread with every item meeting it, in item order. An item whose rows lie within two
  // neighbouring blocks (item_reach.hpp, known before its geometry is built) is local: the
  // thread of each block it meets prepares it, draws the block's rows and drops it, as one
  // thread does, so its geometry stays in cache and memory holds one such item per thread (one
  // in a few small items is prepared twice, which costs less than keeping them all). The other
  // items (long strokes, and every item under a filter other than the box) are shared: prepared
  // first, by all threads, and drawn in each block they meet. A row's coverage is the same
  // whichever block, thread or preparation gives it (strips are aligned to the bands), so the
  // bytes do not depend on the thread count.
  const std::size_t n = items.size();
  std::vector<int> lo_row(n, 0), hi_row(n, H);  // conservative rows [lo, hi) of each item
  if (box)
    for (std::size_t i = 0; i < n; ++i) {
      double y0, y1;
      if (!item_y_range(items[i], y0, y1)) continue;
      lo_row[i] = static_cast<int>(std::clamp(std::floor(y0), 0.0, static_cast<double>(H)));
      hi_row[i] = static_cast<int>(std::clamp(std::ceil(y1), 0.0, static_cast<double>(H)));
    }
  // Blocks of whole bands, handed out in order to whichever thread is free, in decreasing sizes
  // (guided scheduling): each a (2 x threads)-th of the bands left, down to one band, so that
  // the first blocks are large (few local items are met by two) and the last ones small (the
  // threads finish together). 1024 rows on 2 threads: 16, 12, 9, 7, 5, 4, 3, 2, 2, 1, 1, 1, 1
  // bands.
  std::vector<int> block_row0;         // each block's first row; the last entry is H
  std::vector<std::uint32_t> block_of;  // each band's block
  for (int b = 0; b < bands;) {
    const int size = std::max(1, (bands - b + 2 * nthreads - 1) / (2 * nthreads));
    block_row0.push_back(b * kBandRows);
    block_of.insert(block_of.end(), static_cast<std::size_t>(size), static_cast<std::uint32_t>(block_row0.size() - 1));
    b += size;
  }
  block_row0.push_back(H);
  block_of.resize(static_cast<std::size_t>(bands));
  const std::size_t blocks = block_row0.size() - 1;
  auto first_block = [&](int row) { return block_of[static_cast<std::size_t>(row / kBandRows)]; };
  auto last_block = [&](int row_end) { return block_of[static_cast<std::size_t>((row_end - 1) / kBandRows)]; };
  // Local items met by two blocks count their work and the bands drawn from their pieces in a
  // slot shared by the two blocks' threads, numbered after the shared items' below.
  constexpr std::uint32_t kNoSlot = Prepared::kNoWorkSlot;
  std::vector<std::uint8_t> local(n, 0);
  std::vector<std::uint32_t> local_slot(n, kNoSlot);
  std::uint32_t local_slots = 0;
  std::vector<std::uint32_t> shared;  // the shared items, in order
  for (std::size_t i = 0; i < n; ++i) {
    if (hi_row[i] <= lo_row[i]) continue;  // nothing on the canvas
    const std::uint32_t k = last_block(hi_row[i]) - first_block(lo_row[i]) + 1;
    if (box && k <= 2) {
      local[i] = 1;
      if (k == 2) local_slot[i] = local_slots++;
    } else {
      shared.push_back(static_cast<std::uint32_t>(i));
    }
  }

  // Shared items are prepared in runs of consecutive ones, each run into a geometry of its own. An
  // item's chains and vertices are the same in any run (they are appended in order and only
  // their relative order matters), so the bytes do not depend on how items fall into runs. A long
  // stroke's outline is built in pieces by its preparer and helper threads it starts
  // (prepare.hpp); while other runs are being prepared too, the threads outnumber the cores for
  // that while, which costs a little time and no bytes.
  std::vector<Prepared> prep;
  reserve_huge(prep, shared.size());
  prep.resize(shared.size());
  const std::size_t runs = std::min<std::size_t>(shared.size(), static_cast<std::size_t>(nthreads) * 8);
  std::vector<Geometry> geoms(runs);
  std::vector<std::uint32_t> run_of(shared.size());
  std::vector<double> excess(n, 0.0);  // crossings past the limit, found before sweeping
  {
    auto run_begin = [&](std::size_t r) { return r * shared.size() / runs; };
    for (std::size_t r = 0; r < runs; ++r)
      for (std::size_t k = run_begin(r); k < run_begin(r + 1); ++k) run_of[k] = static_cast<std::uint32_t>(r);
    parallel_for(runs, nthreads, [&](std::size_t r, int) {
      for (std::size_t k = run_begin(r); k < run_begin(r + 1); ++k) {
        const std::size_t i = shared[k];
        prepare(i, prep[k], geoms[r], nthreads);
        if (prep[k].row1 > prep[k].row0 && !eligible(i)) excess[i] = excess_crossings(geoms[r], prep[k], scene.max_crossings_);
      }
    });
  }
  // Each shared item's sweep work over all blocks, against the one limit: an item is refused
  // exactly when its total passes the limit, whichever blocks and threads counted it (a block
  // stops once the total, with its own share, passes it; the totals of items drawn in full do
  // not depend on the order). A local item is counted by its block, or by its two blocks in its
  // slot in the same way. The first refused item is the one named: once an item is refused, later items are
  // skipped, earlier ones still drawn in full, so the lowest index left is the first item over
  // the limit on any thread count.
  std::uint32_t slots = 0;
  for (Prepared& p : prep)
    if (!p.raster && !p.shape.simple && !p.shape.empty() && p.row1 > p.row0) p.work_slot = slots++;
  for (std::uint32_t& slot : local_slot)
    if (slot != kNoSlot) slot += slots;
  slots += local_slots;
  std::vector<std::atomic<std::uint64_t>> spent(slots);
  std::vector<std::atomic<int>> slot_piece_bands(slots);
  std::vector<LazyPieces> lazy(slots);
  std::atomic<std::size_t> first_over{n};
  auto note_over = [&](std::size_t i) {
    std::size_t cur = first_over.load();
    while (i < cur && !first_over.compare_exchange_weak(cur, i)) {}
  };
  for (std::size_t k = 0; k < shared.size(); ++k)
    if (excess[shared[k]] > 0) note_over(shared[k]);
  // Which items meet which block, in item order: (item, shared index or kLocal).
  constexpr std::uint32_t kLocal = ~std::uint32_t{0};
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> block_items(blocks);
  for (std::size_t i = 0, k = 0; i < n; ++i) {
    if (local[i]) {
      for (std::uint32_t b = first_block(lo_row[i]); b <= last_block(hi_row[i]); ++b)
        block_items[b].emplace_back(static_cast<std::uint32_t>(i), kLocal);
      continue;
    }
    if (k == shared.size() || shared[k] != i) continue;
    const Prepared& p = prep[k];
    if (p.row1 > p.row0)
      for (std::uint32_t b = first_block(p.row0); b <= last_block(p.row1); ++b)
        block_items[b].emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k));
    ++k;
  }

  // Each thread keeps its scratch (a band's accumulators, the sweep's and the filter's state,
  // a local item's geometry) across the blocks it draws; a block is drawn the same whichever
  // thread draws it.
  struct Scratch {
    BoxBand band;
    FilterScratch fs;
    StripSweep sweep;
    PieceCoverage::Scratch ps;
    Geometry geom;
    Prepared p;
  };
  // Draws rows [r0, r1) of item i under the box filter. Its work counts against the limit in
  // `slot` with the other blocks that draw it (kNoSlot: this block draws all of it, and the work
  // is its own), where the bands drawn from its pieces are added too; `from_pieces` is this
  // block's. False, with the item noted, once it is over the limit.
  auto draw_box = [&](std::size_t i, const Geometry& g, const Prepared& p, LazyPieces* pieces, Scratch& sc, int r0, int r1,
                      std::uint32_t slot, int& from_pieces) {
    std::atomic<std::uint64_t>* total = slot == kNoSlot ? nullptr : &spent[slot];
    const std::uint64_t used = total ? total->load() : 0;
    if (used <= budget) {
      const BandWork w = render_box(g, p, items[i], pieces, img, r0, r1, sc.band, sc.sweep, sc.ps, budget - used);
      from_pieces = w.piece_bands;
      if (total && w.piece_bands) slot_piece_bands[slot] += w.piece_bands;
      if (!w.over && !(total && total->fetch_add(w.work) + w.work > budget)) return true;
    }
    note_over(i);
    return false;
  };
  std::vector<std::unique_ptr<Scratch>> scratch(static_cast<std::size_t>(nthreads));
  parallel_for(blocks, nthreads, [&](std::size_t b, int worker) {
    auto& s = scratch[static_cast<std::size_t>(worker)];
    if (!s) {
      s = std::make_unique<Scratch>();
      s->band.reset(W, kBandRows);
    }
    const int r0 = block_row0[b], r1 = block_row0[b + 1];
    clear_rows(r0, r1);  // by the block's thread, like everything else in its rows
    for (auto [i, k] : block_items[b]) {
      if (i >= first_over.load(std::memory_order_relaxed)) break;
      if (k == kLocal) {
        Prepared& p = s->p;
        s->geom.verts.clear();
        s->geom.chains.clear();
        p = Prepared{};
        prepare(i, p, s->geom, 1);
        if (p.row1 <= p.row0 || p.row1 <= r0 || p.row0 >= r1) continue;
        if (p.row0 < lo_row[i] || p.row1 > hi_row[i]) throw std::logic_error("an item reaching beyond the rows found for it");
        if (!eligible(i))
          if (const double e = excess_crossings(s->geom, p, scene.max_crossings_)) {
            std::atomic_ref<double>(excess[i]).store(e, std::memory_order_relaxed);  // the same from either block
            note_over(i);
            break;
          }
        if (p.raster) {
          composite_raster(*p.raster, comp, img, r0, r1);
          continue;
        }
        LazyPieces pieces;
        int from_pieces = 0;
        if (!draw_box(i, s->geom, p, eligible(i) ? &pieces : nullptr, *s, r0, r1, local_slot[i], from_pieces)) break;
        if (local_slot[i] == kNoSlot) note_bands(i, p, from_pieces);
        else if (report && p.row0 >= r0) item_bands[i] = (p.row1 - 1) / kBandRows - p.row0 / kBandRows + 1;  // one block
        continue;
      }
      const Prepared& p = prep[k];
      const Geometry& g = geoms[run_of[k]];
      if (p.raster) {
        composite_raster(*p.raster, comp, img, r0, r1);
        continue;
      }
      if (box) {
        int from_pieces = 0;
        LazyPieces* pieces = p.work_slot != kNoSlot && eligible(i) ? &lazy[p.work_slot] : nullptr;
        if (!draw_box(i, g, p, pieces, *s, r0, r1, p.work_slot, from_pieces)) break;
        continue;
      }
      std::atomic<std::uint64_t>* total = p.work_slot == kNoSlot ? nullptr : &spent[p.work_slot];
      const std::uint64_t used = total ? total->load() : 0;
      if (used > budget) {
        note_over(i);
        break;
      }
      bool over = false;
      std::uint64_t work = 0;
      for (int y = r0; y < r1 && !over; y += kBandRows) {  // band by band, as one thread
        s->sweep.set_budget(budget - used - std::min(budget - used, work));
        render_filtered(g, p, grid, img, y, std::min(r1, y + kBandRows), s->fs, s->sweep);
        over = s->sweep.over();
        work += s->sweep.work();
      }
      if (total && (over || total->fetch_add(work) + work > budget)) {
        note_over(i);
        break;
      }
    }
  });
  if (const std::size_t i = first_over.load(); i < n) {
    if (excess[i] > 0) refuse_work(items[i], i, excess[i], scene.max_crossings_);
    refuse_sweep(items[i], i, scene.max_crossings_);
  }
  if (report) {
    for (std::size_t i = 0; i < n; ++i)
      if (local_slot[i] != kNoSlot) piece_bands[i] = slot_piece_bands[local_slot[i]].load();
    for (std::size_t k = 0; k < shared.size(); ++k)
      if (prep[k].work_slot != kNoSlot) note_bands(shared[k], prep[k], slot_piece_bands[prep[k].work_slot].load());
  }
  finish();
  return img;
}

}  // namespace splinefig::render
