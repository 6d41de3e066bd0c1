// Placeholder translation unit; replaced as the figures library grows.
namespace splinefig { [[maybe_unused]] static int figures_placeholder = 0; }
