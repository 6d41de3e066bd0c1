#pragma once
// The built-in figures (figures/specs/*.toml) and what `splinefig figures` writes besides
// the images: index.json (docs/figures.md) and the gallery page index.html.
#include <splinefig/figures/figure.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig::figures {

// The directory of the built-in specs: $SPLINEFIG_SPECS_DIR if set, else share/splinefig/specs
// next to the executable (../share/splinefig/specs: an installed or relocated tree), else for a
// program of the build tree the source tree's figures/specs, else the install prefix's. Empty if
// none exists.
std::string builtin_specs_dir();

// Spec files of a directory (*.toml), sorted by their `order` key then by name.
struct SpecFile {
  std::string name;  // file stem: the --only name and output file stem
  std::string path;
};
std::vector<SpecFile> list_specs(const std::string& dir);

// index.json: {"figures": [{"name", "title", "caption", "files", "width", "height",
// "axes": [{"pixel_box", "x_range", "y_range", "x_scale", "y_scale", "series": [{"label",
// "color", "kind"}]}]}]}.
std::string index_json(const std::vector<FigureInfo>& figures);
// Reads index_json()'s output back. Throws std::runtime_error ("index.json: what, where")
// if the text is not such an index.
std::vector<FigureInfo> read_index_json(const std::string& text);
// The index.json of the directory `dir` as a previous run left it; none if there is none. One
// that is not a regular file (a FIFO, a device, a directory: never waited for), has over
// kMaxIndexBytes or is not such an index is not used: `warn` gets one line saying why.
inline constexpr std::size_t kMaxIndexBytes = std::size_t(1) << 26;  // 64 MiB
std::vector<FigureInfo> read_index_file(const std::string& dir, const std::function<void(const std::string&)>& warn);
// A name merge_index accepts for a file of an entry: one file of the directory itself (no '/',
// '\\', ".", "..", control characters).
bool plain_file_name(std::string_view name);
// The index of a directory after some of its figures were rendered again: `rendered`, plus
// every entry of `previous` that was not rendered again and whose files are all still in
// `dir` (plain file names of regular files, not symbolic links: an entry naming
// ../../etc/passwd or /etc/hostname is dropped). Ordered as `specs` lists the names; entries of no listed spec come last, in their
// previous order.
std::vector<FigureInfo> merge_index(const std::vector<FigureInfo>& previous, const std::vector<FigureInfo>& rendered,
                                    const std::vector<SpecFile>& specs, const std::string& dir);
// A self-contained gallery page, responsive from phones to wide screens: the figures in
// sections (the memo's, the filters, the companion texts' by the name prefixes "filter-" and
// "s00"), each with its title, its caption (markup as HTML: b_2 -> b<sub>2</sub>, \beta -> β),
// links to every file written (as URLs: '#', '?', '%' in a name percent-encoded; control
// characters of any text as U+FFFD), the SVG as the high-DPI source when there is one; figures whose
// caption says "at 1:1" are shown at their own pixel size. The footer gives the version and,
// when `date` >= 0 (seconds since 1970, e.g. SOURCE_DATE_EPOCH), the date. After loading it
// marks each <img> with data-loaded="yes" or "no", and <body> with data-images-ok and
// data-overflow (whether the page is wider than the window).
struct GalleryOptions {
  std::string version;  // "0.1.0"
  long long date = -1;
};
std::string gallery_html(const std::vector<FigureInfo>& figures, const GalleryOptions& options = {});

// Writes DIR/index.json and DIR/index.html for `rendered`, holding an advisory lock (flock) on
// DIR/.index.lock, so that runs into one directory at the same time merge one after the other
// instead of writing over each other's entries. With `keep`, the previous index is read under
// the lock (read_index_file) and merged (merge_index) with those of its entries `keep` accepts;
// without, the index is `rendered` alone. Throws std::runtime_error naming the file on failure,
// or when another process has held the lock for 60 s.
void update_index(const std::string& dir, const std::vector<FigureInfo>& rendered, const std::vector<SpecFile>& specs,
                  const std::function<bool(const FigureInfo&)>& keep, const GalleryOptions& gallery,
                  const std::function<void(const std::string&)>& warn);

// A label's markup (figures' rich text: _x, ^{..}, \name, $..$) as HTML: <sub>, <sup>, <i>
// and the UTF-8 symbols; text that is not valid markup is escaped as it is.
std::string markup_html(const std::string& markup);

// Writes `text` to `path` atomically (write_file_atomically, image/atomic_file.hpp); throws
// std::runtime_error naming the path on failure.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace splinefig::figures
