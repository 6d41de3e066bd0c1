// [[axes.fill]] under an element: `under = "LABEL"` names a curve, kernel or series of the same
// axes by its label; the fill goes down (or up) to `baseline` (default 0) or to the element
// labelled `to` (docs/spec.md).
#include "spec_parse.hpp"

#include <string>

namespace splinefig::figures::detail {
namespace {

// The label of a curve, kernel or series (polygon, markers, generated series), if it has one.
const std::string* fillable_label(const PlotElement& e) {
  if (const auto* c = std::get_if<CurveElement>(&e)) return &c->label.label;
  if (const auto* k = std::get_if<KernelElement>(&e)) return &k->label.label;
  if (const auto* s = std::get_if<SeriesElement>(&e)) return &s->look.label.label;
  return nullptr;
}

}  // namespace

FillElement parse_fill_under(TableReader& r) {
  FillElement f;
  for (const char* key : {"points", "x", "y", "y2"})
    if (r.has(key)) r.fail(key, std::string("give either under or ") + key + ", not both");
  const auto label = [&](const char* key) {
    const std::string v = r.string(key, "");
    if (v.empty()) r.fail(key, "expected the label of a curve, kernel or series of these axes");
    return v;
  };
  f.origin = r.origin("under");
  f.under = label("under");
  if (r.has("to")) {
    if (r.has("baseline")) r.fail("baseline", "give either to or baseline, not both");
    f.to_origin = r.origin("to");
    f.to = label("to");
    if (f.to == f.under) r.fail("to", "the same element as under");
  }
  f.baseline = r.number("baseline", 0);
  f.color = r.color("color", *render::parse_hex_color("#1f77b440"));
  f.label = parse_labelling(r);
  return f;
}

void check_fill_references(const AxesSpec& ax) {
  for (const PlotElement& e : ax.elements) {
    const auto* f = std::get_if<FillElement>(&e);
    if (!f || f->under.empty()) continue;
    for (const std::string* want : {&f->under, &f->to}) {
      if (want->empty()) continue;
      int found = 0;
      std::string labels;
      for (const PlotElement& other : ax.elements)
        if (const std::string* l = fillable_label(other); l && !l->empty()) {
          found += *l == *want;
          labels += (labels.empty() ? "" : ", ") + ("\"" + *l + "\"");
        }
      const SpecLocation& key = want == &f->to ? f->to_origin : f->origin;
      if (found == 0)
        throw SpecFileError(key, "no curve, kernel or series labelled \"" + *want + "\" in these axes (" +
                            (labels.empty() ? std::string("none has a label") : "labels: " + labels) + ")");
      if (found > 1)
        throw SpecFileError(key, std::to_string(found) + " elements are labelled \"" + *want +
                            "\"; give them different labels");
    }
  }
}

}  // namespace splinefig::figures::detail
