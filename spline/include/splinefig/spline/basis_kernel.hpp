#pragma once
// Basis functions as kernels (kernel/kernel.hpp): the basis matrix's columns taken exactly as
// the pieces, and the spec parser that knows the comparison filters too.
#include <splinefig/kernel/kernel.hpp>
#include <splinefig/spline/basis.hpp>

#include <string>
#include <string_view>

namespace splinefig {

// k(s) of basis.hpp as a piecewise polynomial: piece p (on [h-n+p, h-n+p+1)) is column n - p
// of U M, its u^m coefficient M(n - m, n - p). Named by the basis's canonical spec.
Kernel basis_kernel(const Basis& b);

// Any basis spec (parse_basis), or one of known_filters(). Throws SpecError naming the unknown
// filter or the bad parameter.
Kernel parse_kernel(std::string_view spec);
// The filter names parse_kernel knows besides the bases, comma-separated: "box, tent, lanczos3"
// (lanczos3 is Lanczos's windowed sinc with a = 3).
std::string known_filters();

}  // namespace splinefig
