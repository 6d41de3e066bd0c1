// Basis functions as kernels, exactly from the matrix columns; the filter spec parser.
#include <splinefig/spline/basis_kernel.hpp>
#include <splinefig/spline/near_miss.hpp>
#include <splinefig/spline/points_csv.hpp>

#include <string>

namespace splinefig {

Kernel basis_kernel(const Basis& b) {
  const int n = b.degree;
  std::vector<std::vector<double>> pieces;
  for (int p = 0; p <= n; ++p) {
    std::vector<double> c;
    for (int m = 0; m <= n; ++m) c.push_back(b(n - m, n - p));
    pieces.push_back(std::move(c));
  }
  return Kernel::piecewise(b.spec, kernel_support(b).lo, std::move(pieces));
}

Kernel parse_kernel(std::string_view spec) {
  if (spec == "box") return Kernel::box();
  if (spec == "tent") return Kernel::tent();
  if (spec == "lanczos3") return Kernel::lanczos(3);
  if (spec.substr(0, spec.find(':')).empty()) throw SpecError("empty filter name");
  // The fixed kernels take no parameters: "lanczos3:a=2" is a parameter error, not an unknown name.
  if (const auto colon = spec.find(':'); colon != std::string_view::npos) {
    const std::string_view name = spec.substr(0, colon), rest = spec.substr(colon + 1);
    if (name == "box" || name == "tent" || name == "lanczos3") {
      if (rest.empty()) throw SpecError(std::string(name) + ": empty parameter list after ':'");
      throw SpecError(std::string(name) + ": unknown parameter " + excerpt(rest.substr(0, rest.find_first_of("=,")), '\'') +
                      " (it takes none" + (name == "lanczos3" ? "; its a is 3" : "") + ")");
    }
  }
  try {
    return basis_kernel(parse_basis(spec));
  } catch (const SpecError& e) {
    const std::string what = e.what();
    if (what.rfind("unknown basis", 0) == 0) {
      const std::string_view name = spec.substr(0, spec.find(':'));
      auto known = split_names(known_bases());
      const auto filters = split_names(known_filters());
      known.insert(known.begin(), filters.begin(), filters.end());
      const auto near = near_misses(name, known);
      throw SpecError("unknown filter " + excerpt(name, '\'') + " (" +
                      (near.empty() ? "" : "did you mean " + or_list(near) + "? ") +
                      "known: " + known_filters() + " and the bases " + known_bases() + ")");
    }
    throw;
  }
}

std::string known_filters() { return "box, tent, lanczos3"; }

}  // namespace splinefig
